// Gas evolved in 3D (common/extreme_hydro.hpp) instantiated (a file per dimension; one unit in a unity build).
#include "verification/cases/common/extreme_hydro.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas<3>(sph::Particles<3>&, const sph::Box<3>&, const Method&, sph::HydroHooks<3>);
}  // namespace sphv::extreme
