#include "reference/direct_sum.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace reference {
namespace {

// Up to `lanes` targets and their sums.
constexpr int lanes = 8;
struct Block {
  double tx[lanes], ty[lanes], tz[lanes];
  double ax[lanes] = {}, ay[lanes] = {}, az[lanes] = {}, phi[lanes] = {};
};

// The field at a block's targets from the sources j < n; with skip_self, target l is source
// first + l and skips its own mass. Each target adds the sources in index order, a pair's
// operations in the order written, as a loop over its sources alone would; its own term is
// computed and not added (subtracting +0.0 leaves a sum as it was). Compiled for the portable
// default and for AVX2 without FMA (target_clones, chosen when the program is loaded), the
// targets in vector lanes: no contraction in either, so both give the same bits.
[[gnu::target_clones("avx2", "default")]] void block_field(Block& k, const double* x, const double* y, const double* z,
                                                           const double* m, std::size_t n, double G, double eps2,
                                                           bool skip_self, std::size_t first) {
  for (std::size_t j = 0; j < n; ++j) {
    const double xj = x[j], yj = y[j], zj = z[j], gm = G * m[j];
    const bool own_block = skip_self && j >= first && j < first + lanes;
    const int own = own_block ? static_cast<int>(j - first) : -1;
#pragma omp simd
    for (int l = 0; l < lanes; ++l) {
      const double dx = k.tx[l] - xj, dy = k.ty[l] - yj, dz = k.tz[l] - zj;
      const double inv = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz + eps2);
      const double f3 = gm * inv * inv * inv;
      const bool in = l != own;
      k.phi[l] -= in ? gm * inv : 0.0;
      k.ax[l] -= in ? f3 * dx : 0.0, k.ay[l] -= in ? f3 * dy : 0.0, k.az[l] -= in ? f3 * dz : 0.0;
    }
  }
}

DirectField sum(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                std::span<const double> m, double G, double eps, std::span<const double> px,
                std::span<const double> py, std::span<const double> pz, bool skip_self) {
  const std::size_t n = x.size(), nt = px.size();
  if (y.size() != n || z.size() != n || m.size() != n || py.size() != nt || pz.size() != nt)
    throw std::invalid_argument("direct_sum: arrays of different lengths");
  DirectField f{std::vector<double>(nt), std::vector<double>(nt), std::vector<double>(nt), std::vector<double>(nt)};
  const double eps2 = eps * eps;
  const std::size_t blocks = (nt + lanes - 1) / lanes;
#pragma omp parallel for schedule(dynamic, 2)
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t first = b * lanes, count = std::min<std::size_t>(lanes, nt - first);
    Block k;
    for (std::size_t l = 0; l < lanes; ++l) {  // spare lanes repeat the last target; their sums are dropped
      const std::size_t i = first + std::min(l, count - 1);
      k.tx[l] = px[i], k.ty[l] = py[i], k.tz[l] = pz[i];
    }
    block_field(k, x.data(), y.data(), z.data(), m.data(), n, G, eps2, skip_self, first);
    for (std::size_t l = 0; l < count; ++l)
      f.ax[first + l] = k.ax[l], f.ay[first + l] = k.ay[l], f.az[first + l] = k.az[l], f.phi[first + l] = k.phi[l];
  }
  return f;
}

}  // namespace

DirectField direct_sum(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                       std::span<const double> m, double G, double eps) {
  return sum(x, y, z, m, G, eps, x, y, z, true);
}

DirectField direct_sum_at(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                          std::span<const double> m, double G, double eps, std::span<const double> px,
                          std::span<const double> py, std::span<const double> pz) {
  return sum(x, y, z, m, G, eps, px, py, pz, false);
}

}  // namespace reference
