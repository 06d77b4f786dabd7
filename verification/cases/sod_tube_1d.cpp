// The 1D shock tube, instantiated in its own translation unit (parallel builds).
#include "verification/cases/sod_simulate.hpp"

namespace sphv {
template TubeRun simulate_tube<1>(const TubeProblem&, const TubeMethod&, long);
}  // namespace sphv
