#pragma once
// The chapter's scheme, the default (9.2-9.4): summation density (27) with the kernel K, an ideal
// gas (35), the Euler equation in the symmetric form (23), an energy form (36)-(42) ((38) unless
// chosen), artificial viscosity (44)-(48), h by a fixed neighbour number (50) solved with the
// density in the density phase (or integrated by (53), or kept), and the Courant condition with the
// viscous signal speed (time/timestep.hpp). Two neighbour loops an evaluation: density (with its
// Newton passes for h, density/fixed_neighbours_newton.hpp), then force.
//
// Energy form: (23) conserves total energy exactly with either (38) or (41) (sum the pair terms
// symmetrically). (38) changes u_i in proportion to p_i, so u_i stays positive for any small step;
// (41) also feeds the neighbour's pressure p_j into du_i/dt, and next to a hot particle a cold one
// expanding with it is driven to u < 0 (the Sedov blast shows it). Hence (38) by default.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "sph/density/fixed_neighbours.hpp"
#include "sph/density/fixed_neighbours_newton.hpp"
#include "sph/density/summation.hpp"
#include "sph/density/variable_h.hpp"
#include "sph/hydro/energy.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/euler.hpp"
#include "sph/hydro/forms.hpp"
#include "sph/hydro/storage_order.hpp"
#include "sph/hydro/viscosity.hpp"
#include "sph/schemes/scheme.hpp"
#include "sph/search/verlet_list.hpp"

namespace sph {

// Energy: the energy term (hydro/energy.hpp); rate53: h integrated by (53) (else set by (50) or
// kept); Extra: further force-loop terms after the chapter's (e.g. SelfGravity&, held by reference
// so that the caller reads what it keeps).
//
// The force loop computes (53)'s dh/dt in every hmode (one scene type for all three): with
// rate53 the integrator integrates h by it; with iterate50 it only predicts h for the next
// evaluation (the integrators kick h before an evaluation, Derivatives::h_set), whose density
// phase solves (50) from there, so that most particles need one pass; with fixed it is dropped.
template <int D, class K = CubicSpline<D>, class Energy = EnergyAsymmetric<D, EnergyForm::difference38>,
          bool rate53 = false, class... Extra>
class Chapter {
 public:
  static constexpr int dim = D;
  using Kernel = K;
  using Gas = EquationOfState<D, IdealGas>;
  // The force loop's terms in the order they add to a pair's sums: the pressure and sound speed
  // (35) before the loop, then (23), the energy form, (44)-(48), (53), the extra terms.
  using Forces = Scene<D, WithKernel<K>, Gas, EulerSymmetric<D, Lambda1>, Energy, ArtificialViscosity<D>,
                       SmoothingLengthRate<D>, Extra...>;
  static constexpr bool reorderable = !(keeps_particle_arrays<Extra> || ...);

  explicit Chapter(const SchemeOptions& o, Extra... extra) : Chapter(o, Energy{}, extra...) {}
  Chapter(const SchemeOptions& o, const Energy& energy, Extra... extra)
      : h_{o.hfact, o.h_max}, iterate_h_(o.hmode == "iterate50"), fixed_h_(o.hmode == "fixed"),
        forces_{make_forces(o, energy, extra...)} {
    if (rate53 != (o.hmode == "rate53") || (o.hmode != "iterate50" && o.hmode != "rate53" && o.hmode != "fixed"))
      throw std::invalid_argument("scheme chapter: hmode " + o.hmode + " does not match the scheme's type");
    if (o.alpha_u != 1.0) throw std::invalid_argument("scheme chapter has no artificial conduction (alpha_u)");
    if (o.vsig_u != "pressure") throw std::invalid_argument("scheme chapter has no artificial conduction (vsig_u)");
  }

  // Before the first step: h by (50) iterated with (27), in every hmode (9.4.4).
  void start(Particles<D>& p, const Box<D>& box) {
    try {
      smoothing_length_iterate<D, K>(p, box, h_);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("initial smoothing length: ") + e.what());
    }
  }

  // Density loop: rho by (27); with hmode iterate50, h by (50) solved with it from the h on entry,
  // on the lists evolve reuses (nb.lists), whose pairs it selects anew for the h it sets.
  void density(Particles<D>& p, const Neighbourhood<D>& nb) {
    if (!iterate_h_) return density_summation<D, K>(p, nb.list, nb.box, xs_);
    if (!nb.lists) throw std::logic_error("scheme chapter: hmode iterate50 sets h in the density phase, on reused lists");
    h_solver_.solve(p, *nb.lists, nb.list, nb.box, h_);
  }

  // Force loop: p and c by (35), then dv/dt, du/dt, max_j |mu_ij| and dh/dt (53), as hmode uses it.
  void force(Particles<D>& p, const Neighbourhood<D>& nb, Derivatives<D>& d) {
    forces_.derivatives(p, nb, d);
    d.h_set = iterate_h_;
    if (fixed_h_) std::fill(d.dhdt.begin(), d.dhdt.end(), 0.0);
  }

  // The Courant condition with the viscosity's signal speed (or (43), as TimeStepControl says).
  double time_step(const Particles<D>& p, const Derivatives<D>& d, const TimeStepControl& c) const {
    const auto& visc = std::get<ArtificialViscosity<D>>(forces_.terms);
    return hydro_time_step(p, d, visc.alpha, visc.beta, c);
  }

  Forces& forces() { return forces_; }

 private:
  static Forces make_forces(const SchemeOptions& o, const Energy& energy, Extra... extra) {
    const Gas eos{{o.gamma}};
    const ArtificialViscosity<D> visc{o.alpha, o.beta, 0.01, 0.5};
    return Forces{{{}, eos, {}, energy, visc, {}, extra...}};
  }

  SmoothingLengthControl h_;
  bool iterate_h_, fixed_h_;
  FixedNeighboursNewton<D, K> h_solver_;
  Components<D> xs_;  // the positions' columns, kept (Scene::xs)
  Forces forces_;
};

// The registry's entry (schemes.hpp): the name, and the scheme's type for the options' forms,
// chosen once per run.
struct ChapterScheme {
  static constexpr const char* name = "chapter";
  // The scheme with its default forms (energy (38), hmode iterate50), for the options' numbers.
  template <int D, class K>
  using Default = Chapter<D, K>;
  // f(scheme) with the energy form and hmode of o; K the kernel, Extra the extra force terms.
  template <int D, class K, class F, class... Extra>
  static void with(const SchemeOptions& o, F&& f, Extra&... extra) {
    with_energy_form<D>(o.energy, 1.0, [&](auto energy) {
      using E = decltype(energy);
      if (o.hmode == "rate53") {
        Chapter<D, K, E, true, Extra&...> s(o, energy, extra...);
        f(s);
      } else {
        Chapter<D, K, E, false, Extra&...> s(o, energy, extra...);
        f(s);
      }
    });
  }
};

}  // namespace sph
