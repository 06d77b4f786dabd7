// Case `evrard`: the adiabatic collapse of a cold gas sphere (Evrard 1988) in 3D, SPH with
// self-gravity from the Barnes-Hut tree (sph/gravity/self_gravity.hpp) as a scene term.
// G = M = R = 1, rho(r) = M / (2 pi R^2 r), u = 0.05 G M / R, at rest. The sphere falls in,
// bounces at t ~ 1 and an outgoing shock heats it (virialisation). Errors: conservation of the
// total energy E = E_kin + E_th + W through the bounce, the energy curves against an independent
// 1D spherical Lagrangian solver (reference/evrard_lagrangian), sampled at common times, and the
// profiles of density, radial velocity and u at t_end against that solver's (evrard/errors.hpp,
// which `sphv score evrard` shares).
#include <algorithm>
#include <cmath>

#include "reference/interpolate.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/common/gas_self_gravity.hpp"
#include "verification/cases/evrard/errors.hpp"
#include "verification/cases/evrard/snapshots.hpp"
#include "verification/cases/evrard/setup.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::evrard_case {
namespace {

// Energy curves of the SPH run, one entry per recorded state.
struct Curves {
  std::vector<double> t, kinetic, thermal, potential;
  void add(const sph::Particles<3>& p, double time, double w) {
    double k = 0.0, u = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) k += 0.5 * p.m[i] * p.v[i].squaredNorm(), u += p.m[i] * p.u[i];
    t.push_back(time), kinetic.push_back(k), thermal.push_back(u), potential.push_back(w);
  }
  double total(std::size_t k) const { return kinetic[k] + thermal[k] + potential[k]; }
  // Linear interpolation in time (the SPH steps are much finer than the sample spacing).
  double at(const std::vector<double>& c, double s) const { return reference::interpolate_linear(t, c, s); }
};

Result run(const Params& prm) {
  extreme::Method m = extreme::method(prm);
  m.controls.t_end = prm.real("t_end");
  m.h_max = 2.0;  // the sphere's diameter: an escaping particle's h stops growing there
  const double u0 = prm.real("u0");
  if (radial::centre<3>(prm) != sph::Vec<3>::Zero())
    throw InputError("evrard: centre is for scoring snapshots (sphv score); sphv run puts the sphere at the origin");
  sph::SelfGravity gravity{{prm.real("theta"), prm.real("eps"), 1.0, sph::Multipole::quadrupole,
                            sph::Opening::robust},
                           {}};
  sph::Particles<3> p = evrard::sphere(prm.integer("n"), u0, m.hfact);
  const sph::Box<3> box = sph::unit_box<3>(false);

  Curves sph_e;
  double w_min = 0.0;
  std::vector<double> r_comp, rho_comp;
  double t_comp = 0.0;
  sph::HydroHooks<3> hooks;
  hooks.evaluated = [&](const sph::Particles<3>& q, const sph::Derivatives<3>&) {
    if (sph_e.t.empty()) sph_e.add(q, 0.0, gravity.potential_energy(q));  // the initial state
  };
  hooks.stepped = [&](const sph::Particles<3>& q, const sph::Derivatives<3>&, long, double t) {
    const double w = gravity.potential_energy(q);  // phi of the last evaluation: the state at t
    sph_e.add(q, t, w);
    if (w < w_min) w_min = w, t_comp = t, r_comp = extreme::radii(q), rho_comp = q.rho;
  };
  const sph::HydroOutcome out = extreme::evolve_gas(p, box, m, hooks, gravity);

  Result r;
  r.n_particles = p.size();
  r.verdict = out.verdict == "ok" ? "stable" : out.verdict;
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"t_end", m.controls.t_end}};
  if (out.verdict != "ok" || sph_e.t.empty()) return r;

  const int zones = static_cast<int>(prm.integer("zones"));
  const auto ref = evrard::reference_solution(zones, m.gamma, u0, m.controls.t_end);
  const auto ref_half = evrard::reference_solution(zones / 2, m.gamma, u0, m.controls.t_end);
  // Curve differences at the reference's output times, relative to |W(0)| = 2/3 G M^2 / R.
  const double scale = 2.0 / 3.0;
  struct Diff {
    double l1 = 0.0, max = 0.0;
  };
  auto diff = [&](const std::vector<double>& a, auto&& b) {
    Diff d;
    for (std::size_t k = 0; k < ref.t.size(); ++k) {
      const double e = std::abs(sph_e.at(a, ref.t[k]) - b(k)) / scale;
      d.l1 += e / ref.t.size(), d.max = std::max(d.max, e);
    }
    return d;
  };
  const Diff dk = diff(sph_e.kinetic, [&](std::size_t k) { return ref.kinetic[k]; });
  const Diff du = diff(sph_e.thermal, [&](std::size_t k) { return ref.thermal[k]; });
  const Diff dw = diff(sph_e.potential, [&](std::size_t k) { return ref.potential[k]; });
  double drift = 0.0;
  for (std::size_t k = 0; k < sph_e.t.size(); ++k)
    drift = std::max(drift, std::abs(sph_e.total(k) - sph_e.total(0)) / std::abs(sph_e.total(0)));
  // The reference's own discretisation error: zones against zones / 2, same measure.
  double ref_err = 0.0;
  for (std::size_t k = 0; k < ref.t.size(); ++k)
    for (auto [a, b] : {std::pair{&ref.kinetic, &ref_half.kinetic}, std::pair{&ref.thermal, &ref_half.thermal},
                        std::pair{&ref.potential, &ref_half.potential}})
      ref_err = std::max(ref_err, std::abs((*a)[k] - ref_half.at(*b, ref.t[k])) / scale);

  r.errors = {{"energy_conservation", drift}, {"kinetic_L1", dk.l1}, {"kinetic_max", dk.max},
              {"thermal_L1", du.l1},          {"thermal_max", du.max}, {"potential_L1", dw.l1},
              {"potential_max", dw.max}};
  evrard::measure_profiles(r, p.x, p.v, p.m, p.rho, p.u, ref.at_end, ref_half.at_end, out.t);
  const auto th_peak = std::max_element(sph_e.thermal.begin(), sph_e.thermal.end()) - sph_e.thermal.begin();
  r.functionals = {{"thermal_peak", sph_e.thermal[th_peak]}, {"potential_min", w_min}, {"t_max_compression", t_comp}};
  const auto ref_peak = std::max_element(ref.thermal.begin(), ref.thermal.end()) - ref.thermal.begin();
  r.extra["W0"] = sph_e.potential.front();
  r.extra["E0"] = sph_e.total(0);
  r.extra["thermal_peak_time"] = sph_e.t[th_peak];
  r.extra["reference"] = {{"zones", zones},
                          {"steps", ref.steps},
                          {"thermal_peak", ref.thermal[ref_peak]},
                          {"thermal_peak_time", ref.t[ref_peak]},
                          {"potential_min", *std::min_element(ref.potential.begin(), ref.potential.end())},
                          {"t_max_compression", ref.t_max_compression},
                          {"max_difference_to_half_zones", ref_err}};

  Figure fe{"energies", "Evrard collapse, N = " + std::to_string(p.size()) + ": energies, SPH and 1D Lagrangian",
            "t (sqrt(R^3 / G M))", "energy (G M^2 / R)", "linear", "linear", {}};
  const std::size_t stride = std::max<std::size_t>(1, sph_e.t.size() / 400);
  auto curve = [&](const std::string& label, const std::vector<double>& c) {
    Series s{"SPH " + label, {}, {}, "line"};
    for (std::size_t k = 0; k < sph_e.t.size(); k += stride) s.x.push_back(sph_e.t[k]), s.y.push_back(c[k]);
    return s;
  };
  std::vector<double> total(sph_e.t.size());
  for (std::size_t k = 0; k < total.size(); ++k) total[k] = sph_e.total(k);
  fe.series = {curve("E_kin", sph_e.kinetic), curve("E_th", sph_e.thermal), curve("W", sph_e.potential),
               curve("E_tot", total)};
  for (auto [label, c] : {std::pair{"E_kin", &ref.kinetic}, std::pair{"E_th", &ref.thermal},
                          std::pair{"W", &ref.potential}})
    fe.series.push_back({std::string("1D Lagrangian ") + label, ref.t, *c, "dashed"});
  r.figures.push_back(fe);

  Figure fp{"profile_rho", "Density at maximum compression (SPH t = " + std::to_string(t_comp) + ", 1D t = " +
                               std::to_string(ref.t_max_compression) + ")",
            "r (R)", "rho (M / R^3)", "log", "log", {}};
  Series pts{"SPH particles", {}, {}, "points"};
  const std::size_t ps = std::max<std::size_t>(1, r_comp.size() / 3000);
  for (std::size_t i = 0; i < r_comp.size(); i += ps)
    if (r_comp[i] > 0.0) pts.x.push_back(r_comp[i]), pts.y.push_back(rho_comp[i]);
  fp.series = {pts, {"1D Lagrangian", ref.r_profile, ref.rho_profile, "line"}};
  r.figures.push_back(fp);
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

void validate(const Params& p) {
  if (p.integer("n") < 100) throw InputError("evrard: need n >= 100 particles");
  if (p.integer("zones") < 20) throw InputError("evrard: need zones >= 20 for the 1D reference");
  if (p.real("theta") > 1.0) throw InputError("evrard: opening angle theta must be <= 1");
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const auto& r = s.runs[k];
    const std::string level = "n" + std::to_string(s.levels[k]);
    c.push_back({level + "_stable", double(r.verdict == "stable"), 1.0, 1.0,
                 "runs through the bounce to t_end with a finite, positive state"});
    if (r.verdict != "stable") continue;
    // Measured at n = 912 (theta 0.5, eps 0.01, rate53): max |E(t) - E(0)| / |E(0)| = 5.5e-4 (no grad-h
    // terms with (53), the tree force is not the exact gradient of the tree potential, time steps);
    // 4.0e-4 at n = 2176. Bound 2e-3 (margin ~4).
    c.push_back({level + "_energy_conservation", r.errors.at("energy_conservation"), 0.0, 2e-3,
                 "total energy through the bounce (measured 5.5e-4 at n = 912, margin ~4)", Check::Kind::drift,
                 "energy_conservation"});
    // Curve errors (L1 over t, relative to |W(0)|) against the 800-zone reference, measured at
    // n = 912: kinetic 0.182, thermal 0.325, potential 0.519 (the SPH bounce is softer: W_min -1.78
    // against -2.53). Bounds 1.5 x measured. A collapse without gravity or without a bounce fails them
    // (W would stay near -0.67 against a mean of about -1.6: potential_L1 ~ 1.4).
    for (const auto& [name, bound] : {std::pair{"kinetic_L1", 0.27}, std::pair{"thermal_L1", 0.49},
                                      std::pair{"potential_L1", 0.78}})
      c.push_back({level + "_" + name, r.errors.at(name), 0.0, bound,
                   "energy curve against the 1D Lagrangian reference (measured at n = 912, margin 1.5)",
                   Check::Kind::drift, name});
    // The curves' maxima over time and the profiles at t_end, measured at n = 912: kinetic_max
    // 0.349, thermal_max 1.214, potential_max 1.327; rho 0.847, v_r 0.101, u 0.127. Bounds 1.5 x
    // measured (the density profile's error falls: 0.690 at n = 2176, 0.370 at 4224).
    for (const auto& [name, bound] :
         {std::pair{"kinetic_max", 0.52}, std::pair{"thermal_max", 1.82}, std::pair{"potential_max", 2.0},
          std::pair{"rho_profile_L1", 1.27}, std::pair{"vr_profile_L1", 0.15}, std::pair{"u_profile_L1", 0.19}})
      c.push_back({level + "_" + name, r.errors.at(name), 0.0, bound,
                   "against the 1D Lagrangian reference (measured at n = 912, margin 1.5)", Check::Kind::drift,
                   name});
    // Peak thermal energy: 1.1-1.2 for published SPH runs with ~1e3-1e4 particles as quoted in the
    // task brief (Evrard 1988, Steinmetz & Mueller 1993, Springel 2005; not confirmed from a table);
    // measured here 1.15 at n = 912, 1.24 at 2176; the 1D reference peaks at 1.75 (800 zones, converging
    // upwards to ~1.76). The run must lie between a clearly bounced state (0.9) and just above the 1D value.
    c.push_back({level + "_thermal_peak", r.functionals.at("thermal_peak"), 0.9, 1.8,
                 "peak E_th between a bounced low-resolution SPH value and the converged 1D value"});
  }
  // More particles, closer curves (measured potential_L1: 0.519, 0.451 at n = 912, 2176).
  if (s.runs.size() >= 2 && s.runs.front().verdict == "stable" && s.runs.back().verdict == "stable")
    c.push_back({"potential_L1_decreases", s.runs.back().errors.at("potential_L1") / s.runs.front().errors.at("potential_L1"),
                 0.0, 1.0, "the finest level is closer to the reference than the coarsest", Check::Kind::verification,
                 "potential_L1"});
  return c;
}

const Registration reg{Case{
    .name = "evrard",
    .summary = "Evrard collapse (3D, self-gravity by tree): energy conservation; energy curves and end-time profiles "
               "against a 1D spherical Lagrangian solver",
    .n_counts = "particles in the sphere (the lattice with the nearest count: 912, 2176, 4224 are exact)",
    .tags = {"gate", "extreme", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 912, "particles (a cubic lattice of round((6 n / pi)^(1/3)) cells per diameter cut to the ball)"),
                                   real_param("theta", 0.5, "Barnes-Hut opening angle (89), robust criterion", 0.0),
                                   real_param("eps", 0.01, "Plummer softening (77), units of R", 0.0),
                                   real_param("t_end", 3.0, "end time, units of sqrt(R^3 / G M)", 0.0),
                                   real_param("u0", 0.05, "initial specific internal energy, units of G M / R", 0.0),
                                   integer_param("zones", 800, "zones of the 1D Lagrangian reference (compared with zones / 2 for its own error)"),
                                   radial::centre_param()};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      // Variable h by (53) here: as accurate on this case as (50) iterated and ~1.5x faster (the
      // iteration's grid searches dominate with the wide range of h in a collapsing sphere).
      for (auto& q : ps)
        if (q.name == "hmode") q.default_value = "rate53";
      return ps;
    }(),
    // Lattices of 12, 16, 20, 24, 32 cells per diameter (exact counts, so that the order fit sees
    // the real N). The cost grows ~N^(4/3) (more steps as h shrinks, tree N log N; times:
    // docs/cases/evrard.md). Quick: one level (bounds only); standard: the four smallest lattices
    // (a fit over the three smallest has too large a standard error to resolve the band); full: up
    // to 1.7e4 particles (publication size).
    .levels = {.quick = {912}, .standard = {912, 2176, 4224, 7208}, .full = {2176, 4224, 7208, 17256}},
    // Band 0.15 around 1/3: the energy curves and their maxima measure 0.31-0.36 on the standard
    // levels; the profiles' fits lie further off, within two standard errors of the band (the
    // bounce shock's smearing still falling faster, resp. slower, than its limit at these N;
    // docs/cases/evrard.md).
    .orders =
        [](const Params&) {
          const OrderClaim third{1.0 / 3.0, 0.15,
                                 "the bounce shock is smeared over a few h by the artificial viscosity: curve errors "
                                 "first order in h ~ N^(-1/3) at fixed hfact, i.e. order 1/3 in the particle number"};
          // The maxima over time and the profiles at t_end reach the 1D reference in the limit too:
          // the same smeared bounce shock sets their error.
          return OrderClaims{{"kinetic_L1", third}, {"thermal_L1", third}, {"potential_L1", third},
                             {"kinetic_max", third}, {"thermal_max", third}, {"potential_max", third},
                             {"rho_profile_L1", third}, {"vr_profile_L1", third}, {"u_profile_L1", third},
                             {"energy_conservation", no_order("conservation, not convergence: time-step and tree-force "
                                                              "error at fixed theta and eps, bounded at every level")}};
        },
    .error_defs = {{"energy_conservation", "max over t of |E(t) - E(0)| / |E(0)|, E = kinetic + thermal + potential"},
                   {"kinetic_L1", "mean over the reference's output times of |E_kin(t) - E_kin,ref(t)| / |W(0)|, W(0) = -2/3 G M^2/R"},
                   {"thermal_L1", "mean over the reference's output times of |E_th(t) - E_th,ref(t)| / |W(0)|"},
                   {"potential_L1", "mean over the reference's output times of |W(t) - W_ref(t)| / |W(0)|"},
                   {"kinetic_max", "max over the reference's output times of |E_kin(t) - E_kin,ref(t)| / |W(0)|"},
                   {"thermal_max", "max over the reference's output times of |E_th(t) - E_th,ref(t)| / |W(0)|"},
                   {"potential_max", "max over the reference's output times of |W(t) - W_ref(t)| / |W(0)|"},
                   {"rho_profile_L1", evrard::profile_error_defs.at("rho_profile_L1")},
                   {"vr_profile_L1", evrard::profile_error_defs.at("vr_profile_L1")},
                   {"u_profile_L1", evrard::profile_error_defs.at("u_profile_L1")},
                   {"mismatch", evrard::profile_error_defs.at("mismatch")}},
    .variants = {{}},
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = evrard::scorer(),
    .ic = evrard::initial_conditions,
}};

}  // namespace
}  // namespace sphv::evrard_case
