// The 3D shock tube, instantiated in its own translation unit (parallel builds).
#include "verification/cases/sod_simulate.hpp"

namespace sphv {
template TubeRun simulate_tube<3>(const TubeProblem&, const TubeMethod&, long);
}  // namespace sphv
