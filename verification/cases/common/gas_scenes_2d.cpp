// Gas evolved in 2D (common/extreme_hydro.hpp) instantiated (a file per dimension; one unit in a unity build).
#include "verification/cases/common/extreme_hydro.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas<2>(sph::Particles<2>&, const sph::Box<2>&, const Method&, sph::HydroHooks<2>);
}  // namespace sphv::extreme
