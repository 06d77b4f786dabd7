// Gas evolved in 3D (common/extreme_hydro.hpp) with the kernel named: the other kernels' scenes, one
// each, in a unit of its own (the file name keeps it out of the extreme_gas unit, CMakeLists.txt).
#include "verification/cases/common/extreme_hydro.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas_kernel<3>(const std::string&, sph::Particles<3>&, const sph::Box<3>&,
                                                      const Method&, sph::HydroHooks<3>);
}  // namespace sphv::extreme
