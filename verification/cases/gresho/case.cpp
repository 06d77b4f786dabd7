// Case `gresho`: the Gresho-Chan triangular vortex in 2D (reference/gresho), a stationary rotating
// flow held by its pressure gradient, in the periodic unit box with the vortex at its centre
// (gresho/setup.hpp: a square lattice). Summation density (27), ideal gas (gamma 5/3), Euler (23),
// energy (38), leapfrog, artificial viscosity (44)-(48) with constant alpha, h by (50); or, with
// scheme=gradh_switches, the grad-h scheme with the viscosity switch and artificial conduction
// (sph/schemes/gradh_switches.hpp, the cubic spline only).
//
// The flow is stationary, so every error is the method's. Two sources, with different limits:
// - the artificial viscosity (45): a constant alpha acts on the ring's shear (the rigid core has
//   v_ij . r_ij = 0 and none), a kinematic viscosity ~ alpha c_s h (c_s ~ 3 here), first order in
//   h ~ 1/n at fixed hfact;
// - the zeroth-order error E0 of the momentum equation (23) (Read, Hayfield & Agertz 2010; Dehnen
//   & Aly 2012): a disordered particle set turns the large uniform pressure p0 = 5 into force
//   noise ~ p E0 / h. The shear of the ring disorders the initial lattice within a fraction of a
//   turn; at a fixed neighbour number E0 does not fall with h, so the noise, and the velocity
//   error it drives, does not converge at fixed hfact. Wider kernels with more neighbours lower E0
//   (Wendland kernels do so without the pairing instability); the floor is then reached later.
// The default (cubic spline, hfact 2.4, alpha 1) and the cubic at alpha 0.1 are therefore known
// failures of the first-order claim: the viscosity smears the vortex and the E0 noise keeps the
// error from falling. Without viscosity the E0 noise grows unchecked. The Wendland C4 kernel at
// hfact 4.5 (64 neighbours) with alpha 0.1 is the experiment that converges at first order over
// the levels run; alpha 1 at that hfact (h twice the cubic's) smears the vortex far out of the
// asymptotic range and is not a catalogue variant. The measured series per variant:
// docs/cases/gresho.md; the current numbers: the report's page of the case.
#include <cmath>
#include <string>

#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/gresho/errors.hpp"
#include "verification/cases/gresho/setup.hpp"
#include "verification/cases/gresho/snapshots.hpp"
#include "verification/cases/common/pairing.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::gresho_case {
namespace {

Result run(const Params& prm) {
  gresho::check_centre(prm);
  const int n = static_cast<int>(prm.integer("n"));
  extreme::Method m = extreme::method(prm);
  m.controls.t_end = prm.real("t_end");
  m.h_max = 0.45;  // below half the periodic box
  const reference::GreshoVortex g = gresho::vortex(prm);
  sph::Particles<2> p = gresho::initial_particles(prm);
  const std::string kernel = prm.text("kernel");
  const sph::Box<2> box = sph::unit_box<2>(true);
  const sph::HydroOutcome out =
      extreme::evolve_gas_kernel<2>(kernel, p, box, m);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"kernel", kernel}, {"hfact", m.hfact}, {"alpha", m.alpha},
             {"equilibrium_error", gresho::equilibrium_error(g)}};
  if (r.verdict != "stable") return r;
  std::vector<sph::Vec<2>> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = p.x[i] - sph::Vec<2>(0.5, 0.5);
  gresho::measure(r, x, p.v, p.m, out.t, g, n);
  r.extra["paired_fraction"] = extreme::paired_fraction(p, box, 0.5 / n);
  r.extra["h_mean"] = extreme::mean_h(p);
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

void validate(const Params& p) {
  const long n = p.integer("n");
  if (n < 8) throw InputError("gresho: need n >= 8 particles per unit length (the vortex's radius 0.4 spans n / 2.5)");
  if (!(p.real("t_end") >= 0.0)) throw InputError("gresho: t_end must be >= 0 (0: score an initial state)");
  if (!(p.real("p0") > 0.0)) throw InputError("gresho: the central pressure p0 must be > 0, got " + p.text("p0"));
  if (double(n) * double(n) > p.real("max_particles"))
    throw InputError("gresho: n = " + std::to_string(n) + " means " + std::to_string(n * n) +
                     " particles, above max_particles (raise it)");
  if (p.text("kernel") != "cubic_spline" && (p.text("hmode") == "rate53" || p.text("energy") != "38"))
    throw InputError("gresho: kernel=" + p.text("kernel") + " runs with hmode=iterate50 or fixed, energy=38 only");
  if (p.text("kernel") != "cubic_spline" && p.text("scheme") != sph::ChapterScheme::name)
    throw InputError("gresho: kernel=" + p.text("kernel") + " runs with scheme=" + sph::ChapterScheme::name + " only");
}

// The experiment: the catalogue variant that converges (Wendland C4, a wider support, weak viscosity).
const char* const converging = "alpha=0.1,hfact=4.5,kernel=wendland_c4";
// The kernel comparison (report): every kernel at the experiment's hfact and alpha. The cubic's
// many neighbours pair (Dehnen & Aly 2012), and its error stalls where the others keep the first
// order (docs/cases/gresho.md).
bool wide(const Params& p) { return p.real("hfact") == 4.5 && p.real("alpha") == 0.1; }
bool converges(const Params& p) { return wide(p) && p.text("kernel") != "cubic_spline"; }

// Band 0.3: the converging variant measured local orders 0.74, 0.85 on n = 16, 32, 64, rising
// towards 1 as the viscosity's O(h) share overtakes the E0 noise's (a fifth of L1_v at n = 64).
//
// scheme=gradh_switches (grad-h, the Cullen & Dehnen switch, conduction; the cubic spline at
// hfact 2.4): the switch's limiter keeps alpha low in the ring's shear, so the viscosity no longer
// smears the vortex (peak v_phi 0.41, 0.58, 0.63 at n = 16, 32, 64 against the default's 0.21,
// 0.37, 0.44), and nothing damps the E0 noise either: mean |v_r| 0.081, 0.073, 0.063, three times
// the default's. L1_v 0.2465, 0.1604, 0.1204 (n = 24, 48: 0.1852, 0.1302), local orders 0.62,
// 0.41 (24 -> 48: 0.51), fit 0.52 +- 0.06: below the default's L1_v by 30 % at n = 64, but
// falling towards the noise's floor, not at first order. The noise is the cause: with alpha_max 0
// (no viscosity at all) L1_v is 0.1994, 0.1584, 0.1254 (order 0.33), the switch's run by n = 64;
// without the conduction (alpha_u = 0, in a build made for the test: the scheme has no option
// for it) 0.2282, 0.1556, 0.1182, the same. So the first-order claim is a known failure, as for
// the default; the case runs this scheme with the cubic spline only (extreme::evolve_gas_kernel),
// so its experiment is the chapter's forms with the Wendland C4 kernel, whose many neighbours
// lower the noise.
OrderClaims gresho_orders(const Params& p) {
  OrderClaims c;
  const std::string first = "the artificial viscosity's smearing of the ring's shear, nu ~ alpha c_s h at fixed hfact: "
                            "first order in h ~ 1/n while the zeroth-order (E0) force noise of the disordered particles "
                            "stays below it";
  if (p.text("scheme") != sph::ChapterScheme::name) {
    c["L1_v"] = known_failure(
        1.0, 0.3,
        "the E0 error of the grad-h momentum equation: the ring's shear disorders the lattice, and at fixed hfact = "
        "{extra.hfact} (the cubic spline's few neighbours) the pressure p0 drives force noise that does not fall with h; "
        "the switch keeps alpha low in the shear (peak v_phi {extra.v_phi_peak}, exact 1), so nothing damps the noise "
        "(mean |v_r| {extra.L1_v_r}, exact 0): L1_v {L1_v} at {levels}, order {order.L1_v}, tending to the noise's "
        "floor; this scheme runs with the cubic spline only, and the chapter's forms with the Wendland C4 kernel's many "
        "neighbours converge",
        converging);
    return c;
  }
  if (converges(p)) {
    c["L1_v"] = OrderClaim{1.0, 0.3, first + " (many neighbours with a kernel that does not pair there, Dehnen & Aly 2012)"};
    return c;
  }
  if (wide(p)) {
    c["L1_v"] = known_failure(
        1.0, 0.3,
        "the pairing instability of the cubic spline with many neighbours (hfact = {extra.hfact}; Dehnen & Aly 2012): "
        "particles pair (a fraction {extra.paired_fraction} of them with another within half a lattice spacing at t_end), "
        "the E0 noise grows, and the error stalls (mean |v_r| {extra.L1_v_r}, exact 0); L1_v {L1_v} at "
        "{levels}, order {order.L1_v}, where the Wendland kernels at the same hfact converge",
        converging);
    return c;
  }
  c["L1_v"] = known_failure(
      1.0, 0.3,
      "the E0 error of the momentum equation (23): the ring's shear disorders the lattice, and at fixed hfact = "
      "{extra.hfact} (the cubic spline's few neighbours) the pressure p0 drives force noise that does not fall with h (mean "
      "|v_r| {extra.L1_v_r}, exact 0); L1_v {L1_v} at {levels}, order {order.L1_v}, against the viscosity's first "
      "order (alpha = {extra.alpha})",
      converging);
  return c;
}

// L1_v measured at n = 16, the coarsest level of the standard and full tiers, below the quick
// tier's 24 where a variant starts there (one thread; the noise is chaotic, so round-off moves
// it between instruction-set paths): bounds at 1.2 times these (sedov's margin) at every level,
// which the finer levels' smaller errors meet.
double l1_measured(const Params& p) {
  if (p.text("scheme") != sph::ChapterScheme::name) return 0.2465;  // gradh_switches
  if (wide(p)) {
    const std::string k = p.text("kernel");
    if (k == "wendland_c2") return 0.1675;
    if (k == "wendland_c6") return 0.1717;
    if (k == "quintic_spline") return 0.1695;
    if (k == "cubic_spline") return 0.1746;
    return 0.1721;  // Wendland C4
  }
  return p.real("alpha") == 0.1 ? 0.2148 : 0.2573;
}

std::vector<Check> gates(const Sweep& s) {
  const double bound = 1.2 * l1_measured(find_case(s.case_name).parse(s.settings));
  return radial::per_level(s, [&](const std::string& level, const Result& r, std::vector<Check>& c) {
    // The set-up's pressure balances its rotation: the closed form against the quadrature of
    // dp/dr = rho v_phi^2 / r, whose tolerance is 1e-13 relative (reference/quadrature.hpp); bound
    // 1e-10. The run's L1_v at t = 1 is dominated by the method's errors and hardly sees a wrong
    // set-up pressure (a core pressure 12.5 r^2 too high moved it by 7 %).
    c.push_back({level + "_equilibrium", r.extra.value("equilibrium_error", 1.0), 0.0, 1e-10,
                 "the initial pressure in radial equilibrium with v_phi (closed form against quadrature)",
                 Check::Kind::verification, "L1_v"});
    // The bound is this code's own earlier output (a drift check); the equilibrium above and the
    // order claims are the verification.
    c.push_back({level + "_L1_v", r.errors.at("L1_v"), 0.0, bound,
                 "L1_v of v_phi at most 1.2 times its value measured at n = 16 (gresho/case.cpp)",
                 Check::Kind::drift, "L1_v"});
  });
}

// Levels: n = 16 resolves the vortex's radius 0.4 with 6.4 spacings; n = 128 costs eight times
// n = 64 (full tier only). The variants at alpha 0.1 run the quick tier on 24, 48, where their
// local orders lie clear of the band's edges (from 16 to 32 the quintic's and the cubic's sit at
// the edge, before the cubic pairs; docs/cases/gresho.md).
const Levels levels = {.quick = {16, 32}, .standard = {16, 32, 64}, .full = {16, 32, 64, 128}};

const Registration reg{Case{
    .name = "gresho",
    .summary = "Gresho-Chan vortex (2D), periodic unit box: v_phi at t_end against the exact stationary vortex",
    .n_counts = "particles per unit length (per side of the periodic unit box)",
    .tags = {"gate", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {
          integer_param("n", 32, "particles per unit length (the box's side)"),
          real_param("rho0", 1.0, "density", 0.0),
          real_param("p0", 5.0, "central pressure (5: the standard set-up)"),
          real_param("t_end", 1.0, "end time (the vortex's peak, at r = 0.2, turns once in 0.4 pi)"),
          real_param("max_particles", 3e5, "refuse runs with more particles than this", 0.0),
          choice_param("kernel", "cubic_spline",
                       "the kernel (sph/kernel/kernels.hpp); other than cubic_spline: hmode=iterate50 or fixed, energy=38",
                       sph::kernel_names()),
          gresho::centre_param()};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = levels,
    .orders = gresho_orders,
    .error_defs = gresho::error_defs,
    .variants = {{},
                 {"alpha=0.1"},
                 {"kernel=wendland_c4", "hfact=4.5", "alpha=0.1"},
                 {"kernel=wendland_c2", "hfact=4.5", "alpha=0.1"},
                 {"kernel=wendland_c6", "hfact=4.5", "alpha=0.1"},
                 {"kernel=quintic_spline", "hfact=4.5", "alpha=0.1"},
                 {"kernel=cubic_spline", "hfact=4.5", "alpha=0.1"},
                 {"scheme=gradh_switches"}},
    .levels_for = [](const Params& p) {
      // scheme=gradh_switches: its quick order 0.51 on 24, 48 lies clear of the claim's window
      // (0.62 on 16, 32, at 0.08 from its edge). Standard stops at 48: the scheme costs about
      // 2.3 times the chapter's a step, and its n = 64 alone 5.4 s of CPU (16, 24, 32, 48: 3.3 s
      // together; fit 0.58 +- 0.04, clear of the window too). Full as the default's.
      if (p.text("scheme") != sph::ChapterScheme::name)
        return Levels{.quick = {24, 48}, .standard = {16, 24, 32, 48}, .full = {16, 32, 64, 128}};
      if (p.real("alpha") == 0.1 && (p.text("kernel") == "cubic_spline" || wide(p)))
        return Levels{.quick = {24, 48}, .standard = {16, 32, 64}, .full = {16, 32, 64, 128}};
      return levels;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = gresho::scorer(),
    .ic = gresho::initial_conditions,
}};

}  // namespace
}  // namespace sphv::gresho_case
