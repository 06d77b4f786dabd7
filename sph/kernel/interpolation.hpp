#pragma once
#include <vector>

#include "sph/core/particles.hpp"
#include "sph/hydro/pairs.hpp"
#include "sph/kernel/cubic_spline.hpp"

namespace sph {

// SPH interpolant of a field given at the particles, eq (18):
// f_i = sum_j m_j / rho_j f_j W_ij (self term included). K, here and below: the kernel
// (sph/kernel/kernels.hpp).
template <int D, class K = CubicSpline<D>>
std::vector<double> interpolate(const Particles<D>& p, const std::vector<double>& f,
                                const NeighbourList& nl, const Box<D>& box) {
  const std::size_t n = p.size();
  std::vector<double> out(n);
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) out[i] = p.m[i] / p.rho[i] * f[i] * K::W(0.0, p.h[i]);
  for_each_pair<D, K>(p.x, p.h, nl, box, [&](std::size_t i, int j, const Vec<D>&, double r, double h) {
    out[i] += p.m[j] / p.rho[j] * f[j] * K::W(r, h);
  });
  return out;
}

// Gradient, eq (19): grad f_i = sum_j m_j / rho_j f_j grad_i W_ij.
template <int D, class K = CubicSpline<D>>
std::vector<Vec<D>> gradient_direct(const Particles<D>& p, const std::vector<double>& f,
                                    const NeighbourList& nl, const Box<D>& box) {
  std::vector<Vec<D>> out(p.size(), Vec<D>::Zero());
  for_each_pair<D, K>(p.x, p.h, nl, box, [&](std::size_t i, int j, const Vec<D>& rij, double r, double h) {
    out[i] += p.m[j] / p.rho[j] * f[j] * K::gradW(rij, r, h);
  });
  return out;
}

// Gradient in the difference form, eq (32): grad f_i = sum_j m_j / rho_i (f_j - f_i) grad_i W_ij.
// The gradient of a constant vanishes exactly.
template <int D, class K = CubicSpline<D>>
std::vector<Vec<D>> gradient_difference(const Particles<D>& p, const std::vector<double>& f,
                                        const NeighbourList& nl, const Box<D>& box) {
  std::vector<Vec<D>> out(p.size(), Vec<D>::Zero());
  for_each_pair<D, K>(p.x, p.h, nl, box, [&](std::size_t i, int j, const Vec<D>& rij, double r, double h) {
    out[i] += p.m[j] / p.rho[i] * (f[j] - f[i]) * K::gradW(rij, r, h);
  });
  return out;
}

}  // namespace sph
