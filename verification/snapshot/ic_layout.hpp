#pragma once
// A case's particles as initial conditions for another code (the writers beside each case:
// verification/cases/*_snapshots.cpp).
#include <optional>

#include "sph/core/particles.hpp"
#include "verification/snapshot/initial_state.hpp"

namespace sphv::ic_layout {

// A particle set as a snapshot at t = 0: positions, velocities, m, rho, u, h and, for a gas,
// p = (gamma - 1) rho u.
template <int D>
Snapshot at_start(const sph::Particles<D>& p, std::optional<double> gamma) {
  Snapshot s;
  s.dim = D;
  s.time = 0.0;
  for (int d = 0; d < D; ++d) {
    auto& x = s.columns[std::string(1, "xyz"[d])];
    auto& v = s.columns["v" + std::string(1, "xyz"[d])];
    for (std::size_t i = 0; i < p.size(); ++i) x.push_back(p.x[i][d]), v.push_back(p.v[i][d]);
  }
  s.columns["m"] = p.m;
  s.columns["rho"] = p.rho;
  s.columns["u"] = p.u;
  s.columns["h"] = p.h;
  if (!gamma) return s;
  auto& pres = s.columns["p"];
  for (std::size_t i = 0; i < p.size(); ++i) pres.push_back((*gamma - 1.0) * p.rho[i] * p.u[i]);
  return s;
}

// The state in sphv's layout, or (IcLayout::swift) moved by `shift` along every axis into the
// periodic box [0, box).
inline InitialState placed(Snapshot s, std::optional<double> gamma, IcLayout layout, double shift, double box) {
  InitialState st{std::move(s), {{box, box, box}, gamma}};
  if (layout == IcLayout::swift)
    for (int d = 0; d < st.s.dim; ++d)
      for (double& x : st.s.columns.at(std::string(1, "xyz"[d]))) x += shift;
  return st;
}

}  // namespace sphv::ic_layout
