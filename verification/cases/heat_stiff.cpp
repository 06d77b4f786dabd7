// Case `heat_stiff`: the stiff limit of SPH conduction. Large K on a fine 1D lattice (h = 2 dx,
// where the Brookshaw operator is the 3-point Laplacian): explicit steps are capped by
// 2 / lambda_max ~ dx^2 / (2 K) and need thousands of steps, CVODE's BDF does not.
// Error against wall time: forward Euler and Heun at several dt, CVODE at several tolerances and
// with each linear solver; errors measured against CVODE at rtol 1e-12 (the time-exact reference
// of the semi-discretisation, dense Newton; CVODE itself is checked on the sine mode in `heat`).
#include <cmath>
#include <numbers>

#include "reference/heat_analytic.hpp"
#include "verification/case.hpp"
#include "verification/cases/heat_run.hpp"
#include "verification/sweep.hpp"

namespace sphv {
namespace {

constexpr double T0 = 1.0, A = 0.5;

double rms(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / a.size()) / A;
}

Result run(const Params& prm) {
  constexpr int D = 1;
  const int n = static_cast<int>(prm.integer("n"));
  const double K = prm.real("K"), hfact = 2.0;
  const heat::ParticleSet<D> s(n, hfact, 0.0);
  const sph::ConductionParams k{K, 1.0};
  const heat::Rate f = heat::make_rate<D>(s, "brookshaw", k);
  const double chi = K / s.p.rho[0];
  const double kk = 4.0 * std::numbers::pi * std::numbers::pi;
  const double t_end = 1.0 / (chi * kk);  // the fundamental mode decays by e
  // Initial state: a narrow Gaussian pulse (sigma 4 dx) on the sine mode: all scales present.
  std::vector<double> u0(s.p.size());
  for (std::size_t i = 0; i < u0.size(); ++i)
    u0[i] = reference::gaussian_pulse(s.coords(i), 0.0, chi, 0.0, A, 4.0 / n, 0.5) +
            reference::sine_mode(s.coords(i), 0.0, chi, T0, A, 1);

  reference::CvodeOptions ref_opt;
  ref_opt.rtol = 1e-12;
  ref_opt.atol = 1e-12 * A;
  ref_opt.solver = n <= 1024 ? reference::LinearSolver::Dense : reference::LinearSolver::Spgmr;  // exact Newton
  const auto ref = heat::integrate_cvode(f, u0, t_end, ref_opt);
  Result r;
  r.n_particles = s.p.size();
  if (ref.verdict != "ok") {
    r.verdict = ref.verdict;
    return r;
  }
  const double dt_bound = 2.0 / heat::lattice_lambda_max<D>(n, hfact, "brookshaw", K);
  Figure fig{"stiff_error_wall", "Time error against wall time, 1D n = " + std::to_string(n) + ", K = " + std::to_string(K),
             "wall time (s)", "RMS error / amplitude vs CVODE rtol 1e-12", "log", "log", {}};
  nlohmann::json runs = nlohmann::json::array();
  double euler_err = NAN, euler_wall = NAN;
  long euler_steps = 0;
  for (const char* method : {"euler", "heun"}) {
    Series sr{method, {}, {}, "line"};
    for (double frac : {0.95, 0.5, 0.25}) {
      if (std::string(method) == "heun" && frac < 0.5) continue;
      const auto e = heat::integrate_explicit(f, u0, t_end, frac * dt_bound, method);
      if (e.verdict != "ok") {
        r.verdict = std::string(method) + " " + e.verdict;
        continue;
      }
      const double err = rms(e.u, ref.u);
      sr.x.push_back(e.wall_s), sr.y.push_back(err);
      runs.push_back({{"method", method}, {"dt_over_bound", frac}, {"steps", e.steps}, {"error", err}, {"wall_s", e.wall_s}});
      if (std::string(method) == "euler" && frac == 0.95) euler_err = err, euler_wall = e.wall_s, euler_steps = e.steps;
    }
    fig.series.push_back(sr);
  }
  double best_cvode_wall = INFINITY;
  long cvode_steps = 0, cvode_rhs = 0;
  std::string best_solver;
  for (const char* solver : {"spgmr", "band", "dense"}) {
    if (std::string(solver) == "dense" && n > 2048) continue;  // O(n^3) factorisations
    Series sr{std::string("CVODE ") + solver, {}, {}, "points"};
    // band drops the periodic wrap entries of the Jacobian: an inexact Newton that needs
    // thousands of steps (measured), shown at one tolerance only.
    for (double tol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
      if (std::string(solver) == "band" && tol != 1e-5) continue;
      reference::CvodeOptions o;
      o.rtol = tol;
      o.atol = tol * A;
      o.solver = reference::linear_solver_from_name(solver);
      o.bandwidth = 2;
      const auto c = heat::integrate_cvode(f, u0, t_end, o);
      if (c.verdict != "ok") continue;
      const double err = rms(c.u, ref.u);
      sr.x.push_back(c.wall_s), sr.y.push_back(err);
      runs.push_back({{"method", std::string("cvode_") + solver}, {"rtol", tol}, {"steps", c.stats.steps},
                      {"rhs_evals", c.stats.rhs_evals}, {"linear_iters", c.stats.linear_iters},
                      {"jacobian_evals", c.stats.jacobian_evals}, {"error", err}, {"wall_s", c.wall_s}});
      // The cheapest CVODE run at least as accurate as forward Euler at 0.95 of its limit.
      if (err <= euler_err && c.wall_s < best_cvode_wall)
        best_cvode_wall = c.wall_s, cvode_steps = c.stats.steps, cvode_rhs = c.stats.rhs_evals, best_solver = solver;
    }
    fig.series.push_back(sr);
  }
  r.figures.push_back(fig);
  r.errors["time_euler_at_bound"] = euler_err;
  r.extra = {{"t_end", t_end}, {"dt_bound", dt_bound}, {"dt_bound_K_over_dx2", dt_bound * K * n * n},
             {"explicit_steps", euler_steps}, {"explicit_wall_s", euler_wall}, {"explicit_error", euler_err},
             {"cvode_steps", cvode_steps}, {"cvode_rhs_evals", cvode_rhs}, {"cvode_best_solver", best_solver},
             {"cvode_wall_s", best_cvode_wall},
             {"speedup_equal_error", std::isfinite(best_cvode_wall) ? euler_wall / best_cvode_wall : 0.0},
             {"reference", {{"steps", ref.stats.steps}, {"rhs_evals", ref.stats.rhs_evals}, {"wall_s", ref.wall_s}}},
             {"runs", runs}};
  return r;
}

void validate(const Params& p) {
  if (!(p.real("K") > 0.0)) throw InputError("heat_stiff: conductivity K must be > 0");
  if (p.integer("n") < 16) throw InputError("heat_stiff: need n >= 16");
}

std::vector<Check> gates(const Sweep& s) {
  const auto& x = s.runs.back().extra;
  const double expl = x["explicit_steps"].get<double>(), impl = x["cvode_steps"].get<double>();
  return {
      // The stiff regime the case is for: explicit needs thousands of steps (t_end lambda_max / 2).
      {"explicit_steps", expl, 1000.0, 1e9, "stiff case: t_end / (2 / lambda_max) >= 1000"},
      // BDF steps are set by accuracy, not lambda_max: at equal error at least 10x fewer steps.
      {"cvode_steps_over_explicit", impl / expl, 1e-9, 0.1, "A-stable BDF (orders 1-2) is not step-limited by lambda_max"},
      // Reference fact (reference-values.md): at h = 2 dx the bound is 0.5 dx^2 / K.
      {"dt_bound_K_over_dx2", x["dt_bound_K_over_dx2"], 0.5 - 1e-9, 0.5 + 1e-9, "3-point FD Laplacian: dt <= 0.5 dx^2 / K"},
  };
}

const Registration reg{Case{
    .name = "heat_stiff",
    .summary = "stiff conduction (1D, h = 2 dx, large K): explicit step limit vs CVODE BDF, error against wall time",
    .n_counts = "particles on the periodic unit interval",
    .tags = {"gate"},
    .params = {integer_param("n", 256, "particles"),
               real_param("K", 10.0, "conductivity (rho c_v = 1 at h = 2 dx)", 0.0)},
    .levels = {.quick = {256}, .standard = {256, 512}, .full = {256, 512}},
    .orders = [](const Params&) {
      return OrderClaims{{"time_euler_at_bound", {2.0, 0.5, "Euler O(dt) at dt = 0.95 * 2 / lambda_max ~ dx^2: O(n^-2)"}}};
    },
    .error_defs = {{"time_euler_at_bound", "rms over particles of |u_Euler - u_ref| / amplitude at t_end, forward Euler at "
                                           "0.95 of its stability bound, u_ref from CVODE at rtol 1e-12"}},
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv
