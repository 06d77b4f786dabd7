#pragma once
// Shared by the conduction cases (laplacian, heat, heat_stability, heat_stiff) and interpolation: particle sets in
// the periodic unit box, and the Fourier symbols of the SPH second-derivative operators on a
// lattice, computed by direct sums over lattice offsets (no neighbour search, no pair loop, no
// SPH operator code): the independent reference for eigenvalues and lattice errors.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "sph/core/lattice.hpp"
#include "sph/density/summation.hpp"
#include "sph/hydro/scene.hpp"
#include "sph/kernel/cubic_spline.hpp"
#include "sph/search/grid_search.hpp"

namespace sphv::heat {

// A particle set with its neighbourhood: n per side, h = hfact dx, density by summation (27).
template <int D>
struct ParticleSet {
  sph::Box<D> box = sph::unit_box<D>(true);
  sph::Particles<D> p;
  sph::NeighbourList nl;
  ParticleSet(int n, double hfact, double jitter, unsigned seed = 7) {
    p = sph::lattice<D>(n, box, 1.0, hfact, jitter, seed);
    nl = sph::grid_search<D>(p.x, p.h, box);
    sph::density_summation<D>(p, nl, box);
  }
  sph::Neighbourhood<D> nb() const { return {nl, box}; }
  std::vector<double> coords(std::size_t i) const { return {p.x[i].data(), p.x[i].data() + D}; }
};

// Calls f(offset vector in units of dx) for every non-zero lattice offset within ratio = h/dx.
template <int D, class F>
void for_each_offset(double ratio, F&& f) {
  const int k = static_cast<int>(std::ceil(ratio));
  sph::Vec<D> o;
  std::vector<int> idx(D, -k);
  while (true) {
    for (int d = 0; d < D; ++d) o[d] = idx[d];
    if (o.norm() > 0.0 && o.norm() < ratio) f(o);
    int d = 0;
    while (d < D && ++idx[d] > k) idx[d++] = -k;
    if (d == D) break;
  }
}

// S0 = sum_j dx^D W(r_j, h) over the lattice, self term included: summation density / rho0.
template <int D>
double lattice_kernel_sum(double ratio) {
  double s = sph::CubicSpline<D>::W(0.0, ratio);
  for_each_offset<D>(ratio, [&](const sph::Vec<D>& o) { s += sph::CubicSpline<D>::W(o.norm(), ratio); });
  return s;
}

// Eigenvalue -lambda(k) of the Brookshaw operator (69) on a lattice of spacing dx for the mode
// exp(i k.x), with V_j = dx^D / S0:  lambda = (2 / S0) sum_r dx^D (-W'(r) / r) (1 - cos k.r).
template <int D>
double brookshaw_symbol(const sph::Vec<D>& k, double ratio, double dx) {
  double s = 0.0;
  const double h = ratio * dx;
  for_each_offset<D>(ratio, [&](const sph::Vec<D>& o) {
    const sph::Vec<D> r = o * dx;
    s += -sph::CubicSpline<D>::dWdr(r.norm(), h) / r.norm() * (1.0 - std::cos(k.dot(r)));
  });
  return 2.0 * s * std::pow(dx, D) / lattice_kernel_sum<D>(ratio);
}

// Symbol of the SPH interpolant (18) with V_j = dx^D / S0: the factor by which it multiplies the
// modes exp(i k.x) with k = +-k_a per axis (equal by the lattice's mirror symmetry):
// sum_r dx^D W(r) cos(k.r) / S0, self term included.
template <int D>
double interpolant_symbol(const sph::Vec<D>& k, double ratio, double dx) {
  double s = sph::CubicSpline<D>::W(0.0, ratio * dx);
  for_each_offset<D>(ratio, [&](const sph::Vec<D>& o) {
    s += sph::CubicSpline<D>::W(o.norm() * dx, ratio * dx) * std::cos(k.dot(o * dx));
  });
  return s * std::pow(dx, D) / lattice_kernel_sum<D>(ratio);
}

// Symbol of the SPH gradient (19) (and (32), equal on a lattice, where sum_j V_j grad W_ij = 0):
// grad f_i = sum_j V_j f_j grad_i W_ij maps exp(i k.x) to i g(k) exp(i k.x) with
// g(k) = -sum_r V sin(k.r) grad W(r), so the exact gradient is g(k) = k.
template <int D>
sph::Vec<D> gradient_symbol(const sph::Vec<D>& k, double ratio, double dx) {
  sph::Vec<D> g = sph::Vec<D>::Zero();
  const double h = ratio * dx;
  for_each_offset<D>(ratio, [&](const sph::Vec<D>& o) {
    const sph::Vec<D> r = o * dx;
    g -= std::sin(k.dot(r)) * sph::CubicSpline<D>::gradW(r, r.norm(), h);
  });
  return g * (std::pow(dx, D) / lattice_kernel_sum<D>(ratio));
}

// Same for the two-pass form (56)-(59) (both variants agree on a uniform lattice): the square of
// the gradient's symbol, lambda = |g(k)|^2. It vanishes at k = pi/dx: the two-pass form does
// not damp the lattice's odd-even mode.
template <int D>
double two_pass_symbol(const sph::Vec<D>& k, double ratio, double dx) {
  return gradient_symbol<D>(k, ratio, dx).squaredNorm();
}

// The lattice floor at fixed h/dx = ratio: the relative error of the operator's long-wave rate,
// symbol(k) / k^2 - 1 as k dx -> 0 (signed; k = 1e-3 / h, where the (k h)^2 term is 1e-6 of it):
// the lattice's second moment against the continuum's.
template <int D>
double long_wave_rate_error(const std::string& form, double ratio, double dx) {
  const sph::Vec<D> k = sph::Vec<D>::Constant(1e-3 / (ratio * dx));
  const double sym = form == "brookshaw" ? brookshaw_symbol<D>(k, ratio, dx) : two_pass_symbol<D>(k, ratio, dx);
  return sym / k.squaredNorm() - 1.0;
}

// Whether the dim-dimensional lattice leaves a floor at fixed h/dx = ratio for the form: its
// long-wave rate error eps (a function of the ratio alone, dx scales out) above 1e-5 in magnitude,
// where the (k h)^2 term's residue in long_wave_rate_error is of order 1e-7 (2D at h/dx 4: 8.6e-4;
// 1D at 2 or 4: the sums are exact).
inline bool has_lattice_floor(int dim, const std::string& form, double ratio) {
  const double eps = dim == 1   ? long_wave_rate_error<1>(form, ratio, 1.0)
                     : dim == 2 ? long_wave_rate_error<2>(form, ratio, 1.0)
                                : long_wave_rate_error<3>(form, ratio, 1.0);
  return std::abs(eps) > 1e-5;
}

// Relative error of the Hessian tensor (73) (errata: the (d + 2) factor) on the sine product
// prod_a sin(k_a x_a) with k_a = k for every a: for the mode exp(i q.x) its symbol is
// H(q) = sum_r V (cos(q.r) - 1) F(r) ((d + 2) r r^T / r^2 - I), F = -W'(r) / r, against the exact
// -q q^T. Every mode q = k (+-1, ..., +-1) of the product has the same relative error e_d on the
// diagonal and e_o off it, and the exact components have equal mean squares over the box, so
// the Frobenius error is sqrt((d e_d^2 + d (d - 1) e_o^2) / d^2).
template <int D>
double hessian_symbol_error(double k, double ratio, double dx) {
  double diag = 0.0, off = 0.0;
  const double h = ratio * dx;
  for_each_offset<D>(ratio, [&](const sph::Vec<D>& o) {
    const sph::Vec<D> r = o * dx;
    const double rn = r.norm(), c = (std::cos(k * r.sum()) - 1.0) * -sph::CubicSpline<D>::dWdr(rn, h) / rn;
    diag += c * ((D + 2.0) * r[0] * r[0] / (rn * rn) - 1.0);
    if constexpr (D > 1) off += c * (D + 2.0) * r[0] * r[1] / (rn * rn);
  });
  const double V = std::pow(dx, D) / lattice_kernel_sum<D>(ratio);
  const double e_d = diag * V / -(k * k) - 1.0, e_o = D > 1 ? off * V / -(k * k) - 1.0 : 0.0;
  return std::sqrt((D * e_d * e_d + D * (D - 1) * e_o * e_o) / (D * D));
}

// Largest eigenvalue over the modes k = 2 pi m, 0 <= m_a <= n/2, of the periodic n^D lattice
// (the symbols are even in each k_a).
template <int D, class Symbol>
double lambda_max(int n, double ratio, Symbol&& symbol) {
  const double dx = 1.0 / n;
  double best = 0.0;
  std::vector<int> m(D, 0);
  while (true) {
    sph::Vec<D> k;
    for (int d = 0; d < D; ++d) k[d] = 2.0 * std::numbers::pi * m[d];
    best = std::max(best, symbol(k, ratio, dx));
    int d = 0;
    while (d < D && ++m[d] > n / 2) m[d++] = 0;
    if (d == D) break;
  }
  return best;
}

// Relative L2 norm ||a - b|| / ||b||.
inline double relative_l2(const std::vector<double>& a, const std::vector<double>& b) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) num += (a[i] - b[i]) * (a[i] - b[i]), den += b[i] * b[i];
  return std::sqrt(num / den);
}

}  // namespace sphv::heat
