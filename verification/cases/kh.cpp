// Case `kh`: the linear growth of the Kelvin-Helmholtz instability from smooth initial conditions
// (McNally, Lyra & Passy 2012, ApJS 201, 18): the periodic unit box in 2D, rho 1 and 2, shear
// +-0.5 joined by piecewise exponentials of width L = 0.025 at y = 1/4 and 3/4, p0 = 2.5, gamma
// 5/3, seed v_y = 0.01 sin(4 pi x) (kh_setup.hpp). The error is the growth rate of McNally et al.'s
// mode amplitude M(t) fitted over the linear window, against the same fit to the linear evolution
// of the same seed (reference/kh_linear), whose late slope is the smooth profile's unstable
// eigenvalue (2.8319 at the paper's values; the vortex sheet would give 5.58, the interface width
// halves it).
#include <algorithm>
#include <cmath>
#include <string>

#include "verification/case.hpp"
#include "verification/cases/extreme_hydro.hpp"
#include "verification/cases/kh_errors.hpp"
#include "verification/cases/kh_setup.hpp"
#include "verification/cases/kh_snapshots.hpp"
#include "verification/cases/radial_result.hpp"
#include "verification/sweep.hpp"

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
  const sph::HydroOutcome out = extreme::evolve_gas(p, sph::unit_box<2>(true), m, hooks);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"alpha", m.alpha}};
  if (r.verdict != "stable") return r;
  kh::growth_result(r, prm, kh::fit_growth(ts, Ms, prm.real("t_fit_lo"), prm.real("t_fit_hi")), ts, Ms);
  double h = 0.0;
  for (double hi : p.h) h += hi / p.size();
  r.extra["h_mean"] = h;
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
  if (double(n) * n > p.real("max_particles"))
    throw InputError("kh: n = " + std::to_string(n) + " means " + std::to_string(n * n) +
                     " particles, above max_particles (raise it)");
}

// The growth error's largest value measured on the variant's quick and standard levels (alpha =
// 1: 0.311, 0.369, 0.387 at n = 32, 64, 96; alpha = 0: 0.393, 0.692, 0.798); the gate holds each
// level at 1.5 times it. Not a convergence claim (kh_orders): a loose bound, which a fault that
// stops the growth or doubles it crosses; the exact check of the measurement is M0.
double growth_measured(const Params& p) { return p.real("alpha") > 0.0 ? 0.387 : 0.798; }

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
                 "levels (kh.cpp; no convergence claimed)", Check::Kind::verification, "growth"});
  });
}

// No order: the error has no convergent limit at fixed h/dx here. Two parts of the scheme's
// error do not shrink with n at a fixed neighbour number: on the square lattice the linearised
// pressure force carries the kernel's lattice sums (sound_wave_errors.hpp: sound runs 4.8 % fast
// in 2D at h/dx = 2.4, whatever n), and as the layers shear the lattice past itself, the
// zeroth-order inconsistency of the SPH gradient (McNally et al. 2012, section 6) leaves a
// pressure-gradient noise of order p0 / h times a lattice error that no n removes (convergence
// needs the neighbour number to grow with n: Zhu, Hernquist & Li 2015, ApJ 800, 6). Both act on
// the pressure perturbation that drives the growth, a few 1e-3 of p0 here. Measured: alpha = 0,
// rates 1.79, 0.91, 0.60 at n = 32, 64, 96 (1.41 at 128 before u was set from the summation
// density) against the linear evolution's 2.95; alpha = 1, 2.03, 1.86, 1.81, with M falling to
// a tenth of the linear evolution's by t = 0.6 (the viscosity damps the seed) before it grows. The fitted rate
// wanders with n and stays far below; the zero of the 2D lattice floor (h/dx = 2.7515,
// hmode=fixed) gives 0.80, 1.58 at n = 32, 64, no better, nor does h/dx = 3 (M saturates by
// t = 0.8) or a wider layer (L = 0.05: errors 0.29, 0.57).
OrderClaims kh_orders(const Params&) {
  OrderClaims c;
  c["growth"] = no_order(
      "no convergent limit at fixed h/dx: the growth rates {extra.growth_rate} at {levels} against the linear "
      "evolution's {extra.growth_rate_ref} (eigenvalue {extra.growth_rate_eigen}); the linearised pressure force "
      "carries the square lattice's kernel sums and the shearing lattice the SPH gradient's zeroth-order error, "
      "neither shrinking with n at a fixed neighbour number, and both acting on the pressure perturbation that "
      "drives the growth (kh.cpp)");
  return c;
}

// Standard stops at n = 96: n = 128 costs about a minute of CPU a variant.
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
      return ps;
    }(),
    .levels = levels,
    .orders = kh_orders,
    .error_defs = kh::error_defs,
    .variants = {{}, {"alpha=0"}},
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = kh::scorer(),
    .ic = kh::initial_conditions,
}};

}  // namespace
}  // namespace sphv::kh_case
