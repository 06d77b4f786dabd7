#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sph/core/particles.hpp"
#include "sph/hydro/scene.hpp"

namespace sph {

// Time-step criteria. `courant` is the default (errata); `chapter43` is (43) as written.
enum class TimeStepCriterion { courant, chapter43 };

struct TimeStepControl {
  TimeStepCriterion criterion = TimeStepCriterion::courant;
  double C = 0.3;        // Courant number (Monaghan 1992, Phantom C_cour)
  double C_force = 0.25; // acceleration criterion (Phantom C_force)
  double C_energy = 0.25; // cooling criterion: u_i may fall by at most this fraction per step
  double eta = 0.3;      // (43)
};

// Monaghan (1992) signal-speed Courant condition and the acceleration criterion, with
// Monaghan's smoothing length h_i / 2 (this chapter's h is the full support radius):
//   dt = min_i min(C (h_i/2) / (c_i + |v_i| + 1.2 (alpha c_i + beta max_j |mu_ij|)),
//                  C_force sqrt((h_i/2) / |a_i|), C_energy u_i / |du_i/dt| where du_i/dt < 0).
// The last keeps u positive where a cold particle borders a much hotter one (Toro 3, 4: the
// symmetric energy forms cool it at a rate set by the hot neighbour's pressure).
// max_j |mu_ij| is d.mu_max (0 without artificial viscosity, and then alpha, beta do not matter).
template <int D>
double courant_time_step(const Particles<D>& p, const Derivatives<D>& d, double alpha, double beta,
                         const TimeStepControl& c) {
  double dt = std::numeric_limits<double>::infinity();
  const std::size_t n = p.size();
#pragma omp parallel for reduction(min : dt) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    const double hm = 0.5 * p.h[i], mu = d.mu_max[i];
    const double signal = p.c[i] + p.v[i].norm() + 1.2 * (alpha * p.c[i] + beta * mu);
    if (signal > 0.0) dt = std::min(dt, c.C * hm / signal);
    const double a = d.dvdt[i].norm();
    if (a > 0.0) dt = std::min(dt, c.C_force * std::sqrt(hm / a));
    if (d.dudt[i] < 0.0 && c.C_energy > 0.0) dt = std::min(dt, c.C_energy * p.u[i] / -d.dudt[i]);
  }
  return dt;
}

// The Courant condition on the signal speed of a scheme whose viscosity writes max_j v_sig,ij into
// d.mu_max (hydro/signal_viscosity.hpp), with the acceleration and cooling criteria of
// courant_time_step and Monaghan's smoothing length h_i / 2:
//   dt = min_i min(C (h_i/2) / v_sig,i, C_force sqrt((h_i/2) / |a_i|), C_energy u_i / |du_i/dt| where du_i/dt < 0),
// v_sig,i = max_j v_sig,ij, or 2 c_i (a pair at rest's) for a particle without neighbours.
template <int D>
double signal_time_step(const Particles<D>& p, const Derivatives<D>& d, const TimeStepControl& c) {
  double dt = std::numeric_limits<double>::infinity();
  const std::size_t n = p.size();
#pragma omp parallel for reduction(min : dt) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    const double hm = 0.5 * p.h[i], signal = std::max(d.mu_max[i], 2.0 * p.c[i]);
    if (signal > 0.0) dt = std::min(dt, c.C * hm / signal);
    const double a = d.dvdt[i].norm();
    if (a > 0.0) dt = std::min(dt, c.C_force * std::sqrt(hm / a));
    if (d.dudt[i] < 0.0 && c.C_energy > 0.0) dt = std::min(dt, c.C_energy * p.u[i] / -d.dudt[i]);
  }
  return dt;
}

// (43) as written: dt = eta h / max_i |v_i| (h: the smallest support radius), and dt = eta^2
// when every particle is at rest. Ignores the sound speed: unsafe for a gas (errata).
template <int D>
double chapter_time_step(const Particles<D>& p, const TimeStepControl& c) {
  double vmax = 0.0, h = std::numeric_limits<double>::infinity();
  const std::size_t n = p.size();
#pragma omp parallel for reduction(max : vmax) reduction(min : h) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) vmax = std::max(vmax, p.v[i].norm()), h = std::min(h, p.h[i]);
  return vmax > 0.0 ? c.eta * h / vmax : c.eta * c.eta;
}

}  // namespace sph
