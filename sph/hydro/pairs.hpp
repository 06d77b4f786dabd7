#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include <omp.h>

#include "sph/core/box.hpp"
#include "sph/core/isa.hpp"
#include "sph/core/stretches.hpp"
#include "sph/core/threads.hpp"
#include "sph/core/uninitialized.hpp"
#include "sph/kernel/cubic_spline.hpp"
#include "sph/search/neighbour_list.hpp"

namespace sph {

// Symmetric smoothing length of a pair (errata, 9.4.4): h_ij = (h_i + h_j) / 2.
inline double h_ij(double hi, double hj) { return 0.5 * (hi + hj); }

// A vector field (positions, velocities) as one array per dimension, x_i[d] = xs[d][i]: the pair
// loops gather them, and a vector gather takes an index times 8 bytes, not times 24 (Vec<3>).
// Columns are written whole after they are sized (default-initialised, no zeros written first).
template <int D>
using Components = std::array<std::vector<double, DefaultInitAllocator<double>>, D>;

template <int D>
void copy_components(const std::vector<Vec<D>>& x, Components<D>& xs) {
  const std::size_t n = x.size();
  for (int d = 0; d < D; ++d)
    xs[d].resize(n);  // default-initialised: no zeros before the copy below
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < D; ++d) xs[d][i] = x[i][d];
}
template <int D>
Components<D> components(const std::vector<Vec<D>>& x) {
  Components<D> xs;
  copy_components<D>(x, xs);
  return xs;
}

// |r_i - r_j|^2 at the nearest image, from positions held one array per dimension: the distance
// of the vectorised density loop (weight_sum_of).
// The loop over dimensions is unrolled by the pragma, here and in every loop over dimensions
// inside a vectorised pair loop: -O3 unrolls it anyway, but at -O2 (how the scenes are built,
// CMakeLists.txt) a loop left inside keeps the pair loop scalar. -O3's code is unchanged by the
// pragmas.
template <int D>
inline double distance2(std::size_t i, int j, const Components<D>& xs, const Vec<D>& L, const Vec<D>& wrap) {
  double r2 = 0.0;
#pragma GCC unroll 3
  for (int d = 0; d < D; ++d) {
    const double dx = min_image(xs[d][i] - xs[d][j], L[d], wrap[d]);
    r2 += dx * dx;
  }
  return r2;
}

// The geometry of a batch of listed pairs (i, j_t), t < nb: r_ij = r_i - r_j at the nearest image
// (dx[d][t]), |r_ij|, h_ij and the factor g_ij = K::dWdr(|r_ij|, h_ij) / |r_ij| of
// grad_i W_ij = g_ij r_ij (9) (0 at r = 0).
template <int D>
struct PairBatch {
  static constexpr int size = 64;
  double dx[D][size], r[size], h[size], g[size];
};

// The batch's geometry in the copy of one instruction set (pair_geometry below).
namespace detail {
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
}  // namespace detail

// Fills b for the pairs (i, js[t]), t < nb, without a branch, in a loop the compiler vectorises
// (gathers of x_j and h_j, the kernel's pieces as masks); in the copy of path (loop_path,
// core/isa.hpp). The cubic spline's copies are compiled once, in hydro/pair_geometry.cpp, rather
// than inlined into every scene's pair loop (the scenes do not change them, and the build would
// compile them again in each); another kernel's are compiled where a scene selects it.
template <int D, class K>
void pair_geometry([[maybe_unused]] IsaPath path, std::size_t i, const int* js, int nb, const Components<D>& xs,
                   const std::vector<double>& h, const Vec<D>& L, const Vec<D>& wrap, PairBatch<D>& b) {
#ifdef SPH_AVX2_COPY
  if constexpr (D == 3)  // the copies of loop_path (core/isa.hpp)
    if (path == IsaPath::avx512) return detail::batch_geometry_avx512<D, K>(i, js, nb, xs, h, L, wrap, b);
  if constexpr (D >= 2)
    if (path != IsaPath::portable) return detail::batch_geometry_avx2<D, K>(i, js, nb, xs, h, L, wrap, b);
#endif
  detail::batch_geometry<D, K>(i, js, nb, xs, h, L, wrap, b);
}

extern template void pair_geometry<1, CubicSpline<1>>(IsaPath, std::size_t, const int*, int, const Components<1>&,
                                                      const std::vector<double>&, const Vec<1>&, const Vec<1>&,
                                                      PairBatch<1>&);
extern template void pair_geometry<2, CubicSpline<2>>(IsaPath, std::size_t, const int*, int, const Components<2>&,
                                                      const std::vector<double>&, const Vec<2>&, const Vec<2>&,
                                                      PairBatch<2>&);
extern template void pair_geometry<3, CubicSpline<3>>(IsaPath, std::size_t, const int*, int, const Components<3>&,
                                                      const std::vector<double>&, const Vec<3>&, const Vec<3>&,
                                                      PairBatch<3>&);

// The pairs of particle i, in batches: the batch's geometry (pair_geometry), then, in list order,
// the pairs that interact (|r_ij| < h_ij: W_ij and grad W_ij vanish beyond): f(acc, i, j, r_ij,
// |r_ij|, h_ij, g_ij) adds pair j's share to acc (a local, so the sum stays in registers and no
// store inside the loop can alias the particle data the next pair reads), and store(i, acc) writes
// i's outputs once. The sums are in list order whatever the vector width. The loop of the kernel
// and Laplacian interpolants (for_each_pair); a scene's terms go through Scene::sums_of, which
// also vectorises the terms.
template <int D, class K, class Acc, class F, class Store>
inline void pairs_of(std::size_t i, IsaPath path, const Components<D>& xs, const std::vector<double>& h,
                     const NeighbourList& nl, const Vec<D>& L, const Vec<D>& wrap, F& f, Store& store) {
  PairBatch<D> b;
  const int* js = nl.j.data() + nl.offset[i];
  const int count = static_cast<int>(nl.offset[i + 1] - nl.offset[i]);
  Acc acc{};
  for (int t0 = 0; t0 < count; t0 += b.size) {
    const int nb = std::min(count - t0, b.size);
    pair_geometry<D, K>(path, i, js + t0, nb, xs, h, L, wrap, b);
    for (int t = 0; t < nb; ++t)
      if (b.r[t] < b.h[t]) {
        Vec<D> rij;
        for (int d = 0; d < D; ++d) rij[d] = b.dx[d][t];
        f(acc, i, js[t0 + t], rij, b.r[t], b.h[t], b.g[t]);
      }
  }
  store(i, acc);
}

// The sum over i's listed pairs of g(j, |r_ij|, h_ij) for a g that vanishes for |r_ij| >= h_ij (a
// kernel weight: W(r, h) = 0 beyond h, (6)): like pairs_of, every listed pair is evaluated without
// a branch, in vectorised batches, each summed in list order (the density (27)). The portable
// path has no vector gathers and stays scalar.
template <int D, class G>
inline double weight_sum_of(std::size_t i, const Components<D>& xs, const std::vector<double>& h,
                            const NeighbourList& nl, const Vec<D>& L, const Vec<D>& wrap, G& g) {
  constexpr int batch = 128;
  double value[batch];
  const int* js = nl.j.data() + nl.offset[i];
  const int count = static_cast<int>(nl.offset[i + 1] - nl.offset[i]);
  const double hi = h[i];
  double sum = 0.0;
  for (int t0 = 0; t0 < count; t0 += batch) {
    const int nb = std::min(count - t0, batch);
#pragma omp simd
    for (int t = 0; t < nb; ++t) {
      const int j = js[t0 + t];
      value[t] = g(j, std::sqrt(distance2<D>(i, j, xs, L, wrap)), h_ij(hi, h[j]));
    }
    for (int t = 0; t < nb; ++t) sum += value[t];
  }
  return sum;
}

// visit(i) for the particles the loop visits k0 .. k1-1, in three copies (core/isa.hpp): portable,
// with AVX2 and FMA, and with AVX-512 (3D only). Flattened: every call inside (the pair loop, the
// scene's terms, the kernel) is inlined and so compiled for the copy's instruction set; left to
// GCC's heuristics, a term that many scenes use (the viscosity) stays a portable call inside the
// AVX2 loop.
template <class Visit>
[[gnu::flatten]] void particles_in_portable(std::size_t k0, std::size_t k1, const NeighbourList& nl, Visit& visit) {
  for (std::size_t k = k0; k < k1; ++k) visit(nl.visit(k));
}
#ifdef SPH_AVX2_COPY
template <class Visit>
[[gnu::flatten, gnu::target("avx2,fma")]] void particles_in_avx2(std::size_t k0, std::size_t k1,
                                                                 const NeighbourList& nl, Visit& visit) {
  for (std::size_t k = k0; k < k1; ++k) visit(nl.visit(k));
}
template <class Visit>
[[gnu::flatten, gnu::target(SPH_AVX512_TARGET)]] void particles_in_avx512(std::size_t k0, std::size_t k1,
                                                                         const NeighbourList& nl, Visit& visit) {
  for (std::size_t k = k0; k < k1; ++k) visit(nl.visit(k));
}
#endif

// visit(i) for every particle i, in the list's visiting order. Each thread starts on one stretch of
// that order, the stretches holding about equal work (a particle's pairs, plus one for the
// particle): consecutive particles share most neighbours, which then stay in the thread's cache
// (small chunks handed to threads as they come free would interleave the threads' particles). A
// thread done with its stretch takes over the back of another's (core/stretches.hpp), so that a
// slowed core does not hold the other up. The stretches hold equal work, not equal length, so
// that taking over is the exception, not the rule. Each i is handled by one thread
// and writes only i's outputs, so the result is independent of the thread count and of which
// thread takes which chunk. The copies compiled are those up to `widest`; the one run is
// loop_path's (core/isa.hpp).
template <int D, IsaPath widest = IsaPath::avx512, class Visit>
void for_each_particle(std::size_t n, const NeighbourList& nl, Visit&& visit) {
  [[maybe_unused]] const IsaPath path = loop_path<D>(isa_path(), widest);
  auto stretch = [&](std::size_t k0, std::size_t k1) {
#ifdef SPH_AVX2_COPY
    if constexpr (D == 3 && widest == IsaPath::avx512)
      if (path == IsaPath::avx512) return particles_in_avx512(k0, k1, nl, visit);
    if constexpr (D >= 2 && widest != IsaPath::portable)
      if (path == IsaPath::avx2) return particles_in_avx2(k0, k1, nl, visit);
#endif
    particles_in_portable(k0, k1, nl, visit);
  };
  if (n < parallel_threshold) return stretch(0, n);
  Stretches stretches;
#pragma omp parallel
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    {
      std::vector<std::size_t> from(nt + 1, n);  // thread t's stretch: from[t] .. from[t + 1] - 1
      from[0] = 0;
      const double total = static_cast<double>(nl.pairs() + n);
      double work = 0.0;
      for (std::size_t k = 0, next = 1; k < n && next < static_cast<std::size_t>(nt); ++k) {
        const std::size_t i = nl.visit(k);
        work += static_cast<double>(nl.offset[i + 1] - nl.offset[i] + 1);
        for (; next < static_cast<std::size_t>(nt) && work >= total * next / nt; ++next) from[next] = k + 1;
      }
      stretches.reset(std::move(from));
    }
    stretches.work(t, [&](std::size_t, std::size_t k0, std::size_t k1) { stretch(k0, k1); });
  }
}

// visit(which[k]) for k < which.size(), in the copies of for_each_particle, the threads taking
// stretches of equal length (Stretches). `which` lists a subset of the particles, in the lists'
// visiting order for locality (the unconverged particles of an iteration). Each visit writes only
// its particle's outputs, so the result is independent of the thread count.
template <class Visit>
[[gnu::flatten]] void listed_in_portable(std::size_t k0, std::size_t k1, const int* which, Visit& visit) {
  for (std::size_t k = k0; k < k1; ++k) visit(static_cast<std::size_t>(which[k]));
}
#ifdef SPH_AVX2_COPY
template <class Visit>
[[gnu::flatten, gnu::target("avx2,fma")]] void listed_in_avx2(std::size_t k0, std::size_t k1, const int* which,
                                                              Visit& visit) {
  for (std::size_t k = k0; k < k1; ++k) visit(static_cast<std::size_t>(which[k]));
}
template <class Visit>
[[gnu::flatten, gnu::target(SPH_AVX512_TARGET)]] void listed_in_avx512(std::size_t k0, std::size_t k1,
                                                                      const int* which, Visit& visit) {
  for (std::size_t k = k0; k < k1; ++k) visit(static_cast<std::size_t>(which[k]));
}
#endif
template <int D, class Visit>
void for_each_listed(const std::vector<int>& which, Visit&& visit) {
  [[maybe_unused]] const IsaPath path = loop_path<D>(isa_path());
  auto stretch = [&](std::size_t k0, std::size_t k1) {
#ifdef SPH_AVX2_COPY
    if constexpr (D == 3)
      if (path == IsaPath::avx512) return listed_in_avx512(k0, k1, which.data(), visit);
    if constexpr (D >= 2)
      if (path == IsaPath::avx2) return listed_in_avx2(k0, k1, which.data(), visit);
#endif
    listed_in_portable(k0, k1, which.data(), visit);
  };
  const std::size_t n = which.size();
  if (n < parallel_threshold) return stretch(0, n);
  Stretches stretches;
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
#pragma omp single
    stretches.reset(n, omp_get_num_threads());
    stretches.work(t, [&](std::size_t, std::size_t k0, std::size_t k1) { stretch(k0, k1); });
  }
}

// The pair loop over every particle i (pairs_of), with the kernel K of grad W.
template <int D, class Acc, class K = CubicSpline<D>, class F, class Store>
void sum_over_pairs(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                    const Box<D>& box, F&& f, Store&& store) {
  const Vec<D> L = box.length(), wrap = box.wrap_factor();
  const Components<D> xs = components<D>(x);
  const IsaPath path = loop_path<D>(isa_path());
  for_each_particle<D>(x.size(), nl,
                       [&](std::size_t i) { pairs_of<D, K, Acc>(i, path, xs, h, nl, L, wrap, f, store); });
}

// store(i, sum of g(j, |r_ij|, h_ij) over i's pairs) for every particle i (weight_sum_of: g must
// vanish for |r_ij| >= h_ij). xs: the caller's buffer for the positions' columns, kept from one
// call to the next (see Scene::xs, hydro/scene.hpp).
template <int D, class G, class Store>
void sum_weights_over_pairs(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                            const Box<D>& box, Components<D>& xs, G&& g, Store&& store) {
  const Vec<D> L = box.length(), wrap = box.wrap_factor();
  copy_components<D>(x, xs);
  for_each_particle<D>(x.size(), nl, [&](std::size_t i) { store(i, weight_sum_of<D>(i, xs, h, nl, L, wrap, g)); });
}

// Calls f(i, j, r_ij, |r_ij|, h_ij) for every interacting pair (|r_ij| < h_ij); f may only write to i's own
// outputs (the pair loop above without an accumulator). K: the kernel whose support (every kernel's
// is h) and grad W the loop computes.
template <int D, class K = CubicSpline<D>, class F>
void for_each_pair(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                   const Box<D>& box, F&& f) {
  struct None {};
  sum_over_pairs<D, None, K>(
      x, h, nl, box,
      [&](None&, std::size_t i, int j, const Vec<D>& rij, double r, double hij, double) { f(i, j, rij, r, hij); },
      [](std::size_t, const None&) {});
}

}  // namespace sph
