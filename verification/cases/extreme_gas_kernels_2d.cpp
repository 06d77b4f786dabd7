// Gas evolved in 2D (extreme_hydro.hpp) with the kernels other than the cubic spline, one scene
// each, in a unit of its own (the file name keeps it out of the extreme_gas unit, CMakeLists.txt).
#include "verification/cases/extreme_hydro.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas_other_kernel<2>(const std::string&, sph::Particles<2>&, const sph::Box<2>&,
                                                      const Method&, sph::HydroHooks<2>);
}  // namespace sphv::extreme
