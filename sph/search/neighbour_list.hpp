#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "sph/core/uninitialized.hpp"

namespace sph {

// Interaction partners of every particle in compressed rows: the neighbours of i are
// j[offset[i]] .. j[offset[i+1]-1]. Lists are full (j in list(i) <=> i in list(j)); i itself
// is not listed, so self contributions (e.g. m_i W_ii in (27)) are added explicitly.
// `order` (optional) lists the particles in the search's spatial order (cell by cell): pair loops
// visit i in that order, so consecutive i share most neighbours while they are in cache, however
// the particles are stored. Each i's sum is unchanged by the order of the i.
struct NeighbourList {
  std::vector<std::size_t> offset;
  std::vector<int, DefaultInitAllocator<int>> j;  // written whole after each resize
  std::vector<int> order;

  // The k-th particle a pair loop visits.
  std::size_t visit(std::size_t k) const { return order.empty() ? k : static_cast<std::size_t>(order[k]); }

  std::span<const int> of(std::size_t i) const {
    return {j.data() + offset[i], j.data() + offset[i + 1]};
  }
  std::size_t pairs() const { return j.size(); }
};

}  // namespace sph
