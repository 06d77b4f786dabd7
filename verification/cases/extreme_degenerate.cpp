// Case `extreme_degenerate`: degenerate inputs that must end with a verdict, never a crash or a
// NaN. kind = isolated: one particle with no neighbour; its density is the self-density (49)
// m W(0, h) with h at the cap h_max (sph/density/fixed_neighbours.hpp), and it must stay at rest.
// kind = coincident: a periodic 2D lattice at rest with one particle duplicated on top of
// another (r_ij = 0, grad W = 0). kind = contrast: a 1D periodic gas at rest in pressure
// equilibrium whose density jumps by `contrast` (masses, same spacing); the exact solution is
// rest and uniform pressure, the error is the spurious motion and pressure blip at the contacts.
#include <cmath>

#include "verification/case.hpp"
#include "verification/cases/extreme_hydro.hpp"
#include "verification/sweep.hpp"

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

Result contrast(const Params& prm, const extreme::Method& m) {
  const int n = static_cast<int>(prm.integer("n"));
  const double R = prm.real("contrast");
  sph::Box<1> box = sph::unit_box<1>(true);
  sph::Particles<1> p = sph::lattice<1>(n, box, 1.0, m.hfact);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool light = p.x[i][0] >= 0.25 && p.x[i][0] < 0.75;
    p.m[i] /= light ? R : 1.0;
    p.u[i] = 1.0 / ((m.gamma - 1.0) * (light ? 1.0 / R : 1.0));  // p = 1 everywhere
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
  const std::string kind = find_case(s.case_name).parse(s.settings).text("kind");
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
    if (kind == "contrast" && r.verdict == "stable" && s.levels[k] == 16) {  // the measured level
      // Summation density (27) smooths the mass across the contact, so next to it the light gas
      // gets a density of the order of the dense one's and, with its u, a pressure of the order of
      // the contrast: the known SPH contact error (Agertz et al. 2007; Saitoh & Makino 2013), not
      // a bug. Measured at n = 16, contrast 1e3, t = 0.005: max |p - 1| = 60.5, max |v| / c =
      // 13.6. Gated between half and 1.2x the measured values: a method that removes the blip
      // (e.g. pressure-energy SPH) must move the claim on purpose.
      for (const auto& [name, measured] : {std::pair{"pressure_blip", 60.47}, std::pair{"speed_over_c_dense", 13.64}})
        c.push_back({level + "_" + name, r.errors.at(name), 0.5 * measured, 1.2 * measured,
                     std::string("SPH contact error at contrast 1e3: between half and 1.2x the measured ") +
                         std::to_string(measured),
                     Check::Kind::verification, name});
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
                                   real_param("t_end", 0.05, "end time", 0.0)};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = {.quick = {16}, .standard = {16, 32}, .full = {16, 32}},
    .orders = [](const Params&) {
      const std::string why = "a degenerate input has a verdict and exact values, not a convergence rate";
      const std::string contact = "the SPH contact error is set by the density contrast at the contact, not by "
                                  "the resolution: gated between a floor and a bound at one level";
      return OrderClaims{{"self_density", no_order(why)}, {"speed", no_order(why)},
                         {"speed_over_c_dense", no_order(contact)}, {"pressure_blip", no_order(contact)}};
    },
    .error_defs = {{"self_density", "isolated particle: |rho - m W(0, h_max)| / (m W(0, h_max)), (49)"},
                   {"speed", "isolated particle: max |v| at t_end (exact 0: no neighbour, no force)"},
                   {"speed_over_c_dense", "contact at rest: max_i |v_i| / c of the dense side at t_end (exact 0)"},
                   {"pressure_blip", "contact at rest: max_i |p_i - 1| at t_end (exact p = 1 everywhere)"}},
    .variants = {{"kind=isolated"}, {"kind=coincident"}, {"kind=contrast", "t_end=0.005"}},
    .validate = {},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::extreme_degenerate_case
