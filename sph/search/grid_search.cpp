// The grid search (search/grid_search.hpp), compiled once per dimension; in 3D its candidate
// loop has copies for AVX2 and AVX-512 (core/isa.hpp).
#include "sph/search/grid_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <omp.h>

#include "sph/core/isa.hpp"
#include "sph/core/stretches.hpp"
#include "sph/core/threads.hpp"
#include "sph/search/lane_compaction.hpp"

#ifdef SPH_AVX2_COPY
#include <immintrin.h>
#endif

namespace sph {

namespace {

// Candidates read past a run's end by the vectorised loops; the sorted arrays are padded by as many.
constexpr std::size_t lanes = 8;

// A run of consecutive cells of a stencil along x: the particles [first, last) in sorted order,
// with the image shift that brings them next to the searching particle's cell.
template <int D>
struct Run {
  std::int64_t first, last;
  Vec<D> shift;
};

// The sorted copies: positions one array per dimension, support radii, particle indices.
template <int D>
struct Sorted {
  std::array<const double*, D> x;
  const double* h;
  const int* index;
};

// |(x_s - x_k) - shift|^2 of sorted particles s and k, summed as Eigen's squaredNorm sums it
// (x^2 + (y^2 + z^2) in 3D), which the vectorised loop repeats.
template <int D>
inline double distance2(const Sorted<D>& v, std::size_t s, std::int64_t k, const Vec<D>& shift) {
  Vec<D> dx;
  for (int d = 0; d < D; ++d) dx[d] = (v.x[d][s] - v.x[d][k]) - shift[d];
  return dx.squaredNorm();
}

// The candidates of sorted particle s in its stencil's runs: the particles k != s with
// |r_sk| < max(h_s, h_k), their indices written to out in stencil order; returns how many. Each
// candidate is written and the end of the list advances only if it is kept: no branch (a
// kept/rejected test mispredicts about a third of the time).
template <int D>
inline std::size_t candidates(std::size_t s, const std::vector<Run<D>>& sten, const Sorted<D>& v, int* out) {
  int* const begin = out;
  const double hi = v.h[s];
  for (const Run<D>& run : sten)
    for (std::int64_t k = run.first; k < run.last; ++k) {
      const double rs = std::max(hi, v.h[k]);
      *out = v.index[k];
      out += (distance2(v, s, k, run.shift) < rs * rs) & (k != static_cast<std::int64_t>(s));
    }
  return static_cast<std::size_t>(out - begin);
}

// The counts own_reach writes.
struct Found {
  std::size_t listed, missed;
};

// With wide h: the candidates k of sorted particle s (particle i) within its own h_s, written to
// out in stencil order, and the pairs the other end misses (h_k <= |r_sk| < h_s) as (k, i) to
// miss, both without a branch. Not inlined: inside the search's loop GCC 12 spills `kept` as a
// byte and reloads it as a word, a failed store forwarding per candidate.
template <int D>
[[gnu::noinline]] Found own_reach(std::size_t s, int i, const std::vector<Run<D>>& sten, const Sorted<D>& v,
                                  int* out, std::array<int, 2>* miss) {
  int* const out0 = out;
  std::array<int, 2>* const miss0 = miss;
  const double hi = v.h[s];
  for (const Run<D>& run : sten)
    for (std::int64_t k = run.first; k < run.last; ++k) {
      const double r2 = distance2(v, s, k, run.shift);
      const bool kept = (r2 < hi * hi) & (k != static_cast<std::int64_t>(s));
      const int j = v.index[k];
      *out = j;
      out += kept;
      *miss = {j, i};
      miss += kept & !(r2 < v.h[k] * v.h[k]);
    }
  return {static_cast<std::size_t>(out - out0), static_cast<std::size_t>(miss - miss0)};
}

#ifdef SPH_AVX2_COPY
// candidates in 3D with AVX2, four consecutive candidates at a time, the kept ones moved to the
// front of a 4-lane store (which may write entries past them: the list has room); with `wide`,
// own_reach: kept within h_s, and the few pairs the other end misses written one by one, in their
// order. Without FMA, so each lane rounds as the portable loop does: the same lists on every path
// (verification/tests/grid_search.cpp).
template <bool wide>
[[gnu::target("avx2")]] Found reach_avx2(std::size_t s, int i, const std::vector<Run<3>>& sten, Sorted<3> v, int* out,
                                         std::array<int, 2>* miss) {
  const __m256d xi = _mm256_set1_pd(v.x[0][s]), yi = _mm256_set1_pd(v.x[1][s]), zi = _mm256_set1_pd(v.x[2][s]),
                hi = _mm256_set1_pd(v.h[s]);
  std::size_t used = 0, missed = 0;
  for (const Run<3>& run : sten) {
    const __m256d sx = _mm256_set1_pd(run.shift[0]), sy = _mm256_set1_pd(run.shift[1]),
                  sz = _mm256_set1_pd(run.shift[2]);
    for (std::int64_t k = run.first; k < run.last; k += 4) {
      const __m256d dx = _mm256_sub_pd(_mm256_sub_pd(xi, _mm256_loadu_pd(v.x[0] + k)), sx),
                    dy = _mm256_sub_pd(_mm256_sub_pd(yi, _mm256_loadu_pd(v.x[1] + k)), sy),
                    dz = _mm256_sub_pd(_mm256_sub_pd(zi, _mm256_loadu_pd(v.x[2] + k)), sz);
      const __m256d r2 =
          _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_add_pd(_mm256_mul_pd(dy, dy), _mm256_mul_pd(dz, dz)));
      const __m256d hk = _mm256_loadu_pd(v.h + k);
      const __m256d hm = wide ? hi : _mm256_max_pd(hk, hi);  // std::max(h_s, h_k)
      const std::int64_t left = run.last - k;
      const std::uint64_t self = static_cast<std::uint64_t>(s) - static_cast<std::uint64_t>(k);
      const int keep = _mm256_movemask_pd(_mm256_cmp_pd(r2, _mm256_mul_pd(hm, hm), _CMP_LT_OQ)) &
                       (left >= 4 ? 15 : (1 << left) - 1) & (self < 4 ? ~(1 << self) : 15);
      const __m128i j4 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(v.index + k));
      _mm_storeu_si128(
          reinterpret_cast<__m128i*>(out + used),
          _mm_shuffle_epi8(j4, _mm_loadu_si128(reinterpret_cast<const __m128i*>(compaction[keep].data()))));
      used += static_cast<std::size_t>(__builtin_popcount(keep));
      if constexpr (wide)  // kept, and not within h_k
        for (int m = keep & _mm256_movemask_pd(_mm256_cmp_pd(r2, _mm256_mul_pd(hk, hk), _CMP_NLT_UQ)); m; m &= m - 1)
          miss[missed++] = {v.index[k + __builtin_ctz(m)], i};
    }
  }
  return {used, missed};
}

// reach_avx2 with AVX-512, eight candidates at a time, compacted by vpcompressd into a register
// (the form that writes memory is slow on AMD's Zen 4). The file is compiled without FMA
// contraction (CMakeLists.txt), which AVX-512 would otherwise allow.
template <bool wide>
[[gnu::target(SPH_AVX512_TARGET)]] Found reach_avx512(std::size_t s, int i, const std::vector<Run<3>>& sten,
                                                      Sorted<3> v, int* out, std::array<int, 2>* miss) {
  const __m512d xi = _mm512_set1_pd(v.x[0][s]), yi = _mm512_set1_pd(v.x[1][s]), zi = _mm512_set1_pd(v.x[2][s]),
                hi = _mm512_set1_pd(v.h[s]);
  std::size_t used = 0, missed = 0;
  for (const Run<3>& run : sten) {
    const __m512d sx = _mm512_set1_pd(run.shift[0]), sy = _mm512_set1_pd(run.shift[1]),
                  sz = _mm512_set1_pd(run.shift[2]);
    for (std::int64_t k = run.first; k < run.last; k += 8) {
      const __m512d dx = _mm512_sub_pd(_mm512_sub_pd(xi, _mm512_loadu_pd(v.x[0] + k)), sx),
                    dy = _mm512_sub_pd(_mm512_sub_pd(yi, _mm512_loadu_pd(v.x[1] + k)), sy),
                    dz = _mm512_sub_pd(_mm512_sub_pd(zi, _mm512_loadu_pd(v.x[2] + k)), sz);
      const __m512d r2 =
          _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_add_pd(_mm512_mul_pd(dy, dy), _mm512_mul_pd(dz, dz)));
      const __m512d hk = _mm512_loadu_pd(v.h + k);
      // std::max(h_s, h_k); the masked form: GCC 12 warns that _mm512_max_pd's undefined operand
      // may be used uninitialised
      const __m512d hm = wide ? hi : _mm512_maskz_max_pd(0xff, hk, hi);
      const std::int64_t left = run.last - k;
      const std::uint64_t self = static_cast<std::uint64_t>(s) - static_cast<std::uint64_t>(k);
      const unsigned keep = _mm512_cmp_pd_mask(r2, _mm512_mul_pd(hm, hm), _CMP_LT_OQ) &
                            (left >= 8 ? 255u : (1u << left) - 1) & (self < 8 ? ~(1u << self) : 255u);
      const __m256i j8 = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(v.index + k));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + used),
                          _mm256_maskz_compress_epi32(static_cast<__mmask8>(keep), j8));
      used += static_cast<std::size_t>(__builtin_popcount(keep));
      if constexpr (wide)  // kept, and not within h_k
        for (unsigned m = keep & _mm512_cmp_pd_mask(r2, _mm512_mul_pd(hk, hk), _CMP_NLT_UQ); m; m &= m - 1)
          miss[missed++] = {v.index[k + __builtin_ctz(m)], i};
    }
  }
  return {used, missed};
}
#endif

// own_reach in the copy of path, as candidates_on.
template <int D>
inline Found own_reach_on([[maybe_unused]] IsaPath path, std::size_t s, int i, const std::vector<Run<D>>& sten,
                          const Sorted<D>& v, int* out, std::array<int, 2>* miss) {
#ifdef SPH_AVX2_COPY
  if constexpr (D == 3) {
    if (path == IsaPath::avx512) return reach_avx512<true>(s, i, sten, v, out, miss);
    if (path == IsaPath::avx2) return reach_avx2<true>(s, i, sten, v, out, miss);
  }
#endif
  return own_reach<D>(s, i, sten, v, out, miss);
}

// candidates in the copy of path (loop_path, core/isa.hpp): in 3D the vectorised ones.
template <int D>
inline std::size_t candidates_on([[maybe_unused]] IsaPath path, std::size_t s, const std::vector<Run<D>>& sten,
                                 const Sorted<D>& v, int* out) {
#ifdef SPH_AVX2_COPY
  if constexpr (D == 3) {
    if (path == IsaPath::avx512) return reach_avx512<false>(s, 0, sten, v, out, nullptr).listed;
    if (path == IsaPath::avx2) return reach_avx2<false>(s, 0, sten, v, out, nullptr).listed;
  }
#endif
  return candidates(s, sten, v, out);
}

}  // namespace

// [[gnu::flatten]]: every callee inlined at -O2 too (the tests' build), where GCC otherwise keeps
// calls in the candidate loop, which then runs at about half -O3's speed.
template <int D>
[[gnu::flatten]] void grid_search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box,
                                  NeighbourList& nl, GridSearchBuffers<D>& buf) {
  const std::size_t n = x.size();
  const std::size_t last_pairs = nl.j.size();  // the last search's, when nl is kept from it
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
      const std::array<double, 4> c{0.5 * quantile(1.0), 0.5 * quantile(0.99), 0.5 * quantile(0.9), 0.5 * quantile(0.5)};
      // Each candidate's volume summed over fixed blocks of hq on all threads (serially the sums are
      // a noticeable share of a threaded search), the blocks in order: the same sums on any thread
      // count.
      constexpr std::size_t blocks = 64;
      std::array<std::array<double, 4>, blocks> part;
      const std::size_t nq = hq.size();
#pragma omp parallel for if (nq >= parallel_threshold)
      for (std::size_t k = 0; k < blocks; ++k) {
        std::array<double, 4> volume{};
        for (std::size_t q = nq * k / blocks; q < nq * (k + 1) / blocks; ++q)
          for (int m = 0; m < 4; ++m) {
            const double side = (2.0 * std::max(1.0, std::ceil(hq[q] / c[m] - 1e-12)) + 1.0) * c[m];
            double v = side;
            for (int d = 1; d < D; ++d) v *= side;
            volume[m] += v;
          }
        part[k] = volume;
      }
      double least = std::numeric_limits<double>::infinity();
      for (int m = 0; m < 4; ++m) {
        double volume = 0.0;
        for (const std::array<double, 4>& b : part) volume += b[m];
        if (volume < least) least = volume, width = c[m];
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

  // Counting sort by cell, stable (by index within a cell, as a serial sort): each thread counts
  // the cells of a contiguous range of indices, a cell's slots go to the threads in order, and each
  // thread places its range. Positions then copied in that order (wrapped into a periodic box).
  auto& [coord, cell_of, start, fill, sorted, owner, xs, hs, local, parts, missed] = buf;
  coord.resize(n);
  cell_of.resize(n);
  start.resize(ncell + 1);  // every entry is written below
  // Padded by a vector's lanes of zeros (vectorised loads past the last candidate).
  sorted.resize(n + lanes);
  for (int d = 0; d < D; ++d) xs[d].resize(n + lanes);
  hs.resize(n + lanes);
  for (std::size_t k = n; k < n + lanes; ++k) {
    sorted[k] = 0;
    for (int d = 0; d < D; ++d) xs[d][k] = 0.0;
    hs[k] = 0.0;
  }
#pragma omp parallel if (n >= parallel_threshold)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const std::size_t first = n * t / nt, last = n * (t + 1) / nt;
#pragma omp single
    fill.resize(static_cast<std::size_t>(nt * ncell));
    std::int64_t* mine = fill.data() + t * ncell;  // this thread's count, then next slot, of each cell
    std::fill(mine, mine + ncell, 0);
    for (std::size_t i = first; i < last; ++i) {
      for (int d = 0; d < D; ++d) {
        double xd = x[i][d] - lo[d];
        if (box.periodic[d]) xd -= L[d] * std::floor(xd / L[d]);
        coord[i][d] = std::clamp(static_cast<int>(xd / ext[d] * nc[d]), 0, nc[d] - 1);
      }
      cell_of[i] = flat(coord[i]);
      ++mine[cell_of[i]];
    }
#pragma omp barrier
#pragma omp single
    {
      start[0] = 0;
      for (std::int64_t c = 0; c < ncell; ++c) {
        std::int64_t at = start[c];
        for (int u = 0; u < nt; ++u) {  // thread u's count of cell c becomes its first slot there
          const std::int64_t count = fill[u * ncell + c];
          fill[u * ncell + c] = at;
          at += count;
        }
        start[c + 1] = at;
      }
    }
    for (std::size_t i = first; i < last; ++i) sorted[mine[cell_of[i]]++] = static_cast<int>(i);
  }
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = sorted[k];
    for (int d = 0; d < D; ++d)
      xs[d][k] = box.periodic[d] ? lo[d] + (x[i][d] - lo[d]) - L[d] * std::floor((x[i][d] - lo[d]) / L[d]) : x[i][d];
    hs[k] = h[i];
  }
  Sorted<D> view{{}, hs.data(), sorted.data()};
  for (int d = 0; d < D; ++d) view.x[d] = xs[d].data();
  const IsaPath path = loop_path<D>(isa_path());

  // The stencil of a cell as runs of consecutive cells along x (contiguous in the sorted
  // arrays), each with the image shift that brings it next to the cell.
  auto stencil = [&](const std::array<int, D>& c, int reach, std::vector<Run<D>>& out) {
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
  // thread fills the lists of the chunks it takes (core/stretches.hpp; first its own stretch of
  // the order) into its own buffer, noting each particle's place there. Nearly uniform h (cells
  // of h_max/2): every particle searches h_max and keeps |r_ij| < max(h_i, h_j) (candidates). Wide
  // h: i searches its own h_i, keeps |r_ij| < h_i and notes the pairs the other end misses as
  // (j, i) in visiting order (h_j <= |r_ij| < h_i), recording where each chunk's are.
  const bool wide_h = width < 0.5 * hmax;
  owner.resize(n);
  local.resize(n);
  Stretches stretches;
  struct Missed {
    std::size_t thread, at, count;  // missed[thread][at .. at + count - 1]
  };
  std::vector<Missed> chunk_missed;
#pragma omp parallel if (n >= parallel_threshold)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    {
      if (parts.size() < static_cast<std::size_t>(nt)) parts.resize(nt), missed.resize(nt);
      stretches.reset(n, nt);
      chunk_missed.resize(stretches.chunks());
    }
    // Two rules keep a later search from reallocating a buffer, which would fault its pages in
    // again. (1) Room from the start for all the last search's pairs and an eighth more, whatever
    // share of them this thread lists (it takes chunks from the others). (2) Short of room (a first
    // search, a longer list), grown to every particle's pairs at the rate this thread has listed so
    // far, with an eighth to spare, keeping only the pairs listed (grow_keeping). Both are needed:
    // (1) alone would reallocate at the second search a buffer that grew by doubling in the first;
    // (2) alone would leave a thread that listed few pairs at first, or ran after a search on fewer
    // threads, to grow it again later. The pairs for the other end (wide h) are listed pairs too:
    // their buffer has as much room, unset, so that it is not reallocated whenever the thread takes
    // more wide particles than before.
    auto& js = parts[t];
    auto& mt = missed[t];
    std::size_t used = 0, nm = 0, scanned = 0;  // the pairs this thread listed, those for the other end, its particles
    auto room_for = [&](std::size_t pairs) {
      if (js.size() < pairs) grow_keeping(js, used, pairs);
      if (wide_h && mt.size() < js.size()) grow_keeping(mt, nm, js.size());  // nm <= used
    };
    room_for(std::max(last_pairs + last_pairs / 8, n / nt * 64));
    std::vector<Run<D>> sten;
    std::size_t sten_size = 0;  // the stencil's candidates
    std::int64_t sten_of = -1;
    int sten_reach = 0;
    auto scan = [&](auto wide, std::size_t c, std::size_t first, std::size_t last) {  // wide: known at compile time
      const std::size_t nm0 = nm;  // this chunk's missed pairs start here (wide h)
      for (std::size_t s = first; s < last; ++s) {
        const std::size_t i = sorted[s];
        const double hi = hs[s];
        const int reach = reach_of(wide ? hi : hmax);
        if (cell_of[i] != sten_of || reach != sten_reach) {
          stencil(coord[i], reach, sten), sten_of = cell_of[i], sten_reach = reach;
          sten_size = 0;
          for (const Run<D>& run : sten) sten_size += run.last - run.first;
        }
        owner[i] = t;
        local[i] = used;
        if (used + sten_size + lanes > js.size())
          room_for(std::max(2 * js.size(), used / std::max<std::size_t>(scanned, 1) * (n + n / 8)) + sten_size + lanes);
        ++scanned;
        if constexpr (wide) {
          const Found f = own_reach_on(path, s, static_cast<int>(i), sten, view, js.data() + used, mt.data() + nm);
          used += f.listed;
          nm += f.missed;
        } else {
          used += candidates_on(path, s, sten, view, js.data() + used);
        }
        nl.offset[i + 1] = used - local[i];
      }
      if constexpr (wide) chunk_missed[c] = {static_cast<std::size_t>(t), nm0, nm - nm0};
    };
    if (wide_h)
      stretches.work(t, [&](std::size_t c, std::size_t a, std::size_t b) { scan(std::true_type{}, c, a, b); });
    else
      stretches.work(t, [&](std::size_t c, std::size_t a, std::size_t b) { scan(std::false_type{}, c, a, b); });
  }
  // The lists joined: particle i's row holds the pairs it listed, then (wide h) those the other
  // end missed, in the visiting order of the particles that found them (the chunks in order). Each
  // thread takes the rows of an equal range of indices: it counts the missed pairs of its rows
  // (reading every chunk's, keeping its own), sums its rows, and after the sums of the ranges
  // before it copies them and places their missed pairs. The same list on any thread count.
  fill.resize(n);  // a row's missed pairs, then where its next one goes
  std::vector<std::size_t> range_pairs;  // the pairs of each thread's rows, then where they start
#pragma omp parallel if (n >= parallel_threshold)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const std::size_t a = n * t / nt, b = n * (t + 1) / nt;
    auto each_mine = [&](auto&& f) {  // the missed pairs (j, i) of this thread's rows j, in order
      for (const Missed& c : chunk_missed)
        for (std::size_t k = c.at; k < c.at + c.count; ++k) {
          const std::array<int, 2>& jm = missed[c.thread][k];
          if (static_cast<std::size_t>(jm[0]) - a < b - a) f(jm);
        }
    };
    std::fill(fill.begin() + a, fill.begin() + b, 0);
    if (wide_h) each_mine([&](const std::array<int, 2>& jm) { ++fill[jm[0]]; });
    std::size_t sum = 0;
    for (std::size_t i = a; i < b; ++i) sum += nl.offset[i + 1] + fill[i];
#pragma omp single
    range_pairs.assign(nt, 0);
    range_pairs[t] = sum;
#pragma omp barrier
#pragma omp single
    {
      std::size_t total = 0;
      for (std::size_t& r : range_pairs) total += std::exchange(r, total);
      resize_for_overwrite(nl.j, total);
    }
    std::size_t at = range_pairs[t];
    for (std::size_t i = a; i < b; ++i) {  // nl.offset[i + 1]: the pairs i listed, then where its row ends
      const std::size_t own = nl.offset[i + 1], missed_here = fill[i];
      std::copy_n(parts[owner[i]].begin() + local[i], own, nl.j.begin() + at);
      fill[i] = static_cast<std::int64_t>(at + own);
      at += own + missed_here;
      nl.offset[i + 1] = at;
    }
    if (wide_h) each_mine([&](const std::array<int, 2>& jm) { nl.j[fill[jm[0]]++] = jm[1]; });
  }
  sorted.resize(n);       // the padding dropped
  nl.order.swap(sorted);  // the last order's array becomes the next search's buffer
}


template void grid_search<1>(const std::vector<Vec<1>>&, const std::vector<double>&, const Box<1>&, NeighbourList&,
                               GridSearchBuffers<1>&);
template NeighbourList grid_search<1>(const std::vector<Vec<1>>&, const std::vector<double>&, const Box<1>&);
template void grid_search<2>(const std::vector<Vec<2>>&, const std::vector<double>&, const Box<2>&, NeighbourList&,
                               GridSearchBuffers<2>&);
template NeighbourList grid_search<2>(const std::vector<Vec<2>>&, const std::vector<double>&, const Box<2>&);
template void grid_search<3>(const std::vector<Vec<3>>&, const std::vector<double>&, const Box<3>&, NeighbourList&,
                               GridSearchBuffers<3>&);
template NeighbourList grid_search<3>(const std::vector<Vec<3>>&, const std::vector<double>&, const Box<3>&);

}  // namespace sph
