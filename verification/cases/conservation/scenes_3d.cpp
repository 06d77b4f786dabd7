// The conservation catalogue instantiated in 3D (a file per dimension; one unit in a unity build).
#include "verification/cases/conservation/catalogue.hpp"

namespace sphv::conservation {
template Catalogue catalogue<3>(const CatalogueSetup&);
}
