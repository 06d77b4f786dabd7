#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

#include "sph/core/box.hpp"
#include "sph/core/isa.hpp"
#include "sph/core/threads.hpp"
#include "sph/search/neighbour_list.hpp"

namespace sph {

// Symmetric smoothing length of a pair (errata, 9.4.4): h_ij = (h_i + h_j) / 2.
inline double h_ij(double hi, double hj) { return 0.5 * (hi + hj); }

// The pairs of one particle i: for every listed j that interacts with it (|r_ij| < h_ij: W_ij and
// grad W_ij vanish beyond), f(acc, i, j, r_ij, |r_ij|, h_ij) with r_ij = r_i - r_j at the nearest
// image adds pair j's share to acc (a local, so the sum stays in registers and no store inside the
// loop can alias the particle data the next pair reads), then store(i, acc) writes i's outputs once.
template <int D, class Acc, class F, class Store>
inline void pairs_of(std::size_t i, const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                     const Vec<D>& L, const Vec<D>& wrap, F& f, Store& store) {
  Acc acc{};
  const Vec<D> xi = x[i];
  const double hi = h[i];
  for (int j : nl.of(i)) {
    const Vec<D> rij = min_image<D>(xi - x[j], L, wrap);
    const double r = rij.norm(), hij = h_ij(hi, h[j]);
    if (r < hij) f(acc, i, j, rij, r, hij);
  }
  store(i, acc);
}

// The particles the loop visits k0 .. k1-1, in two copies (core/isa.hpp): portable, and with
// AVX2 and FMA (1.4x on the 3D force loop). Flattened: every call inside (f, the scene's terms,
// the kernel) is inlined and so compiled for the copy's instruction set; left to GCC's
// heuristics, a term that many scenes use (the viscosity) stayed a portable call inside the AVX2
// loop, 10 % of a 3D step.
template <int D, class Acc, class F, class Store>
[[gnu::flatten]] void pairs_in_portable(std::size_t k0, std::size_t k1, const std::vector<Vec<D>>& x,
                                        const std::vector<double>& h, const NeighbourList& nl, const Vec<D>& L,
                                        const Vec<D>& wrap, F& f, Store& store) {
  for (std::size_t k = k0; k < k1; ++k) pairs_of<D, Acc>(nl.visit(k), x, h, nl, L, wrap, f, store);
}
#if defined(__x86_64__) && defined(__GNUC__)
#define SPH_AVX2_COPY 1
template <int D, class Acc, class F, class Store>
[[gnu::flatten, gnu::target("avx2,fma")]] void pairs_in_avx2(std::size_t k0, std::size_t k1,
                                                             const std::vector<Vec<D>>& x,
                                                             const std::vector<double>& h, const NeighbourList& nl,
                                                             const Vec<D>& L, const Vec<D>& wrap, F& f, Store& store) {
  for (std::size_t k = k0; k < k1; ++k) pairs_of<D, Acc>(nl.visit(k), x, h, nl, L, wrap, f, store);
}
#endif

// The pair loop over every particle i, in the list's visiting order, in chunks of 256 handed out
// to threads as they come free. Each i is handled by one thread and writes only i's outputs, so
// the result is independent of the thread count. 1D keeps the portable copy only: 1D runs are
// small, and a second copy would cost compile time, not run time.
template <int D, class Acc, class F, class Store>
void sum_over_pairs(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                    const Box<D>& box, F&& f, Store&& store) {
  const Vec<D> L = box.length(), wrap = box.wrap_factor();
  const std::size_t n = x.size();
  constexpr std::size_t chunk = 256;
  [[maybe_unused]] const bool avx2 = D >= 2 && isa_path() == IsaPath::avx2;
#pragma omp parallel for schedule(dynamic) if (n >= parallel_threshold)
  for (std::size_t k0 = 0; k0 < n; k0 += chunk) {
    const std::size_t k1 = std::min(n, k0 + chunk);
#ifdef SPH_AVX2_COPY
    if constexpr (D >= 2)
      if (avx2) {
        pairs_in_avx2<D, Acc>(k0, k1, x, h, nl, L, wrap, f, store);
        continue;
      }
#endif
    pairs_in_portable<D, Acc>(k0, k1, x, h, nl, L, wrap, f, store);
  }
}

// Calls f(i, j, r_ij, |r_ij|, h_ij) for every interacting pair (|r_ij| < h_ij); f may only write to i's own
// outputs (the pair loop above without an accumulator).
template <int D, class F>
void for_each_pair(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                   const Box<D>& box, F&& f) {
  struct None {};
  sum_over_pairs<D, None>(
      x, h, nl, box,
      [&](None&, std::size_t i, int j, const Vec<D>& rij, double r, double hij) { f(i, j, rij, r, hij); },
      [](std::size_t, const None&) {});
}

}  // namespace sph
