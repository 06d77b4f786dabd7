#pragma once
// Tree gravity against the direct sum: plain-array conversion, relative errors, percentiles.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reference/direct_sum.hpp"
#include "sph/gravity/tree_gravity.hpp"

namespace sphv::gravity {

struct Columns {
  std::vector<double> x, y, z;
};
inline Columns columns(const std::vector<sph::Vec<3>>& v) {
  Columns c;
  for (const auto& p : v) c.x.push_back(p[0]), c.y.push_back(p[1]), c.z.push_back(p[2]);
  return c;
}

inline reference::DirectField direct(const std::vector<sph::Vec<3>>& x, const std::vector<double>& m, double eps) {
  const Columns c = columns(x);
  return reference::direct_sum(c.x, c.y, c.z, m, 1.0, eps);
}

// |a_tree - a_direct| / |a_direct| per particle.
inline std::vector<double> relative_force_error(const sph::GravityField& t, const reference::DirectField& d) {
  std::vector<double> e(t.a.size());
  for (std::size_t i = 0; i < e.size(); ++i) {
    const sph::Vec<3> ad(d.ax[i], d.ay[i], d.az[i]);
    e[i] = (t.a[i] - ad).norm() / ad.norm();
  }
  return e;
}

// Potential energy W = 1/2 sum_i m_i phi_i.
inline double potential_energy(const std::vector<double>& m, const std::vector<double>& phi) {
  double w = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) w += 0.5 * m[i] * phi[i];
  return w;
}

// Nearest-rank percentiles of |errors|: median, 90th, 99th and the maximum.
struct Percentiles {
  double p50, p90, p99, max;
};
inline Percentiles percentiles(std::vector<double> e) {
  if (e.empty()) return {NAN, NAN, NAN, NAN};
  std::sort(e.begin(), e.end());
  auto at = [&](double p) { return e[std::min(e.size() - 1, std::size_t(std::ceil(p * e.size())) - 1)]; };
  return {at(0.5), at(0.9), at(0.99), e.back()};
}

// The errors `sphv score gravity` reports for a snapshot's own accelerations (and potential).
inline const std::map<std::string, std::string> score_error_defs = {
    {"force_p50", "sphv score: median over particles of |a_code - a_direct| / |a_direct| (particles with a_direct = 0 "
                  "left out); a_direct: O(N^2) direct sum, G = 1, Plummer softening eps"},
    {"force_p90", "sphv score: 90th percentile (nearest rank) of the same"},
    {"force_p99", "sphv score: 99th percentile (nearest rank) of the same"},
    {"force_max", "sphv score: maximum of the same"},
    {"energy", "sphv score: |W_code - W_direct| / |W_direct|, W = 1/2 sum_i m_i phi_i (when the snapshot has a potential)"}};

}  // namespace sphv::gravity
