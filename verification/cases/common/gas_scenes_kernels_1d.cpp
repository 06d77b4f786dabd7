// Gas evolved in 1D (common/extreme_hydro.hpp) with the kernel named: the other kernels' scenes, one
// each, in a unit of its own (the file name keeps it out of the extreme_gas unit, CMakeLists.txt).
#include "verification/cases/common/extreme_hydro.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas_kernel<1>(const std::string&, sph::Particles<1>&, const sph::Box<1>&,
                                                      const Method&, sph::HydroHooks<1>);
}  // namespace sphv::extreme
