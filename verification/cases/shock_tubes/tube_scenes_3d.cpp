// The 3D shock tube instantiated (a file per dimension; one unit in a unity build, CMakeLists.txt).
#include "verification/cases/shock_tubes/simulate.hpp"

namespace sphv {
template TubeRun simulate_tube<3>(const TubeProblem&, const TubeMethod&, long);
}  // namespace sphv
