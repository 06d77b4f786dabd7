#pragma once
// The scheme modern SPH codes run (Phantom: Price et al. 2018, PASA 35, e031, Sec. 2.2-2.5; in one
// place: Price 2012, JCP 231, 759): the grad-h formulation with h by (50), a time-dependent
// viscosity switch and artificial conduction, beside the chapter's (chapter.hpp):
//   density: rho_i = sum_j m_j W(r_ij, h_i) and h_i by (50) solved together by Newton, particle by
//            particle (density/fixed_neighbours_newton.hpp, own_h); Omega_i from the same sums
//            (hydro/grad_h.hpp); div v and curl v for the switch (hydro/velocity_gradient.hpp,
//            a second loop over the same pairs);
//   force:   an ideal gas (35), the grad-h momentum and energy equations (hydro/grad_h.hpp), the
//            signal-velocity viscosity with alpha_ij = (alpha_i + alpha_j)/2
//            (hydro/signal_viscosity.hpp), artificial conduction (conduction/artificial_conduction.hpp),
//            and (53)'s dh/dt, which only predicts h for the next density phase (as in Chapter);
//   after every step: the Cullen & Dehnen switch advances alpha_i (hydro/viscosity_switch.hpp);
//   time step: the Courant condition on the signal speed (time/timestep.hpp, signal_time_step).
// Three neighbour loops an evaluation: the density's (with its Newton passes), the velocity
// gradient's and the force's.
//
// Options: gamma, hfact, h_max as for the chapter's scheme; alpha is the switch's alpha_max, beta
// the signal velocity's coefficient and alpha_u the conduction's (0: none, for an experiment);
// vsig_u the conduction's signal velocity, "pressure" (Price 2008's, the default) or "velocity"
// (conduction/artificial_conduction.hpp).
// hmode must be iterate50 (grad-h conserves energy only with h tied to rho by (50) at every
// evaluation) and energy 38 (the scheme's energy equation is (38)'s form with the kernel at h_i
// and 1/Omega_i): others throw std::invalid_argument.
//
// Not reorderable: alpha_i and the div v_i of the last step are arrays over the particles that the
// storage order (hydro/storage_order.hpp) does not permute.
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/conduction/artificial_conduction.hpp"
#include "sph/density/fixed_neighbours.hpp"
#include "sph/density/fixed_neighbours_newton.hpp"
#include "sph/density/variable_h.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/grad_h.hpp"
#include "sph/hydro/signal_viscosity.hpp"
#include "sph/hydro/velocity_gradient.hpp"
#include "sph/hydro/viscosity_switch.hpp"
#include "sph/schemes/scheme.hpp"
#include "sph/search/verlet_list.hpp"
#include "sph/time/timestep.hpp"

namespace sph {

// Extra: further force-loop terms after the scheme's (e.g. SelfGravity&, held by reference).
template <int D, class K = CubicSpline<D>, class... Extra>
class GradhSwitches {
 public:
  static constexpr int dim = D;
  using Kernel = K;
  using Gas = EquationOfState<D, IdealGas>;
  using Forces = Scene<D, WithKernel<K>, Gas, GradhEuler<D>, GradhEnergy<D>, SignalVelocityViscosity<D>,
                       ArtificialConduction<D>, SmoothingLengthRate<D>, Extra...>;
  static constexpr bool reorderable = false;

  // h is solved to a relative residual of (50) of 1e-10: the semi-discrete energy conservation of
  // grad-h holds for h and rho that satisfy (50), and a residual at the chapter's 1e-3 would leave
  // an energy error of that order, which no time step reduces. Newton's quadratic convergence makes
  // this one pass more at most.
  static constexpr double h_tol = 1e-10;

  explicit GradhSwitches(const SchemeOptions& o, Extra... extra)
      : h_{.hfact = o.hfact, .h_max = o.h_max, .tol = h_tol}, switch_({.alpha_max = o.alpha}),
        forces_{{{}, Gas{{o.gamma}}, {&omega_}, {&omega_}, {&switch_.alpha, o.beta}, conduction(o), {}, extra...}} {
    if (o.hmode != "iterate50")
      throw std::invalid_argument("scheme gradh_switches: hmode " + o.hmode + " (grad-h needs h by (50), iterate50)");
    if (o.energy != "38")
      throw std::invalid_argument("scheme gradh_switches: energy form " + o.energy + " (it has its own, (38)'s grad-h form)");
  }
  // The force terms point at omega_ and the switch's alpha.
  GradhSwitches(const GradhSwitches&) = delete;
  GradhSwitches& operator=(const GradhSwitches&) = delete;

  // Before the first step: h by (50) with the chapter's (27) (smoothing_length_iterate), then with
  // the scheme's own-h density; the switch at alpha_max.
  void start(Particles<D>& p, const Box<D>& box) {
    try {
      smoothing_length_iterate<D, K>(p, box, SmoothingLengthControl{.hfact = h_.hfact, .h_max = h_.h_max});
      VerletList<D> lists(h_.skin);
      h_solver_.solve(p, lists, lists.update(p.x, p.h, box), box, h_);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("initial smoothing length: ") + e.what());
    }
    switch_.start(p.size());
  }

  // Density loop: rho and h by (50), Omega; then div v and curl v on the pairs selected for that h.
  void density(Particles<D>& p, const Neighbourhood<D>& nb) {
    if (!nb.lists) throw std::logic_error("scheme gradh_switches sets h in the density phase, on reused lists");
    h_solver_.solve(p, *nb.lists, nb.list, nb.box, h_);
    grad_h_omega<D>(p, h_solver_.drho_dh(), omega_);
    velocity_divergence_curl<D, K>(p, nb.list, nb.box, omega_, div_, curl_, xs_, vs_);
    switch_.observe(div_, curl_);
  }

  // Force loop: p and c by (35), then dv/dt, du/dt, max_j v_sig,ij and (53)'s prediction of h.
  void force(Particles<D>& p, const Neighbourhood<D>& nb, Derivatives<D>& d) {
    if (omega_.size() != p.size() || switch_.alpha.size() != p.size())
      throw std::logic_error("scheme gradh_switches: the force loop reads Omega and alpha of its start and density phase");
    forces_.derivatives(p, nb, d);
    d.h_set = true;
  }

  // The Courant condition on the signal speed (or (43), as TimeStepControl says).
  double time_step(const Particles<D>& p, const Derivatives<D>& d, const TimeStepControl& c) const {
    return c.criterion == TimeStepCriterion::courant ? signal_time_step(p, d, c) : chapter_time_step(p, c);
  }

  // After a step that ends at time t: the switch advances alpha_i over the step.
  void stepped(const Particles<D>& p, double t) { switch_.advance(p, t); }

  const std::vector<double>& omega() const { return omega_; }
  const std::vector<double>& alpha() const { return switch_.alpha; }
  Forces& forces() { return forces_; }

 private:
  static ArtificialConduction<D> conduction(const SchemeOptions& o) {
    if (o.vsig_u == "pressure") return {.alpha_u = o.alpha_u, .by_pressure = 1.0, .by_velocity = 0.0};
    if (o.vsig_u == "velocity") return {.alpha_u = o.alpha_u, .by_pressure = 0.0, .by_velocity = 1.0};
    throw std::invalid_argument("scheme gradh_switches: conduction signal velocity " + o.vsig_u +
                                " (pressure or velocity)");
  }

  SmoothingLengthControl h_;
  FixedNeighboursNewton<D, K, true> h_solver_;
  std::vector<double> omega_, div_, curl_;
  Components<D> xs_, vs_;  // velocity_divergence_curl's buffers
  ViscositySwitch<D> switch_;
  Forces forces_;
};

// The registry's entry (schemes.hpp).
struct GradhSwitchesScheme {
  static constexpr const char* name = "gradh_switches";
  template <int D, class K>
  using Default = GradhSwitches<D, K>;
  template <int D, class K, class F, class... Extra>
  static void with(const SchemeOptions& o, F&& f, Extra&... extra) {
    GradhSwitches<D, K, Extra&...> s(o, extra...);
    f(s);
  }
};

}  // namespace sph
