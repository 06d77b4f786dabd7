#pragma once
// The Sedov blast's errors and profiles at time t, shared by `sphv run` and `sphv score`.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reference/sedov.hpp"
#include "sph/core/vec.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/cases/sedov/smoothed.hpp"
#include "verification/harness/params.hpp"

namespace sphv::sedov {

inline const std::map<std::string, std::string> error_defs = {
    {"shock_radius",
     "|R_front - R_front(rho_h)| / R, R = xi_0 (E t^2 / rho0)^(1/(d+2)); R_front: where the particles' density averaged "
     "with a tent weight of half-width 1/n around radii 0.25/n apart on [0, 0.5) falls, going outwards from its "
     "peak, through (rho0 + peak) / 2 (linear between those radii); R_front(rho_h): the same estimator on the same bins applied to rho_h(r_i, h_i), the "
     "exact density convolved with the cubic spline at each particle's support h_i (the SPH estimate of the exact "
     "field). Not reported for a snapshot without h (extra shock_radius_halfrise: |R_front - R| / R)"},
    {"L1_rho", "sum over particles with r < 1.2 R of (m_i/rho_i) |rho_i - rho_exact(r_i, t)|, divided by the ball's "
               "volume vol_d(1.2 R) and by rho0 (r from the blast centre; exact: the Sedov-Taylor similarity solution)"},
    {"mismatch", "sphv score's check that a snapshot holds the problem its settings describe (not an error): every "
                 "particles farther than R + 2 support radii from the centre (h, or 3 spacings (m/rho)^(1/d) without "
                 "h) are ambient gas at rest: median rho within 5 % of rho0 and median |v| within 5 % of the shock "
                 "speed U, at most a tenth of them off by more; otherwise the verdict is mismatch"}};

// The shock radius sphv's runs end at (box half-width 0.5).
constexpr double R_target = 0.3;

// The end time: the parameter t, or (t = 0) when the shock reaches R_target.
inline double end_time(const Params& p) {
  const double E = p.real("E"), rho0 = p.real("rho0"), t = p.real("t");
  const int d = static_cast<int>(p.integer("dim"));
  return t > 0.0 ? t : std::sqrt(std::pow(R_target / reference::Sedov(d, p.real("gamma")).xi0(), d + 2) * rho0 / E);
}

// The exact share of the blast's energy that is kinetic, sigma_d alpha^2 xi_0^(d+2) int_0^1
// g f^2 / 2 xi^(d-1) dxi (the kinetic part of the energy integral, reference/sedov.hpp), by the
// midpoint rule on 10^5 cells (the profiles are tabulated and linear between their points).
inline double kinetic_share(const reference::Sedov& exact, int d) {
  const double sigma = d == 2 ? 2.0 * M_PI : 4.0 * M_PI, alpha = 2.0 / (d + 2);
  const int cells = 100000;
  double sum = 0.0;
  for (int k = 0; k < cells; ++k) {
    const double xi = (k + 0.5) / cells, f = exact.f(xi);
    sum += 0.5 * exact.g(xi) * f * f * std::pow(xi, d - 1);
  }
  return sigma * alpha * alpha * std::pow(exact.xi0(), d + 2) * sum / cells;
}

// vol_d(1.2 R): the ball the density's L1 errors are taken over, and their denominator.
template <int D>
double error_ball(double R) {
  return radial::ball_volume(D, 1.2 * R);
}

// Sum over the particles with r < 1.2 R of their volumes m/rho times |a - b|, over vol_d(1.2 R)
// rho0: L1_rho's norm (a, b: the particles' and a reference's densities at their radii).
template <int D>
double ball_l1(const std::vector<double>& rad, const std::vector<double>& volume, const std::vector<double>& a,
               const std::vector<double>& b, double R, double rho0) {
  double l1 = 0.0;
  for (std::size_t i = 0; i < rad.size(); ++i)
    if (rad[i] < 1.2 * R) l1 += volume[i] * std::abs(a[i] - b[i]);
  return l1 / error_ball<D>(R) / rho0;
}

// The front of a radial density profile: the mean density of the particles weighted by a tent of
// half-width one spacing (1/n) around each radius of a grid of quarter-spacing steps on [0, 0.5),
// and where that profile falls, going outwards from its peak, through half-way between the
// ambient density and the peak. A lattice's shells of equal-density particles lie a fraction of a
// spacing apart; with a weight that is continuous in the radius, a shell that moves by a small
// distance changes the profile by as little (a bin's edge, or a window's, would move the shell's
// whole weight at once, and at n = 32 one shell of eight particles crossing an edge moves the
// half-rise point by a tenth of a spacing). The half-rise point of a symmetrically smoothed step
// is the step; behind a blast the profile is a spike, and the level is crossed outside R by a
// fraction of the kernel's support that does not depend on the code (hence the comparison with
// rho_h below). found: the profile falls through the half level beyond its peak (else r_front is
// the peak's); no particle within 0.5 of the centre (a scored snapshot's centre off its blast):
// no profile, NaN.
struct Front {
  double r_front, r_peak, rho_peak;
  bool found;
};
inline extreme::Profile tent_profile(const std::vector<double>& rad, const std::vector<double>& rho, int n) {
  constexpr int steps = 4;       // grid points per spacing; the tent spans steps on either side
  const int points = 2 * n;      // 0.5 / (0.25 / n)
  const double dr = 0.5 / points;
  std::vector<double> sum(points, 0.0), weight(points, 0.0);
  for (std::size_t i = 0; i < rad.size(); ++i) {
    const double q = rad[i] / dr;  // compared before the cast (NaN and huge q stay out)
    if (!(q >= 0.0 && q < points + steps)) continue;
    const int k = static_cast<int>(q);
    for (int j = std::max(0, k - steps + 1); j <= std::min(points - 1, k + steps); ++j) {
      const double w = 1.0 - std::abs(q - j) / steps;
      if (w > 0.0) sum[j] += w * rho[i], weight[j] += w;
    }
  }
  extreme::Profile prof;
  for (int j = 0; j < points; ++j)
    if (weight[j] > 0.0) prof.r.push_back(j * dr), prof.mean.push_back(sum[j] / weight[j]);
  return prof;
}
inline Front front(const std::vector<double>& rad, const std::vector<double>& rho, double rho0, int n) {
  const extreme::Profile prof = tent_profile(rad, rho, n);
  if (prof.mean.empty()) return {std::nan(""), std::nan(""), std::nan(""), false};
  const auto peak = std::max_element(prof.mean.begin(), prof.mean.end()) - prof.mean.begin();
  const double fall = radial::falling_through(prof, 0.5 * (rho0 + prof.mean[peak]), prof.r[peak], -1.0);
  return {fall < 0.0 ? prof.r[peak] : fall, prof.r[peak], prof.mean[peak], fall >= 0.0};
}

// Fills r.errors, r.functionals, the profile figures and extras from the particles at time t
// (positions relative to the blast centre); n: particles per side of the unit box (the tent 1 / n);
// h: the particles' smoothing lengths (empty: the snapshot has none), whose kernel support is
// support_per_h h (1 in sphv, whose h is the support, and for SWIFT files, whose reader
// converts; 2 for SPH-EXA). K: the kernel the reference density is smoothed with, the run's.
template <int D, class K = sph::CubicSpline<D>>
void measure(Result& r, const std::vector<sph::Vec<D>>& x, const std::vector<sph::Vec<D>>& v, const std::vector<double>& m,
             const std::vector<double>& rho, const std::vector<double>& h, double support_per_h, int n, double E,
             double rho0, double t, const reference::Sedov& exact) {
  const double R = exact.shock_radius(E, rho0, t), dx = 1.0 / n;
  std::vector<double> rad(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) rad[i] = x[i].norm();
  const Front f = front(rad, rho, rho0, n);
  // L1 density error over the ball r < 1.2 R (shocked gas and some ambient gas), per unit volume
  // of the ball.
  std::vector<double> volume(x.size()), rho_exact(x.size());
  double in_ball = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    volume[i] = m[i] / rho[i];
    rho_exact[i] = rad[i] < 1.2 * R ? exact.density(rad[i], E, rho0, t) : rho0;
    if (rad[i] < 1.2 * R) ++in_ball;
  }
  r.errors = {{"L1_rho", ball_l1<D>(rad, volume, rho, rho_exact, R, rho0)}};
  r.functionals = {{"R_front", f.r_front}, {"rho_peak", f.rho_peak}};
  r.extra["R_front_halfrise"] = f.r_front;
  r.extra["shock_radius_halfrise"] = std::abs(f.r_front - R) / R;
  r.extra["front_found"] = f.found;
  r.extra["ball_particles"] = in_ball;
  r.extra["R_peak"] = f.r_peak;
  r.extra["rho_peak_binned"] = f.rho_peak;
  r.extra["rho_peak_exact"] = exact.g(1.0) * rho0;
  r.extra["tent_half_width"] = dx;  // on radii dx / 4 apart
  const auto densest = std::max_element(rho.begin(), rho.end()) - rho.begin();
  if (!rho.empty()) r.extra["R_densest"] = rad[densest];
  if (h.size() == x.size()) {
    // rho_h at every binned particle; beyond r - h_i > R the kernel sees only ambient gas.
    std::vector<double> rho_h(x.size(), rho0);
    for (std::size_t i = 0; i < x.size(); ++i)
      if (rad[i] < 0.5 && rad[i] - support_per_h * h[i] < R)
        rho_h[i] = smoothed_density<D, K>(exact, rad[i], support_per_h * h[i], E, rho0, t);
    const Front fh = front(rad, rho_h, rho0, n);
    r.errors["shock_radius"] = std::abs(f.r_front - fh.r_front) / R;
    r.extra["R_front_smoothed_exact"] = fh.r_front;
    r.extra["front_offset"] = (f.r_front - fh.r_front) / R;
    r.extra["R_peak_smoothed_exact"] = fh.r_peak;
  } else {
    r.extra["shock_radius_note"] = "no h column: shock_radius (against the kernel-smoothed exact front) not computed";
  }

  const std::string dim = std::to_string(D) + "D";
  r.figures.push_back(radial::profile_figure(
      "profile_rho", "Sedov " + dim + ", n = " + std::to_string(n) + ": density at t = " + std::to_string(t),
      "r / R(t)", "rho / rho0", rad, rho, 1.5 * R, R, "Sedov-Taylor (similarity solution)",
      [&](double s) { return exact.density(s, E, rho0, t) / rho0; }));
  if (v.empty()) return;
  const double U = exact.shock_speed(E, rho0, t);
  std::vector<double> v_r(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) v_r[i] = v[i].dot(x[i]) / std::max(rad[i], 1e-300) / U;
  r.figures.push_back(radial::profile_figure("profile_v", "Sedov " + dim + ": radial velocity", "r / R(t)",
                                             "v_r / (dR/dt)", rad, v_r, 1.5 * R, R, "Sedov-Taylor",
                                             [&](double s) { return exact.f(s / R); }));
}

}  // namespace sphv::sedov
