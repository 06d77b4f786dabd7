#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

#include "sph/search/neighbour_list.hpp"
#include "sph/search/tree.hpp"

namespace sph {

// Neighbour search by tree walk (9.4.3), open boundaries: from the root, descend into every
// node whose particles' bounding box comes closer to particle i than the largest search radius
// max(h_i, h_max of the node), and test the particles of the leaves reached. Pairs are kept
// when |r_ij| < max(h_i, h_j), the rule of grid_search, so both give the same neighbour sets.
// Each list is sorted by index (independent of the thread count).
template <int D>
NeighbourList tree_search(const Tree<D>& t, const std::vector<Vec<D>>& x, const std::vector<double>& h) {
  const std::size_t n = x.size();
  NeighbourList nl;
  nl.offset.assign(n + 1, 0);
  if (n == 0) return nl;
  // Largest support radius in each node, from the leaves up.
  std::vector<double> hmax(t.nodes.size(), 0.0);
  for (int k = static_cast<int>(t.nodes.size()) - 1; k >= 0; --k) {
    const auto& nd = t.nodes[k];
    if (nd.leaf())
      for (int q = nd.begin; q < nd.end; ++q) hmax[k] = std::max(hmax[k], h[t.order[q]]);
    else
      for (int c = 0; c < nd.n_children; ++c) hmax[k] = std::max(hmax[k], hmax[nd.first_child + c]);
  }
  auto visit = [&](std::size_t i, std::vector<int>& stack, auto&& emit) {
    stack.assign(1, 0);
    while (!stack.empty()) {
      const auto& nd = t.nodes[stack.back()];
      const double rs = std::max(h[i], hmax[stack.back()]);
      stack.pop_back();
      // Squared distance from x_i to the box; a relative margin of 1e-12 keeps a particle at
      // exactly the search radius from being pruned by the rounding of this distance.
      const Vec<D> gap = (nd.lo - x[i]).cwiseMax(x[i] - nd.hi).cwiseMax(0.0);
      if (gap.squaredNorm() > rs * rs * (1.0 + 1e-12)) continue;
      if (!nd.leaf()) {
        for (int c = 0; c < nd.n_children; ++c) stack.push_back(nd.first_child + c);
        continue;
      }
      for (int q = nd.begin; q < nd.end; ++q) {
        const int j = t.order[q];
        if (static_cast<std::size_t>(j) == i) continue;
        const double rs_ij = std::max(h[i], h[j]);
        if ((x[i] - x[j]).squaredNorm() < rs_ij * rs_ij) emit(j);
      }
    }
  };
  // Two passes (count, then fill) keep the list contiguous without locks.
#pragma omp parallel
  {
    std::vector<int> stack;
#pragma omp for schedule(dynamic, 256)
    for (std::size_t i = 0; i < n; ++i) {
      int count = 0;
      visit(i, stack, [&](int) { ++count; });
      nl.offset[i + 1] = count;
    }
  }
  for (std::size_t i = 0; i < n; ++i) nl.offset[i + 1] += nl.offset[i];
  nl.j.resize(nl.offset[n]);
#pragma omp parallel
  {
    std::vector<int> stack;
#pragma omp for schedule(dynamic, 256)
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t k = nl.offset[i];
      visit(i, stack, [&](int j) { nl.j[k++] = j; });
      std::sort(nl.j.begin() + nl.offset[i], nl.j.begin() + nl.offset[i + 1]);
    }
  }
  nl.order = t.order;  // leaf by leaf: a spatial order for the pair loops
  return nl;
}

}  // namespace sph
