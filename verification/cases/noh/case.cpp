// Case `noh`: Noh's implosion in 1D, 2D and 3D (planar, cylindrical, spherical). Cold gas
// (gamma = 5/3, rho0 = 1, u ~ 0) falls at unit speed onto the centre; a shock leaves it at speed
// 1/3 with density 4^d behind it and the gas at rest. Independent reference: reference/noh (the
// exact solution). Wall heating (Noh 1987) overheats and underdensifies the gas within a few h
// of the centre; the zone shrinks with h, it is measured, and the density error looks away from it.
//
// In 1D the gas behind the shock is a lattice of a quarter of the initial spacing, and with h set
// by (50) it keeps h/dx = hfact there. Summation density (27) and the pressure force (23) then
// carry the kernel's lattice-sum errors at that ratio: S0 = dx sum_j W(j dx) (density) and
// S1 = -dx sum_j x_j W'(x_j) (the momentum flux through the lattice), both exactly 1 only at
// h/dx = 2 and 4 (errata). The jump conditions with those sums put the shock at
// v_s = (gamma - 1) u_post S1 / S0 and the summed plateau at S0 (1 + 1 / v_s), independent of n: a
// floor that the run reproduces to four digits, and that vanishes at hfact 2 (the variant that
// converges).
#include <algorithm>
#include <cmath>

#include "reference/noh.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/common/lattice_sums.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/noh/errors.hpp"
#include "verification/cases/noh/snapshots.hpp"
#include "verification/cases/noh/setup.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::noh_case {
namespace {

// The 1D plateau density that summation density reports behind the shock on a lattice at
// h/dx = hfact, from the kernel's lattice sums and the jump conditions (the file's head comment):
// u_post = 1/2 (the inflow's kinetic energy), rho0 = 1, unit inflow. The grad-h scheme's force
// divides the flux by Omega, and on a lattice S1 = S0 Omega (with W = f(x/h)/h,
// S1 = S0 + hfact dS0/dhfact and Omega = 1 + hfact (dS0/dhfact) / S0): its flux is S0, as its
// density's, so the jump conditions hold with v_s exact and the summed plateau is S0 times the
// exact one.
double lattice_plateau(double hfact, double gamma, bool grad_h) {
  const LatticeSums s = lattice_sums<1>(hfact);
  const double v_s = (gamma - 1.0) * 0.5 * (grad_h ? 1.0 : s.S1 / s.S0);
  return s.S0 * (1.0 + 1.0 / v_s);
}
bool gradh(const Params& p) { return p.text("scheme") != sph::ChapterScheme::name; }

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  extreme::Method m = extreme::method(prm);
  const double t_end = prm.real("t_end");
  m.controls.t_end = t_end;
  if (radial::centre<D>(prm) != sph::Vec<D>::Zero())
    throw InputError("noh: centre is for scoring snapshots (sphv score); sphv run puts the centre at the origin");
  const reference::Noh exact(D, m.gamma);
  auto [box, p, R0] = noh::initial<D>(prm, m.hfact);
  const double h0 = m.hfact * (1.0 / n);  // as noh::initial computes it
  // The free surface's self-density floor (49): h at most 3 h0 (its density is never used).
  m.h_max = 3.0 * h0;

  const sph::HydroOutcome out = extreme::evolve_gas(p, box, m);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"rho_post_exact", exact.post_shock_density()}, {"R0", R0},
             {"shock_radius_exact", exact.shock_radius(out.t)}};
  if (r.verdict != "stable") return r;

  noh::measure<D>(r, p.x, p.v, p.m, p.rho, p.u, out.t, m.gamma, n);
  if constexpr (D == 1) r.extra["rho_post_lattice_sums"] = lattice_plateau(m.hfact, m.gamma, gradh(prm));
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

Result run(const Params& p) {
  noh::check_size(p);
  return by_dimension(p, [&](auto d) { return run_dim<d>(p); });
}

void validate(const Params& p) {
  const long d = p.integer("dim"), n = p.integer("n");
  const double t_end = p.real("t_end"), hfact = p.real("hfact");
  if (d < 1 || d > 3) throw InputError("noh: dim must be 1, 2 or 3");
  if (!(t_end > 0.0)) throw InputError("noh: t_end must be > 0");
  if (!(p.real("u_cold") >= 0.0)) throw InputError("noh: u_cold must be >= 0");
  // Behind the shock the spacing, and so h, is a quarter of the initial one (density 4^d): ask
  // for three post-shock support radii inside R_s = t_end / 3, else there is no post-shock state.
  if (hfact * 2.25 > n * t_end)
    throw InputError("noh: resolution too coarse: need n t_end >= 2.25 hfact (three post-shock h inside the shock)");
}

// Per level, bounds on each error from measurements at the coarsest quick level (the errors fall
// with n, so they hold at every finer level), with the margin stated.
std::vector<Check> gates(const Sweep& s) {
  const Params prm = find_case(s.case_name).parse(s.settings);
  const long d = prm.integer("dim");
  const bool exact_sums = d == 1 && (prm.real("hfact") == 2.0 || prm.real("hfact") == 4.0);
  return radial::per_level(s, [&](const std::string& level, const Result& r, std::vector<Check>& c) {
    // Swept mass, an integral measure of the shock's position. Measured: 1D n = 100 9.8e-3 (hfact
    // 2.4), 4.0e-3 (hfact 2); 2D n = 35 3.1e-2; 3D n = 10 0.57. Bounds: margins 1.5, 1.6, 1.4.
    const double tol_swept = d == 1 ? 0.015 : d == 2 ? 0.05 : 0.8;
    c.push_back({level + "_swept_mass", r.errors.at("swept_mass"), 0.0, tol_swept,
                 "mass brought to rest vs rho0 vol(4 t / 3) (measured, margin >= 1.4)", Check::Kind::drift,
                 "swept_mass"});
    // 3D below n = 20 (R_s under 1.7 initial h): no post-shock plateau and no front (binned peak
    // ~12 against 64 at n = 10); the swept mass above is the measure there. 1D/2D: the front must
    // be found.
    const bool front = r.extra.value("shock_front_found", false);
    if (d == 3 && !front) return;
    c.push_back({level + "_shock_front_found", front ? 1.0 : 0.0, 1.0, 1.0,
                 "the binned density rises through the midpoint of the post- and pre-shock values",
                 Check::Kind::verification, "shock_speed"});
    if (!r.errors.count("rho_post")) return;
    // Plateau density: measured 1D n = 100 1.40e-2 (hfact 2.4: the lattice-sum floor), 3.6e-4
    // (hfact 2: exact sums); 2D n = 35 0.121; 3D n = 20 0.565. Bounds: margins 2.1, 2.8, 1.65, 1.4.
    const double tol_rho = exact_sums ? 1e-3 : d == 1 ? 0.03 : d == 2 ? 0.2 : 0.8;
    c.push_back({level + "_rho_post", r.errors.at("rho_post"), 0.0, tol_rho,
                 "post-shock density 4^d away from the wall (measured error, margin >= 1.4)", Check::Kind::drift,
                 "rho_post"});
    // The grad-h plateau against its lattice-sum prediction S0 4 (lattice_plateau): measured 1D
    // n = 100 -5.1e-4 relative, -3e-5 and -8e-5 from n = 200 on (the integrator's share, as at
    // hfact 2). Bound 1e-3: it tells S0 4 from 4 itself (1.8e-3 apart at hfact 2.4) and from the
    // chapter's prediction (1.5 % lower).
    if (d == 1 && !exact_sums && gradh(prm))
      c.push_back({level + "_rho_post_lattice_sums",
                   std::abs(r.extra.value("rho_post_measured", 0.0) / r.extra.value("rho_post_lattice_sums", 1.0) - 1.0),
                   0.0, 1e-3, "the plateau at the lattice sums' prediction: grad-h's flux S1 / Omega equals S0",
                   Check::Kind::verification, "rho_post"});
    // Shock speed: measured 1D n = 100 3.0e-2 (hfact 2.4), 2.05e-2 (hfact 2); 2D n = 35 7.9e-2;
    // 3D n = 20 0.19. Bounds: margins 3.3, 1.95, 1.9, 1.6.
    const double tol_speed = exact_sums ? 0.04 : d == 1 ? 0.1 : d == 2 ? 0.15 : 0.3;
    c.push_back({level + "_shock_speed", r.errors.at("shock_speed"), 0.0, tol_speed,
                 "shock speed 1/3 (measured error, margin >= 1.6)", Check::Kind::drift, "shock_speed"});
  });
}

// Shocks limit the convergence of L1-type errors to first order in h ~ 1/n: the shock is smeared
// over a few h and the wall-heated zone is a few h wide. In 1D at a support ratio other than 2 or
// 4 the lattice-sum floor (head comment) holds every error at a constant: a known failure, proven
// by the lattice prediction beside the measured plateau and by the variant at hfact 2. There the
// plateau is exact to the integrator's energy error at a fixed Courant number (a particle crosses
// the shock in the same number of steps at every n), which is not an error in n.
//
// The swept mass in 2D and 3D: two terms, the front's offset, O(h) of the radius, and the start-up,
// where the inflow first meets itself in a ball a few h wide and any error of that phase misplaces
// a mass O(h^d) of the ball's; the slope of their sum lies between 1 and d (1D: both first order,
// and the planar flow brings no start-up ball). The sum's slope tends to the slower term's, so theory
// bounds the order from below: at least 1.
//
// scheme=gradh_switches (1D, hfact 2.4; grad-h, the Cullen & Dehnen switch, conduction) on
// n = 100, 200, 400, 800 (one thread): the plateau sits at 4.0052, 4.0071, 4.0069, 4.0069, S0 4 =
// 4.0072 (lattice_plateau), the summed density's reading of an exact compression; rho_post
// 1.29e-3, 1.77e-3, 1.72e-3, 1.72e-3 (the default's 1.33e-2). shock_speed 1.85e-2, 9.28e-3,
// 4.66e-3 on 100..400, local orders 1.00, 0.99 (the default's 3.00e-2, 3.16e-2, 2.72e-2, 2.22e-2 on
// 100..800, held up by its plateau's floor): first order, verified. swept_mass 3.1e-4, 8.7e-4, 3.4e-4, 7.8e-4 (signed all below the
// exact), local orders -1.48, 1.34, -1.17: the post-shock gas rings, the switch lets alpha decay
// behind the shock, and the swept mass counts a particle moving outwards as at rest, so the
// ringing's outward speed (swept_outward 3.1e-3, 2.3e-3, 1.1e-3, 1.1e-3) biases it; the swept
// mass plus that bias, 2.8e-3, 1.4e-3, 7.2e-4, 3.6e-4, falls at first order. With the switch
// held at alpha 1 (alpha_min 1, in a build made for the test) the bias is 5.7e-5 .. 7.4e-6 and
// swept_mass falls at 0.99 (2.81e-3 .. 3.63e-4); without the conduction it stays as it is
// (5.0e-4 .. 7.0e-4). So swept_mass is a known failure whose experiment is the chapter's forms
// at hfact 2, with constant alpha (the scheme has no option for alpha_min).
OrderClaims noh_orders(const Params& p) {
  const OrderClaim first{1.0, 0.3, "shocks and the wall-heated zone are a few h wide: first order in h ~ 1/n"};
  if (p.integer("dim") == 1 && gradh(p)) {
    const double hfact = p.real("hfact");
    const bool exact_sums = hfact == 2.0 || hfact == 4.0;
    return {{"rho_post",
             no_order(exact_sums ? "the 1D lattice sums are exact at this h/dx: the plateau's error {rho_post} at {levels} "
                                   "is the integrator's energy error at a fixed Courant number, bounded"
                                 : "the summed density reads S0 times the true one (S0 the lattice's density sum at h/dx = "
                                   "hfact): the plateau sits at {extra.rho_post_measured} at {levels}, where the lattice "
                                   "sums predict {extra.rho_post_lattice_sums} (grad-h's flux S1 / Omega equals S0, so the "
                                   "jump conditions hold and the compression is exact), whatever n")},
            {"shock_speed", OrderClaim{1.0, 0.3, "the shock smeared over a few h: first order in h ~ 1/n (grad-h's "
                                                 "flux through the lattice equals its density's sum, so no lattice "
                                                 "floor holds the front)"}},
            {"swept_mass",
             known_failure(first,
                           "the post-shock gas rings: the switch lets alpha decay behind the shock, and the swept "
                           "mass counts a particle moving outwards as at rest, so the ringing biases it (the outward "
                           "share {extra.swept_outward} at {levels}, falling slower than h): swept_mass {swept_mass}, "
                           "order {order.swept_mass}; with constant alpha the chapter's forms at exact lattice sums "
                           "converge",
                           "hfact=2")}};
  }
  if (const long d = p.integer("dim"); d > 1) {
    const OrderClaim swept = at_least(1.0, "the front's offset, first order in h, plus the start-up ball's misplaced "
                                           "mass, order d: the slope of the sum lies between 1 and d");
    return {{"rho_post", first}, {"shock_speed", first}, {"swept_mass", swept}};
  }
  const double hfact = p.real("hfact");
  if (hfact == 2.0 || hfact == 4.0)
    return {{"rho_post", no_order("the 1D lattice sums are exact at this h/dx: the plateau's error {rho_post} at "
                                  "{levels} is the integrator's energy error at a fixed Courant number C (a particle "
                                  "crosses the shock in the same number of steps at every n), bounded; it shrinks with C")},
            {"shock_speed", {1.0, 0.25, "the shock smeared over a few h: first order in h ~ 1/n"}},
            {"swept_mass", {1.0, 0.3, "the shock smeared over a few h: first order in h ~ 1/n"}}};
  const std::string floor = "kernel lattice-sum floor at h/dx = hfact: the plateau sits at {extra.rho_post_measured} "
                            "at {levels}, where the lattice sums and the jump conditions predict "
                            "{extra.rho_post_lattice_sums} (exact: rho0 (gamma + 1) / (gamma - 1)), whatever n";
  // The plateau's error has no limit in n at a fixed hfact and Courant number (the lattice floor plus
  // the integrator's error, as at hfact 2): no order. The front's speed and swept mass converge
  // where the sums are exact: the floor is the cause, hfact 2 the experiment.
  return {{"rho_post", no_order(floor + "; at fixed hfact and Courant number the plateau's error has no limit in n")},
          {"shock_speed", known_failure(first, floor, "hfact=2")},
          {"swept_mass", known_failure(first, floor, "hfact=2")}};
}

// Levels: 1D two in quick (the order claims are gated in CI), three in standard. 2D: n = 100 costs
// about 1.7 times n = 71, so it is full only. 3D: the front is resolved from n = 20 on (R_s = 1.7
// initial h; below it only the swept mass is reported), so the levels start there. The shock
// speed's local order is 0.42 from n = 20 to 24 and 1.17, 0.95 on to 28 and 32 (measured): the
// standard tier's three (n = 28 holds 83,000 particles) do not resolve its order (se 0.21); the
// full tier adds n = 32 (120,000 particles, about twice n = 28's time), where the rule
// verifies it (CPU times: docs/cases/noh.md).
const Levels levels = {.quick = {100, 200}, .standard = {200, 400, 800}, .full = {200, 400, 800, 1600}};

const Registration reg{Case{
    .name = "noh",
    .summary = "Noh implosion (1D/2D/3D): post-shock density 4^d and shock speed 1/3 against the exact solution",
    .n_counts = "particles per unit length of the initial lattice",
    .tags = {"gate", "extreme", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 200, "particles per unit length (a 1D size: use ~50 in 2D, 10-20 in 3D)"),
                                   integer_param("dim", 1, "dimension 1, 2 or 3"),
                                   real_param("t_end", 0.6, "end time (shock at t_end / 3)", 0.0),
                                   real_param("u_cold", 1e-6, "specific internal energy of the inflowing gas"),
                                   real_param("max_particles", 1.5e5, "refuse runs with more particles than this", 0.0),
                                   radial::centre_param()};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      // The full tier's finest levels: 1D n = 1600 takes about 24,000 Courant steps to t_end, 3D
      // n = 32 holds about 120,000 particles (max_particles above).
      for (auto& q : ps)
        if (q.name == "max_steps") q.default_value = "40000";
      return ps;
    }(),
    .levels = levels,
    .orders = noh_orders,
    .error_defs = noh::error_defs,
    .variants = {{}, {"hfact=2"}, {"dim=2"}, {"dim=3"}, {"scheme=gradh_switches"}},
    .levels_for = [](const Params& p) {
      const long d = p.integer("dim");
      // scheme=gradh_switches in 1D: standard 100, 200, 400, where the shock speed's local orders
      // 0.80, 0.94 verify its claim; n = 800 would cost 4.5 s of CPU more (the scheme costs about
      // 2.3 times the chapter's a step). Full as the default's.
      if (d == 1 && gradh(p)) return Levels{.quick = {100, 200}, .standard = {100, 200, 400}, .full = {200, 400, 800, 1600}};
      if (d == 2) return Levels{.quick = {35, 50}, .standard = {35, 50, 71}, .full = {35, 50, 71, 100}};
      if (d == 3) return Levels{.quick = {10}, .standard = {20, 24, 28}, .full = {20, 24, 28, 32}};
      return levels;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = noh::scorer(),
    .ic = noh::initial_conditions,
}};

}  // namespace
}  // namespace sphv::noh_case
