// Case `stability_map_heat`: a stability map of explicit SPH conduction. For a grid of particle
// disorder (lattice jitter, the physical parameter that decides the two-pass forms' fate) and
// time-step factor C = dt chi / h^2, each point integrates random noise for `steps` steps and is
// classed by its verdict: stable, or unstable (the first step and particle where |T - mean|
// grew). The independent reference is the lattice bound 2 / lambda_max (Fourier symbol of the
// lattice operator): on the undisturbed lattice (jitter 0) the map's boundary must sit there.
#include <cmath>

#include "verification/harness/case.hpp"
#include "verification/cases/heat/run.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::stability_map_heat_case {
namespace {

const std::vector<double> jitters = {0.0, 0.05, 0.1, 0.2, 0.3};                     // in units of dx
const std::vector<double> factors = {0.25, 0.5, 0.7, 0.9, 1.1, 1.3, 1.6, 2.0, 3.0};  // times the lattice bound

// A stable step of the (similar to symmetric) Brookshaw operator on a disordered set cannot
// raise the noise norm by more than the similarity's condition number sqrt(rho_max / rho_min)
// (< 1.4 at jitter 0.3); an unstable mode grows geometrically. Factor 2 separates the two.
constexpr double growth_limit = 2.0;

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  const long M = prm.integer("steps");
  const double hfact = prm.real("hfact");
  const std::string form = prm.text("form"), method = prm.text("method");
  const sph::ConductionParams k{prm.real("K"), 1.0};
  const double dx = 1.0 / n, h = hfact * dx;
  Result r;
  Series stable{"stable", {}, {}, "points"}, unstable{"unstable", {}, {}, "points"};
  Series bound{"lattice bound 2 / lambda_max", {}, {}, "dashed"};
  // chi = K / (rho c_v) with the lattice summation density rho0 S0 (heat/run.hpp).
  const double C_bound = 2.0 / heat::lattice_lambda_max<D>(n, hfact, form, k.K) * k.K / (h * h);
  nlohmann::json rows = nlohmann::json::array();
  long n_stable = 0, n_unstable = 0;
  for (double jitter : jitters) {
    const heat::ParticleSet<D> s(n, hfact, jitter);
    r.n_particles = s.p.size();
    const heat::Rate f = heat::make_rate<D>(s, form, k);
    const std::vector<double> u0 = heat::noisy_field(s.p.size());
    double rho_min = s.p.rho[0];
    for (double rho : s.p.rho) rho_min = std::min(rho_min, rho);
    double largest_stable = 0.0;
    for (double fac : factors) {
      const double C = fac * C_bound;
      // dt = C h^2 / chi at the smallest density (the diffusion criterion's choice).
      const double dt = C * h * h * rho_min / k.K;
      const auto e = heat::integrate_explicit(f, u0, M * dt, dt, method, growth_limit);
      const bool ok = e.verdict == "ok";
      (ok ? stable : unstable).x.push_back(jitter);
      (ok ? stable : unstable).y.push_back(C);
      ok ? ++n_stable : ++n_unstable;
      if (ok) largest_stable = std::max(largest_stable, C);
      rows.push_back({{"jitter", jitter}, {"C", C}, {"factor", fac}, {"verdict", ok ? "stable" : e.verdict}});
    }
    r.extra["largest_stable_C_jitter_" + std::to_string(jitter).substr(0, 4)] = largest_stable;
  }
  bound.x = {jitters.front(), jitters.back()};
  bound.y = {C_bound, C_bound};
  r.extra["points"] = rows;
  r.extra["C_bound"] = C_bound;
  r.extra["dim"] = D;
  r.verdict = "ok: " + std::to_string(n_stable) + " stable, " + std::to_string(n_unstable) + " unstable points";
  r.figures.push_back({"stability_map", "Stability map, " + std::to_string(D) + "D " + form + " " + method +
                                            ", h/dx = " + std::to_string(hfact).substr(0, 4),
                       "lattice jitter (units of dx)", "time-step factor C = dt chi / h^2", "linear", "log",
                       {stable, unstable, bound}});
  return r;
}

Result run(const Params& p) {
  return by_dimension(p, [&](auto d) { return run_dim<d>(p); });
}

void validate(const Params& p) {
  if (p.integer("dim") < 1 || p.integer("dim") > 3) throw InputError("stability_map_heat: dim must be 1, 2 or 3");
  if (!(2.0 * p.real("hfact") < p.integer("n")))
    throw InputError("stability_map_heat: the support radius hfact/n must stay below half the box");
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  for (const auto& r : s.runs) {
    const std::string tag = "_n" + std::to_string(r.params["n"].get<long>());
    // On the lattice the map's boundary is the bound (theory: forward Euler and Heun are stable
    // iff dt lambda_max <= 2); the factors 0.9 and 1.1 sit 10% either side of it, far outside
    // the detection slack ln(sqrt N) / (2 steps) < 1%.
    double wrong = 0.0, points = 0.0;
    for (const auto& row : r.extra["points"]) {
      if (row["jitter"].get<double>() != 0.0) continue;
      const bool stable = row["verdict"] == "stable";
      wrong += (row["factor"].get<double>() < 1.0) != stable;
      ++points;
    }
    c.push_back({"lattice_points_off_bound" + tag, wrong, 0.0, 0.0,
                 "jitter 0: stable exactly below 2 / lambda_max (lattice symbol)"});
    c.push_back({"lattice_points" + tag, points, double(factors.size()), double(factors.size()),
                 "every point of the jitter-0 column has a verdict"});
  }
  return c;
}

// A map of verdicts per resolution, no convergence: full adds one larger set (cost: particles x
// fixed steps; CPU times: docs/cases/heat.md).
const Levels levels = {.quick = {32}, .standard = {32, 64}, .full = {32, 64, 128}};

const Registration reg{Case{
    .name = "stability_map_heat",
    .summary = "stability map of explicit SPH conduction: verdict over (lattice jitter, dt chi / h^2)",
    .n_counts = "particles per side of the periodic set",
    .tags = {"gate", "extreme"},
    .params = {integer_param("n", 32, "particles per side"),
               integer_param("dim", 1, "dimension 1, 2 or 3"),
               real_param("hfact", 2.5, "support radius / spacing", 0.0),
               real_param("K", 1.0, "conductivity", 0.0),
               integer_param("steps", 300, "steps a stable point must survive"),
               choice_param("form", "brookshaw", "conduction form", {"brookshaw", "flux_56_58", "flux_57_59"}),
               choice_param("method", "euler", "explicit method", {"euler", "heun"})},
    .levels = levels,
    .orders = [](const Params&) { return OrderClaims{}; },  // no convergence: a map of verdicts per resolution: no errors, only verdicts and bounds
    .variants = {{}, {"form=flux_57_59"}, {"form=flux_56_58"}, {"dim=2"}, {"dim=2", "form=flux_57_59"}},
    .levels_for = [](const Params& p) {
      Levels l = levels;
      if (p.integer("dim") > 1)
        for (auto* v : {&l.quick, &l.standard, &l.full})
          for (auto& n : *v) n /= 2;
      return l;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::stability_map_heat_case
