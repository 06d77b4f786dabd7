#include "reference/evrard_lagrangian.hpp"

#include "reference/interpolate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace reference {
namespace {

// The energies at t into out; at a new least W (maximum compression), the density profile too.
void record(const Lagrangian1D& mesh, const LagrangianState& s, double t, EvrardSolution& out) {
  const std::vector<double>&mnode = mesh.node_mass(), &menc = mesh.enclosed_mass(), &dm = mesh.zone_mass();
  const int n = mesh.zones();
  double kin = 0.0, th = 0.0, w = 0.0;
  for (int i = 1; i <= n; ++i) kin += 0.5 * mnode[i] * s.v[i] * s.v[i], w -= mnode[i] * menc[i] / s.r[i];
  for (int k = 0; k < n; ++k) th += dm[k] * s.e[k];
  out.t.push_back(t);
  out.kinetic.push_back(kin);
  out.thermal.push_back(th);
  out.potential.push_back(w);
  if (w <= *std::min_element(out.potential.begin(), out.potential.end())) {
    out.t_max_compression = t;
    RadialProfile p = mesh.profile(s);
    out.r_profile = std::move(p.r_zone);
    out.rho_profile = std::move(p.rho);
  }
}

}  // namespace

double EvrardSolution::at(const std::vector<double>& curve, double s) const {
  return t.empty() ? 0.0 : interpolate_linear(t, curve, s);
}

EvrardSolution evrard_lagrangian(const EvrardOptions& o) {
  if (o.zones < 2) throw std::invalid_argument("evrard reference: need at least 2 zones");
  if (!(o.gamma > 1.0)) throw std::invalid_argument("evrard reference: gamma must be > 1");
  if (!(o.u0 > 0.0)) throw std::invalid_argument("evrard reference: u0 must be > 0");
  if (!(o.t_end > 0.0) || !(o.dt_out > 0.0)) throw std::invalid_argument("evrard reference: t_end, dt_out must be > 0");
  const int n = o.zones;
  LagrangianState s{std::vector<double>(n + 1), std::vector<double>(n + 1, 0.0), std::vector<double>(n, o.u0)};
  for (int i = 0; i <= n; ++i) s.r[i] = static_cast<double>(i) / n;
  std::vector<double> dm(n);
  for (int k = 0; k < n; ++k) dm[k] = s.r[k + 1] * s.r[k + 1] - s.r[k] * s.r[k];  // M(r) = r^2
  LagrangianOptions lo;
  lo.dim = 3, lo.gamma = o.gamma, lo.c1 = o.c1, lo.c2 = o.c2, lo.courant = o.courant, lo.self_gravity = true;
  lo.max_steps = o.max_steps, lo.name = "evrard reference";
  Lagrangian1D mesh(lo, std::move(dm));

  EvrardSolution out;
  const long n_out = std::lround(o.t_end / o.dt_out);
  double t = 0.0;
  record(mesh, s, t, out);
  for (long j = 1; j <= n_out || t < o.t_end; ++j) {
    mesh.advance(s, t, std::min(o.t_end, j * o.dt_out));
    record(mesh, s, t, out);
  }
  out.steps = mesh.steps();
  out.at_end = mesh.profile(s);
  return out;
}

}  // namespace reference
