// The conservation catalogue instantiated in 2D (a file per dimension; one unit in a unity build).
#include "verification/cases/conservation/catalogue.hpp"

namespace sphv::conservation {
template Catalogue catalogue<2>(const CatalogueSetup&);
template Drifts run_pairing<2>(const sph::Particles<2>&, const EulerChoice&, const std::string&, bool,
                              sph::IntegratorKind, double, long);
}
