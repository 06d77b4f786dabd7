// Gas evolved in 1D (common/extreme_hydro.hpp) instantiated (a file per dimension; one unit in a unity build).
#include "verification/cases/common/extreme_hydro.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas<1>(sph::Particles<1>&, const sph::Box<1>&, const Method&, sph::HydroHooks<1>);
}  // namespace sphv::extreme
