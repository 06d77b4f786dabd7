// Gas evolved in 2D (common/extreme_hydro.hpp) with the kernel named: the other kernels' scenes, one
// each, in a unit of its own (the file name keeps it out of the extreme_gas unit, CMakeLists.txt).
#include "verification/cases/common/extreme_hydro.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas_kernel<2>(const std::string&, sph::Particles<2>&, const sph::Box<2>&,
                                                      const Method&, sph::HydroHooks<2>);
}  // namespace sphv::extreme
