#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <omp.h>

#include "sph/box.hpp"
#include "sph/neighbour_list.hpp"
#include "sph/pairs.hpp"

namespace sph {

// Linked-cell grid search of section 9.4.3. Pairs are kept when |r_ij| < max(h_i, h_j)
// (errata: symmetric interactions with variable h). Cost O(N) for bounded density contrast
// (errata). Cells are half the largest support radius wide and a particle searches the 5^D
// cells around its own (fewer candidates than 3^D cells of width h). The chapter's linked list
// is stored as a counting sort, so each cell's positions lie contiguously; a periodic image is
// a shift per stencil cell, so the distance test needs no rounding. Each particle's list is in
// a fixed order (by stencil cell, then by index): results do not depend on the thread count.
// The cell order of the particles is returned as the list's visiting order.
template <int D>
NeighbourList grid_search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
  const std::size_t n = x.size();
  NeighbourList nl;
  nl.offset.assign(n + 1, 0);
  if (n == 0) return nl;
  const double hmax = *std::max_element(h.begin(), h.end());
  if (!(hmax > 0.0) || !std::isfinite(hmax))
    throw std::invalid_argument("grid search: support radius h must be > 0 and finite");

  // Extent: the box in periodic dimensions, the particles' bounding box in open ones.
  const Vec<D> L = box.length();
  Vec<D> lo = box.lo, ext = L;
  for (int d = 0; d < D; ++d) {
    if (box.periodic[d]) {
      if (hmax > 0.5 * L[d]) throw std::invalid_argument("grid search: support radius exceeds half the periodic box");
      continue;
    }
    double a = x[0][d], b = x[0][d];
    for (const auto& xi : x) a = std::min(a, xi[d]), b = std::max(b, xi[d]);
    lo[d] = a;
    ext[d] = std::max(b - a, hmax);
  }
  // Cells of width >= hmax/2, widened so that there are at most ~2N cells (a clustered set in
  // a large open box would otherwise ask for far more cells than particles).
  double width = 0.5 * hmax;
  auto cells_along = [&](int d) { return std::max(1, static_cast<int>(std::min(ext[d] / width, 1e6))); };
  for (;;) {
    double total = 1.0;
    for (int d = 0; d < D; ++d) total *= cells_along(d);
    if (total <= 2.0 * n + 64) break;
    width *= 1.26;
  }
  std::array<int, D> nc;
  int reach = 1;  // stencil half-width in cells
  std::int64_t ncell = 1;
  for (int d = 0; d < D; ++d) {
    nc[d] = cells_along(d);
    reach = std::max(reach, static_cast<int>(std::ceil(hmax / (ext[d] / nc[d]) - 1e-12)));
    ncell *= nc[d];
  }
  auto flat = [&](const std::array<int, D>& c) {
    std::int64_t k = 0;
    for (int d = D - 1; d >= 0; --d) k = k * nc[d] + c[d];
    return k;
  };

  // Counting sort by cell; positions copied in that order (wrapped into a periodic box).
  std::vector<std::array<int, D>> coord(n);
  std::vector<std::int64_t> cell_of(n), start(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) {
      double xd = x[i][d] - lo[d];
      if (box.periodic[d]) xd -= L[d] * std::floor(xd / L[d]);
      coord[i][d] = std::clamp(static_cast<int>(xd / ext[d] * nc[d]), 0, nc[d] - 1);
    }
    cell_of[i] = flat(coord[i]);
    ++start[cell_of[i] + 1];
  }
  for (std::int64_t c = 0; c < ncell; ++c) start[c + 1] += start[c];
  std::vector<int> sorted(n);
  std::vector<Vec<D>> xs(n);
  std::vector<double> hs(n);
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t k = fill[cell_of[i]]++;
      sorted[k] = static_cast<int>(i);
      xs[k] = x[i];
      for (int d = 0; d < D; ++d)
        if (box.periodic[d]) xs[k][d] = lo[d] + (x[i][d] - lo[d]) - L[d] * std::floor((x[i][d] - lo[d]) / L[d]);
      hs[k] = h[i];
    }
  }

  // The stencil of a cell as runs of consecutive cells along x (contiguous in the sorted
  // arrays), each with the image shift that brings it next to the cell.
  struct Run {
    std::int64_t first, last;  // particle range [first, last) in sorted order
    Vec<D> shift;
  };
  auto stencil = [&](const std::array<int, D>& c, std::vector<Run>& out) {
    out.clear();
    std::array<int, D> o;
    o.fill(-reach);
    for (;;) {  // over the offsets in y, z; o[0] is unused
      std::array<int, D> cc;
      Vec<D> shift = Vec<D>::Zero();
      bool inside = true;
      for (int d = 1; d < D; ++d) {
        cc[d] = c[d] + o[d];
        if (box.periodic[d]) {
          const int wraps = static_cast<int>(std::floor(static_cast<double>(cc[d]) / nc[d]));
          cc[d] -= wraps * nc[d];
          shift[d] = wraps * L[d];
        } else if (cc[d] < 0 || cc[d] >= nc[d]) {
          inside = false;
        }
      }
      // Along x: split [c0 - reach, c0 + reach] where it wraps (periodic) or clip it (open).
      for (int a = c[0] - reach; inside && a <= c[0] + reach;) {
        int wraps = 0, b = c[0] + reach;
        if (box.periodic[0]) {
          wraps = static_cast<int>(std::floor(static_cast<double>(a) / nc[0]));
          b = std::min(b, (wraps + 1) * nc[0] - 1);
        } else {
          a = std::max(a, 0);
          b = std::min(b, nc[0] - 1);
          if (a > b) break;
        }
        cc[0] = a - wraps * nc[0];
        const std::int64_t first = flat(cc);
        shift[0] = wraps * L[0];
        out.push_back({start[first], start[first + (b - a) + 1], shift});
        a = b + 1;
      }
      int d = 1;
      while (d < D && ++o[d] > reach) o[d++] = -reach;
      if (d >= D) break;
    }
  };

  // One pass over the particles in cell order (each cell's stencil built once): each thread
  // fills the lists of a contiguous range into its own buffer; the lists are then copied into
  // particle order. Candidates are appended without a branch: each is written, and the end of
  // the list advances only if it is kept (a kept/rejected test mispredicts about a third of the time).
  std::vector<std::vector<int>> parts;
  std::vector<int> owner(n);
  std::vector<std::size_t> local(n);
#pragma omp parallel if (n >= parallel_threshold)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    parts.resize(nt);
    const std::size_t first = n * t / nt, last = n * (t + 1) / nt;
    std::vector<int>& js = parts[t];
    js.resize((last - first) * 64);
    std::size_t used = 0;
    std::vector<Run> sten;
    std::int64_t sten_of = -1;
    for (std::size_t s = first; s < last; ++s) {
      const std::size_t i = sorted[s];
      if (cell_of[i] != sten_of) stencil(coord[i], sten), sten_of = cell_of[i];
      owner[i] = t;
      local[i] = used;
      const double hi = hs[s];
      for (const Run& run : sten) {
        const Vec<D> xi = xs[s] - run.shift;
        if (used + (run.last - run.first) > js.size()) js.resize(2 * js.size() + (run.last - run.first));
        int* out = js.data() + used;
        for (std::int64_t k = run.first; k < run.last; ++k) {
          const double rs = std::max(hi, hs[k]);
          *out = sorted[k];
          out += ((xi - xs[k]).squaredNorm() < rs * rs) & (k != static_cast<std::int64_t>(s));
        }
        used = out - js.data();
      }
      nl.offset[i + 1] = used - local[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) nl.offset[i + 1] += nl.offset[i];
  nl.j.resize(nl.offset[n]);
  nl.order = std::move(sorted);
#pragma omp parallel for schedule(static) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
    std::copy_n(parts[owner[i]].begin() + local[i], nl.offset[i + 1] - nl.offset[i], nl.j.begin() + nl.offset[i]);
  return nl;
}

}  // namespace sph
