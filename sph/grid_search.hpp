#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "sph/box.hpp"
#include "sph/neighbour_list.hpp"

namespace sph {

// Linked-cell grid search of section 9.4.3. Cells are at least as wide as the largest
// support radius, so the neighbours of a particle lie in its own and the adjacent cells.
// Pairs are kept when |r_ij| < max(h_i, h_j) (errata: symmetric interactions with variable h).
// Cost O(N) for bounded density contrast (errata). Each particle's list is in a fixed order
// (by cell, then by index), so results do not depend on the thread count.
template <int D>
NeighbourList grid_search(const std::vector<Vec<D>>& x, const std::vector<double>& h,
                          const Box<D>& box) {
  const std::size_t n = x.size();
  NeighbourList nl;
  nl.offset.assign(n + 1, 0);
  if (n == 0) return nl;
  const double hmax = *std::max_element(h.begin(), h.end());
  if (!(hmax > 0.0)) throw std::invalid_argument("grid search: support radius h must be > 0");

  // Extent: the box in periodic dimensions, the particles' bounding box in open ones.
  Vec<D> lo = box.lo, ext = box.length();
  for (int d = 0; d < D; ++d) {
    if (box.periodic[d]) {
      if (hmax > 0.5 * ext[d])
        throw std::invalid_argument("grid search: support radius exceeds half the periodic box");
      continue;
    }
    double a = x[0][d], b = x[0][d];
    for (const auto& xi : x) a = std::min(a, xi[d]), b = std::max(b, xi[d]);
    lo[d] = a;
    ext[d] = std::max(b - a, hmax);
  }
  std::array<int, D> nc;
  Vec<D> inv_cell;
  for (int d = 0; d < D; ++d) {
    nc[d] = std::max(1, std::min(1 << 20, static_cast<int>(ext[d] / hmax)));
    inv_cell[d] = nc[d] / ext[d];
  }
  auto cell_coord = [&](const Vec<D>& xi, int d) {
    int c = static_cast<int>(std::floor((xi[d] - lo[d]) * inv_cell[d]));
    if (box.periodic[d]) c = ((c % nc[d]) + nc[d]) % nc[d];
    return std::clamp(c, 0, nc[d] - 1);
  };
  auto flat = [&](const std::array<int, D>& c) {
    std::int64_t k = 0;
    for (int d = D - 1; d >= 0; --d) k = k * nc[d] + c[d];
    return k;
  };
  std::int64_t ncell = 1;
  for (int d = 0; d < D; ++d) ncell *= nc[d];

  // Counting sort of particles by cell (the chapter's linked list, stored contiguously).
  std::vector<std::int64_t> cell_of(n);
  std::vector<std::int64_t> start(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<int, D> c;
    for (int d = 0; d < D; ++d) c[d] = cell_coord(x[i], d);
    cell_of[i] = flat(c);
    ++start[cell_of[i] + 1];
  }
  for (std::int64_t c = 0; c < ncell; ++c) start[c + 1] += start[c];
  std::vector<int> sorted(n);
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) sorted[fill[cell_of[i]]++] = static_cast<int>(i);
  }

  // The distinct adjacent cells of a cell (fewer than 3^D when a periodic axis has < 3 cells).
  auto adjacent = [&](std::int64_t cell) {
    std::array<int, D> c;
    for (int d = 0; d < D; ++d) c[d] = static_cast<int>(cell % nc[d]), cell /= nc[d];
    std::vector<std::int64_t> out;
    std::array<int, D> o;
    o.fill(-1);
    while (true) {
      std::array<int, D> cc;
      bool inside = true;
      for (int d = 0; d < D; ++d) {
        cc[d] = c[d] + o[d];
        if (box.periodic[d]) cc[d] = (cc[d] + nc[d]) % nc[d];
        else if (cc[d] < 0 || cc[d] >= nc[d]) inside = false;
      }
      if (inside) out.push_back(flat(cc));
      int d = 0;
      while (d < D && ++o[d] > 1) o[d++] = -1;
      if (d == D) break;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  };

  const Vec<D> L = box.length(), wrap = box.wrap_factor();
  auto visit = [&](std::size_t i, auto&& emit) {
    for (std::int64_t c : adjacent(cell_of[i]))
      for (std::int64_t k = start[c]; k < start[c + 1]; ++k) {
        const int j = sorted[k];
        if (static_cast<std::size_t>(j) == i) continue;
        const double rs = std::max(h[i], h[j]);
        if (min_image<D>(x[i] - x[j], L, wrap).squaredNorm() < rs * rs) emit(j);
      }
  };
  // Two passes (count, then fill) keep the list contiguous without locks.
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    int count = 0;
    visit(i, [&](int) { ++count; });
    nl.offset[i + 1] = count;
  }
  for (std::size_t i = 0; i < n; ++i) nl.offset[i + 1] += nl.offset[i];
  nl.j.resize(nl.offset[n]);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t k = nl.offset[i];
    visit(i, [&](int j) { nl.j[k++] = j; });
  }
  return nl;
}

}  // namespace sph
