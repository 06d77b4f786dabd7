// The 2D shock tube instantiated (a file per dimension; one unit in a unity build, CMakeLists.txt).
#include "verification/cases/shock_tubes/simulate.hpp"

namespace sphv {
template TubeRun simulate_tube<2>(const TubeProblem&, const TubeMethod&, long);
}  // namespace sphv
