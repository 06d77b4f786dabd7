// The conservation catalogue instantiated in 3D (compiled apart from the other dimension).
#include "verification/cases/conservation_catalogue.hpp"

namespace sphv::conservation {
template Catalogue catalogue<3>(const CatalogueSetup&);
}
