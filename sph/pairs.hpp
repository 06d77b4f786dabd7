#pragma once
#include <cstddef>
#include <vector>

#include "sph/box.hpp"
#include "sph/isa.hpp"
#include "sph/neighbour_list.hpp"
#include "sph/threads.hpp"

namespace sph {

// Symmetric smoothing length of a pair (errata, 9.4.4): h_ij = (h_i + h_j) / 2.
inline double h_ij(double hi, double hj) { return 0.5 * (hi + hj); }

// The pairs of one particle i: for every listed j that interacts with it (|r_ij| < h_ij: W_ij and
// grad W_ij vanish beyond), f(acc, i, j, r_ij, |r_ij|, h_ij) with r_ij = r_i - r_j at the nearest
// image adds pair j's share to acc (a local, so the sum stays in registers and no store inside the
// loop can alias the particle data the next pair reads), then store(i, acc) writes i's outputs once.
// Always inlined, so it is compiled for the instruction set of the loop that calls it.
template <int D, class Acc, class F, class Store>
[[gnu::always_inline]] inline void pairs_of(std::size_t i, const std::vector<Vec<D>>& x, const std::vector<double>& h,
                                            const NeighbourList& nl, const Vec<D>& L, const Vec<D>& wrap, F& f,
                                            Store& store) {
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

// The pair loop over every particle i, in the list's visiting order. Each i is handled by one
// thread and writes only i's outputs, so the result is independent of the thread count. Two copies
// (isa.hpp): the portable one, and for 2D and 3D one with AVX2 and FMA (1.4x on the 3D force loop).
template <int D, class Acc, class F, class Store>
void pair_loop_portable(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                        const Vec<D>& L, const Vec<D>& wrap, F& f, Store& store) {
  const std::size_t n = x.size();
#pragma omp parallel for schedule(dynamic, 256) if (n >= parallel_threshold)
  for (std::size_t k = 0; k < n; ++k) pairs_of<D, Acc>(nl.visit(k), x, h, nl, L, wrap, f, store);
}

#if defined(__x86_64__) && defined(__GNUC__)
template <int D, class Acc, class F, class Store>
[[gnu::target("avx2,fma")]] void pair_loop_avx2(const std::vector<Vec<D>>& x, const std::vector<double>& h,
                                                const NeighbourList& nl, const Vec<D>& L, const Vec<D>& wrap, F& f,
                                                Store& store) {
  const std::size_t n = x.size();
#pragma omp parallel for schedule(dynamic, 256) if (n >= parallel_threshold)
  for (std::size_t k = 0; k < n; ++k) pairs_of<D, Acc>(nl.visit(k), x, h, nl, L, wrap, f, store);
}
#endif

template <int D, class Acc, class F, class Store>
void sum_over_pairs(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                    const Box<D>& box, F&& f, Store&& store) {
  const Vec<D> L = box.length(), wrap = box.wrap_factor();
#if defined(__x86_64__) && defined(__GNUC__)
  if constexpr (D >= 2)  // 1D runs are small: a second copy would cost compile time, not run time
    if (isa_path() == IsaPath::avx2) return pair_loop_avx2<D, Acc>(x, h, nl, L, wrap, f, store);
#endif
  pair_loop_portable<D, Acc>(x, h, nl, L, wrap, f, store);
}

// Calls f(i, j, r_ij, |r_ij|, h_ij) for every interacting pair (|r_ij| < h_ij); f may only write to i's own
// outputs (the pair loop above without an accumulator).
template <int D, class F>
void for_each_pair(const std::vector<Vec<D>>& x, const std::vector<double>& h, const NeighbourList& nl,
                   const Box<D>& box, F&& f) {
  struct None {};
  sum_over_pairs<D, None>(
      x, h, nl, box,
      [&](None&, std::size_t i, int j, const Vec<D>& rij, double r, double hij)
          __attribute__((always_inline)) { f(i, j, rij, r, hij); },
      [](std::size_t, const None&) {});
}

}  // namespace sph
