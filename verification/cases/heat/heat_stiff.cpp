// Case `heat_stiff`: the stiff limit of SPH conduction. Large K on a fine 1D lattice (h = 2 dx,
// where the Brookshaw operator is the 3-point Laplacian): explicit steps are capped by
// 2 / lambda_max ~ dx^2 / (2 K) and need thousands of steps, CVODE's BDF does not.
// Error against wall time: forward Euler and Heun at several dt, CVODE at several tolerances and
// with each linear solver; errors measured against CVODE at rtol 1e-12 (the time-exact reference
// of the semi-discretisation, dense Newton; CVODE itself is checked on the sine mode in `heat`).
#include <cmath>
#include <limits>
#include <numbers>

#include "reference/heat_analytic.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/heat/run.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::heat_stiff_case {
namespace {

constexpr double T0 = 1.0, A = 0.5;

double rms(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / a.size()) / A;
}

// The linear lattice system mode by mode: the lattice is translation invariant, so the DFT of u0
// diagonalises the Brookshaw operator with eigenvalues lambda_m = K / S0 * symbol(2 pi m) from
// direct lattice sums (heat/lattice.hpp; no pair loop, no scene).
struct LatticeModes {
  std::vector<double> re, im, lambda;
  LatticeModes(const std::vector<double>& u0, double K, double hfact) {
    const std::size_t n = u0.size();
    const double dx = 1.0 / n, S0 = heat::lattice_kernel_sum<1>(hfact);
    re.assign(n, 0.0), im.assign(n, 0.0), lambda.resize(n);
    for (std::size_t m = 0; m < n; ++m) {
      for (std::size_t j = 0; j < n; ++j) {
        const double phase = 2.0 * std::numbers::pi * double((m * j) % n) / n;
        re[m] += u0[j] * std::cos(phase), im[m] -= u0[j] * std::sin(phase);
      }
      lambda[m] = K / S0 * heat::brookshaw_symbol<1>(sph::Vec<1>::Constant(2.0 * std::numbers::pi * m), hfact, dx);
    }
  }
  // Forward Euler multiplies mode m by (1 - lambda_m dt) per step where the exact flow multiplies
  // it by exp(-lambda_m dt): Euler's error at t_end, the RMS over particles over the amplitude A
  // (Parseval).
  double euler_error(double t_end, long steps) const {
    const double dt = t_end / steps;
    double sum = 0.0;
    for (std::size_t m = 0; m < re.size(); ++m) {
      const double g = std::pow(1.0 - lambda[m] * dt, double(steps)) - std::exp(-lambda[m] * t_end);
      sum += (re[m] * re[m] + im[m] * im[m]) * g * g;
    }
    return std::sqrt(sum) / re.size() / A;
  }
  // The exact state at t: the inverse DFT of the modes times exp(-lambda_m t).
  std::vector<double> exact(double t) const {
    const std::size_t n = re.size();
    std::vector<double> u(n, 0.0);
    for (std::size_t m = 0; m < n; ++m) {
      const double g = std::exp(-lambda[m] * t) / n;
      for (std::size_t j = 0; j < n; ++j) {
        const double phase = 2.0 * std::numbers::pi * double((m * j) % n) / n;
        u[j] += g * (re[m] * std::cos(phase) - im[m] * std::sin(phase));
      }
    }
    return u;
  }
};

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
  long cvode_steps = 0, cvode_rhs = 0, cheapest_rhs = 0;
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
      // The same by evaluations of f (each one pair loop over the set): a cost free of timing noise.
      if (err <= euler_err && (cheapest_rhs == 0 || c.stats.rhs_evals < cheapest_rhs)) cheapest_rhs = c.stats.rhs_evals;
    }
    fig.series.push_back(sr);
  }
  r.figures.push_back(fig);
  r.errors["time_euler_at_bound"] = euler_err;
  const LatticeModes modes(u0, K, hfact);
  r.extra = {{"t_end", t_end}, {"dt_bound", dt_bound}, {"dt_bound_K_over_dx2", dt_bound * K * n * n},
             {"explicit_steps", euler_steps}, {"explicit_wall_s", euler_wall}, {"explicit_error", euler_err},
             {"cvode_steps", cvode_steps}, {"cvode_rhs_evals", cvode_rhs}, {"cvode_best_solver", best_solver},
             {"cvode_wall_s", best_cvode_wall}, {"cvode_cheapest_rhs_evals_equal_error", cheapest_rhs},
             {"explicit_error_predicted", modes.euler_error(t_end, euler_steps)},
             {"reference_error_vs_fourier", rms(ref.u, modes.exact(t_end))},
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
  const auto& fine = s.runs.back();
  const auto& x = fine.extra;
  const double expl = x["explicit_steps"].get<double>(), impl = x["cvode_steps"].get<double>();
  const double cheapest = x["cvode_cheapest_rhs_evals_equal_error"].get<double>();
  return {
      // The stiff regime the case is for: explicit needs thousands of steps (t_end lambda_max / 2).
      {"explicit_steps", expl, 1000.0, 1e9, "stiff case: t_end / (2 / lambda_max) >= 1000"},
      // BDF steps are set by accuracy, not lambda_max: at equal error at least 10x fewer steps.
      {"cvode_steps_over_explicit", impl / expl, 1e-9, 0.1, "A-stable BDF (orders 1-2) is not step-limited by lambda_max"},
      // Reference fact (reference-values.md): at h = 2 dx the bound is 0.5 dx^2 / K.
      {"dt_bound_K_over_dx2", x["dt_bound_K_over_dx2"], 0.5 - 1e-9, 0.5 + 1e-9, "3-point FD Laplacian: dt <= 0.5 dx^2 / K"},
      // The reference itself against the exact lattice flow (LatticeModes::exact): CVODE at rtol
      // 1e-12, measured 6.9e-12 at n = 512 (dense Newton) and 1.6e-10 at 2048 (Krylov); bound 1e-9.
      {"reference_vs_fourier", x["reference_error_vs_fourier"], 0.0, 1e-9,
       "CVODE at rtol 1e-12 against the lattice system's exact flow, mode by mode", Check::Kind::verification,
       "time_euler_at_bound"},
      // The SPH side: forward Euler's error at 0.95 of its bound against its prediction from the
      // lattice symbol mode by mode. By the triangle inequality the two differ by at most the
      // reference's own error (above) plus Euler's round-off, at most steps x machine epsilon of
      // the state (measured: 5.7e-13 against 1.3e-11 allowed at n = 512, 1.63e-10 against
      // 2.6e-10 at 2048).
      {"time_euler_vs_fourier_prediction",
       std::abs(x["explicit_error"].get<double>() - x["explicit_error_predicted"].get<double>()) /
           (x["reference_error_vs_fourier"].get<double>() + expl * std::numeric_limits<double>::epsilon() / A),
       0.0, 1.0, "Euler's amplification (1 - lambda dt)^steps per lattice mode, to the reference's error and round-off",
       Check::Kind::verification, "time_euler_at_bound"},
      // Its time against CVODE's at equal error, counted in evaluations of f (pair loops): explicit
      // steps grow as n^2 (dt ~ dx^2), CVODE's as accuracy demands. Measured 11.2 (n = 256) and
      // 12.5 (n = 512) times more for Euler than for the cheapest CVODE run at least as accurate;
      // bound 5 (margin > 2).
      {"explicit_rhs_over_cvode_equal_error", cheapest > 0 ? expl / cheapest : 0.0, 5.0, 1e9,
       "at equal error CVODE needs fewer evaluations of the SPH operator", Check::Kind::verification,
       "time_euler_at_bound"},
  };
  // Wall time at equal error (extra "speedup_equal_error") is reported, not gated: on a loaded
  // machine it varies between repeated runs by up to a factor of two (docs/cases/heat.md), and
  // a gate on it would fail on the load, not on the code. The evaluation count above is the
  // same comparison without the timing noise.
}

const Registration reg{Case{
    .name = "heat_stiff",
    .summary = "stiff conduction (1D, h = 2 dx, large K): explicit step limit vs CVODE BDF, error against wall time",
    .n_counts = "particles on the periodic unit interval",
    .tags = {"gate"},
    .params = {integer_param("n", 256, "particles"),
               real_param("K", 10.0, "conductivity (rho c_v = 1 at h = 2 dx)", 0.0)},
    // Explicit cost grows as n^3 and the dense references as n^3, so n = 1024 and 2048 (spgmr
    // reference) are full only (CPU times: docs/cases/heat.md).
    .levels = {.quick = {128, 256}, .standard = {128, 256, 512}, .full = {256, 512, 1024, 2048}},
    .orders = [](const Params&) {
      // Band 0.05: the sine mode's error (1/sqrt 2) e^-1 lambda_1 dt / 2 ~ n^-2 dominates (the
      // pulse's share changes slowly with n); measured 2.012 +- 0.001 over n = 128, 256, 512.
      return OrderClaims{{"time_euler_at_bound", {2.0, 0.05, "Euler O(dt) at dt = 0.95 * 2 / lambda_max ~ dx^2: O(n^-2)"}}};
    },
    .error_defs = {{"time_euler_at_bound", "rms over particles of |u_Euler - u_ref| / amplitude at t_end, forward Euler at "
                                           "0.95 of its stability bound, u_ref from CVODE at rtol 1e-12"}},
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::heat_stiff_case
