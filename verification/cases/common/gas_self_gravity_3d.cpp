// Gas with tree self-gravity in 3D (common/gas_self_gravity.hpp), in a unit of its own (the file name
// keeps it out of the cases' units, CMakeLists.txt).
#include "verification/cases/common/gas_self_gravity.hpp"

namespace sphv::extreme {
template sph::HydroOutcome evolve_gas<3, sph::SelfGravity>(sph::Particles<3>&, const sph::Box<3>&, const Method&,
                                                           sph::HydroHooks<3>, sph::SelfGravity&);
}  // namespace sphv::extreme
