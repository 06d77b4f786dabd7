#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <omp.h>

#include "sph/core/box.hpp"
#include "sph/hydro/pairs.hpp"
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
// [[gnu::flatten]]: every callee inlined at -O2 too (the tests' build), where GCC otherwise keeps
// calls in the candidate loop: measured 0.040 s -> 0.021 s per search of 3e4 particles (-O3 0.019 s).
//
// The search's arrays (the sorted copies, the threads' lists, the list itself) are kept by the
// caller from one search to the next (GridSearchBuffers): a run that searches every few steps then
// does not allocate, zero and fault in tens of megabytes each time (measured: a fifth of evolve's
// time at N = 125,000).
template <int D>
struct GridSearchBuffers {
  std::vector<std::array<int, D>> coord;
  std::vector<std::int64_t> cell_of, start;
  std::vector<int> sorted, owner;
  std::vector<Vec<D>> xs;
  std::vector<double> hs;
  std::vector<std::size_t> local, extra;
  std::vector<std::vector<int>> parts;                      // each thread's lists
  std::vector<std::vector<std::array<int, 2>>> missed;      // each thread's pairs for the other end
};

// The search into nl, with buffers kept from the last search (the list's own arrays as well).
template <int D>
[[gnu::flatten]] void grid_search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box,
                                  NeighbourList& nl, GridSearchBuffers<D>& buf) {
  const std::size_t n = x.size();
  nl.offset.assign(n + 1, 0);
  nl.j.clear();
  nl.order.clear();
  if (n == 0) return;
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
  // Cells of width >= h_c/2. h_c = h_max when h is nearly uniform (h_max < 1.5 h_median); else
  // the one among h_max and quantiles of h that minimises the volume searched,
  // sum_i ((2 ceil(h_i / (h_c/2)) + 1) h_c/2)^D: the bulk's h when a few particles are far wider.
  double width = 0.5 * hmax;
  double hmin = hmax;  // of the positive finite h
  for (double hi : h)
    if (hi > 0.0 && hi < hmin) hmin = hi;
  if (hmax >= 1.5 * hmin) {  // else h_max < 1.5 h_median for sure: no quantiles needed
    std::vector<double> hq;  // the positive finite h (a NaN would break the ordering)
    hq.reserve(n);
    for (double hi : h)
      if (hi > 0.0 && hi <= hmax) hq.push_back(hi);
    auto quantile = [&](double q) {
      const auto at = hq.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(hq.size() - 1));
      std::nth_element(hq.begin(), at, hq.end());
      return *at;
    };
    if (!hq.empty() && hmax >= 1.5 * quantile(0.5)) {
      double least = std::numeric_limits<double>::infinity();
      for (double q : {1.0, 0.99, 0.9, 0.5}) {
        const double c = 0.5 * quantile(q);
        double volume = 0.0;
        for (double hi : hq) {
          const double side = (2.0 * std::max(1.0, std::ceil(hi / c - 1e-12)) + 1.0) * c;
          double v = side;
          for (int d = 1; d < D; ++d) v *= side;
          volume += v;
        }
        if (volume < least) least = volume, width = c;
      }
    }
  }
  auto cells_along = [&](int d) { return std::max(1, static_cast<int>(std::min(ext[d] / width, 1e6))); };
  for (;;) {
    double total = 1.0;
    for (int d = 0; d < D; ++d) total *= cells_along(d);
    if (total <= 2.0 * n + 64) break;
    width *= 1.26;
  }
  std::array<int, D> nc;
  double cell = 0.0;  // the narrowest cell side
  std::int64_t ncell = 1;
  for (int d = 0; d < D; ++d) {
    nc[d] = cells_along(d);
    cell = d == 0 ? ext[0] / nc[0] : std::min(cell, ext[d] / nc[d]);
    ncell *= nc[d];
  }
  // Stencil half-width in cells for a support radius hv (NaN or h <= 0: the own cell's neighbours).
  auto reach_of = [&](double hv) { return hv > 0.0 ? std::max(1, static_cast<int>(std::ceil(hv / cell - 1e-12))) : 1; };
  auto flat = [&](const std::array<int, D>& c) {
    std::int64_t k = 0;
    for (int d = D - 1; d >= 0; --d) k = k * nc[d] + c[d];
    return k;
  };

  // Counting sort by cell; positions copied in that order (wrapped into a periodic box).
  auto& [coord, cell_of, start, sorted, owner, xs, hs, local, extra, parts, missed] = buf;
  coord.resize(n);
  cell_of.resize(n);
  start.assign(ncell + 1, 0);
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) {
      double xd = x[i][d] - lo[d];
      if (box.periodic[d]) xd -= L[d] * std::floor(xd / L[d]);
      coord[i][d] = std::clamp(static_cast<int>(xd / ext[d] * nc[d]), 0, nc[d] - 1);
    }
    cell_of[i] = flat(coord[i]);
  }
  for (std::size_t i = 0; i < n; ++i) ++start[cell_of[i] + 1];
  for (std::int64_t c = 0; c < ncell; ++c) start[c + 1] += start[c];
  sorted.resize(n);
  xs.resize(n);
  hs.resize(n);
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) sorted[fill[cell_of[i]]++] = static_cast<int>(i);
  }
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = sorted[k];
    xs[k] = x[i];
    for (int d = 0; d < D; ++d)
      if (box.periodic[d]) xs[k][d] = lo[d] + (x[i][d] - lo[d]) - L[d] * std::floor((x[i][d] - lo[d]) / L[d]);
    hs[k] = h[i];
  }

  // The stencil of a cell as runs of consecutive cells along x (contiguous in the sorted
  // arrays), each with the image shift that brings it next to the cell.
  struct Run {
    std::int64_t first, last;  // particle range [first, last) in sorted order
    Vec<D> shift;
  };
  auto stencil = [&](const std::array<int, D>& c, int reach, std::vector<Run>& out) {
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

  // One pass over the particles in cell order (a stencil built once per cell and reach): each
  // thread fills the lists of a contiguous range into its own buffer. Nearly uniform h (cells of
  // h_max/2): every particle searches h_max and keeps |r_ij| < max(h_i, h_j). Wide h: i searches
  // its own h_i, keeps |r_ij| < h_i and notes the pairs the other end misses as (j, i) in visiting
  // order (h_j <= |r_ij| < h_i). Candidates are appended without a branch: each is written, and
  // the end of the list advances only if it is kept (a kept/rejected test mispredicts about a
  // third of the time).
  owner.resize(n);
  local.resize(n);
  std::size_t team = 1;  // threads of this search (the buffers may have more, from an earlier one)
#pragma omp parallel if (n >= parallel_threshold)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    {
      team = static_cast<std::size_t>(nt);
      if (parts.size() < team) parts.resize(team), missed.resize(team);
    }
    const std::size_t first = n * t / nt, last = n * (t + 1) / nt;
    std::vector<int>& js = parts[t];
    std::vector<std::array<int, 2>>& mt = missed[t];
    js.resize(std::max(js.size(), (last - first) * 64));
    std::size_t used = 0, nm = 0;
    std::vector<Run> sten;
    std::int64_t sten_of = -1;
    int sten_reach = 0;
    auto scan = [&](auto wide) {  // a compile-time choice: no test of the mode per candidate
      for (std::size_t s = first; s < last; ++s) {
        const std::size_t i = sorted[s];
        const double hi = hs[s];
        const int reach = reach_of(wide ? hi : hmax);
        if (cell_of[i] != sten_of || reach != sten_reach) stencil(coord[i], reach, sten), sten_of = cell_of[i], sten_reach = reach;
        owner[i] = t;
        local[i] = used;
        for (const Run& run : sten) {
          const std::size_t cand = run.last - run.first;
          if (used + cand > js.size()) js.resize(2 * js.size() + cand);
          if (wide && nm + cand > mt.size()) mt.resize(2 * mt.size() + cand);
          int* out = js.data() + used;
          std::array<int, 2>* miss = mt.data() + nm;
          for (std::int64_t k = run.first; k < run.last; ++k) {
            const double r2 = (xs[s] - xs[k] - run.shift).squaredNorm();
            const double rs = wide ? hi : std::max(hi, hs[k]);
            const bool kept = (r2 < rs * rs) & (k != static_cast<std::int64_t>(s));
            *out = sorted[k];
            out += kept;
            if constexpr (wide) {
              *miss = {sorted[k], static_cast<int>(i)};
              miss += kept & !(r2 < hs[k] * hs[k]);
            }
          }
          used = out - js.data();
          nm = miss - mt.data();
        }
        nl.offset[i + 1] = used - local[i];
      }
    };
    if (width < 0.5 * hmax) scan(std::true_type{});
    else scan(std::false_type{});
    mt.resize(nm);
  }
  // The missed pairs, counted per receiving particle in visiting order (threads' ranges in order).
  extra.assign(n + 1, 0);
  for (std::size_t t = 0; t < team; ++t)
    for (const auto& jm : missed[t]) ++extra[jm[0] + 1];
  for (std::size_t i = 0; i < n; ++i) extra[i + 1] += extra[i];
  for (std::size_t i = 0; i < n; ++i) nl.offset[i + 1] += nl.offset[i] + (extra[i + 1] - extra[i]);
  nl.j.resize(nl.offset[n]);
  {
    std::vector<std::size_t> fill(n);
    for (std::size_t i = 0; i < n; ++i) fill[i] = nl.offset[i + 1] - (extra[i + 1] - extra[i]);
    for (std::size_t t = 0; t < team; ++t)
      for (const auto& jm : missed[t]) nl.j[fill[jm[0]]++] = jm[1];
  }
#pragma omp parallel for schedule(static) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
    std::copy_n(parts[owner[i]].begin() + local[i], nl.offset[i + 1] - nl.offset[i] - (extra[i + 1] - extra[i]),
                nl.j.begin() + nl.offset[i]);
  nl.order.swap(sorted);  // the last order's array becomes the next search's buffer
}

// A search with buffers of its own (a run that searches again keeps them: VerletList).
template <int D>
NeighbourList grid_search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
  NeighbourList nl;
  GridSearchBuffers<D> buf;
  grid_search<D>(x, h, box, nl, buf);
  return nl;
}

// Compiled once, in sph/search/grid_search.cpp, instead of in each of the ~40 files that search
// (about 0.9 s of compile time each per dimension, measured).
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
