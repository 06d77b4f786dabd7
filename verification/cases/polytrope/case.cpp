// Case `polytrope`: the n = 1 polytrope in hydrostatic equilibrium (3D), SPH with self-gravity
// from the Barnes-Hut tree (sph/gravity/self_gravity.hpp) as a scene term, as in `evrard`.
// Units G = M = R = 1 (K = 2 / pi). Independent reference: reference/polytrope (the Lane-Emden
// solution of index 1, rho = rho_c sin(pi r / R) / (pi r / R)).
//
// The star starts at rest on the analytic profile (a stretched lattice, polytrope/setup.hpp),
// without a relaxation: the errors are those of the scheme's evolution of the exact equilibrium.
// It is off the scheme's own equilibrium (the kernel's smoothing, the softening, the truncated
// kernel at the surface), so the star rings; the central density's drift measures that swing, and
// it shrinks with N. A damped relaxation before the free evolution (v damped on 0.2 t_dyn for
// 2 t_dyn, p = K rho^2 kept) gives a larger rho_profile_L1 at every N measured and a drift that
// does not fall with N, so there is none.
// Softening eps = eps_dx (m / rho_c)^(1/3), a fixed fraction of the central spacing, so that it
// converges with N like h.
//
// Pressure: the chapter's ideal gas with gamma = 2 and u = K rho (p = (gamma - 1) rho u = K rho^2),
// not the polytropic equation of state (35): the same gas + self-gravity scene as evrard's (no
// new scene to compile), and the state other codes start from (SWIFT, Phantom and SPH-EXA evolve
// u): an adiabatic flow keeps p / rho^2 = K, and only the viscosity's heating, where the star
// rings, moves it.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "verification/harness/case.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/common/gas_self_gravity.hpp"
#include "verification/cases/polytrope/errors.hpp"
#include "verification/cases/polytrope/setup.hpp"
#include "verification/cases/polytrope/snapshots.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::polytrope_case {
namespace {

sph::Vec<3> centre_of_mass(const sph::Particles<3>& p) {
  sph::Vec<3> c = sph::Vec<3>::Zero();
  double m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) c += p.m[i] * p.x[i], m += p.m[i];
  return c / m;
}

Result run(const Params& prm) {
  extreme::Method m = extreme::method(prm);
  m.controls.t_end = prm.real("t_end");
  const reference::Polytrope1 star = polytrope::star(prm);
  if (radial::centre<3>(prm) != sph::Vec<3>::Zero())
    throw InputError("polytrope: centre is for scoring snapshots (sphv score); sphv run puts the star at the origin");
  m.h_max = 2.0 * star.radius();  // the star's diameter: an escaping particle's h stops growing there
  sph::Particles<3> p = polytrope::sphere(prm.integer("n"), star, m.gamma, m.hfact);
  const sph::Box<3> box = sph::unit_box<3>(false);
  // The central spacing (m / rho_c)^(1/3) sets the softening, so that it shrinks with N.
  const double spacing = std::cbrt(p.m[0] / star.central_density());
  const double eps = prm.real("eps_dx") * spacing;
  sph::SelfGravity gravity{{prm.real("theta"), eps, star.G(), sph::Multipole::quadrupole, sph::Opening::robust}, {}};
  // u from the summation density (27) of the initial h iteration: p = K rho_i^2 with the density
  // the pressure force sees, not the profile's (they differ by the kernel's smoothing).
  try {
    sph::smoothing_length_iterate(p, box, sph::SmoothingLengthControl{m.hfact, m.h_max});
  } catch (const std::invalid_argument& e) {  // a verdict, as evolve_gas gives it
    return radial::start(p.size(), {0, 0.0, std::string("unstable: initial smoothing length: ") + e.what()});
  }
  for (std::size_t i = 0; i < p.size(); ++i) p.u[i] = star.K() * p.rho[i] / (m.gamma - 1.0);

  // Radii from the origin, where the star was set up (and sphv score's centre of a snapshot at its
  // box's middle): the centre of mass stays there but for the tree force's momentum error, which
  // extra.centre_of_mass_offset reports.
  const sph::Vec<3> origin = sph::Vec<3>::Zero();
  std::vector<double> t_rec, rho_in;
  auto record = [&](const sph::Particles<3>& q, double t) {
    t_rec.push_back(t);
    rho_in.push_back(polytrope::inner_density(polytrope::radii(q.x, origin), q.m, q.rho, polytrope::inner_mass_fraction));
  };
  sph::HydroHooks<3> hooks;
  hooks.evaluated = [&](const sph::Particles<3>& q, const sph::Derivatives<3>&) {
    if (t_rec.empty()) record(q, 0.0);
  };
  hooks.stepped = [&](const sph::Particles<3>& q, const sph::Derivatives<3>&, long, double t) { record(q, t); };
  const sph::HydroOutcome out = extreme::evolve_gas(p, box, m, hooks, gravity);

  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"t_end", m.controls.t_end}, {"eps", eps},
             {"spacing_centre", spacing}};
  if (r.verdict != "stable" || rho_in.empty()) return r;
  r.extra["centre_of_mass_offset"] = centre_of_mass(p).norm();
  polytrope::measure(r, polytrope::radii(p.x, origin), p.m, p.rho, star.K(), star.G(), out.t);
  double drift = 0.0;
  for (double v : rho_in) drift = std::max(drift, std::abs(v / rho_in.front() - 1.0));
  r.errors["central_density_drift"] = drift;
  r.extra["rho_inner_start"] = rho_in.front();
  double u_max_ratio = 0.0;  // the largest p / (K rho^2) - 1: the heating that moved the polytropic law
  for (std::size_t i = 0; i < p.size(); ++i)
    u_max_ratio = std::max(u_max_ratio, std::abs((m.gamma - 1.0) * p.u[i] / (star.K() * p.rho[i]) - 1.0));
  r.extra["entropy_change_max"] = u_max_ratio;

  Figure fc{"central_density", "Mean density of the inner tenth of the mass against time, N = " + std::to_string(p.size()),
            "t (sqrt(R^3 / G M))", "rho_in / rho_in,ref", "linear", "linear", {}};
  Series s{"SPH", {}, {}, "line"}, ref{"n = 1 Lane-Emden", {}, {}, "dashed"};
  const double in_ref = star.mean_density_within_mass_fraction(polytrope::inner_mass_fraction);
  const std::size_t stride = std::max<std::size_t>(1, t_rec.size() / 400);
  for (std::size_t k = 0; k < t_rec.size(); k += stride) s.x.push_back(t_rec[k]), s.y.push_back(rho_in[k] / in_ref);
  ref.x = {0.0, out.t}, ref.y = {1.0, 1.0};
  fc.series = {s, ref};
  r.figures.push_back(fc);
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

void validate(const Params& p) {
  if (p.integer("n") < 100) throw InputError("polytrope: need n >= 100 particles");
  if (p.real("gamma") != 2.0)
    throw InputError("polytrope: gamma = " + p.text("gamma") + ": the n = 1 polytrope needs gamma = 2 (p = K rho^2 "
                     "with u = K rho)");
  if (!(p.real("K") > 0.0) || !(p.real("G") > 0.0)) throw InputError("polytrope: K and G must be > 0");
  if (p.real("theta") > 1.0) throw InputError("polytrope: opening angle theta must be <= 1");
  if (!(p.real("t_end") >= 0.0)) throw InputError("polytrope: t_end must be >= 0 (0: score an initial state)");
}

// Bounds at 1.5 times the errors measured at the coarsest quick level, N = 552 (they fall with N):
// rho_profile_L1 0.0410, central_density_drift 0.0832 (the analytic start rings the star; the
// drift is the swing's first maximum).
std::vector<Check> gates(const Sweep& s) {
  return radial::per_level(s, [&](const std::string& level, const Result& r, std::vector<Check>& c) {
    c.push_back({level + "_rho_profile_L1", r.errors.at("rho_profile_L1"), 0.0, 1.5 * 0.0410,
                 "density profile against the n = 1 Lane-Emden solution (measured 0.0410 at N = 552, margin 1.5)",
                 Check::Kind::drift, "rho_profile_L1"});
    c.push_back({level + "_central_density_drift", r.errors.at("central_density_drift"), 0.0, 1.5 * 0.0832,
                 "central density stays within its first swing (measured 0.0832 at N = 552, margin 1.5)",
                 Check::Kind::drift, "central_density_drift"});
    // The star stays whole: its outermost particle within 1.2 R (measured at most 1.066 R on
    // N = 552..4224: the surface layer rings; the bound is 3 times the largest excursion).
    c.push_back({level + "_bound", r.extra.value("r_max_over_R", 1e9), 0.0, 1.2,
                 "outermost particle within 1.2 R at t_end: the star neither expands nor sheds its surface",
                 Check::Kind::verification, "rho_profile_L1"});
  });
}

OrderClaims orders(const Params&) {
  // Band 0.15: the fit measures 0.67 +- 0.01 on the standard levels, 0.59 +- 0.04 on the full
  // tier's, whose last step falls short of 2/3 (docs/cases/polytrope.md): a floor (the fixed
  // opening angle, the (50) iteration's tolerance) or a pre-asymptotic range that the full tier
  // does not resolve.
  const OrderClaim profile{
      2.0 / 3.0, 0.15,
      "the kernel's smoothing error O(h^2) inside and, at the surface where rho falls linearly to 0, an O(1) relative "
      "error over a layer of thickness ~h holding a mass fraction O(h^2): second order in h ~ N^(-1/3) at fixed hfact "
      "and eps / spacing, order 2/3 in the particle number"};
  // Band 0.15: the fit measures 0.30 +- 0.02 on the standard levels, 0.21 +- 0.01 on the full
  // tier's, inside the band but falling (docs/cases/polytrope.md): the full tier is where this
  // claim would fail first.
  const OrderClaim drift{
      1.0 / 3.0, 0.15,
      "the star starts on the analytic profile, off the scheme's own equilibrium by the smoothing and softening "
      "errors and, first in h, by the surface layer's displacement: it rings with an amplitude first order in "
      "h ~ N^(-1/3), order 1/3 in the particle number"};
  return {{"rho_profile_L1", profile}, {"central_density_drift", drift}};
}

const Registration reg{Case{
    .name = "polytrope",
    .summary = "n = 1 polytrope in hydrostatic equilibrium (3D, self-gravity by tree): density profile and central "
               "density against the Lane-Emden solution after several dynamical times",
    .n_counts = "particles in the star (the lattice with the nearest count: 552, 1189, 2176, 4224, 7208 are exact)",
    .tags = {"gate", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 552, "particles (a cubic lattice of round((6 n / pi)^(1/3)) cells per diameter cut to the ball, stretched radially)"),
                                   real_param("K", 2.0 / std::numbers::pi, "polytropic constant of p = K rho^2 (2 / pi: R = 1 at G = 1)", 0.0),
                                   real_param("G", 1.0, "gravitational constant", 0.0),
                                   real_param("theta", 0.5, "Barnes-Hut opening angle (89), robust criterion", 0.0),
                                   real_param("eps_dx", 0.5, "Plummer softening (77) in units of the central spacing (m / rho_c)^(1/3)", 0.0),
                                   real_param("t_end", 3.0, "end time of the free evolution, units of sqrt(R^3 / G M)"),
                                   radial::centre_param()};
      for (auto& q : extreme::method_params(2.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    // Lattices of 10, 13, 16, 20, 24 cells per diameter (exact counts, so that the order fit sees the
    // real N); verification/harness/costs.json has what each level costs.
    .levels = {.quick = {552, 1189}, .standard = {552, 1189, 2176}, .full = {1189, 2176, 4224, 7208}},
    .orders = orders,
    .error_defs = polytrope::error_defs,
    .variants = {{}},
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = polytrope::scorer(),
    .ic = polytrope::initial_conditions,
}};

}  // namespace
}  // namespace sphv::polytrope_case
