#include "verification/io/gravity_input.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "verification/harness/params.hpp"

namespace sphv {

gravity::ParticleSet gravity_particles(const Snapshot& s, double eps) {
  const std::string f = s.path.string(), who = "gravity (x, y, z, m)";
  gravity::ParticleSet set;
  set.x.assign(s.size(), sph::Vec<3>::Zero());
  for (int d = 0; d < s.dim; ++d) {
    const auto& c = s.at(std::string(1, "xyz"[d]), who);
    for (std::size_t i = 0; i < c.size(); ++i) set.x[i][d] = c[i];
  }
  set.m = s.at("m", who);
  for (std::size_t i = 0; i < set.m.size(); ++i)
    if (!(set.m[i] > 0.0))
      throw InputError(f + ": particle " + std::to_string(i) + " has mass " + std::to_string(set.m[i]) +
                       " (" + s.taken_from.at("m") + "; masses must be > 0)");
  if (eps > 0.0) return set;
  // Coincident particles: neighbours in lexicographic order.
  std::vector<std::size_t> order(set.x.size());
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(set.x[a].begin(), set.x[a].end(), set.x[b].begin(), set.x[b].end());
  };
  std::sort(order.begin(), order.end(), less);
  for (std::size_t k = 1; k < order.size(); ++k)
    if (set.x[order[k]] == set.x[order[k - 1]]) {
      const auto& p = set.x[order[k]];
      throw InputError(f + ": particles " + std::to_string(std::min(order[k], order[k - 1])) + " and " +
                       std::to_string(std::max(order[k], order[k - 1])) + " coincide at (" + std::to_string(p[0]) +
                       ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
                       "): with zero softening their force is infinite (give a softening > 0)");
    }
  return set;
}

std::vector<double> finite_values(const std::vector<double>& v) {
  std::vector<double> out;
  for (double e : v)
    if (std::isfinite(e)) out.push_back(e);
  return out;
}

}  // namespace sphv
