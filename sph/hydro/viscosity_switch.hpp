#pragma once
// The time-dependent viscosity switch of Cullen & Dehnen (2010, MNRAS 408, 669, Sec. 3): each
// particle's alpha_i follows a local target set by how fast the flow converges,
//   A_i = xi_i max(-d(div v_i)/dt, 0),
//   alpha_loc,i = alpha_max h_i^2 A_i / (c_i^2 + h_i^2 A_i),
// rises to it at once where alpha_i < alpha_loc,i (a shock is met with full viscosity) and
// otherwise decays to it over tau_i = h_i / (2 l c_i):
//   alpha_i <- alpha_loc,i + (alpha_i - alpha_loc,i) exp(-dt / tau_i),
// never below alpha_min. The rate of div v is the difference of div v over the step (Cullen &
// Dehnen also derive it from the gradient of the acceleration, at the cost of a second gradient
// estimate). The limiter is the Balsara-type ratio of Price et al. (2018, PASA 35, e031, Sec.
// 2.2.9), xi_i = |div v_i|^2 / (|div v_i|^2 + |curl v_i|^2), 1 where both vanish: in a shear flow
// (a vortex, a shear layer), where div v oscillates with the particles' noise, it keeps alpha low.
// The sound speed c_i stands for Cullen & Dehnen's signal speed in alpha_loc and tau (as in Price et
// al. 2018); the two differ only where particles approach faster than sound, at a shock, where
// alpha is at its maximum anyway.
//
// Constants: alpha_max = 1 and alpha_min = 0 (Price et al. 2018's defaults; Cullen & Dehnen
// allow up to 2); l = 0.1, with h this chapter's support radius (twice the smoothing length h of
// Price et al. for the cubic spline) tau_i = h_i / (0.2 c_i) is Phantom's decay time for its
// sigma_decay = 0.1.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "sph/core/particles.hpp"

namespace sph {

struct ViscositySwitchParams {
  double alpha_min = 0.0, alpha_max = 1.0, l = 0.1;
};

// The switch's state over a run: alpha_i (the viscosity reads it), and div v_i at the end of the
// last step with that step's end time. An array over the particles in their storage order: a
// scheme that keeps it is not reorderable (schemes/scheme.hpp).
template <int D>
class ViscositySwitch {
 public:
  explicit ViscositySwitch(const ViscositySwitchParams& k) : k_(k) {}

  // Before the first step: alpha_i = alpha_max (a shock in the initial state, a Riemann problem,
  // meets full viscosity before a first rate of div v exists; elsewhere alpha decays within a few
  // tau), and no div v yet, at t = 0.
  void start(std::size_t n) {
    alpha.assign(n, k_.alpha_max);
    div_before_.clear();
    t_before_ = 0.0;
  }

  // div v and |curl v| at the state being evaluated (velocity_gradient.hpp). The first one is the
  // initial state's, from which the first step's rate is taken.
  void observe(const std::vector<double>& div, const std::vector<double>& curl) {
    div_ = div;
    curl_ = curl;
    if (div_before_.empty()) div_before_ = div;
  }

  // After a step that ends at time t, at its end state (h_i, c_i) with its div v observed:
  // alpha_i as above with dt = t - (the previous step's end).
  void advance(const Particles<D>& p, double t) {
    const double dt = t - t_before_;
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double d2 = div_[i] * div_[i], c2 = curl_[i] * curl_[i];
      const double xi = d2 + c2 > 0.0 ? d2 / (d2 + c2) : 1.0;
      const double A = xi * std::max(-(div_[i] - div_before_[i]) / dt, 0.0);
      const double h2A = p.h[i] * p.h[i] * A;
      const double loc = h2A > 0.0 ? k_.alpha_max * h2A / (p.c[i] * p.c[i] + h2A) : 0.0;  // a cold gas at rest: 0, not 0/0
      const double tau = p.h[i] / (2.0 * k_.l * p.c[i]);
      alpha[i] = alpha[i] < loc ? loc : loc + (alpha[i] - loc) * std::exp(-dt / tau);
      alpha[i] = std::max(alpha[i], k_.alpha_min);
    }
    div_before_ = div_;
    t_before_ = t;
  }

  std::vector<double> alpha;

 private:
  ViscositySwitchParams k_;
  std::vector<double> div_, curl_, div_before_;
  double t_before_ = 0.0;
};

}  // namespace sph
