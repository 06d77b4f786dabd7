#pragma once
#include <cmath>
#include <cstdint>
#include <random>

#include "sph/core/box.hpp"
#include "sph/core/particles.hpp"

namespace sph {

// Initial distribution (9.3.1) on a cubic lattice: n particles per side of the box, spacing
// dx = L/n, equal masses rho0 dx^D, support radius h = hfact dx. jitter > 0 displaces every
// particle uniformly by up to jitter*dx per axis (seeded, reproducible).
template <int D>
Particles<D> lattice(int n, const Box<D>& box, double rho0, double hfact, double jitter = 0.0,
                     std::uint64_t seed = 1) {
  Particles<D> p;
  std::size_t total = 1;
  for (int d = 0; d < D; ++d) total *= static_cast<std::size_t>(n);
  p.resize(total);
  const Vec<D> L = box.length();
  const Vec<D> dx = L / n;
  double vol = 1.0;
  for (int d = 0; d < D; ++d) vol *= dx[d];
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> shift(-jitter, jitter);
  for (std::size_t k = 0; k < total; ++k) {
    std::size_t rest = k;
    for (int d = 0; d < D; ++d) {
      const double c = static_cast<double>(rest % n) + 0.5 + (jitter > 0 ? shift(rng) : 0.0);
      rest /= n;
      p.x[k][d] = box.lo[d] + c * dx[d];
      if (box.periodic[d]) p.x[k][d] = box.lo[d] + std::fmod(p.x[k][d] - box.lo[d] + L[d], L[d]);
    }
    p.m[k] = rho0 * vol;
    p.rho[k] = rho0;
    p.h[k] = hfact * dx.maxCoeff();
  }
  return p;
}

}  // namespace sph
