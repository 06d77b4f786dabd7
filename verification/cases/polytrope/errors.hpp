#pragma once
// The polytrope's errors at time t, shared by `sphv run` and `sphv score`: the particles' density
// against the n = 1 Lane-Emden profile (reference/polytrope) around a centre; the mean density of
// the innermost mass shell (the central density), whose drift over the run `sphv run` reports.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "reference/polytrope.hpp"
#include "sph/core/vec.hpp"
#include "verification/harness/result.hpp"

namespace sphv::polytrope {

// The inner shell whose mean density stands for the central density: the innermost particles
// holding this fraction of the mass (about 50 particles at N = 500; its radius is 0.34 R).
inline constexpr double inner_mass_fraction = 0.1;

inline const std::map<std::string, std::string> error_defs = {
    {"rho_profile_L1",
     "sum_i m_i |rho_i - rho(r_i)| / (M rho_c) over all particles at t_end, r_i = |x_i - centre|, rho(r) = rho_c "
     "sin(pi r / R) / (pi r / R) inside R and 0 beyond (the n = 1 Lane-Emden profile, M = sum_i m_i)"},
    {"central_density_drift",
     "max over the steps t of the free evolution of |rho_in(t) / rho_in(0) - 1|, rho_in = sum m_i rho_i / sum m_i "
     "over the innermost particles (by r_i) holding a tenth of the mass"},
    {"mismatch", "sphv score's check that a snapshot holds the problem its settings describe (not an error): the "
                 "particles' total mass is the star's M = 1 within 1e-4 and their median p / rho^gamma is K within 5 % "
                 "(an adiabatic star keeps its entropy); otherwise the verdict is mismatch"}};

// rho_in: the mass-weighted mean of rho over the innermost particles (radii rad) holding the
// mass fraction q (the particle that crosses q counted with its share).
inline double inner_density(const std::vector<double>& rad, const std::vector<double>& m,
                            const std::vector<double>& rho, double q) {
  std::vector<std::size_t> order(rad.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rad[a] < rad[b]; });
  const double total = std::accumulate(m.begin(), m.end(), 0.0), want = q * total;
  double mass = 0.0, sum = 0.0;
  for (std::size_t i : order) {
    const double take = std::min(m[i], want - mass);
    if (take <= 0.0) break;
    mass += take, sum += take * rho[i];
  }
  return mass > 0.0 ? sum / mass : 0.0;
}

template <class Vec>
std::vector<double> radii(const std::vector<Vec>& x, const Vec& centre) {
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) r[i] = (x[i] - centre).norm();
  return r;
}

// The error rho_profile_L1 of particles at radii rad against the star of
// their total mass and K, G, the profile figure, and extras.
inline void measure(Result& r, const std::vector<double>& rad, const std::vector<double>& m,
                    const std::vector<double>& rho, double K, double G, double t) {
  const double mass = std::accumulate(m.begin(), m.end(), 0.0);
  const reference::Polytrope1 star(mass, K, G);
  double e = 0.0;
  for (std::size_t i = 0; i < rad.size(); ++i) e += m[i] * std::abs(rho[i] - star.density(rad[i]));
  r.errors["rho_profile_L1"] = e / (mass * star.central_density());
  const double in = inner_density(rad, m, rho, inner_mass_fraction);
  const double in_ref = star.mean_density_within_mass_fraction(inner_mass_fraction);
  // The inner shell's density against the profile's at this one time: an extra, not an error (it
  // oscillates with the star's ringing, so its value at t_end depends on the phase).
  r.extra["central_density_offset"] = in / in_ref - 1.0;
  r.extra["rho_inner"] = in;
  r.extra["rho_inner_reference"] = in_ref;
  r.extra["profile_time"] = t;
  r.extra["R"] = star.radius();
  r.extra["rho_c"] = star.central_density();
  r.extra["M"] = mass;
  double r_max = 0.0;
  for (double ri : rad) r_max = std::max(r_max, ri);
  r.extra["r_max_over_R"] = r_max / star.radius();

  Series pts{"SPH particles", {}, {}, "points"}, line{"n = 1 Lane-Emden", {}, {}, "line"};
  const std::size_t stride = std::max<std::size_t>(1, rad.size() / 3000);
  for (std::size_t i = 0; i < rad.size(); i += stride) pts.x.push_back(rad[i]), pts.y.push_back(rho[i]);
  const double span = std::max(r_max, star.radius());
  for (int k = 0; k <= 400; ++k) {
    const double s = span * k / 400.0;
    line.x.push_back(s), line.y.push_back(star.density(s));
  }
  r.figures.push_back({"profile_rho", "n = 1 polytrope at t = " + std::to_string(t) + ", N = " +
                                          std::to_string(rad.size()) + ": density",
                       "r", "rho", "linear", "linear", {pts, line}});
}

}  // namespace sphv::polytrope
