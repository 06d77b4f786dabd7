#pragma once
// A scheme of the registry (sph/schemes/) on the colliding blobs at a fixed time step (FixedStep):
// its own forms, viscosity and smoothing lengths, with the drifts of conservation/scene.hpp, for
// the conservation cases' `scheme` parameter.
#include <string>

#include "sph/schemes/fixed_step.hpp"
#include "sph/schemes/schemes.hpp"
#include "verification/cases/conservation/scene.hpp"

namespace sphv::conservation {

// The scheme named, with the cubic spline, gamma = 5/3 and the options' defaults otherwise, from a
// copy of `initial` for `steps` steps of dt in an open box: the drifts of P, L and E = sum_i m_i
// (v_i^2/2 + u_i) after every step, the largest energy-rate residual over the evaluations, and the
// verdict. The scheme's start sets h and rho from (50) first (u and v are the initial ones, so E(0)
// is too).
template <int D>
Drifts run_scheme(const sph::Particles<D>& initial, const std::string& scheme, sph::IntegratorKind integrator,
                  double dt, long steps) {
  Drifts out;
  sph::Particles<D> p = initial;
  const sph::Box<D> open = sph::unit_box<D>(false);
  const Invariants first = invariants(p);
  const double E0 = kinetic_plus_internal(p);
  auto record = [&](const sph::Particles<D>& q, double t) {
    const Invariants now = invariants(q);
    out.t.push_back(t);
    out.momentum.push_back((now.P - first.P).norm() / first.P_scale);
    out.angular.push_back((now.L - first.L).norm() / first.L_scale);
    out.energy.push_back(std::abs(kinetic_plus_internal(q) - E0) / E0);
  };
  record(p, 0.0);
  sph::HydroHooks<D> hooks;
  hooks.evaluated = [&](const sph::Particles<D>& q, const sph::Derivatives<D>& d) {
    const auto t = sph::totals(q, d, 0, q.size());
    if (t.rate_scale > 0.0) out.energy_rate = std::max(out.energy_rate, std::abs(t.energy_rate) / t.rate_scale);
  };
  hooks.stepped = [&](const sph::Particles<D>& q, const sph::Derivatives<D>&, long, double t) { record(q, t); };
  sph::HydroControls c;
  c.integrator = integrator;
  c.t_end = dt * steps;
  sph::SchemeOptions o;
  o.gamma = 5.0 / 3.0;
  sph::with_scheme<D, sph::CubicSpline<D>>(scheme, o, [&](auto& s) {
    sph::FixedStep<std::remove_cvref_t<decltype(s)>> fixed{s, dt};
    out.verdict = sph::evolve(fixed, p, open, c, hooks).verdict;
  });
  return out;
}

}  // namespace sphv::conservation
