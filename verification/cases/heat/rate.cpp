// The heat cases' rate functions (heat/run.hpp), instantiated once for the three dimensions.
#include "verification/cases/heat/run.hpp"

namespace sphv::heat {
template Rate make_rate<1>(const ParticleSet<1>&, const std::string&, const sph::ConductionParams&);
template Rate make_rate<2>(const ParticleSet<2>&, const std::string&, const sph::ConductionParams&);
template Rate make_rate<3>(const ParticleSet<3>&, const std::string&, const sph::ConductionParams&);
}  // namespace sphv::heat
