#pragma once
// Shared by the radially symmetric hydro cases (sedov, noh): the result of a run compared with an
// exact radial profile. The verdict, where a binned profile falls through a level (a smeared
// shock's position), the figure of particle values against the exact curve, and the per-level
// gates of a sweep.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::radial {

// Volume of the d-ball of radius r.
inline double ball_volume(int d, double r) { return (d == 1 ? 2.0 : d == 2 ? M_PI : 4.0 / 3.0 * M_PI) * std::pow(r, d); }

// A run's result before its measurements: particle count, verdict "stable" when the run reached
// t_end, else the integrator's verdict (the first step and particle that went bad).
inline Result start(std::size_t n_particles, const sph::HydroOutcome& out) {
  Result r;
  r.n_particles = n_particles;
  r.verdict = out.verdict == "ok" ? "stable" : out.verdict;
  return r;
}

// The first radius beyond r_from where the binned profile falls, going outwards, through level
// (linear interpolation between the two bins' centres); `none` if it never does.
inline double falling_through(const extreme::Profile& prof, double level, double r_from, double none) {
  for (std::size_t b = 0; b + 1 < prof.r.size(); ++b)
    if (prof.r[b] >= r_from && prof.mean[b] >= level && prof.mean[b + 1] < level)
      return prof.r[b] + (prof.r[b + 1] - prof.r[b]) * (prof.mean[b] - level) / (prof.mean[b] - prof.mean[b + 1]);
  return none;
}

// Particle values (at most ~4000 of those with r < r_max) against the exact curve sampled at 600
// radii, both with the radius divided by r_unit.
inline Figure profile_figure(std::string name, std::string title, std::string xlabel, std::string ylabel,
                             const std::vector<double>& radius, const std::vector<double>& value, double r_max,
                             double r_unit, const std::string& exact_label, const std::function<double(double)>& exact) {
  Series pts{"SPH particles", {}, {}, "points"}, line{exact_label, {}, {}, "line"};
  const std::size_t stride = std::max<std::size_t>(1, radius.size() / 4000);
  for (std::size_t i = 0; i < radius.size(); i += stride)
    if (radius[i] < r_max) pts.x.push_back(radius[i] / r_unit), pts.y.push_back(value[i]);
  for (int k = 0; k <= 600; ++k) {
    const double r = r_max * k / 600.0;
    line.x.push_back(r / r_unit), line.y.push_back(exact(r));
  }
  return {std::move(name), std::move(title), std::move(xlabel), std::move(ylabel), "linear", "linear", {pts, line}};
}

// Gates of a sweep: per level "n<level>_stable", then level_checks(prefix, run) for the stable runs.
inline std::vector<Check> per_level(const Sweep& s,
                                    const std::function<void(const std::string&, const Result&, std::vector<Check>&)>& level_checks) {
  std::vector<Check> c;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const Result& r = s.runs[k];
    const std::string level = "n" + std::to_string(s.levels[k]);
    c.push_back({level + "_stable", double(r.verdict == "stable"), 1.0, 1.0, "runs to t_end with a finite, positive state"});
    if (r.verdict == "stable") level_checks(level, r, c);
  }
  return c;
}

}  // namespace sphv::radial
