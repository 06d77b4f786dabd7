#pragma once
// The Gresho-Chan vortex's errors at time t, shared by `sphv run` and `sphv score`: the azimuthal
// velocity against the exact stationary profile (reference/gresho.hpp) within r < 0.5 of the
// vortex's centre (the disc inscribed in the unit box; the vortex ends at r = 0.4).
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reference/gresho.hpp"
#include "sph/core/vec.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/harness/result.hpp"

namespace sphv::gresho {

// The disc the errors are taken over.
inline constexpr double r_scored = 0.5;

inline const std::map<std::string, std::string> error_defs = {
    {"L1_v", "sum_i m_i |v_phi,i - v_phi(r_i)| / sum_i m_i over the particles with r_i < 0.5 (mass-weighted; "
             "per particle for equal masses), r_i the distance from the vortex's centre, v_phi,i = (x_i - c) x v_i "
             "/ r_i, v_phi the exact stationary profile (reference/gresho; peak 1 at r = 0.2). extra: L1_v_r the same "
             "mean of |v_r,i| (exact 0), v_phi_peak the largest mean v_phi of 0.02-wide radial bins (exact 1)"},
    {"mismatch", "sphv score's check that a snapshot holds the problem its settings describe (not an error): every "
                 "particles beyond r = 0.4 + 2 support radii (h, or 3 spacings (m/rho)^(1/2) without h) hold rho0 and "
                 "the outer pressure p(0.4): medians within 5 % relative, at most a tenth of them off by more; "
                 "otherwise the verdict is mismatch"}};

// Fills r.errors (L1_v), extras and the profile figure from the particles at time t; x relative to
// the vortex's centre.
inline void measure(Result& r, const std::vector<sph::Vec<2>>& x, const std::vector<sph::Vec<2>>& v,
                    const std::vector<double>& m, double t, const reference::GreshoVortex& g, long n) {
  double mass = 0.0, l1 = 0.0, l1_r = 0.0, max_err = 0.0;
  std::vector<double> radius(x.size()), vphi(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double rad = x[i].norm();
    const double vp = rad > 0.0 ? (x[i][0] * v[i][1] - x[i][1] * v[i][0]) / rad : 0.0;
    const double vr = rad > 0.0 ? (x[i][0] * v[i][0] + x[i][1] * v[i][1]) / rad : v[i].norm();
    radius[i] = rad, vphi[i] = vp;
    if (!(rad < r_scored)) continue;
    const double e = std::abs(vp - g.v_phi(rad));
    mass += m[i];
    l1 += m[i] * e;
    l1_r += m[i] * std::abs(vr);
    max_err = std::max(max_err, e);
  }
  if (!(mass > 0.0)) {
    r.verdict = "no particle within r < 0.5 of the vortex's centre";
    return;
  }
  r.errors = {{"L1_v", l1 / mass}};
  const extreme::Profile prof = extreme::radial_profile(radius, vphi, r_scored, 25);
  double peak = 0.0;
  for (double vb : prof.mean) peak = std::max(peak, vb);
  r.functionals = {{"v_phi_peak", peak}};
  r.extra["L1_v_r"] = l1_r / mass;
  r.extra["max_v_phi_error"] = max_err;
  r.extra["v_phi_peak"] = peak;
  r.extra["t"] = t;
  r.figures.push_back(radial::profile_figure(
      "profile_vphi", "Gresho vortex, n = " + std::to_string(n) + ": v_phi at t = " + std::to_string(t), "r",
      "v_phi", radius, vphi, r_scored, 1.0, "exact stationary vortex", [&](double s) { return g.v_phi(s); }));
}

}  // namespace sphv::gresho
