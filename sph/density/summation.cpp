// Density by summation (sph/density/summation.hpp), compiled once per dimension.
#include "sph/density/summation.hpp"

namespace sph {
template void density_summation<1>(Particles<1>&, const NeighbourList&, const Box<1>&, Components<1>&);
template void density_summation<2>(Particles<2>&, const NeighbourList&, const Box<2>&, Components<2>&);
template void density_summation<3>(Particles<3>&, const NeighbourList&, const Box<3>&, Components<3>&);
}  // namespace sph
