#pragma once
// The columns a scorer reads from another code's snapshot, as the cases' error functions take
// them (the scorers beside each case: verification/cases/*_snapshots.cpp).
#include <string>
#include <vector>

#include "sph/core/vec.hpp"
#include "verification/harness/params.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv::snapshot_columns {

// Positions (minus centre) or velocities of the first D axes as vectors.
template <int D>
std::vector<sph::Vec<D>> vectors(const Snapshot& s, const std::string& prefix, const std::string& who,
                                 const sph::Vec<D>& centre = sph::Vec<D>::Zero()) {
  std::vector<sph::Vec<D>> v(s.size());
  for (int d = 0; d < D; ++d) {
    const auto& c = s.at(prefix + std::string(1, "xyz"[d]), who);
    for (std::size_t i = 0; i < v.size(); ++i) v[i][d] = c[i] - centre[d];
  }
  return v;
}

// u, or (gamma - 1)^-1 p / rho from the pressure when the snapshot has no u (SPH-EXA).
inline std::vector<double> internal_energy(const Snapshot& s, double gamma, const std::string& who) {
  if (s.has("u") || !s.has("p")) return s.at("u", who + " (or p)");
  const auto &p = s.at("p", who), &rho = s.at("rho", who);
  std::vector<double> u(s.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = p[i] / ((gamma - 1.0) * rho[i]);
  return u;
}
inline std::vector<double> pressure(const Snapshot& s, double gamma, const std::string& who) {
  if (s.has("p") || !s.has("u")) return s.at("p", who + " (or u)");
  const auto &u = s.at("u", who), &rho = s.at("rho", who);
  std::vector<double> p(s.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = (gamma - 1.0) * rho[i] * u[i];
  return p;
}

inline void positive(const Snapshot& s, const std::string& name, const std::string& who) {
  const auto& c = s.at(name, who);
  for (std::size_t i = 0; i < c.size(); ++i)
    if (!(c[i] > 0.0))
      throw InputError(s.path.string() + ": " + s.taken_from.at(name) + " of particle " + std::to_string(i) + " is " +
                       std::to_string(c[i]) + " (must be > 0)");
}

// A case whose particles have D coordinates (2 or 3) refuses a file with another number.
inline void require_dim(const Snapshot& s, int D, const std::string& who) {
  if (s.dim != D)
    throw InputError(s.path.string() + ": " + who + " needs " + std::to_string(D) + "D particles (" +
                     (D == 2 ? "x, y" : "x, y, z") + "), the file has " + std::to_string(s.dim) + " coordinate(s)");
}

// The time and the adiabatic index of the cases whose parameters name them t_end and gamma.
inline double real_t_end(const Params& p) { return p.real("t_end"); }
inline double real_gamma(const Params& p) { return p.real("gamma"); }

}  // namespace sphv::snapshot_columns
