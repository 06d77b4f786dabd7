// The geometry of a batch of pairs (hydro/pairs.hpp), compiled once per dimension and
// instruction-set path.
#include <cmath>

#include "sph/hydro/pairs.hpp"

namespace sph {

namespace {
template <int D, class K>
inline void batch_geometry(std::size_t i, const int* js, int nb, const Components<D>& xs,
                           const std::vector<double>& h, const Vec<D>& L, const Vec<D>& wrap, PairBatch<D>& b) {
  const double hi = h[i];
#pragma omp simd
  for (int t = 0; t < nb; ++t) {
    const int j = js[t];
    double r2 = 0.0;
#pragma GCC unroll 3
    for (int d = 0; d < D; ++d) {
      b.dx[d][t] = min_image(xs[d][i] - xs[d][j], L[d], wrap[d]);
      r2 += b.dx[d][t] * b.dx[d][t];
    }
    b.r[t] = std::sqrt(r2);
    b.h[t] = h_ij(hi, h[j]);
    b.g[t] = b.r[t] > 0.0 ? K::dWdr(b.r[t], b.h[t]) / b.r[t] : 0.0;
  }
}

#ifdef SPH_AVX2_COPY
template <int D, class K>
[[gnu::target("avx2,fma"), gnu::flatten]] void batch_geometry_avx2(std::size_t i, const int* js, int nb,
                                                                   const Components<D>& xs,
                                                                   const std::vector<double>& h, const Vec<D>& L,
                                                                   const Vec<D>& wrap, PairBatch<D>& b) {
  batch_geometry<D, K>(i, js, nb, xs, h, L, wrap, b);
}
template <int D, class K>
[[gnu::target(SPH_AVX512_TARGET), gnu::flatten]] void batch_geometry_avx512(std::size_t i, const int* js, int nb,
                                                                          const Components<D>& xs,
                                                                          const std::vector<double>& h,
                                                                          const Vec<D>& L, const Vec<D>& wrap,
                                                                          PairBatch<D>& b) {
  batch_geometry<D, K>(i, js, nb, xs, h, L, wrap, b);
}
#endif
}  // namespace

template <int D, class K>
void pair_geometry([[maybe_unused]] IsaPath path, std::size_t i, const int* js, int nb, const Components<D>& xs,
                   const std::vector<double>& h, const Vec<D>& L, const Vec<D>& wrap, PairBatch<D>& b) {
#ifdef SPH_AVX2_COPY
  if constexpr (D == 3)  // the copies of loop_path (core/isa.hpp)
    if (path == IsaPath::avx512) return batch_geometry_avx512<D, K>(i, js, nb, xs, h, L, wrap, b);
  if constexpr (D >= 2)
    if (path != IsaPath::portable) return batch_geometry_avx2<D, K>(i, js, nb, xs, h, L, wrap, b);
#endif
  batch_geometry<D, K>(i, js, nb, xs, h, L, wrap, b);
}

template void pair_geometry<1, CubicSpline<1>>(IsaPath, std::size_t, const int*, int, const Components<1>&,
                                               const std::vector<double>&, const Vec<1>&, const Vec<1>&, PairBatch<1>&);
template void pair_geometry<2, CubicSpline<2>>(IsaPath, std::size_t, const int*, int, const Components<2>&,
                                               const std::vector<double>&, const Vec<2>&, const Vec<2>&, PairBatch<2>&);
template void pair_geometry<3, CubicSpline<3>>(IsaPath, std::size_t, const int*, int, const Components<3>&,
                                               const std::vector<double>&, const Vec<3>&, const Vec<3>&, PairBatch<3>&);

}  // namespace sph
