#pragma once
#include <utility>
#include <vector>

#include "sph/core/particles.hpp"
#include "sph/hydro/scene.hpp"

namespace sph {

// Time integrators of 9.3.2. Both advance x, v and the evolved scalars u, rho, h (the last two
// change only where a scene term writes drhodt or dhdt). `derivs(p, d)` evaluates the scene at
// the current state. On entry d holds the derivatives at t; on exit, those at t + dt.

// Advances y += s * dy for the evolved scalars (h too unless `h` is false).
template <int D>
void kick_scalars(Particles<D>& p, const Derivatives<D>& d, double s, bool h = true) {
  const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    p.u[i] += s * d.dudt[i];
    p.rho[i] += s * d.drhodt[i];
    if (h) p.h[i] += s * d.dhdt[i];
  }
}

// The chapter's leapfrog exactly as written: half kick and half drift with the rates at t,
// rates at t + dt/2, full kick from t, final half drift with the new velocity. Two evaluations
// per step (midpoint method, second order).
template <int D, class Derivs>
void chapter_leapfrog_step(Particles<D>& p, Derivatives<D>& d, double dt, Derivs&& derivs) {
  const std::vector<Vec<D>> v0 = p.v;
  const std::vector<double> u0 = p.u, rho0 = p.rho, h0 = p.h;
  const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    p.x[i] += 0.5 * dt * p.v[i];   // r(t + dt/2) = r(t) + dt/2 v(t)
    p.v[i] += 0.5 * dt * d.dvdt[i];  // v(t + dt/2) = v(t) + dt/2 a(t)
  }
  kick_scalars(p, d, 0.5 * dt);
  derivs(p, d);  // a(t + dt/2)
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    p.v[i] = v0[i] + dt * d.dvdt[i];  // v(t + dt) = v(t) + dt a(t + dt/2)
    p.x[i] += 0.5 * dt * p.v[i];      // r(t + dt) = r(t + dt/2) + dt/2 v(t + dt)
    p.u[i] = u0[i];
    p.rho[i] = rho0[i];
    p.h[i] = h0[i];
  }
  kick_scalars(p, d, dt);
  derivs(p, d);  // a(t + dt), needed by the next step
}

// Kick-drift-kick leapfrog, one evaluation per step, symplectic for position-dependent forces.
// Velocity-dependent rates (viscosity, energy, continuity, (53)) are evaluated at v and the
// scalars predicted to t + dt (as in Phantom), not at their half-step values: with the half-step
// values the step is only first order in those terms. at_t is the caller's scratch (it holds the
// rates at t on exit): kept from step to step, it spares a copy of d each step.
template <int D, class Derivs>
void kdk_leapfrog_step(Particles<D>& p, Derivatives<D>& d, Derivatives<D>& at_t, double dt, Derivs&& derivs) {
  const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    p.v[i] += 0.5 * dt * d.dvdt[i];  // v(t + dt/2)
    p.x[i] += dt * p.v[i];           // r(t + dt)
  }
  kick_scalars(p, d, 0.5 * dt);      // scalars at t + dt/2
  std::swap(at_t, d);                // the rates at t move to at_t; d's arrays are reused
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) p.v[i] += 0.5 * dt * at_t.dvdt[i];  // predicted v(t + dt)
  kick_scalars(p, at_t, 0.5 * dt);   // predicted scalars at t + dt
  derivs(p, d);                      // rates at t + dt (may overwrite derived scalars, e.g. rho (27))
  // Correct the prediction: y(t + dt) = y(t + dt/2) + dt/2 rate(t + dt). Written as a change of
  // the predicted value so that scalars a scene term sets directly keep the value it set; an h the
  // evaluation set (Derivatives::h_set) is kept, its rate having served as the prediction.
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) p.v[i] += 0.5 * dt * (d.dvdt[i] - at_t.dvdt[i]);
  kick_scalars(p, at_t, -0.5 * dt, !d.h_set);
  kick_scalars(p, d, 0.5 * dt, !d.h_set);
}

}  // namespace sph
