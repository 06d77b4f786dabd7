// The Sedov shock radius against the kernel-smoothed exact front (sedov/smoothed.hpp,
// sedov/errors.hpp): the smoothing checked against a brute-force convolution, the half-rise bias
// it predicts, and the error on synthetic particles that carry the SPH estimate of the exact field.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "reference/sedov.hpp"
#include "sph/kernel/kernels.hpp"
#include "verification/cases/sedov/errors.hpp"
#include "verification/cases/sedov/smoothed.hpp"

namespace {

constexpr double E = 1.0, rho0 = 1.0, t = 1.0;
// The time at which the shock reaches R = 0.3, the radius sphv's runs end at (box half-width 0.5).
double t_R(const reference::Sedov& ex) { return std::sqrt(std::pow(0.3 / ex.xi0(), ex.dimension() + 2) * rho0 / E); }

// int rho(|x + y|) W(|y|, h) d^D y by the midpoint rule on a Cartesian grid of spacing h / cells
// around a point at radius r on the x axis: an independent route to rho_h (no angular reduction).
template <int D, class K = sph::CubicSpline<D>>
double brute_force_smoothing(const reference::Sedov& ex, double r, double h, int cells) {
  const double dy = h / cells;
  double sum = 0.0;
  const int k = cells;
  for (int a = -k; a < k; ++a)
    for (int b = -k; b < k; ++b)
      for (int c = (D == 3 ? -k : 0); c < (D == 3 ? k : 1); ++c) {
        const double yx = (a + 0.5) * dy, yy = (b + 0.5) * dy, yz = D == 3 ? (c + 0.5) * dy : 0.0;
        const double q = std::sqrt(yx * yx + yy * yy + yz * yz);
        if (q >= h) continue;
        const double s = std::sqrt((r + yx) * (r + yx) + yy * yy + yz * yz);
        sum += ex.density(s, E, rho0, t) * K::W(q, h);
      }
  return sum * std::pow(dy, D);
}

// The half-rise front of rho_h sampled on a fine radial grid (no bins), relative to R - 1.
template <int D>
double half_rise_bias(const reference::Sedov& ex, double support) {
  const double R = ex.shock_radius(E, rho0, t);
  const int N = 1600;
  std::vector<double> r(N), v(N);
  std::size_t peak = 0;
  for (int k = 0; k < N; ++k) {
    r[k] = (k + 0.5) * 1.6 * R / N;
    v[k] = sphv::sedov::smoothed_density<D>(ex, r[k], support, E, rho0, t);
    if (v[k] > v[peak]) peak = k;
  }
  const double level = 0.5 * (rho0 + v[peak]);
  for (std::size_t k = peak; k + 1 < r.size(); ++k)
    if (v[k] >= level && v[k + 1] < level) return (r[k] + (r[k + 1] - r[k]) * (v[k] - level) / (v[k] - v[k + 1])) / R - 1.0;
  return NAN;
}

// Particles on the lattice of n^D sites in [-0.5, 0.5]^D (periodic) with support h = hfact / n,
// whose density is the SPH estimate of the exact field: a lattice sum over sample points of
// spacing dx / sub, rho_i = sum_j (dx / sub)^D rho_exact(y_j) W(|x_i - y_j|, h) (not the radial
// quadrature the measure uses). With sub = 1 the sum samples the post-shock spike, one spacing
// wide at these n, once per spacing, and the aliasing moves the binned front by 2.0 % R (3D,
// n = 32): the check is of the convolution, so it samples finer.
template <int D>
struct Synthetic {
  std::vector<sph::Vec<D>> x;
  std::vector<double> m, rho, h;
};
template <int D>
Synthetic<D> synthetic(const reference::Sedov& ex, int n, double hfact, int sub) {
  const double dx = 1.0 / n, dy = dx / sub, support = hfact * dx;
  const int ns = n * sub, k = static_cast<int>(std::ceil(support / dy));
  auto count = [](int per_side) { return D == 2 ? std::size_t(per_side) * per_side : std::size_t(per_side) * per_side * per_side; };
  std::vector<double> sampled(count(ns));
  for (std::size_t j = 0; j < sampled.size(); ++j) {
    double r2 = 0.0;
    std::size_t q = j;
    for (int d = 0; d < D; ++d) {
      const double y = (double(q % ns) + 0.5) * dy - 0.5;
      r2 += y * y, q /= ns;
    }
    sampled[j] = ex.density(std::sqrt(r2), E, rho0, t_R(ex));
  }
  Synthetic<D> s;
  for (std::size_t i = 0; i < count(n); ++i) {
    // The particle sits on sample site c (sub odd: the particle lattice is a subset of the samples).
    std::array<int, 3> c{};
    sph::Vec<D> x;
    std::size_t q = i;
    for (int d = 0; d < D; ++d) c[d] = int(q % n) * sub + sub / 2, x[d] = (double(q % n) + 0.5) * dx - 0.5, q /= n;
    double sum = 0.0;
    for (int a = -k; a <= k; ++a)
      for (int b = -k; b <= k; ++b)
        for (int e = (D == 3 ? -k : 0); e <= (D == 3 ? k : 0); ++e) {
          const int off[3] = {a, b, e};
          std::size_t j = 0, stride = 1;
          double r2 = 0.0;
          for (int d = 0; d < D; ++d) {
            j += std::size_t(((c[d] + off[d]) % ns + ns) % ns) * stride, stride *= ns;
            r2 += off[d] * dy * off[d] * dy;
          }
          sum += sampled[j] * sph::CubicSpline<D>::W(std::sqrt(r2), support);
        }
    s.x.push_back(x);
    s.rho.push_back(sum * std::pow(dy, D));
    s.m.push_back(rho0 * std::pow(dx, D));
    s.h.push_back(support);
  }
  return s;
}

template <int D>
sphv::Result score(const Synthetic<D>& s, const std::vector<double>& h, double support_per_h, int n,
                   const reference::Sedov& ex) {
  sphv::Result r;
  sphv::sedov::measure<D>(r, s.x, {}, s.m, s.rho, h, support_per_h, n, E, rho0, t_R(ex), ex);
  return r;
}

}  // namespace

TEST_CASE("sedov smoothing: rho_h agrees with a brute-force convolution", "[sedov][sedov_front]") {
  // Midpoint sums at h / 40 (3D) and h / 200 (2D): their error is the jump's sampling, a
  // fraction ~ dy / h of the kernel's mass near the shock (1e-2 at most in the worst point
  // measured, 3D, r = R); the bound 2e-2 is twice that. Far from the jump both sides are smooth
  // and agree to the quadratures' error (the constant: 1e-12).
  for (const int D : {2, 3}) {
    const reference::Sedov ex(D, 5.0 / 3.0);
    const double R = ex.shock_radius(E, rho0, t);
    for (const double h : {0.1 * R, 0.3 * R})
      for (const double r : {0.3 * R, 0.8 * R, 0.95 * R, R, 1.05 * R}) {
        const double quad = D == 3 ? sphv::sedov::smoothed_density<3>(ex, r, h, E, rho0, t)
                                   : sphv::sedov::smoothed_density<2>(ex, r, h, E, rho0, t);
        const double brute = D == 3 ? brute_force_smoothing<3>(ex, r, h, 40) : brute_force_smoothing<2>(ex, r, h, 200);
        INFO("D = " << D << ", h = " << h / R << " R, r = " << r / R << " R: quadrature " << quad << ", brute force " << brute);
        CHECK(std::abs(quad - brute) <= 2e-2 * brute);
      }
    CHECK(std::abs(sphv::sedov::smoothed_density<3>(ex, 2.0 * R, 0.3 * R, E, rho0, t) - rho0) < 1e-12);
  }
}

TEST_CASE("sedov smoothing: rho_h with each kernel agrees with a brute-force convolution", "[sedov][sedov_front]") {
  // As above, for the kernels a sedov run can select (the smoothing's knots and moments are the
  // kernel's): the same grids and bound, at h = 0.3 R, around the jump.
  for (const std::string& name : sph::kernel_names()) {
    const auto check = [&](auto k2, auto k3) {
      using K2 = decltype(k2);
      using K3 = decltype(k3);
      for (const int D : {2, 3}) {
        const reference::Sedov ex(D, 5.0 / 3.0);
        const double R = ex.shock_radius(E, rho0, t), h = 0.3 * R;
        for (const double r : {0.3 * R, 0.95 * R, R, 1.05 * R}) {
          const double quad = D == 3 ? sphv::sedov::smoothed_density<3, K3>(ex, r, h, E, rho0, t)
                                     : sphv::sedov::smoothed_density<2, K2>(ex, r, h, E, rho0, t);
          const double brute =
              D == 3 ? brute_force_smoothing<3, K3>(ex, r, h, 40) : brute_force_smoothing<2, K2>(ex, r, h, 200);
          INFO(name << ", D = " << D << ", r = " << r / R << " R: quadrature " << quad << ", brute force " << brute);
          CHECK(std::abs(quad - brute) <= 2e-2 * brute);
        }
      }
    };
    sph::with_kernel_family(name, [&]<template <int> class K>() { check(K<2>{}, K<3>{}); });
  }
}

TEST_CASE("sedov smoothing: the half-rise rule reads the smoothed exact 3D front outside R", "[sedov][sedov_front]") {
  // Half-rise of the exact 3D profile (gamma 5/3) smoothed with support 0.1, 0.2, 0.3, 0.4 R:
  // +1.25, +3.59, +6.50, +9.84 % (this quadrature, checked above against the brute-force sum).
  // Issue 43 quotes +2.6, +4.1, +6.8, +10.0 %: the three wider supports agree within 0.5 point;
  // at 0.1 R the spike is 0.03 R wide and its half-rise depends on how finely the profile is
  // sampled, which the issue does not state. Bound: 0.05 point, the fine grid's interpolation.
  const reference::Sedov ex(3, 5.0 / 3.0);
  const double R = ex.shock_radius(E, rho0, t);
  const double expected[] = {0.0125, 0.0359, 0.0650, 0.0984};
  for (int k = 0; k < 4; ++k) {
    const double bias = half_rise_bias<3>(ex, 0.1 * (k + 1) * R);
    INFO("support " << 0.1 * (k + 1) << " R: half-rise at " << 100 * bias << " %");
    CHECK(std::abs(bias - expected[k]) < 5e-4);
  }
}

TEST_CASE("sedov shock_radius: zero on particles that carry the smoothed exact field", "[sedov][sedov_front]") {
  // The fine lattice sum differs from the convolution rho_h by its sampling of the jump; the two
  // fronts, profiled alike, then differ by a small fraction of the profile's step (0.25 / n: 2.6 % R
  // in 3D at n = 32, 1.3 % R in 2D at n = 64). Measured: 3D 0.010 %, 2D 0.024 % of R; bound 0.5 %
  // (margin 20 over the larger, and a twelfth of the half-rise bias below). On the same particles
  // the half-rise against R reads the kernel's bias, the old definition's: +6.0 % (3D, support
  // 0.25 R), +1.9 % (2D, support 0.125 R); the bounds below are about 2/3 of those.
  SECTION("3D, n = 32, hfact 2.4 (support 0.25 R)") {
    const reference::Sedov ex(3, 5.0 / 3.0);
    const auto s = synthetic<3>(ex, 32, 2.4, 3);
    const sphv::Result r = score<3>(s, s.h, 1.0, 32, ex);
    INFO(r.extra.dump());
    REQUIRE(r.errors.count("shock_radius"));
    CHECK(r.errors.at("shock_radius") < 5e-3);
    CHECK(r.extra.at("shock_radius_halfrise").get<double>() > 0.04);  // measured 0.0604
    // The same particles scored with the support taken as half their h (a wrong convention): the
    // smoothed front moves in and the error is most of the bias again (measured 0.0257).
    CHECK(score<3>(s, s.h, 0.5, 32, ex).errors.at("shock_radius") > 0.02);
  }
  SECTION("2D, n = 64, hfact 2.4") {
    const reference::Sedov ex(2, 5.0 / 3.0);
    const auto s = synthetic<2>(ex, 64, 2.4, 5);
    const sphv::Result r = score<2>(s, s.h, 1.0, 64, ex);
    INFO(r.extra.dump());
    REQUIRE(r.errors.count("shock_radius"));
    CHECK(r.errors.at("shock_radius") < 5e-3);
    CHECK(r.extra.at("shock_radius_halfrise").get<double>() > 0.012);  // measured 0.0189
  }
  SECTION("no h: shock_radius is not reported, the half-rise is, and the reason is given") {
    const reference::Sedov ex(2, 5.0 / 3.0);
    const auto s = synthetic<2>(ex, 32, 2.4, 1);
    const sphv::Result r = score<2>(s, {}, 1.0, 32, ex);
    CHECK(r.errors.count("shock_radius") == 0);
    CHECK(r.errors.count("L1_rho") == 1);
    CHECK(r.extra.contains("shock_radius_halfrise"));
    CHECK(r.extra.contains("shock_radius_note"));
  }
}

TEST_CASE("sedov front: the front moves no farther than a shell that moves", "[sedov][sedov_front]") {
  // Particles on the 2D lattice (n = 32) carrying the smoothed exact field; every shell of
  // particles at one radius between 0.8 R and 1.1 R (the peak and the fall) moved outwards with
  // its densities, one shell at a time, over a quarter of a spacing in steps of 0.1 % of a spacing.
  // A profile whose weights are continuous in the radius moves its front by at most the shell's
  // share of the weight times the step; one binned (or windowed) a quarter of a spacing wide moves
  // the shell's whole weight at once when the shell crosses an edge, and the front jumps however
  // small the step. Measured: the largest step of the front is 0.17 times the shell's step (on
  // quarter-spacing bins: 166 times); bound 1 (the front moving farther than the shell is a jump).
  const reference::Sedov ex(2, 5.0 / 3.0);
  const int n = 32;
  const auto s = synthetic<2>(ex, n, 2.4, 3);
  const double dx = 1.0 / n, step = 1e-3 * dx;
  std::vector<double> rad(s.x.size());
  for (std::size_t i = 0; i < s.x.size(); ++i) rad[i] = s.x[i].norm();
  const double R = ex.shock_radius(E, rho0, t_R(ex));
  std::vector<double> shells;
  for (double r : rad)
    if (r > 0.8 * R && r < 1.1 * R &&
        std::none_of(shells.begin(), shells.end(), [&](double q) { return std::abs(q - r) < 1e-12; }))
      shells.push_back(r);
  REQUIRE(shells.size() > 10);
  double worst = 0.0;
  for (double shell : shells) {
    auto moved = rad;
    double last = sphv::sedov::front(moved, s.rho, rho0, n).r_front;
    for (int k = 0; k < 250; ++k) {
      for (double& r : moved)
        if (std::abs(r - (shell + k * step)) < 1e-9) r += step;
      const double now = sphv::sedov::front(moved, s.rho, rho0, n).r_front;
      worst = std::max(worst, std::abs(now - last) / step);
      last = now;
    }
  }
  INFO(shells.size() << " shells; the front's largest step is " << worst << " times the shell's");
  CHECK(worst < 1.0);
}
