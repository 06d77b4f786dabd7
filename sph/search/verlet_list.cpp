// The pair filter of the reused neighbour lists (search/verlet_list.hpp), compiled once per
// dimension and instruction-set path.
#include <algorithm>

#include "sph/search/lane_compaction.hpp"
#include "sph/search/verlet_list.hpp"

#ifdef SPH_AVX2_COPY
// GCC 12 warns of the undefined vectors inside its own AVX-512 intrinsics (GCC bug 105593, fixed in
// GCC 13): silenced for the header's lines only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#endif

namespace sph {

namespace {

// The pairs (i, cj[t]), t < count, with |r_ij| < max(h_i, h_j), appended to js in their order;
// returns how many. In batches: a branch-free loop the compiler vectorises marks the pairs to
// keep, then a loop writes every candidate and advances past the kept ones, with no branch to
// mispredict.
template <int D>
inline std::size_t pairs_within(std::size_t i, const int* cj, std::size_t count, const Site* s, const Vec<D>& L,
                                const Vec<D>& wrap, int* js) {
  constexpr std::size_t batch = 128;
  int keep[batch];
  std::size_t used = 0;
  for (std::size_t t0 = 0; t0 < count; t0 += batch) {
    const int nb = static_cast<int>(std::min(count - t0, batch));
#pragma omp simd
    for (int t = 0; t < nb; ++t) {
      const Site& sj = s[cj[t0 + t]];
      double r2 = 0.0;
#pragma GCC unroll 3
      for (int d = 0; d < D; ++d) {
        const double dx = min_image(s[i].x[d] - sj.x[d], L[d], wrap[d]);
        r2 += dx * dx;
      }
      const double hm = std::max(s[i].h, sj.h);
      keep[t] = r2 < hm * hm;
    }
    for (int t = 0; t < nb; ++t) {
      js[used] = cj[t0 + t];
      used += keep[t];
    }
  }
  return used;
}

template <int D, class Within>
inline std::size_t select_range(std::size_t first, std::size_t last, const NeighbourList& list, const int* row,
                                int* js, std::size_t* offset, Within&& within) {
  std::size_t used = 0;
  for (std::size_t i = first; i < last; ++i) {
    const std::size_t r = row ? static_cast<std::size_t>(row[i]) : i;
    used += within(i, list.j.data() + list.offset[r], list.offset[r + 1] - list.offset[r], js + used);
    offset[i + 1] = used;
  }
  return used;
}

#ifdef SPH_AVX2_COPY
// min_image (core/box.hpp) of four separations.
[[gnu::target("avx2,fma")]] inline __m256d image(__m256d dx, __m256d L, __m256d wrap) {
  const __m256d shift = _mm256_set1_pd(min_image_shift);
  return _mm256_fnmadd_pd(L, _mm256_sub_pd(_mm256_fmadd_pd(dx, wrap, shift), shift), dx);
}

// pairs_within in 2D and 3D with AVX2: four candidates at a time, their sites loaded whole and
// transposed, the kept ones moved to the front of a 4-lane store (which may write up to three
// candidates past them, later overwritten or beyond the count). The same operations as the
// compiled loop with FMA contraction, so the same pairs (verification/tests/grid_search.cpp).
// Sites loaded whole and transposed are faster than gathers from one array per dimension, their
// packing included. In 2D a site's x[2] is not written, and not read.
template <int D>
[[gnu::target("avx2,fma")]] inline std::size_t pairs_within_avx2(std::size_t i, const int* cj, std::size_t count,
                                                                  const Site* s, const Vec<D>& L, const Vec<D>& wrap,
                                                                  int* js) {
  static_assert(D == 2 || D == 3);
  // The last dimension's (z in 3D; y again in 2D, where they go unused).
  const __m256d xi = _mm256_set1_pd(s[i].x[0]), yi = _mm256_set1_pd(s[i].x[1]), zi = _mm256_set1_pd(s[i].x[D - 1]),
                hi = _mm256_set1_pd(s[i].h);
  const __m256d Lx = _mm256_set1_pd(L[0]), Ly = _mm256_set1_pd(L[1]), Lz = _mm256_set1_pd(L[D - 1]);
  const __m256d wx = _mm256_set1_pd(wrap[0]), wy = _mm256_set1_pd(wrap[1]), wz = _mm256_set1_pd(wrap[D - 1]);
  std::size_t used = 0, t = 0;
  for (; t + 4 <= count; t += 4) {
    const __m256d s0 = _mm256_load_pd(&s[cj[t]].x[0]), s1 = _mm256_load_pd(&s[cj[t + 1]].x[0]),
                  s2 = _mm256_load_pd(&s[cj[t + 2]].x[0]), s3 = _mm256_load_pd(&s[cj[t + 3]].x[0]);
    const __m256d a = _mm256_unpacklo_pd(s0, s1), b = _mm256_unpackhi_pd(s0, s1), c = _mm256_unpacklo_pd(s2, s3),
                  d = _mm256_unpackhi_pd(s2, s3);
    const __m256d dx = image(_mm256_sub_pd(xi, _mm256_permute2f128_pd(a, c, 0x20)), Lx, wx),
                  dy = image(_mm256_sub_pd(yi, _mm256_permute2f128_pd(b, d, 0x20)), Ly, wy),
                  hm = _mm256_max_pd(hi, _mm256_permute2f128_pd(b, d, 0x31));
    __m256d r2 = _mm256_fmadd_pd(dy, dy, _mm256_mul_pd(dx, dx));
    if constexpr (D == 3) {
      const __m256d dz = image(_mm256_sub_pd(zi, _mm256_permute2f128_pd(a, c, 0x31)), Lz, wz);
      r2 = _mm256_fmadd_pd(dz, dz, r2);
    }
    const int keep = _mm256_movemask_pd(_mm256_cmp_pd(r2, _mm256_mul_pd(hm, hm), _CMP_LT_OQ));
    const __m128i j4 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(cj + t));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(js + used),
                     _mm_shuffle_epi8(j4, _mm_loadu_si128(reinterpret_cast<const __m128i*>(compaction[keep].data()))));
    used += static_cast<std::size_t>(__builtin_popcount(keep));
  }
  return used + pairs_within<D>(i, cj + t, count - t, s, L, wrap, js + used);
}

// min_image (core/box.hpp) of eight separations.
[[gnu::target(SPH_AVX512_TARGET)]] inline __m512d image512(__m512d dx, __m512d L, __m512d wrap) {
  const __m512d shift = _mm512_set1_pd(min_image_shift);
  return _mm512_fnmadd_pd(L, _mm512_sub_pd(_mm512_fmadd_pd(dx, wrap, shift), shift), dx);
}

// The sites of particles a and b in one register: (x_a y_a z_a h_a x_b y_b z_b h_b).
[[gnu::target(SPH_AVX512_TARGET)]] inline __m512d two_sites(const Site* s, int a, int b) {
  return _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_load_pd(&s[a].x[0])), _mm256_load_pd(&s[b].x[0]), 1);
}

// pairs_within_avx2 with AVX-512, eight candidates at a time: their sites loaded whole, two to a
// 512-bit register, and transposed; the kept indices compressed to the front of an 8-lane store
// (which may write up to seven candidates past them). The same operations, so the same pairs.
[[gnu::target(SPH_AVX512_TARGET)]] inline std::size_t pairs_within_avx512(std::size_t i, const int* cj,
                                                                          std::size_t count, const Site* s,
                                                                          const Vec<3>& L, const Vec<3>& wrap,
                                                                          int* js) {
  const __m512d xi = _mm512_set1_pd(s[i].x[0]), yi = _mm512_set1_pd(s[i].x[1]), zi = _mm512_set1_pd(s[i].x[2]),
                hi = _mm512_set1_pd(s[i].h);
  const __m512d Lx = _mm512_set1_pd(L[0]), Ly = _mm512_set1_pd(L[1]), Lz = _mm512_set1_pd(L[2]);
  const __m512d wx = _mm512_set1_pd(wrap[0]), wy = _mm512_set1_pd(wrap[1]), wz = _mm512_set1_pd(wrap[2]);
  std::size_t used = 0, t = 0;
  for (; t + 8 <= count; t += 8) {
    // a = (x0 y0 z0 h0 x2 y2 z2 h2), ...; then p = (x0 x1 z0 z1 x2 x3 z2 z3), q = (y0 y1 h0 h1 ...).
    const __m512d a = two_sites(s, cj[t], cj[t + 2]), b = two_sites(s, cj[t + 1], cj[t + 3]),
                  c = two_sites(s, cj[t + 4], cj[t + 6]), d = two_sites(s, cj[t + 5], cj[t + 7]);
    const __m512d p0 = _mm512_unpacklo_pd(a, b), q0 = _mm512_unpackhi_pd(a, b), p1 = _mm512_unpacklo_pd(c, d),
                  q1 = _mm512_unpackhi_pd(c, d);
    const __m512d dx = image512(_mm512_sub_pd(xi, _mm512_shuffle_f64x2(p0, p1, 0x88)), Lx, wx),
                  dy = image512(_mm512_sub_pd(yi, _mm512_shuffle_f64x2(q0, q1, 0x88)), Ly, wy),
                  dz = image512(_mm512_sub_pd(zi, _mm512_shuffle_f64x2(p0, p1, 0xDD)), Lz, wz),
                  hm = _mm512_max_pd(hi, _mm512_shuffle_f64x2(q0, q1, 0xDD));
    const __m512d r2 = _mm512_fmadd_pd(dz, dz, _mm512_fmadd_pd(dy, dy, _mm512_mul_pd(dx, dx)));
    const __mmask8 keep = _mm512_cmp_pd_mask(r2, _mm512_mul_pd(hm, hm), _CMP_LT_OQ);
    const __m256i j8 = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cj + t));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(js + used), _mm256_maskz_compress_epi32(keep, j8));
    used += static_cast<std::size_t>(__builtin_popcount(keep));
  }
  return used + pairs_within_avx2<3>(i, cj + t, count - t, s, L, wrap, js + used);
}

template <int D>
[[gnu::target("avx2,fma"), gnu::flatten]] std::size_t select_range_avx2(std::size_t first, std::size_t last,
                                                                       const NeighbourList& list, const int* row,
                                                                       const Site* s, const Vec<D>& L,
                                                                       const Vec<D>& wrap, int* js, std::size_t* offset) {
  return select_range<D>(first, last, list, row, js, offset, [&](std::size_t i, const int* cj, std::size_t n,
                                                                 int* out) {
    if constexpr (D >= 2) return pairs_within_avx2<D>(i, cj, n, s, L, wrap, out);
    else return pairs_within<D>(i, cj, n, s, L, wrap, out);
  });
}

[[gnu::target(SPH_AVX512_TARGET), gnu::flatten]] std::size_t select_range_avx512(std::size_t first, std::size_t last,
                                                                                 const NeighbourList& list,
                                                                                 const int* row, const Site* s,
                                                                                 const Vec<3>& L, const Vec<3>& wrap,
                                                                                 int* js, std::size_t* offset) {
  return select_range<3>(first, last, list, row, js, offset,
                         [&](std::size_t i, const int* cj, std::size_t n, int* out) {
                           return pairs_within_avx512(i, cj, n, s, L, wrap, out);
                         });
}
#endif

}  // namespace

template <int D>
std::size_t select_pairs([[maybe_unused]] IsaPath path, std::size_t first, std::size_t last, const NeighbourList& list,
                         const int* row, const Site* sites, const Vec<D>& L, const Vec<D>& wrap, int* js,
                         std::size_t* offset) {
#ifdef SPH_AVX2_COPY
  if constexpr (D == 3)  // the copies of loop_path (core/isa.hpp), as the pair loops'
    if (path == IsaPath::avx512) return select_range_avx512(first, last, list, row, sites, L, wrap, js, offset);
  if constexpr (D >= 2)
    if (path != IsaPath::portable) return select_range_avx2<D>(first, last, list, row, sites, L, wrap, js, offset);
#endif
  return select_range<D>(first, last, list, row, js, offset, [&](std::size_t i, const int* cj, std::size_t n,
                                                                 int* out) {
    return pairs_within<D>(i, cj, n, sites, L, wrap, out);
  });
}

template std::size_t select_pairs<1>(IsaPath, std::size_t, std::size_t, const NeighbourList&, const int*, const Site*,
                                     const Vec<1>&, const Vec<1>&, int*, std::size_t*);
template std::size_t select_pairs<2>(IsaPath, std::size_t, std::size_t, const NeighbourList&, const int*, const Site*,
                                     const Vec<2>&, const Vec<2>&, int*, std::size_t*);
template std::size_t select_pairs<3>(IsaPath, std::size_t, std::size_t, const NeighbourList&, const int*, const Site*,
                                     const Vec<3>&, const Vec<3>&, int*, std::size_t*);

}  // namespace sph
