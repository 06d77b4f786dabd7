// The geometry of a batch of pairs (hydro/pairs.hpp) with the cubic spline, compiled once per
// dimension and instruction-set path.
#include "sph/hydro/pairs.hpp"

namespace sph {

template void pair_geometry<1, CubicSpline<1>>(IsaPath, std::size_t, const int*, int, const Components<1>&,
                                               const std::vector<double>&, const Vec<1>&, const Vec<1>&, PairBatch<1>&);
template void pair_geometry<2, CubicSpline<2>>(IsaPath, std::size_t, const int*, int, const Components<2>&,
                                               const std::vector<double>&, const Vec<2>&, const Vec<2>&, PairBatch<2>&);
template void pair_geometry<3, CubicSpline<3>>(IsaPath, std::size_t, const int*, int, const Components<3>&,
                                               const std::vector<double>&, const Vec<3>&, const Vec<3>&, PairBatch<3>&);

}  // namespace sph
