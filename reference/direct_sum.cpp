#include "reference/direct_sum.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace reference {
namespace {

DirectField sum(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                std::span<const double> m, double G, double eps, std::span<const double> px,
                std::span<const double> py, std::span<const double> pz, bool skip_self) {
  const std::size_t n = x.size(), nt = px.size();
  if (y.size() != n || z.size() != n || m.size() != n || py.size() != nt || pz.size() != nt)
    throw std::invalid_argument("direct_sum: arrays of different lengths");
  DirectField f{std::vector<double>(nt), std::vector<double>(nt), std::vector<double>(nt), std::vector<double>(nt)};
  const double eps2 = eps * eps;
#pragma omp parallel for schedule(dynamic, 16)
  for (std::size_t i = 0; i < nt; ++i) {
    double ax = 0, ay = 0, az = 0, phi = 0;
    for (std::size_t j = 0; j < n; ++j) {
      if (skip_self && j == i) continue;
      const double dx = px[i] - x[j], dy = py[i] - y[j], dz = pz[i] - z[j];
      const double inv = 1.0 / std::sqrt(dx * dx + dy * dy + dz * dz + eps2);
      const double gm = G * m[j];
      phi -= gm * inv;
      const double f3 = gm * inv * inv * inv;
      ax -= f3 * dx, ay -= f3 * dy, az -= f3 * dz;
    }
    f.ax[i] = ax, f.ay[i] = ay, f.az[i] = az, f.phi[i] = phi;
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
