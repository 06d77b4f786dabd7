// Case `sound_wave`: a linear acoustic wave travelling along x through the periodic unit box in
// 1D, 2D and 3D, the one smooth flow of the whole hydro scheme (summation density (27), ideal gas,
// Euler (23), energy (38), leapfrog, artificial viscosity (44)-(48)). rho0 = 1, c_s = 1 (p0 = 3/5
// at gamma 5/3), one wavelength across the box, run for one period L / c_s = 1. Independent
// reference: reference/sound_wave (the linear travelling wave, exact to first order in A).
//
// Amplitude A = 3e-8. The reference neglects the wave's steepening, of relative size
// (gamma + 1)/2 A k c_s t = 8.4 A after a period (reference::AcousticWave::nonlinear_error), so A
// must be small; round-off bounds it from below (the velocity's round-off is ~1e-13 of c_s and
// overtakes the error beyond n = 128 in 1D, so the 1D levels stop there). At 3e-8 the estimate,
// 2.5e-7, is below a tenth of every level's L1_v (a gate at each level). validate refuses an A
// whose estimate exceeds 1 % of the amplitude at t_end.
//
// Smoothing length fixed (hmode=fixed) at the (50) value of the initial state: the solve of (50)
// in every density phase stops once h fits it to 1e-3, a density noise ~1e-3 far above the wave. Courant number C = 0.1: at the hydro cases' 0.3 the leapfrog's phase error cancels
// most of the kernel's in 1D, and an order measured on a cancellation is not the scheme's; at 0.1
// the spatial error dominates.
//
// Without viscosity (alpha = 0, the default here) the scheme is second order in h at fixed h/dx
// for a smooth flow, with one exception: on a cubic lattice the linearised pressure force carries
// the kernel's lattice sums, and the long wave runs at c_lattice = c_s sqrt(S1^2 + (2/gamma)
// (S2/2 - S1^2)) (sound_wave/errors.hpp), not c_s, whatever n: a phase-speed floor of the method
// at fixed h/dx, which L1_v reaches at about 4 |c_lattice / c_s - 1|. It is exactly 1 in 1D at
// h/dx = 2 and 4 (the default hfact = 2) and 1.0003 in 3D at 2.4: those variants verify order 2
// (a gate checks the floor stays below half of L1_v at every level). In 1D at 2.4 (1.031) and in
// 2D at 2.4 (1.048) the floor holds L1_v at a few per cent: known failures, the measured phase
// speed gated against the lattice prediction. In 2D the floor has a zero near h/dx = 2.7515; (50)
// iterated to its 1e-3 tolerance lands at h/dx = 2.751446 from hfact = 2.7536 at every n (a
// lattice), where the floor is 1 + 8.6e-6: that variant verifies order 2 in 2D. Without viscosity
// the square lattice's transverse modes grow from round-off and swamp the wave beyond n = 64, so
// its levels stop at 64.
// The kernel comparison (report) runs in 1D at h/dx = 6, where the cubic, the quintic and
// Wendland C6 have floors below 1e-4 (1 - 4e-6, 1, 1 - 8.2e-5) and verify order 2. The other three
// kernels have no common h/dx without a floor here (at 6: quartic 0.99591, Wendland C2 0.95846, C4
// 1.00156; at 2, every kernel but the cubic is 10-35 % off), and a floor of the smoothing error's
// size cancels part of it, which the floor gates below do not model: they are not variants.
// With the default viscosity (alpha = 1, beta = 2) the wave is damped at the rate nu k^2 / 4,
// nu ~ alpha c_s h, that the continuum limit of (45) predicts (sound_wave/errors.hpp derives it):
// first order in h, the price of the viscosity in a smooth flow; the measured rate converges to
// the prediction at first order.
// scheme=gradh_switches (sph/schemes/gradh_switches.hpp, hmode=iterate50, its only h rule): with
// alpha = 0 (the switch's alpha_max, so no viscosity) its grad-h forces and artificial conduction
// keep the chapter's order 2 (measured L1_v 2.52e-3, 6.26e-4, 1.56e-4 at n = 32, 64, 128: 2.01,
// 2.00). With alpha = 1 the switch starts at alpha_max and decays over tau ~ h / c, so the wave's
// damping is not the constant-alpha rate nu k^2 / 4 (its Gamma measured at 0.31, 0.19, 0.12 of it)
// and L1_v falls at 1.68, 1.72 over those levels, short of the order 2 the decay suggests: no
// claim there yet.
// The measured series behind these statements: docs/cases/sound_wave.md; the current numbers: the
// report's page of the case.
#include <cmath>
#include <string>

#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/cases/sound_wave/errors.hpp"
#include "verification/cases/sound_wave/snapshots.hpp"
#include "verification/cases/sound_wave/setup.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::sound_wave_case {
namespace {

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  extreme::Method m = extreme::method(prm);
  m.controls.t_end = prm.real("t_end");
  m.h_max = 0.45;  // below half the periodic box
  const reference::AcousticWave w = sound_wave::wave(prm);
  sph::Particles<D> p = sound_wave::initial_particles<D>(prm);
  const std::string kernel = prm.text("kernel");
  const sph::Box<D> box = sph::unit_box<D>(true);
  const sph::HydroOutcome out =
      extreme::evolve_gas_kernel<D>(kernel, p, box, m);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"dim", D}, {"A", prm.real("A")}, {"alpha", m.alpha},
             {"kernel", kernel}};
  if (r.verdict != "stable") return r;
  const sound_wave::Fundamental f = sound_wave::measure<D>(r, p.x, p.v, p.m, p.rho, out.t, w, prm.real("A"), n);
  const double h = extreme::mean_h(p);
  r.extra["h_mean"] = h;
  // The floor at the run's own h/dx: (50) sets the initial h (kept fixed) to its tolerance, 1e-3.
  r.extra["h_over_dx"] = h * n;
  double rate = 0.0;
  sph::with_kernel<D>(kernel, [&](auto k) {
    using K = decltype(k);
    r.extra["phase_speed_lattice"] = sound_wave::lattice_phase_speed_ratio<D, K>(h * n, m.gamma);
    // sph::ArtificialViscosity's eps and h_scale as extreme::evolve_gas sets them.
    rate = sound_wave::viscous_damping_rate<D, K>(m.alpha, w.sound_speed(), h, 1.0 / n, 0.01, 0.5, w.wave_number());
  });
  if (m.alpha > 0.0 && out.t > 0.0) {
    const double measured = -std::log(f.amplitude) / out.t;
    r.errors["damping"] = std::abs(measured / rate - 1.0);
    r.functionals["damping_rate"] = measured;
    r.extra["damping_rate_predicted"] = rate;
    r.extra["damping_ratio"] = measured / rate;
  }
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

Result run(const Params& p) { return by_dimension(p, [&](auto d) { return run_dim<d>(p); }); }

void validate(const Params& p) {
  const long d = p.integer("dim"), n = p.integer("n");
  if (d < 1 || d > 3) throw InputError("sound_wave: dim must be 1, 2 or 3");
  if (n < 8) throw InputError("sound_wave: need n >= 8 particles per wavelength");
  const double A = p.real("A"), t_end = p.real("t_end");
  if (!(A > 0.0)) throw InputError("sound_wave: the amplitude A must be > 0, got " + p.text("A"));
  if (!(t_end >= 0.0)) throw InputError("sound_wave: t_end must be >= 0 (0: score an initial state)");
  const double nl = sound_wave::wave(p).nonlinear_error(t_end);
  if (!(nl <= 0.01))
    throw InputError("sound_wave: A = " + p.text("A") + " is not a linear wave by t_end = " + p.text("t_end") +
                     ": its steepening, (gamma + 1)/2 A k c_s t = " + std::to_string(nl) +
                     " of the amplitude, exceeds 1 % (lower A; the reference is the linear wave)");
  if (p.text("kernel") != "cubic_spline" && (p.text("hmode") == "rate53" || p.text("energy") != "38"))
    throw InputError("sound_wave: kernel=" + p.text("kernel") + " runs with hmode=fixed or iterate50, energy=38 only");
  if (std::pow(double(n), double(d)) > p.real("max_particles"))
    throw InputError("sound_wave: n = " + std::to_string(n) + " in " + std::to_string(d) + "D means " +
                     std::to_string(static_cast<long>(std::pow(double(n), double(d)))) +
                     " particles, above max_particles (raise it)");
}

// Whether the lattice-sum floor of the phase speed (lattice_phase_speed_ratio) at this h/dx is
// above 0.1 %: then L1_v levels off at about 4 |c_lattice / c_s - 1| (a phase error of
// 2 pi |c_lattice / c_s - 1| after a period) and the order claim is a known failure.
bool floored(const Params& p) {
  return by_dimension(p, [&](auto d) {
    bool off = false;
    sph::with_kernel<d>(p.text("kernel"), [&](auto k) {
      off = std::abs(sound_wave::lattice_phase_speed_ratio<d, decltype(k)>(p.real("hfact"), p.real("gamma")) - 1.0) > 1e-3;
    });
    return off;
  });
}

// The errors at the coarsest quick level of each catalogue variant (measured at A = 3e-8,
// C = 0.1; they fall with n where an order is verified): bounds at 1.5 times these hold at every
// level. Where the lattice floors L1_v it stays level: the largest value measured on the quick
// and standard levels instead (docs/cases/sound_wave.md).
double l1_measured(const Params& p) {
  const long d = p.integer("dim");
  if (p.real("alpha") > 0.0) return d == 1 ? 0.0875 : d == 2 ? 0.20 : 0.301;
  if (floored(p)) return d == 1 ? 0.125 : d == 2 ? 0.19 : 0.25;
  if (d == 1 && p.real("hfact") == 6.0) {  // the kernel comparison (n = 32)
    const std::string k = p.text("kernel");
    return k == "quintic_spline" ? 6.05e-2 : k == "wendland_c6" ? 5.59e-2 : 8.48e-2;
  }
  return d == 1 ? 2.30e-3 : d == 2 ? 1.73e-2 : 0.236;
}
double damping_measured(const Params& p) {
  const long d = p.integer("dim");
  return d == 1 ? 0.0584 : d == 2 ? 0.1 : 0.194;
}

std::vector<Check> gates(const Sweep& s) {
  const Params prm = find_case(s.case_name).parse(s.settings);
  const bool floor = floored(prm);
  const double l1_bound = 1.5 * l1_measured(prm), damping_bound = 1.5 * damping_measured(prm);
  return radial::per_level(s, [&](const std::string& level, const Result& r, std::vector<Check>& c) {
    const double l1 = r.errors.at("L1_v");
    c.push_back({level + "_L1_v", l1, 0.0, l1_bound,
                 "L1_v below 1.5 times its value measured at the variant's coarsest quick level (sound_wave.cpp)",
                 Check::Kind::drift, "L1_v"});
    // The reference's neglected steepening against the measured error: at most a tenth of it.
    c.push_back({level + "_linear", r.extra.value("nonlinear_error_estimate", 0.0) / l1, 0.0, 0.1,
                 "the linear reference's neglected steepening (gamma + 1)/2 A k c_s t at most a tenth of L1_v",
                 Check::Kind::verification, "L1_v"});
    // A wave along x moves no particle across, but without viscosity the square lattice's
    // transverse modes grow from round-off: measured 0.011 of the amplitude at 2D n = 64 (hfact
    // 2.75), below 1e-5 elsewhere; bound 0.05 (margin 4.5).
    c.push_back({level + "_transverse_v", r.extra.value("transverse_v_max", 1.0), 0.0, 0.05,
                 "max |v_y|, |v_z| / (A c_s): the wave stays planar (no transverse motion beyond round-off's growth)",
                 Check::Kind::verification, "L1_v"});
    const double lat = r.extra.value("phase_speed_lattice", 1.0), meas = r.extra.value("phase_speed_ratio", 1.0);
    if (floor)
      // The floor is the lattice's: the measured phase speed within a fifth of the predicted offset
      // (measured 1D hfact 2.4: 1.0281 and 1.0305 at n = 32, 64 against 1.0308).
      c.push_back({level + "_phase_speed_lattice", std::abs(meas - lat) / std::abs(lat - 1.0), 0.0, 0.2,
                   "the phase speed where the lattice sums put it, c_lattice / c_s (sound_wave/errors.hpp)",
                   Check::Kind::verification, "L1_v"});
    else
      // The claimed order needs the floor, ~4 |c_lattice / c_s - 1| in L1_v, below the error.
      c.push_back({level + "_lattice_floor", 4.0 * std::abs(lat - 1.0) / l1, 0.0, 0.5,
                   "the lattice-sum floor 4 |c_lattice / c_s - 1| at most half of L1_v: the order is the scheme's, "
                   "not the floor's", Check::Kind::verification, "L1_v"});
    if (r.errors.count("damping"))
      c.push_back({level + "_damping", r.errors.at("damping"), 0.0, damping_bound,
                   "the viscous decay rate within 1.5 times its error measured at the coarsest quick level of its "
                   "prediction nu k^2 / 4", Check::Kind::drift, "damping"});
  });
}

OrderClaims sound_orders(const Params& p) {
  const std::string floor =
      "lattice-sum floor at h/dx = hfact: the wave runs at {extra.phase_speed_ratio} c_s at {levels}, where the "
      "linearised scheme's lattice sums predict {extra.phase_speed_lattice} (sound_wave/errors.hpp), whatever n; L1_v "
      "levels off at about 4 |c / c_s - 1|";
  OrderClaims c;
  if (p.real("alpha") == 0.0) {
    // Band: measured 2.01, 2.00 (1D, n = 32..128) and 2.01, 2.02 (3D, n = 8..24) at C = 0.1; 0.3
    // leaves room for the lattice floor's and the round-off's shares at the finest levels (the
    // gates hold both below half and a tenth of L1_v).
    const std::string why = "a smooth flow without viscosity: the kernel's smoothing error O((k h)^2) (a symmetric kernel) "
                            "and the leapfrog's O((omega dt)^2), dt ~ h, at fixed h/dx and C: second order in h ~ 1/n "
                            "(C small enough that the two phase errors, of opposite sign, do not cancel)";
    const long d = p.integer("dim");
    c["L1_v"] = floored(p) ? known_failure(2.0, 0.3, floor, d == 1 ? "hfact=2" : d == 2 ? "dim=2,hfact=2.7536" : "dim=3,hfact=2.4")
                           : OrderClaim{2.0, 0.3, why};
    return c;
  }
  if (p.text("scheme") != sph::ChapterScheme::name)
    return {{"L1_v", no_order("a viscosity switch (sph/schemes/): neither the constant-alpha damping nor the inviscid "
                              "order; measured 1.68, 1.72 at n = 32..128 for gradh_switches (pre-asymptotic)")}};
  // Band 0.2: measured 0.94, 0.99 (1D, 3D standard), the damping's own first-order correction.
  const std::string why = "the viscosity's damping nu k^2 / 4, nu ~ alpha c_s h (sound_wave/errors.hpp), dominates "
                          "the error: first order in h ~ 1/n";
  c["L1_v"] = floored(p) ? known_failure(1.0, 0.2, floor, "alpha=1,dim=1,hfact=2") : OrderClaim{1.0, 0.2, why};
  // Band 0.25: measured 0.90 (1D) and 1.00 (3D) on the standard levels.
  c["damping"] = {1.0, 0.25, "the measured decay rate against its k h -> 0 limit on the run's lattice: the next terms "
                             "(the switch (45) changes sign with dv/dx over a band ~h wide, and the third derivative "
                             "of v in the pair sum) are O(h) relative: first order"};
  return c;
}

// Levels: 1D two in quick, three in standard and full (at A = 3e-8 round-off reaches the error
// beyond n = 128). 2D/3D up to the lattice floor's reach.
const Levels levels = {.quick = {32, 64}, .standard = {32, 64, 128}, .full = {32, 64, 128}};

const Registration reg{Case{
    .name = "sound_wave",
    .summary = "linear acoustic wave (1D/2D/3D), periodic box: v_x after a period against the linear wave; second "
               "order without viscosity; with viscosity, its damping rate against the continuum rate at first order",
    .n_counts = "particles per wavelength (per side of the periodic unit box)",
    .tags = {"gate", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 32, "particles per wavelength (the box's side)"),
                                   integer_param("dim", 1, "dimension 1, 2 or 3 (the wave along x)"),
                                   real_param("A", 3e-8, "relative density amplitude (linear: (gamma+1)/2 A k c_s t_end <= 1 %)"),
                                   real_param("rho0", 1.0, "background density", 0.0),
                                   real_param("c_s", 1.0, "adiabatic sound speed (p0 = rho0 c_s^2 / gamma)", 0.0),
                                   real_param("t_end", 1.0, "end time (one period at c_s = 1)"),
                                   real_param("max_particles", 2e5, "refuse runs with more particles than this", 0.0),
                                   choice_param("kernel", "cubic_spline",
                                                "the kernel (sph/kernel/kernels.hpp); other than cubic_spline: "
                                                "hmode=fixed or iterate50, energy=38", sph::kernel_names())};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.0)) ps.push_back(q);
      for (auto& q : ps)
        if (q.name == "alpha") q.default_value = "0";
        else if (q.name == "hmode") q.default_value = "fixed";
        else if (q.name == "C") q.default_value = "0.1";
      return ps;
    }(),
    .levels = levels,
    .orders = sound_orders,
    .error_defs = sound_wave::error_defs,
    .variants = {{}, {"dim=3", "hfact=2.4"}, {"dim=2", "hfact=2.4"}, {"dim=2", "hfact=2.7536"}, {"hfact=2.4"},
                 {"alpha=1"}, {"alpha=1", "dim=3", "hfact=2.4"},
                 {"hfact=6"}, {"hfact=6", "kernel=quintic_spline"}, {"hfact=6", "kernel=wendland_c6"},
                 {"scheme=gradh_switches", "hmode=iterate50"}},
    .levels_for = [](const Params& p) {
      const long d = p.integer("dim");
      if (d == 2 && !floored(p)) return Levels{.quick = {32, 48}, .standard = {32, 48, 64}, .full = {32, 48, 64}};
      if (d == 2) return Levels{.quick = {32, 64}, .standard = {32, 64, 96}, .full = {32, 64, 96}};
      if (d == 3) return Levels{.quick = {8, 16}, .standard = {8, 16, 24}, .full = {8, 16, 24, 32}};
      return levels;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = sound_wave::scorer(),
    .ic = sound_wave::initial_conditions,
}};

}  // namespace
}  // namespace sphv::sound_wave_case
