// Case `square`: the isobaric square (2D) or cube (3D, dim=3) of Saitoh & Makino 2013 (ApJ 768,
// 44) and Hopkins 2015 (MNRAS 450, 53): density 4 inside the centred square of side 1/2, 1 outside,
// p = 2.5 everywhere (gamma 5/3), at rest or carried by a uniform velocity v_adv through the
// periodic unit box. Independent reference: reference/square, the initial state carried by v_adv
// (exact: uniform p and v make every term of the Euler equations zero). The scheme is the hydro
// cases' (summation density (27), Euler (23), energy (38), artificial viscosity (44)-(48), h by
// (50)), i.e. the density-energy formulation, with the kernel named by `kernel`.
//
// Set-up (square/setup.hpp): equal-mass particles on two lattices (the dense one 2x finer in 2D),
// as in the literature: each phase has the same neighbour number, and the jump is carried by the
// spacing. lattice=one (masses rho(x)/n^d on one lattice) is the alternative for the smooth step.
//
// Errors at t_end = 1 (two sound crossings of the light gas' box, c_out = 2.04): v_rms, the light
// gas' velocity noise over c_out; L1_rho, the density field against the exact step; misfit, the
// area of the particles' cells on the wrong side of the square's edge (square/errors.hpp).
// The density-energy form keeps u discontinuous while (27) smooths rho over h, so p = (gamma - 1)
// rho u has an O(p) blip in a layer of width h at the contact: the spurious surface tension that
// rounds the square's corners and drives the velocity noise. The blip's size does not fall with h,
// and v_rms stays level: a known failure, shown by the smooth step of width 0.05 (lattice=one,
// width=0.05, at alpha = 0.1: the claims say why), where the pressure is uniform to O(h^2) and
// v_rms falls at second order (docs/cases/square.md holds the measured series). L1_rho (the smearing over h) and misfit (the displacement of the
// edge's particles, confined to the layer of width h) converge at first order until the tension
// has rounded the corners into a shape whose size does not shrink with h: at t_end = 0.25 they do
// on n = 32..256, at t_end = 1 they level off from n = 64 (known failures; the smooth step verifies
// L1_rho, t_end = 0.25 misfit).
//
// scheme=gradh_switches (grad-h, the Cullen & Dehnen switch, artificial conduction): on the sharp
// step its errors level off too (known failures: the blip's flow, which its switch leaves
// undamped); on the smooth step its conduction at Price 2008's pressure-based signal velocity
// moves heat that the pressure's own discretisation error drives (known failures), and at the
// velocity-based one (vsig_u=velocity) it converges at second order, the experiment of both.
#include <cmath>
#include <map>
#include <string>

#include "sph/kernel/kernels.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/cases/square/errors.hpp"
#include "verification/cases/square/setup.hpp"
#include "verification/cases/square/snapshots.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::square_case {
namespace {

template <int D>
Result run_dim(const Params& prm) {
  const long n = prm.integer("n");
  extreme::Method m = extreme::method(prm);
  m.controls.t_end = prm.real("t_end");
  m.h_max = 0.45;  // below half the periodic box
  const reference::IsobaricSquare sq = square::problem(prm);
  sph::Particles<D> p = square::initial_particles<D>(prm);
  // The set-up's phases (u is each phase's exact one here), which the run keeps by index.
  const std::vector<char> dense = square::phase_by_u(p.u, sq, m.gamma);
  const std::string kernel = prm.text("kernel");
  const sph::Box<D> box = sph::unit_box<D>(true);
  const sph::HydroOutcome out = extreme::evolve_gas_kernel<D>(kernel, p, box, m);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"dim", D}};
  if (r.verdict != "stable") return r;
  square::measure<D>(r, p.x, p.v, p.m, p.rho, p.u, dense, out.t, sq, m.gamma, n);
  r.extra["phase_tag"] = "set-up";
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

Result run(const Params& p) {
  if (p.integer("dim") == 2) return run_dim<2>(p);
  return run_dim<3>(p);
}

void validate(const Params& p) {
  const long d = p.integer("dim"), n = p.integer("n");
  if (d != 2 && d != 3) throw InputError("square: dim must be 2 or 3");
  if (n < 8 || n % 4 != 0)
    throw InputError("square: n must be a multiple of 4 and at least 8 (the light lattice's cells tile the outside of "
                     "the square [1/4, 3/4)^d), got " + std::to_string(n));
  const double w = p.real("width");
  if (!(w >= 0.0 && w <= 0.05))
    throw InputError("square: width must lie in [0, 0.05] (0: the sharp step; above 0.05 the smooth profile's "
                     "tanh tails reach the periodic box's edge), got " + p.text("width"));
  if (w > 0.0 && p.text("lattice") != "one")
    throw InputError("square: width > 0 needs lattice=one (two lattices realise only the sharp step)");
  if (!(p.real("t_end") >= 0.0)) throw InputError("square: t_end must be >= 0 (0: score an initial state)");
  if (p.text("kernel") != "cubic_spline" && (p.text("hmode") != "iterate50" || p.text("energy") != "38"))
    throw InputError("square: kernel=" + p.text("kernel") + " runs with hmode=iterate50, energy=38 only");
  const double count = std::pow(double(n), double(d)) *
                       (p.text("lattice") == "two" ? 1.0 + std::pow(0.5, double(d)) * (p.real("contrast") - 1.0) : 1.0);
  if (count > p.real("max_particles"))
    throw InputError("square: n = " + std::to_string(n) + " in " + std::to_string(d) + "D means about " +
                     std::to_string(static_cast<long>(count)) + " particles, above max_particles (raise it)");
}

// Whether the parameters are the smooth step's (the experiment that converges).
bool smooth(const Params& p) { return p.real("width") > 0.0; }

// Whether the viscosity is the chapter's alpha = 1, which damps the smooth step's acoustic pattern
// (the claims), or lower (the catalogue's smooth step, at alpha = 0.1).
bool full_viscosity(const Params& p) { return p.real("alpha") >= 1.0; }

// Whether the scheme is the grad-h scheme with the viscosity switch and artificial conduction
// (sph/schemes/gradh_switches.hpp), and whether it conducts with the pressure-based signal
// velocity (Price 2008, its default; alpha_u = 0 runs it without conduction).
bool gradh(const Params& p) { return p.text("scheme") != sph::ChapterScheme::name; }
bool pressure_conduction(const Params& p) {
  return gradh(p) && p.real("alpha_u") > 0.0 && p.text("vsig_u") == "pressure";
}

// The grad-h scheme's smooth step with the velocity-based conduction: the experiment of its
// known failures (the claims).
const std::string gradh_smooth = "scheme=gradh_switches,lattice=one,width=0.05,vsig_u=velocity";

// Whether the run ends before the contact's spurious surface tension has rounded the corners:
// a quarter of the end time's two sound crossings (the experiment whose edge errors converge).
bool early(const Params& p) { return p.real("t_end") <= 0.25; }

// Drift baselines (the code's own earlier output): per catalogue variant and error the largest
// value measured on its levels of every tier (t_end = 1 unless set, C = 0.3, 2 cores; the errors
// that fall are largest at the coarsest level, the sharp step's do not fall), bounds at 1.5 times
// these. The series: docs/cases/square.md.
std::map<std::string, double> measured(const Params& p) {
  if (gradh(p) && smooth(p) && pressure_conduction(p)) return {{"L1_rho", 5.023e-2}, {"v_rms", 1.222e-2}};
  if (gradh(p) && smooth(p)) return {{"L1_rho", 1.924e-2}, {"v_rms", 9.382e-3}};  // vsig_u=velocity
  if (gradh(p) && !early(p)) return {{"L1_rho", 9.956e-2}, {"misfit", 1.460e-1}, {"v_rms", 1.946e-2}};
  if (smooth(p) && !full_viscosity(p)) return {{"L1_rho", 1.284e-2}, {"v_rms", 6.816e-3}};  // alpha 0.1
  if (smooth(p)) return {{"L1_rho", 1.256e-2}, {"v_rms", 3.128e-3}};
  if (early(p)) return {{"L1_rho", 2.603e-2}, {"misfit", 2.149e-2}, {"v_rms", 8.342e-3}};
  const std::string k = p.text("kernel");
  if (k == "quintic_spline") return {{"L1_rho", 2.111e-2}, {"misfit", 3.089e-2}, {"v_rms", 3.392e-3}};
  if (k == "wendland_c4") return {{"L1_rho", 2.285e-2}, {"misfit", 3.247e-2}, {"v_rms", 3.184e-3}};
  if (p.real("v_adv") != 0.0) return {{"L1_rho", 2.689e-2}, {"misfit", 3.296e-2}, {"v_rms", 3.634e-3}};
  return {{"L1_rho", 2.689e-2}, {"misfit", 3.285e-2}, {"v_rms", 4.990e-3}};
}

std::vector<Check> gates(const Sweep& s) {
  const Params prm = find_case(s.case_name).parse(s.settings);
  const auto bound = measured(prm);
  return radial::per_level(s, [&](const std::string& level, const Result& r, std::vector<Check>& c) {
    for (const auto& [e, v] : bound)
      c.push_back({level + "_" + e, r.errors.at(e), 0.0, 1.5 * v,
                   e + " below 1.5 times the largest value measured on the variant's levels (square/case.cpp)",
                   Check::Kind::drift, e});
    // A scored snapshot's phase tag (square/errors.hpp) reads u against sqrt(u_in u_out), a factor
    // 2 from either phase's u at contrast 4: it holds while no particle's u moves by a third of its
    // own (measured at most 0.084 in the chapter's scheme). A run tags by the set-up, and the smooth
    // step has u between the phases' by construction: no check.
    if (!smooth(prm) && r.extra.value("phase_tag", std::string("u")) == "u") c.push_back({level + "_phase_tag", r.extra.value("u_deviation_max", 1.0), 0.0, 1.0 / 3.0,
                 "max |u_i / u_phase - 1| below 1/3: the phases stay apart in u, so the tag the errors use is sound",
                 Check::Kind::verification, "v_rms"});
  });
}

OrderClaims orders(const Params& p) {
  OrderClaims c;
  if (smooth(p)) {
    // Bands 0.3. L1_rho's local orders 1.74, 1.84, 1.67 (n = 32..256) at alpha = 1, 1.64, 1.88,
    // 1.71 at 0.1. The velocity is a box-scale acoustic pattern that the O(h^2) pressure error
    // starts: at alpha = 0.1 its local orders are 2.33, 2.12, 1.92 (n = 32..256). At alpha = 1 the
    // viscosity damps the pattern at a rate that itself depends on h, and the local orders wander
    // (3.56, 1.00, 1.34), whatever the time step (C = 0.15) or the h solve's tolerance (1e-8): its
    // fit does not decide the order (2.28 +- 0.74 on 32..128), so the catalogue's smooth step runs
    // at alpha = 0.1 (docs/cases/square.md).
    c["L1_rho"] = {2.0, 0.3, "a smooth density at uniform pressure: the summation density (27) errs by O(h^2 rho'') "
                             "with a symmetric kernel: second order"};
    c["v_rms"] = {2.0, 0.3, "the pressure (gamma - 1) rho u errs by the density's O(h^2 rho''), and the velocity it "
                            "drives with it: second order"};
    if (!pressure_conduction(p)) return c;
    // The grad-h scheme's conduction at Price 2008's signal velocity sqrt(|P_i - P_j| / rho_ij):
    // the pressure's O(h^2) error makes it O(h), not zero, and the heat it moves across the
    // four-fold u profile is a pressure error that drives more noise. With the velocity-based
    // signal velocity (|v_ij . r_ij| / |r_ij|, zero in a gas at rest) the same step converges
    // (v_rms local orders 2.06, 1.68, L1_rho 1.87, 1.79 on n = 32..128; docs/cases/square.md).
    c["v_rms"] = known_failure(
        c["v_rms"],
        "the artificial conduction's signal velocity sqrt(|P_i - P_j| / rho_ij) (Price 2008) is driven by the "
        "pressure's own discretisation error: it moves heat across the smooth step, whose pressure error drives a "
        "velocity noise at the particle scale: v_rms = {v_rms} of c_out at {levels}, observed order {order.v_rms}; "
        "with the velocity-based signal velocity the same step converges",
        gradh_smooth);
    c["L1_rho"] = known_failure(
        c["L1_rho"],
        "the artificial conduction's signal velocity sqrt(|P_i - P_j| / rho_ij) (Price 2008) is driven by the "
        "pressure's own discretisation error and moves heat across the smooth step, and the density follows the "
        "heat at uniform pressure: L1_rho {L1_rho} at {levels}, observed order {order.L1_rho}; with the "
        "velocity-based signal velocity the same step converges",
        gradh_smooth);
    return c;
  }
  const OrderClaim l1{1.0, 0.3, "the summation density (27) spreads the step over the kernel's support h ~ 1/n along "
                                "the edges (an L1 error of the jump times the perimeter times h): first order"};
  const OrderClaim misfit{1.0, 0.3, "the edge's particles move within the layer of width h ~ 1/n where the pressure blip "
                                    "acts: the area they leave on the wrong side of the edge is the perimeter times O(h): "
                                    "first order"};
  const OrderClaim v_rms{2.0, 0.3, "a flow at uniform pressure whose forces err at a smooth flow's order: second order"};
  // The velocity noise: the blip's O(p) jump over a layer of width h whatever n. The viscosity is
  // not what keeps it: at alpha = 0.1 the sharp step's v_rms is 7.5e-3, 6.7e-3, 6.4e-3 at n = 32,
  // 48, 64 (1 thread), where the smooth step's converges at second order.
  if (gradh(p) && !early(p)) {
    // The grad-h scheme on the sharp step: its errors do not fall with or without the conduction
    // (misfit 0.146, 0.134, 0.115 with it at n = 32, 48, 64; 0.224, 0.212, 0.190 at alpha_u = 0),
    // nor at the velocity-based signal velocity (0.196, 0.181, 0.167): the switch lets alpha fall
    // where the chapter's alpha = 1 damps the tension-driven flow (docs/cases/square.md).
    const std::string cause =
        "the sharp contact's pressure blip (the summation density (27) smooths the step over h while u keeps it), "
        "which the conduction does not remove and the viscosity switch, falling to its floor away from shocks, "
        "leaves undamped: ";
    c["v_rms"] = known_failure(v_rms, cause + "v_rms = {v_rms} of c_out at {levels}, observed order {order.v_rms}; the "
                                              "same scheme's smooth step (velocity-based conduction) converges",
                               gradh_smooth);
    c["L1_rho"] = known_failure(l1, cause + "L1_rho {L1_rho} at {levels}, observed order {order.L1_rho}; the same "
                                            "scheme's smooth step (velocity-based conduction) converges",
                                gradh_smooth);
    c["misfit"] = known_failure(misfit, cause + "misfit {misfit} at {levels}, observed order {order.misfit}; the "
                                                "chapter's scheme at a quarter of the end time, before the blip's "
                                                "tension has rounded the corners, converges",
                                "t_end=0.25");
    return c;
  }
  c["v_rms"] = known_failure(
      v_rms,
      "the density-energy form's spurious surface tension at the sharp contact: the summation density (27) smooths the "
      "step over h while u keeps it, so the pressure (gamma - 1) rho u jumps by O(p) across a layer of width h whatever "
      "n (Saitoh & Makino 2013; Hopkins 2015); the noise it drives does not fall at a smooth flow's order: v_rms = "
      "{v_rms} of c_out at {levels}, observed order {order.v_rms}; the smooth step (at a low viscosity, which does "
      "not damp its acoustic pattern) converges",
      "lattice=one,width=0.05,alpha=0.1");
  if (early(p)) {
    // Before the tension has rounded the corners, the smearing over h and the edge's layer are
    // all there is: first order (L1_rho and misfit local orders 0.90, 0.94 and 0.95, 0.87 on
    // n = 32..128 at t_end = 0.25).
    c["L1_rho"] = l1;
    c["misfit"] = misfit;
    return c;
  }
  // The tension acts over time: by t = 1 it has rounded the corners into a shape of its own,
  // whose size does not shrink with h, and both errors level off (local orders from n = 64 to
  // 128 of 0.33 to 0.41 for L1_rho; misfit rises). The smooth step (no blip) verifies L1_rho; the
  // same square at t_end = 0.25 (before the tension has acted) verifies misfit.
  c["L1_rho"] = known_failure(l1,
                              "the contact's spurious surface tension rounds the square's corners into a shape whose size "
                              "does not shrink with h: L1_rho {L1_rho} at {levels}, observed order {order.L1_rho}",
                              "lattice=one,width=0.05,alpha=0.1");
  c["misfit"] = known_failure(misfit,
                              "the contact's spurious surface tension rounds the square's corners into a shape whose size "
                              "does not shrink with h: misfit {misfit} at {levels}, observed order {order.misfit}",
                              "t_end=0.25");
  return c;
}

// The sharp step's edge errors level off from n = 64 (the tension's rounding): the known failures
// show on 48, 96 (quick: L1_rho's local order 0.18 to 0.56) and on 32, 48, 64, 96 (standard: its
// fit 0.4 to 0.65, below the window's 0.7; n = 128 costs twice the other three together); the full
// tier runs to 128, the default to 256.
const Levels levels = {.quick = {48, 96}, .standard = {32, 48, 64, 96}, .full = {32, 64, 128, 256}};
const Registration reg{Case{
    .name = "square",
    .summary = "isobaric square (2D) / cube (3D), density contrast 4 in pressure equilibrium: velocity noise, "
               "density error and the dense phase's misfit against the static (or carried) exact state",
    .n_counts = "light-phase particles per unit length (per side of the periodic unit box; a multiple of 4)",
    .tags = {"gate", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {
          integer_param("n", 32, "light-phase particles per side of the box (a multiple of 4)"),
          integer_param("dim", 2, "dimension 2 or 3"),
          real_param("contrast", 4.0, "rho_in / rho_out", 0.0),
          real_param("rho_out", 1.0, "density of the light gas", 0.0),
          real_param("p0", 2.5, "the uniform pressure", 0.0),
          real_param("v_adv", 0.0, "uniform velocity along every axis (0: at rest)"),
          real_param("width", 0.0, "width of the smooth step (0: sharp; > 0 needs lattice=one)"),
          choice_param("lattice", "two", "equal masses on two lattices (sharp step), or one lattice with masses "
                                         "rho(x) / n^d", {"two", "one"}),
          real_param("t_end", 1.0, "end time"),
          choice_param("kernel", "cubic_spline", "the kernel (sph/kernel/kernels.hpp); other than cubic_spline: "
                                                 "hmode=iterate50, energy=38", sph::kernel_names()),
          real_param("max_particles", 3e5, "refuse runs with more particles than this", 0.0)};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = levels,
    .orders = orders,
    .error_defs = square::error_defs,
    .variants = {{},
                 {"lattice=one", "width=0.05", "alpha=0.1"},
                 {"t_end=0.25"},
                 {"v_adv=0.3"},
                 {"kernel=quintic_spline"},
                 {"kernel=wendland_c4"},
                 {"scheme=gradh_switches"},
                 {"scheme=gradh_switches", "lattice=one", "width=0.05"},
                 {"scheme=gradh_switches", "lattice=one", "width=0.05", "vsig_u=velocity"}},
    .levels_for = [](const Params& p) {
      // The grad-h scheme costs about 2.2 times the chapter's run (n = 48). Its sharp step's errors stay
      // level from n = 32 (the claims): 32, 48, 64 show it.
      if (gradh(p) && !smooth(p) && !early(p))
        return Levels{.quick = {32, 64}, .standard = {32, 48, 64}, .full = {32, 64, 128}};
      // Its smooth step at Price's signal velocity: the noise is level from n = 32 (v_rms 1.22e-2,
      // 1.10e-2, 1.05e-2 on 32, 64, 128); at the velocity-based one the acoustic pattern's phase
      // makes 48 and 96 stray (v_rms local order 0.62 from 32 to 48, 4.0 from 48 to 64): doubled.
      if (pressure_conduction(p) && smooth(p))
        return Levels{.quick = {32, 64}, .standard = {32, 64}, .full = {32, 64, 128}};
      if (gradh(p) && smooth(p))
        return Levels{.quick = {32, 64}, .standard = {32, 64, 128}, .full = {32, 64, 128, 256}};
      // At alpha = 0.1 the local order from 32 to 64 is 2.33, at the window's edge: quick doubles
      // from 64 (2.12).
      if (smooth(p) && !full_viscosity(p))
        return Levels{.quick = {64, 128}, .standard = {32, 64, 128}, .full = {32, 64, 128, 256}};
      if (smooth(p)) return Levels{.quick = {32, 64}, .standard = {32, 64, 128}, .full = {32, 64, 128, 256}};
      if (early(p)) return Levels{.quick = {32, 64}, .standard = {32, 64, 128}, .full = {32, 64, 128, 256}};
      // The carried square and the other kernels show the same failure by n = 128.
      if (p.real("v_adv") != 0.0 || p.text("kernel") != "cubic_spline")
        return Levels{.quick = {48, 96}, .standard = {32, 48, 64, 96}, .full = {32, 64, 128}};
      return levels;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = square::scorer(),
    .ic = square::initial_conditions,
}};

}  // namespace
}  // namespace sphv::square_case
