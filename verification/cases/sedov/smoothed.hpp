#pragma once
// The exact Sedov density as SPH sees it: the similarity profile convolved with the run's kernel
// K (the cubic spline (6) by default, sph/kernel/kernels.hpp) at support h, rho_h(r) = int rho(|x - y|) W(|y|, h) d^D y with |x| = r (the continuum limit
// of the summation (4) at that h). A blast's density is a thin spike behind the jump, so its
// smoothed profile peaks inside R and falls through the half-rise level well outside it; the
// shock-radius error compares the particles' front with the front of this profile, found by the
// same estimator on the same bins, so the kernel's own bias cancels (sedov/errors.hpp).
//
// Reduction to one dimension in the source radius s: rho_h(r) = int rho(s) A(r, s, h) ds with
// A = s^(D-1) int_{S^(D-1)} W(|r e - s n|, h) dn, the kernel's weight on the sphere of radius s.
//   3D: A = (2 pi s / r) int_{|r-s|}^{min(r+s,h)} W(d, h) d dd, in closed form for the cubic (the
//       antiderivative of q w(q) below, w the bracket of (6)), by Gauss-Legendre on each of the
//       kernel's pieces for the others (exact: q w(q) is a polynomial of degree <= 12 on each);
//   2D: A = 2 s int_0^phi_max W(sqrt(r^2 + s^2 - 2 r s cos phi), h) dphi, by Gauss-Legendre in phi
//       split where the distance crosses a knot (the cubic's h/2; W is C^2 there, so each piece
//       converges fast).
// The s-integral is split at the jump R and where A has a kink (|r +- s| = a knot, h), Gauss-Legendre
// on each piece, and divided by the same quadrature of A alone (exactly 1 for the normalised
// kernel), which removes the quadrature's error on the kernel's weight.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>
#include <vector>

#include "reference/sedov.hpp"
#include "sph/kernel/cubic_spline.hpp"

namespace sphv::sedov {

// Gauss-Legendre nodes and weights on [-1, 1], K points (Newton on the Legendre polynomial).
template <int K>
struct GaussLegendre {
  std::array<double, K> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < K; ++i) {
      double z = std::cos(std::numbers::pi * (i + 0.75) / (K + 0.5)), dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= K; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1, p1 = p2;
        }
        dp = K * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-15) break;
      }
      x[i] = z, w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
  // The K-point rule's sum of f over [a, b].
  template <class F>
  double integrate(double a, double b, const F& f) const {
    const double c = 0.5 * (a + b), hw = 0.5 * (b - a);
    double s = 0.0;
    for (int i = 0; i < K; ++i) s += w[i] * f(c + hw * x[i]);
    return s * hw;
  }
};

// int_0^q t w(t) dt, w(t) = 2 (1-t)_+^3 - 8 (1/2-t)_+^3 (the bracket of (6)).
inline double kernel_moment(double q) {
  const double a = std::clamp(q, 0.0, 1.0), b = std::clamp(q, 0.0, 0.5);
  const double a2 = a * a, b2 = b * b;
  return a2 * (1.0 - 2.0 * a + 1.5 * a2 - 0.4 * a2 * a) - b2 * (0.5 - 2.0 * b + 3.0 * b2 - 1.6 * b2 * b);
}

// int_0^q t w(t) dt for the kernel K, w = W(., 1) / sigma: the cubic's closed form, or the 7-point
// Gauss-Legendre rule on each piece of K (exact up to degree 13).
template <class K>
double kernel_moment_of(double q) {
  if constexpr (std::is_same_v<K, sph::CubicSpline<3>>) {
    return kernel_moment(q);
  } else {
    static const GaussLegendre<7> gl;
    double m = 0.0, lo = 0.0;
    for (double k : K::knots) {
      const double hi = std::clamp(q, 0.0, k);
      if (hi > lo) m += gl.integrate(lo, hi, [](double t) { return t * K::W(t, 1.0) / K::sigma; });
      lo = std::max(lo, k);
    }
    return m;
  }
}

// The kernel's weight A(r, s, h) on the sphere (circle) of radius s around a point at radius r.
template <int D, class W = sph::CubicSpline<D>>
double shell_weight(double r, double s, double h) {
  static_assert(D == 2 || D == 3);
  if (r <= 1e-12 * h) return (D == 3 ? 4.0 * std::numbers::pi * s * s : 2.0 * std::numbers::pi * s) * W::W(s, h);
  const double lo = std::abs(r - s);
  if (lo >= h) return 0.0;
  if constexpr (D == 3) {
    const double hi = std::min(r + s, h);
    return 2.0 * std::numbers::pi * s / r * W::sigma / h * (kernel_moment_of<W>(hi / h) - kernel_moment_of<W>(lo / h));
  } else {
    static const GaussLegendre<16> gl;
    const double c = (r * r + s * s - h * h) / (2.0 * r * s);
    const double phi_max = c <= -1.0 ? std::numbers::pi : std::acos(std::min(c, 1.0));
    auto f = [&](double phi) { return W::W(std::sqrt(std::max(r * r + s * s - 2.0 * r * s * std::cos(phi), 0.0)), h); };
    // Split where the distance crosses a knot inside the support (the cubic's h/2), in order.
    double sum = 0.0, from = 0.0;
    for (std::size_t k = 0; k + 1 < W::knots.size(); ++k) {
      const double kh = W::knots[k] * h, c_knot = (r * r + s * s - kh * kh) / (2.0 * r * s);
      if (!(c_knot > -1.0 && c_knot < 1.0)) continue;
      const double phi_knot = std::min(std::acos(c_knot), phi_max);
      sum += gl.integrate(from, phi_knot, f);
      from = phi_knot;
    }
    sum += gl.integrate(from, phi_max, f);
    return 2.0 * s * sum;
  }
}

// rho_h(r): the exact density at time t convolved with the kernel K at support h.
template <int D, class K = sph::CubicSpline<D>>
double smoothed_density(const reference::Sedov& exact, double r, double h, double E, double rho0, double t) {
  static const GaussLegendre<12> gl;
  const double R = exact.shock_radius(E, rho0, t);
  const double lo = std::max(0.0, r - h), hi = r + h;
  std::vector<double> cuts = {lo, hi, R};
  for (std::size_t k = 0; k + 1 < K::knots.size(); ++k) {
    const double kh = K::knots[k] * h;
    cuts.insert(cuts.end(), {r - kh, r + kh, kh - r});
  }
  cuts.push_back(h - r);
  std::erase_if(cuts, [&](double c) { return !(c >= lo && c <= hi); });
  std::sort(cuts.begin(), cuts.end());
  double mass = 0.0, weight = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double c = 0.5 * (cuts[k] + cuts[k + 1]), hw = 0.5 * (cuts[k + 1] - cuts[k]);
    if (!(hw > 0.0)) continue;
    // The nodes never touch a piece's ends, so rho is taken on the piece's own side of the jump.
    for (std::size_t i = 0; i < gl.x.size(); ++i) {
      const double s = c + hw * gl.x[i], a = gl.w[i] * hw * shell_weight<D, K>(r, s, h);
      mass += a * exact.density(s, E, rho0, t), weight += a;
    }
  }
  return mass / weight;
}

}  // namespace sphv::sedov
