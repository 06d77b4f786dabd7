// Case `extreme_degenerate`: degenerate inputs that must end with a verdict, never a crash or a
// NaN. kind = isolated: one particle with no neighbour; its density is the self-density (49)
// m W(0, h) with h at the cap h_max (sph/density/fixed_neighbours.hpp), and it must stay at rest.
// kind = coincident: a periodic 2D lattice at rest with one particle duplicated on top of
// another (r_ij = 0, grad W = 0). kind = contrast: a 1D periodic gas at rest in pressure
// equilibrium whose density jumps by `contrast` (masses, same spacing), or changes by it smoothly
// over `contact_width`; the exact solution is rest and uniform pressure, the error is the spurious
// motion and pressure blip at the contacts.
#include <cmath>

#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::extreme_degenerate_case {
namespace {

double max_speed(const auto& p) {
  double v = 0.0;
  for (const auto& vi : p.v) v = std::max(v, vi.norm());
  return v;
}

// Evolves p to t_end with h capped at h_max; the Result starts with the particle count and verdict.
struct Evolved {
  sph::HydroOutcome out;
  Result r;
};
template <int D>
Evolved evolve(sph::Particles<D>& p, const sph::Box<D>& box, extreme::Method m, double h_max, double t_end) {
  m.h_max = h_max;
  m.controls.t_end = t_end;
  Evolved e{extreme::evolve_gas(p, box, m), {}};
  e.r.n_particles = p.size();
  e.r.verdict = e.out.verdict == "ok" ? "stable" : e.out.verdict;
  return e;
}

Result isolated(const extreme::Method& m) {
  sph::Box<2> box = sph::unit_box<2>(false);
  sph::Particles<2> p;
  p.resize(1);
  p.x[0] = sph::Vec<2>::Constant(0.5);
  p.m[0] = 1e-3;
  p.rho[0] = 1.0;
  p.u[0] = 1.0;
  p.h[0] = 0.05;
  const double h_max = 0.4;
  auto [out, r] = evolve(p, box, m, h_max, 0.1);
  const double self = p.m[0] * sph::CubicSpline<2>::W(0.0, h_max);  // (49)
  r.errors = {{"self_density", std::abs(p.rho[0] - self) / self}, {"speed", max_speed(p)}};
  r.extra = {{"h", p.h[0]}, {"rho", p.rho[0]}, {"rho_self_49", self}, {"steps", out.steps}};
  return r;
}

Result coincident(const Params& prm, const extreme::Method& m) {
  const int n = static_cast<int>(prm.integer("n"));
  sph::Box<2> box = sph::unit_box<2>(true);
  sph::Particles<2> p = sph::lattice<2>(n, box, 1.0, m.hfact);
  for (auto& u : p.u) u = 1.0;
  const std::size_t k = p.size() / 2 + n / 2;
  p.x.push_back(p.x[k]), p.v.push_back(p.v[k]), p.m.push_back(p.m[k]), p.rho.push_back(p.rho[k]);
  p.p.push_back(0.0), p.c.push_back(0.0), p.u.push_back(p.u[k]), p.h.push_back(p.h[k]);
  auto [out, r] = evolve(p, box, m, 0.45, prm.real("t_end"));
  // The pair feels no force from each other and identical forces from the rest: it never
  // separates (an SPH degeneracy the verdict alone does not reveal).
  r.extra = {{"pair_separation", (p.x[k] - p.x.back()).norm()}, {"max_speed", max_speed(p)}, {"steps", out.steps},
             {"rho_pair", p.rho[k]}};
  return r;
}

// The density of the contact set-up: 1 outside [1/4, 3/4), 1 / contrast inside; with a width w > 0
// ln rho falls smoothly, ln rho = -ln(contrast) (tanh((x - 1/4) / w) - tanh((x - 3/4) / w)) / 2,
// a profile the kernel resolves once h << w (the jump at w = 0 is unresolved at every n).
double contact_density(double x, double contrast, double w) {
  if (w == 0.0) return x >= 0.25 && x < 0.75 ? 1.0 / contrast : 1.0;
  return std::exp(-std::log(contrast) * 0.5 * (std::tanh((x - 0.25) / w) - std::tanh((x - 0.75) / w)));
}

Result contrast(const Params& prm, const extreme::Method& m) {
  const int n = static_cast<int>(prm.integer("n"));
  const double R = prm.real("contrast"), w = prm.real("contact_width");
  sph::Box<1> box = sph::unit_box<1>(true);
  sph::Particles<1> p = sph::lattice<1>(n, box, 1.0, m.hfact);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double rho = contact_density(p.x[i][0], R, w);
    p.m[i] *= rho;
    p.u[i] = 1.0 / ((m.gamma - 1.0) * rho);  // p = 1 everywhere
  }
  auto [out, r] = evolve(p, box, m, 0.45, prm.real("t_end"));
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}};
  if (out.verdict != "ok") return r;
  double dp = 0.0;
  for (double pi : p.p) dp = std::max(dp, std::abs(pi - 1.0));
  const double c_dense = std::sqrt(m.gamma);  // p = rho = 1
  r.errors = {{"speed_over_c_dense", max_speed(p) / c_dense}, {"pressure_blip", dp}};
  Series pts{"SPH particles", {}, {}, "points"}, ex{"exact (rest, p = 1)", {0.0, 1.0}, {1.0, 1.0}, "line"};
  for (std::size_t i = 0; i < p.size(); ++i) pts.x.push_back(p.x[i][0]), pts.y.push_back(p.p[i]);
  r.figures.push_back({"pressure", "Contact at rest, density contrast " + std::to_string(R), "x", "pressure p",
                       "linear", "linear", {pts, ex}});
  return r;
}

Result run(const Params& p) {
  const extreme::Method m = extreme::method(p);
  const std::string kind = p.text("kind");
  if (kind == "isolated") return isolated(m);
  if (kind == "coincident") return coincident(p, m);
  return contrast(p, m);
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const Params prm = find_case(s.case_name).parse(s.settings);
  const std::string kind = prm.text("kind");
  const bool smooth = kind == "contrast" && prm.real("contact_width") > 0.0;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const auto& r = s.runs[k];
    const std::string level = "n" + std::to_string(s.levels[k]) + "_" + kind;
    // Every kind must end with a verdict; these three are expected to be stable.
    c.push_back({level + "_stable", double(r.verdict == "stable"), 1.0, 1.0, "ends stable, no NaN"});
    if (kind == "isolated" && r.verdict == "stable") {
      c.push_back({level + "_self_density", r.errors.at("self_density"), 0.0, 1e-12, "(49): rho = m W(0, h_max), round-off",
                   Check::Kind::verification, "self_density"});
      c.push_back({level + "_at_rest", r.errors.at("speed"), 0.0, 0.0, "no neighbour, no force", Check::Kind::verification,
                   "speed"});
    }
    if (kind == "contrast" && !smooth && r.verdict == "stable" && s.levels[k] == 16) {  // the measured level
      // Summation density (27) smooths the mass across the contact, so next to it the light gas
      // gets a density of the order of the dense one's and, with its u, a pressure of the order of
      // the contrast: the known SPH contact error (Agertz et al. 2007; Saitoh & Makino 2013), not
      // a bug. Measured at n = 16, contrast 1e3, t = 0.005, with h fitting (50) at every particle
      // (the same values at the h solve's tolerance 1e-3 and 1e-8): max |p - 1| = 78.2,
      // max |v| / c = 13.7. Gated between half and 1.2x the measured values: a method that
      // removes the blip (e.g. pressure-energy SPH) must move the claim on purpose.
      for (const auto& [name, measured] : {std::pair{"pressure_blip", 78.20}, std::pair{"speed_over_c_dense", 13.72}})
        c.push_back({level + "_" + name, r.errors.at(name), 0.5 * measured, 1.2 * measured,
                     std::string("SPH contact error at contrast 1e3: between half and 1.2x the measured ") +
                         std::to_string(measured),
                     Check::Kind::verification, name});
    }
    if (smooth && r.verdict == "stable" && k + 1 == s.runs.size()) {
      // The finest level: at most the error measured at the finest quick level (n = 400, contrast
      // 1e3, width 0.05, hfact 2, t = 0.005: max |p - 1| = 1.077e-2, max |v| / c = 2.745e-2) + 20 %;
      // the errors fall at second order beyond it.
      for (const auto& [name, measured] : {std::pair{"pressure_blip", 1.077e-2}, std::pair{"speed_over_c_dense", 2.745e-2}})
        c.push_back({level + "_" + name, r.errors.at(name), 0.0, 1.2 * measured,
                     "resolved contact: at most the error measured at n = 400 + 20 %", Check::Kind::verification, name});
    }
  }
  return c;
}

const Registration reg{Case{
    .name = "extreme_degenerate",
    .summary = "degenerate inputs: isolated particle (self-density), coincident particles, density contrast at rest",
    .n_counts = "particles per side",
    .tags = {"gate", "extreme"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 16, "particles per side"),
                                   choice_param("kind", "isolated", "degenerate input", {"isolated", "coincident", "contrast"}),
                                   real_param("contrast", 1e3, "density ratio (kind = contrast)", 1.0),
                                   real_param("contact_width", 0.0, "width of the contacts' smooth density profile (kind = contrast; 0: a jump)", -1e-300),
                                   real_param("t_end", 0.05, "end time", 0.0)};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = {.quick = {16, 32}, .standard = {16, 32}, .full = {16, 32}},
    // The contact at rest converges once the kernel resolves it: with the jump smoothed over a
    // width w >> h the summation density misses the profile by O((h / w)^2) (the kernel's second
    // moment times (ln rho)''), and so do the pressure blip and the motion it drives (measured
    // local orders: docs/cases/extreme.md). hfact 2: the 1D
    // lattice sums are exact there; at 2.4 their error (2.7e-3 in the pressure at rest) floors
    // the blip from n = 1600. The jump itself (w = 0) stays unresolved at every n at fixed h/dx:
    // the light particles beside it sum the dense side's mass whatever n, a known failure with
    // the smooth contact as the variant that converges.
    .orders = [](const Params& p) {
      const std::string why = "a degenerate input has a verdict and exact values, not a convergence rate";
      const OrderClaim resolved{2.0, 0.3, "a contact the kernel resolves: the summation density misses the smooth "
                                          "profile by O((h / w)^2), and so does the pressure (and the motion it drives)"};
      if (p.real("contact_width") > 0.0)
        return OrderClaims{{"speed_over_c_dense", resolved}, {"pressure_blip", resolved}};
      const std::string jump = "the density jump is unresolved at every n (fixed h/dx): the light particles beside it "
                               "sum the dense side's mass whatever n; pressure blip {pressure_blip} and speed "
                               "{speed_over_c_dense} at {levels}";
      const std::string smooth = "kind=contrast,t_end=0.005,contact_width=0.05,hfact=2";
      return OrderClaims{{"self_density", no_order(why)}, {"speed", no_order(why)},
                         {"speed_over_c_dense", known_failure(2.0, 0.3, jump, smooth)},
                         {"pressure_blip", known_failure(2.0, 0.3, jump, smooth)}};
    },
    .error_defs = {{"self_density", "isolated particle: |rho - m W(0, h_max)| / (m W(0, h_max)), (49)"},
                   {"speed", "isolated particle: max |v| at t_end (exact 0: no neighbour, no force)"},
                   {"speed_over_c_dense", "contact at rest: max_i |v_i| / c of the dense side at t_end (exact 0)"},
                   {"pressure_blip", "contact at rest: max_i |p_i - 1| at t_end (exact p = 1 everywhere)"}},
    .variants = {{"kind=isolated"},
                 {"kind=coincident"},
                 {"kind=contrast", "t_end=0.005"},
                 {"kind=contrast", "t_end=0.005", "contact_width=0.05", "hfact=2"}},
    .levels_for = [](const Params& p) {
      if (p.real("contact_width") > 0.0)
        return Levels{.quick = {200, 400}, .standard = {200, 400, 800}, .full = {200, 400, 800, 1600}};
      return Levels{.quick = {16, 32}, .standard = {16, 32}, .full = {16, 32}};
    },
    .validate = {},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::extreme_degenerate_case
