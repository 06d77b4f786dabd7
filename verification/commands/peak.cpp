#include "verification/commands/peak.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace sphv {
namespace {

// 16 independent chains acc = acc * a + b per thread: more than the FMA latency (4 cycles) times
// the FMA pipes (2) of current x86 cores, so the pipes never wait. |a| < 1 keeps acc bounded.
// Unrolled whatever the optimisation level, so the chains stay in registers: at -O2 without it
// the loop over k went through memory and measured 3.5x less (3.2e10 against 1.1e11 flop/s).
constexpr int chains = 16;

#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx512f")]] double chains_avx512(long iterations) {
  __m512d acc[chains];
  const __m512d a = _mm512_set1_pd(0.999999), b = _mm512_set1_pd(1e-6);
  for (int k = 0; k < chains; ++k) acc[k] = _mm512_set1_pd(k);
  for (long it = 0; it < iterations; ++it)
#pragma GCC unroll 16
    for (int k = 0; k < chains; ++k) acc[k] = _mm512_fmadd_pd(acc[k], a, b);
  __m512d s = acc[0];
  for (int k = 1; k < chains; ++k) s = _mm512_add_pd(s, acc[k]);
  alignas(64) double out[8];
  _mm512_store_pd(out, s);
  return out[0] + out[1] + out[2] + out[3] + out[4] + out[5] + out[6] + out[7];
}

[[gnu::target("avx2,fma")]] double chains_avx2(long iterations) {
  __m256d acc[chains];
  const __m256d a = _mm256_set1_pd(0.999999), b = _mm256_set1_pd(1e-6);
  for (int k = 0; k < chains; ++k) acc[k] = _mm256_set1_pd(k);
  for (long it = 0; it < iterations; ++it)
#pragma GCC unroll 16
    for (int k = 0; k < chains; ++k) acc[k] = _mm256_fmadd_pd(acc[k], a, b);
  __m256d s = acc[0];
  for (int k = 1; k < chains; ++k) s = _mm256_add_pd(s, acc[k]);
  alignas(32) double out[4];
  _mm256_store_pd(out, s);
  return out[0] + out[1] + out[2] + out[3];
}
#endif

// Portable: two doubles a chain, a multiply and an add (no FMA in the x86-64 baseline).
double chains_portable(long iterations) {
  double acc[chains][2];
  for (int k = 0; k < chains; ++k) acc[k][0] = acc[k][1] = k;
  for (long it = 0; it < iterations; ++it)
#pragma GCC unroll 16
    for (int k = 0; k < chains; ++k)
      for (double& v : acc[k]) v = v * 0.999999 + 1e-6;
  double s = 0.0;
  for (const auto& c : acc) s += c[0] + c[1];
  return s;
}

}  // namespace

Peak measure_peak(int threads) {
  Peak peak{"sse2", 0.0};
  double (*run)(long) = chains_portable;
  int lanes = 2;
#if defined(__x86_64__) && defined(__GNUC__)
  if (__builtin_cpu_supports("avx512f")) peak.isa = "avx512f", run = chains_avx512, lanes = 8;
  else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) peak.isa = "avx2+fma", run = chains_avx2, lanes = 4;
#endif
  const long iterations = 20'000'000 / lanes;  // about 0.1 s at a few GHz
  double sink = 0.0;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(threads) reduction(+ : sink)
    sink += run(iterations);
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    peak.flops_per_s = std::max(peak.flops_per_s, 2.0 * lanes * chains * iterations * threads / t);
  }
  if (sink == 0.0) peak.flops_per_s = 0.0;  // never: keeps the chains from being optimised away
  return peak;
}

}  // namespace sphv
