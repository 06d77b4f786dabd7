#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sph/core/box.hpp"
#include "sph/search/neighbour_list.hpp"

namespace sph {

// Linked-cell grid search of section 9.4.3. Pairs are kept when |r_ij| < max(h_i, h_j)
// (errata: symmetric interactions with variable h). Cost O(N) for bounded density contrast
// (errata). With nearly uniform h, cells are half the largest support radius wide and every
// particle searches the 5^D cells around its own. When a few particles are far wider than the
// rest (the hot, rarefied centre of a blast wave), cells follow the bulk's h instead (below), so
// the wide ones do not widen everyone's stencil: i searches the cells within its own h_i and keeps
// j when |r_ij| < h_i, and a pair with h_j <= |r_ij| < h_i, which j's own search misses, is then
// added to j's list. The chapter's linked list is stored as a counting sort, so each cell's
// positions lie contiguously; a periodic image is a shift per stencil cell, so the distance test
// needs no rounding, and the separation is computed as (x_i - x_j) - shift, the exact negative of
// j's, so both ends of a pair agree on it. Each particle's list is in a fixed order (its own finds
// by stencil cell, then by index; then any added ones in visiting order): results do not depend
// on the thread count. The cell order of the particles is returned as the list's visiting order.
// Candidates are tested without a branch; with nearly uniform h in 3D, four at a time on the AVX2
// and AVX-512 paths (core/isa.hpp), with the same operations in the same order as the portable
// loop: the same lists on every path. Compiled in search/grid_search.cpp.
//
// The search's arrays (the sorted copies, the threads' lists, the list itself) are kept by the
// caller from one search to the next (GridSearchBuffers): a run that searches every few steps then
// does not allocate, zero and fault in tens of megabytes each time.
template <int D>
struct GridSearchBuffers {
  std::vector<std::array<int, D>> coord;
  std::vector<std::int64_t> cell_of, start;
  std::vector<std::int64_t> fill;  // cursors: per thread and cell (the sort), then per row (missed pairs)
  std::vector<int> sorted, owner;
  std::array<std::vector<double>, D> xs;  // positions in cell order, one array per dimension
  std::vector<double> hs;
  std::vector<std::size_t> local;
  std::vector<std::vector<int, DefaultInitAllocator<int>>> parts;  // each thread's lists
  std::vector<std::vector<std::array<int, 2>, DefaultInitAllocator<std::array<int, 2>>>> missed;  // each thread's pairs for the other end
};

// The search into nl, with buffers kept from the last search (the list's own arrays as well).
// Throws std::invalid_argument when h is not positive and finite, or exceeds half a periodic box.
template <int D>
void grid_search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box, NeighbourList& nl,
                 GridSearchBuffers<D>& buf);

// A search with buffers of its own (a run that searches again keeps them: VerletList).
template <int D>
NeighbourList grid_search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
  NeighbourList nl;
  GridSearchBuffers<D> buf;
  grid_search<D>(x, h, box, nl, buf);
  return nl;
}

extern template void grid_search<1>(const std::vector<Vec<1>>&, const std::vector<double>&, const Box<1>&,
                                       NeighbourList&, GridSearchBuffers<1>&);
extern template NeighbourList grid_search<1>(const std::vector<Vec<1>>&, const std::vector<double>&, const Box<1>&);
extern template void grid_search<2>(const std::vector<Vec<2>>&, const std::vector<double>&, const Box<2>&,
                                       NeighbourList&, GridSearchBuffers<2>&);
extern template NeighbourList grid_search<2>(const std::vector<Vec<2>>&, const std::vector<double>&, const Box<2>&);
extern template void grid_search<3>(const std::vector<Vec<3>>&, const std::vector<double>&, const Box<3>&,
                                       NeighbourList&, GridSearchBuffers<3>&);
extern template NeighbourList grid_search<3>(const std::vector<Vec<3>>&, const std::vector<double>&, const Box<3>&);

}  // namespace sph
