// Case `kh`: the linear growth of the Kelvin-Helmholtz instability from smooth initial conditions
// (McNally, Lyra & Passy 2012, ApJS 201, 18): the periodic unit box in 2D, rho 1 and 2, shear
// +-0.5 joined by piecewise exponentials of width L = 0.025 at y = 1/4 and 3/4, p0 = 2.5, gamma
// 5/3, seed v_y = 0.01 sin(4 pi x) (kh/setup.hpp). The error is the growth rate of McNally et al.'s
// mode amplitude M(t) fitted over the linear window, against the same fit to the linear evolution
// of the same seed (reference/kh_linear), whose late slope is the smooth profile's unstable
// eigenvalue (2.8319 at the paper's values; the vortex sheet would give 5.58, the interface width
// halves it).
#include <algorithm>
#include <cmath>
#include <string>

#include "sph/kernel/kernels.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/kh/errors.hpp"
#include "verification/cases/kh/setup.hpp"
#include "verification/cases/kh/snapshots.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::kh_case {
namespace {

Result run(const Params& prm) {
  extreme::Method m = extreme::method(prm);
  m.controls.t_end = prm.real("t_end");
  m.h_max = 0.45;
  sph::Particles<2> p = kh::initial_particles(prm);
  kh::pressure_equilibrium(p, prm, m.h_max);
  const sph::Vec<2> lo{0.0, 0.0}, len{1.0, 1.0};
  std::vector<double> ts{0.0}, Ms{kh::mode_amplitude(p.x, p.v, p.m, p.rho, lo, len)};
  sph::HydroHooks<2> hooks;
  hooks.index_free = true;  // M sums over the particles in any order
  hooks.stepped = [&](const sph::Particles<2>& q, const sph::Derivatives<2>&, long, double t) {
    ts.push_back(t), Ms.push_back(kh::mode_amplitude(q.x, q.v, q.m, q.rho, lo, len));
  };
  const std::string kernel = prm.text("kernel");
  const sph::HydroOutcome out = extreme::evolve_gas_kernel<2>(kernel, p, sph::unit_box<2>(true), m, hooks);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"alpha", m.alpha}, {"kernel", kernel}, {"hfact", m.hfact}};
  if (r.verdict != "stable") return r;
  kh::growth_result(r, prm, kh::fit_growth(ts, Ms, prm.real("t_fit_lo"), prm.real("t_fit_hi")), ts, Ms);
  r.extra["h_mean"] = extreme::mean_h(p);
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

void validate(const Params& p) {
  const long n = p.integer("n");
  if (n < 16) throw InputError("kh: need n >= 16 particles per side (4 per seeded wavelength at least)");
  if (n % 4 != 0) throw InputError("kh: n must be a multiple of 4 (the interfaces at y = 1/4, 3/4 between lattice rows)");
  if (!(p.real("rho1") > 0.0) || !(p.real("rho2") > 0.0)) throw InputError("kh: rho1 and rho2 must be > 0");
  if (!(p.real("p0") > 0.0)) throw InputError("kh: p0 must be > 0");
  if (!(p.real("U") > 0.0)) throw InputError("kh: the shear velocity U must be > 0 (no shear, no instability)");
  const double L = p.real("L");
  if (!(L > 0.0 && L <= 0.05))
    throw InputError("kh: L must be in (0, 0.05] (the exponential profile must decay within a quarter box), got " +
                     p.text("L"));
  const double A = p.real("A");
  if (!(A > 0.0 && A <= 0.05 * p.real("U")))
    throw InputError("kh: the seed amplitude A must be in (0, 0.05 U] (a linear seed), got " + p.text("A"));
  const double lo = p.real("t_fit_lo"), hi = p.real("t_fit_hi"), t_end = p.real("t_end");
  if (!(lo >= 0.0 && hi > lo)) throw InputError("kh: need 0 <= t_fit_lo < t_fit_hi");
  if (!(t_end >= hi)) throw InputError("kh: t_end must reach t_fit_hi (the fit window)");
  if (p.text("kernel") != "cubic_spline" && (p.text("hmode") == "rate53" || p.text("energy") != "38"))
    throw InputError("kh: kernel=" + p.text("kernel") + " runs with hmode=iterate50 or fixed, energy=38 only");
  if (p.text("kernel") != "cubic_spline" && p.text("scheme") != sph::ChapterScheme::name)
    throw InputError("kh: kernel=" + p.text("kernel") + " runs with scheme=" + sph::ChapterScheme::name + " only");
  if (double(n) * n > p.real("max_particles"))
    throw InputError("kh: n = " + std::to_string(n) + " means " + std::to_string(n * n) +
                     " particles, above max_particles (raise it)");
}

// The experiment: the catalogue variant that converges (Wendland C4, a wider support, weak viscosity).
const char* const converging = "alpha=0.1,hfact=4.5,kernel=wendland_c4";
bool converges(const Params& p) {
  return p.text("kernel") == "wendland_c4" && p.real("hfact") == 4.5 && p.real("alpha") == 0.1;
}

// The growth error's largest value measured on the variant's levels of every tier (cubic alpha 1:
// 1.240 at n = 128, where the rate is negative; alpha 0: 0.798; Wendland C4: 1.184 at n = 32,
// where M does not yet grow; scheme=gradh_switches: 0.607 at n = 64, on its quick and standard
// levels; the series: docs/cases/kh.md); the gate holds each level at 1.5 times it. A loose
// bound, which a fault that stops the growth or doubles it on the Wendland variant crosses; the
// order claim (kh_orders) and the exact check of the measurement (M0) are the verification.
double growth_measured(const Params& p) {
  if (p.text("scheme") != sph::ChapterScheme::name) return 0.607;
  if (converges(p)) return 1.184;
  return p.real("alpha") > 0.0 ? 1.240 : 0.798;
}

std::vector<Check> gates(const Sweep& s) {
  const Params prm = find_case(s.case_name).parse(s.settings);
  const double bound = 1.5 * growth_measured(prm);
  return radial::per_level(s, [&](const std::string& level, const Result& r, std::vector<Check>& c) {
    // M(0) = A exactly: on the lattice the sums of sin^2 and cos^2 (4 pi x_i) over a row are n / 2
    // and of sin cos zero (n >= 8), and the seed is uniform in y, so the weights cancel.
    c.push_back({level + "_M0", std::abs(r.extra.value("M_first", 0.0) / prm.real("A") - 1.0), 0.0, 1e-12,
                 "McNally et al.'s mode amplitude of the initial state equals the seed amplitude A (lattice sums, exact)",
                 Check::Kind::verification, "growth"});
    c.push_back({level + "_fit_samples", r.extra.value("fit_samples", 0.0), 20.0, 1e9,
                 "at least 20 samples of M(t) in the fit window", Check::Kind::verification, "growth"});
    c.push_back({level + "_growth", r.errors.at("growth"), 0.0, bound,
                 "the growth rate within 1.5 times its largest error measured on the variant's quick and standard "
                 "levels (kh/case.cpp)", Check::Kind::drift, "growth"});
  });
}

// The growth rate's error has two sources with different limits:
// - the kernel's smoothing of the layer and the artificial viscosity (45), which damps the seed and
//   the shear (nu ~ alpha c_s h): first order in h ~ 1/n at fixed hfact while the kernel's support
//   is comparable with the layer's width L (2 h / L = 3.8 to 1.9 at hfact 2.4, n = 32 to 96);
// - the zeroth-order error E0 of the momentum equation (23) (McNally et al. 2012, section 6; Read,
//   Hayfield & Agertz 2010): the layers shear the lattice past itself, and at the cubic spline's few
//   neighbours the pressure p0 turns that disorder into force noise that does not fall with h. It
//   drives row-by-row v_y noise ~0.1 (ten times the seed) at alpha = 0, and with alpha = 1 the
//   viscosity that damps the noise damps the seed too.
// With the cubic spline the error does not fall: at alpha 1 the rate stays below the linear one
// and its error rises with n; at alpha 0 the noise swamps the mode; a wider cubic support
// (hfact 3 or 3.6, alpha 0.1) shows no trend, and a uniform density (rho2 = 1) fails the same way,
// so the density contrast is not the cause. With Wendland C4 at hfact 4.5 M grows smoothly and
// its rate converges at first order towards the linear one (the measured rates per variant:
// docs/cases/kh.md). So the cubic variants are known failures of the first-order claim and the
// Wendland C4 kernel at hfact 4.5 (64 neighbours) with alpha 0.1 is the experiment that
// converges, as for gresho. Both
// agree with the literature: McNally et al. (2012) find SPH's growth poor on this set-up and trace
// it to the zeroth-order inconsistency; Tricco (2019, arXiv:1907.03935; on the
// smooth set-up of Lecoanet et al. 2016) needs a high-order kernel to resolve the seed and keep
// spurious modes down, and then converges.
// Band 0.3 as gresho's: the experiment's measured local orders 0.77, 0.85 on n = 32, 64, 96.
//
// scheme=gradh_switches (grad-h, the Cullen & Dehnen switch, conduction; the cubic spline at
// hfact 2.4): growth errors 0.449, 0.607, 0.299 at n = 32, 64, 96 (rates 4.28 +- 0.24, 1.16,
// 2.07 against the linear evolution's 2.95), local orders -0.43, 1.75, fit 0.28 +- 0.57; M at
// t_end is 0.45, 0.88, 1.88 times M(0) (the default's 0.45, 0.63, 0.72; Wendland C4's 0.31,
// 1.37, 2.45). At n = 96 the mode grows, and its rate's error is the lowest of the catalogue's
// (default 0.346, Wendland C4 0.490), but at 32 and 64 M decays: the rate at 32 is a fit to
// noise. The switch is not the cause (with alpha_max 0, no viscosity at all, the rate at n = 64
// is -0.02), nor is the conduction (without it, in a build made for the test, 0.047, 0.619,
// 0.329), nor a seed too small for the noise (A = 0.025: the rate at n = 64 is 0.30). What damps
// the mode is what stops the cubic variants of the chapter's scheme, the E0 error of the sheared
// lattice at the cubic's few neighbours: the Wendland C4 kernel at hfact 4.5 smooths the layer
// more and its mode grows. So the first-order claim is a known failure; this scheme runs with the
// cubic spline only (extreme::evolve_gas_kernel), so the experiment is the chapter's Wendland C4
// variant.
OrderClaims kh_orders(const Params& p) {
  OrderClaims c;
  const std::string first = "the kernel's smoothing of the layer (support comparable with its width L) and the "
                            "artificial viscosity's damping, nu ~ alpha c_s h: first order in h ~ 1/n at fixed hfact "
                            "while the zeroth-order (E0) force noise of the sheared lattice stays below them";
  if (p.text("scheme") != sph::ChapterScheme::name) {
    c["growth"] = known_failure(
        1.0, 0.3,
        "the mode's amplitude M(t_end)/M(0) is {extra.M_end_over_M0} at {levels} (below 1 the mode decays instead of "
        "growing): the E0 error of the grad-h momentum equation at hfact = {extra.hfact} (the cubic spline's few "
        "neighbours) damps the seed on the coarser levels, as it does in the chapter's forms; the switch's viscosity and "
        "the conduction are not the cause (with no viscosity, or no conduction, the mode does not grow there either). "
        "Growth rates {extra.growth_rate} at {levels} against the linear evolution's {extra.growth_rate_ref}, order "
        "{order.growth}; this scheme runs with the cubic spline only, and the chapter's forms with the Wendland C4 "
        "kernel's many neighbours converge",
        converging);
    return c;
  }
  if (converges(p)) {
    c["growth"] = OrderClaim{1.0, 0.3, first + " (a Wendland kernel with many neighbours, Dehnen & Aly 2012)"};
    return c;
  }
  c["growth"] = known_failure(
      1.0, 0.3,
      "the mode's amplitude M(t_end)/M(0) is {extra.M_end_over_M0} at {levels} (below 1 the mode decays instead of "
      "growing); the cause is the E0 error of the momentum equation (23): the shear moves the lattice past itself, and at hfact = {extra.hfact} "
      "(the cubic spline's few neighbours) the pressure p0 drives force noise that does not fall with h and swamps or, "
      "damped by the viscosity (alpha = {extra.alpha}), outlasts the seed: growth rates {extra.growth_rate} at {levels} "
      "against the linear evolution's {extra.growth_rate_ref}, M at t_end {extra.M_last_over_linear} of the linear "
      "evolution's, order {order.growth}",
      converging);
  return c;
}

// Standard stops at n = 96: the cost grows as n^3 (steps ~ n, particles ~ n^2; docs/cases/kh.md).
const Levels levels = {.quick = {32, 64}, .standard = {32, 64, 96}, .full = {32, 64, 128, 256}};

const Registration reg{Case{
    .name = "kh",
    .summary = "Kelvin-Helmholtz growth from smooth initial conditions (McNally et al. 2012), 2D periodic box: the mode "
               "amplitude's growth rate in the linear phase against the smooth profile's linear eigenmode",
    .n_counts = "particles per side of the periodic unit box",
    .tags = {"gate", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 64, "particles per side of the unit box (a multiple of 4)"),
                                   real_param("rho1", 1.0, "density of the outer layers (McNally et al.)", 0.0),
                                   real_param("rho2", 2.0, "density of the middle layer (McNally et al.)", 0.0),
                                   real_param("U", 0.5, "shear velocity: v_x = +U outside, -U inside (McNally et al.)"),
                                   real_param("L", 0.025, "width of the exponential interfaces (McNally et al.)"),
                                   real_param("p0", 2.5, "uniform pressure (McNally et al.)", 0.0),
                                   real_param("A", 0.01, "seed amplitude of v_y = A sin(4 pi x) (McNally et al.)"),
                                   real_param("t_fit_lo", 0.6, "start of the growth fit's window"),
                                   real_param("t_fit_hi", 1.2, "end of the growth fit's window"),
                                   real_param("t_end", 1.2, "end time (at least t_fit_hi)"),
                                   real_param("max_particles", 2e5, "refuse runs with more particles than this", 0.0)};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      ps.push_back(choice_param("kernel", "cubic_spline",
                                "the kernel (sph/kernel/kernels.hpp); other than cubic_spline: hmode=iterate50 or fixed, "
                                "energy=38",
                                sph::kernel_names()));
      return ps;
    }(),
    .levels = levels,
    .orders = kh_orders,
    .error_defs = kh::error_defs,
    .variants = {{}, {"alpha=0"}, {"kernel=wendland_c4", "hfact=4.5", "alpha=0.1"}, {"scheme=gradh_switches"}},
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = kh::scorer(),
    .ic = kh::initial_conditions,
}};

}  // namespace
}  // namespace sphv::kh_case
