// Cases `sod`, `sod2d`, `sod3d`: Sod's shock tube and Toro's Riemann problems 1-5 (or any
// left/right state) with the hydrodynamics of 9.2-9.4.2, against the exact Riemann solver
// (reference/riemann, Toro ch. 4). Errors are L1 over the tube [0, 1] at t_end.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

#include "sph/hydro/forms.hpp"
#include "sph/kernel/kernels.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/hydro_step_params.hpp"
#include "verification/cases/common/lattice_sums.hpp"
#include "verification/cases/common/scheme_param.hpp"
#include "verification/cases/shock_tubes/errors.hpp"
#include "verification/cases/shock_tubes/snapshots.hpp"
#include "verification/cases/shock_tubes/tube.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::sod_case {
namespace {

struct Preset {
  reference::GasState l, r;
  double t_end;
};

// Toro, table 4.1 (gamma = 1.4, x0 = 0.5 on [0, 1]).
const std::map<std::string, Preset> presets = {
    {"sod", {{1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 0.25}},                                // test 1
    {"toro2", {{1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 0.15}},                               // 123, near vacuum
    {"toro3", {{1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 0.012}},                           // left blast wave
    {"toro4", {{1.0, 0.0, 0.01}, {1.0, 0.0, 100.0}, 0.035}},                            // right blast wave
    {"toro5", {{5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, 0.035}},      // colliding shocks
};

const char* const state_keys[] = {"rho_l", "v_l", "p_l", "rho_r", "v_r", "p_r", "gamma", "t_end", "x0"};

// A state parameter: "preset" (take the preset's value) or a number.
double state_value(const Params& p, const std::string& key, double preset_value) {
  const std::string& s = p.text(key);
  if (s == "preset") return preset_value;
  double v = 0.0;
  if (!parse_finite(s, v))
    throw InputError("parameter " + key + ": '" + s + "' is not a finite number");
  return v;
}

// The domain "x_lo,x_hi" (two finite numbers, x_lo < x_hi).
std::pair<double, double> domain(const Params& p) {
  const std::string& s = p.text("domain");
  const auto comma = s.find(',');
  double lo = 0.0, hi = 0.0;
  if (comma == std::string::npos || !parse_finite(std::string_view(s).substr(0, comma), lo) ||
      !parse_finite(std::string_view(s).substr(comma + 1), hi) || !(lo < hi))
    throw InputError("parameter domain: '" + s + "' is not x_lo,x_hi (two finite numbers, x_lo < x_hi)");
  return {lo, hi};
}

// The problem from the preset and any overrides, with one clear line for bad input. The
// interface x0 defaults to the domain's middle (Toro's 0.5 on [0, 1]).
TubeProblem problem(const Params& p) {
  const Preset& ps = presets.at(p.text("preset"));
  const auto [lo, hi] = domain(p);
  TubeProblem pr{{state_value(p, "rho_l", ps.l.rho), state_value(p, "v_l", ps.l.u), state_value(p, "p_l", ps.l.p)},
                 {state_value(p, "rho_r", ps.r.rho), state_value(p, "v_r", ps.r.u), state_value(p, "p_r", ps.r.p)},
                 state_value(p, "gamma", 1.4), state_value(p, "x0", 0.5 * (lo + hi)), state_value(p, "t_end", ps.t_end),
                 lo, hi, p.text("ends")};
  if (!(pr.gamma > 1.0)) throw InputError("gamma must be > 1, got " + p.text("gamma"));
  if (!(pr.left.rho > 0.0 && pr.right.rho > 0.0)) throw InputError("densities rho_l, rho_r must be > 0");
  if (!(pr.left.p > 0.0 && pr.right.p > 0.0)) throw InputError("pressures p_l, p_r must be > 0");
  if (!(pr.x0 > lo && pr.x0 < hi))
    throw InputError("x0 must lie inside the tube's domain (" + shortest(lo) + ", " + shortest(hi) + "), got " + p.text("x0"));
  // t_end = 0 scores initial conditions (sphv ic, then sphv score): the exact solution is the two
  // states on either side of x0 (and of the wrap); a run needs t_end > 0 (run_problem).
  if (!(pr.t_end >= 0.0)) throw InputError("t_end must be >= 0, got " + p.text("t_end"));
  try {
    static_cast<void>(TubeExact{pr});
  } catch (const reference::RiemannError& e) {
    throw InputError(e.what());
  }
  return pr;
}

// The problem of a run: as problem(), with a time to run to.
TubeProblem run_problem(const Params& p) {
  TubeProblem pr = problem(p);
  if (!(pr.t_end > 0.0))
    throw InputError("t_end must be > 0 for a run, got " + p.text("t_end") + " (t = 0 is for scoring initial conditions)");
  return pr;
}

TubeMethod method(const Params& p) {
  TubeMethod m;
  m.density = p.text("density");
  m.euler = p.text("euler");
  m.energy = p.text("energy");
  m.lambda = p.real("lambda");
  m.alpha = p.real("alpha");
  m.beta = p.real("beta");
  m.eps = p.real("eps");
  m.h_scale = p.text("visc_h") == "half" ? 0.5 : 1.0;
  m.controls.integrator = p.text("integrator") == "kdk" ? sph::IntegratorKind::kdk : sph::IntegratorKind::chapter;
  read_time_step(p, m.controls.step);
  m.controls.step.C_force = p.real("C_force");
  m.controls.step.C_energy = p.real("C_energy");
  m.hfact = p.real("hfact");
  m.kernel = p.text("kernel");
  m.scheme = p.text("scheme");
  m.controls.max_steps = p.integer("max_steps");
  return m;
}

Figure profile(const std::string& field, const std::string& label, const TubeRun& run,
               const std::vector<double>& value, const reference::RiemannSolution& exact, double t, long n, int dim) {
  Figure f{"profile_" + field, "Shock tube, " + std::to_string(dim) + "D, n = " + std::to_string(n) + ": " + label +
                                   " at t = " + std::to_string(t),
           "x", label};
  Series pts{"SPH particles", {}, {}, "points"};
  const std::size_t stride = std::max<std::size_t>(1, run.x.size() / 4000);
  for (std::size_t i = 0; i < run.x.size(); i += stride)
    if (run.x[i] >= 0.0 && run.x[i] <= 1.0) pts.x.push_back(run.x[i]), pts.y.push_back(value[i]);
  Series line{"exact (Toro)", {}, {}, "line"};
  for (int k = 0; k <= 2000; ++k) {
    const double x = k / 2000.0;
    const auto s = exact.sample(x, t);
    line.x.push_back(x);
    line.y.push_back(field == "rho" ? s.rho : field == "v" ? s.u : field == "p" ? s.p : s.e);
  }
  f.series = {pts, line};
  return f;
}

// The compression of the gas a shock crosses (rho* over the state ahead of it, 1 without a shock):
// behind it the lattice is c times denser along the tube and as dense as before across it.
double shock_compression(const Params& p) {
  const TubeProblem pr = problem(p);
  const reference::RiemannSolution exact(pr.left, pr.right, pr.gamma, pr.x0);
  return std::max({1.0, exact.rho_star_left() / pr.left.rho, exact.rho_star_right() / pr.right.rho});
}

template <int D>
Result run(const Params& p) {
  const TubeProblem pr = run_problem(p);
  if (pr.x_lo != 0.0 || pr.x_hi != 1.0 || pr.ends != "open")
    throw InputError("domain and ends describe a scored snapshot (sphv score); sphv run's tube is [0, 1], open");
  const long n = p.integer("n");
  const TubeRun run = simulate_tube<D>(pr, method(p), n);
  const TubeExact tube(pr);
  const reference::RiemannSolution& exact = tube.at_x0();
  Result r;
  std::optional<ContactError> contact;  // 1D: the contact's pressure error and blip
  r.n_particles = run.x.size();
  r.verdict = run.outcome.verdict;
  if (r.verdict == "ok" && p.text("preset") != "sod") r.verdict = "stable";
  if (r.verdict == "ok" || r.verdict == "stable") {
    r.errors = tube_l1_errors(run.x, run.v, run.rho, run.p, run.u, run.m, run.active, tube, pr.t_end);
    if constexpr (D == 1) contact = tube_contact_error(run.x, run.rho, run.p, run.m, run.active, tube, pr.t_end);
    if (contact) r.errors["L1_p_contact"] = contact->l1;
    r.figures = {profile("rho", "density rho", run, run.rho, exact, pr.t_end, n, D),
                 profile("v", "velocity v_x", run, run.v, exact, pr.t_end, n, D),
                 profile("p", "pressure p", run, run.p, exact, pr.t_end, n, D),
                 profile("u", "specific internal energy u", run, run.u, exact, pr.t_end, n, D)};
  }
  r.extra = {{"steps", run.outcome.steps},
             {"t_reached", run.outcome.t},
             {"x_extent", {run.box_lo, run.box_hi}},
             {"periodic_width", run.width},
             {"p_star", exact.p_star()},
             {"u_star", exact.u_star()},
             {"momentum_drift", run.momentum_drift},
             {"energy_drift", run.energy_drift},
             {"energy_rate", run.energy_rate},
             {"mass_drift", run.mass_drift},
             {"conservation_note", "active particles only; the boundary layers exert the end pressures"}};
  if (contact) r.extra["contact_blip"] = contact->amplitude;
  // The run's kernel's sums, on the initial lattice and (D > 1) on the one the shock compresses.
  LatticeSums sums, lc;
  const double c = D > 1 ? shock_compression(p) : 1.0;
  sph::with_kernel<D>(p.text("kernel"), [&](auto k) {
    sums = lattice_sums<D, decltype(k)>(p.real("hfact"));
    lc = compressed_lattice_sums<D, decltype(k)>(p.real("hfact"), c);
  });
  r.extra["lattice_S0_minus_1"] = sums.S0 - 1.0;
  r.extra["lattice_S1_minus_1"] = sums.S1 - 1.0;
  if constexpr (D > 1) {
    r.extra["shock_compression"] = c;
    r.extra["compressed_lattice_S1_across_minus_1"] = lc.S1_across - 1.0;
  }
  const char* axes[] = {"x", "y", "z"};
  for (int d = 0; d < D; ++d) r.particles.add(axes[d], run.position[d]);
  r.particles.add("vx", run.v);
  r.particles.add("m", run.m);
  r.particles.add("rho", run.rho);
  r.particles.add("p", run.p);
  r.particles.add("u", run.u);
  r.particles.add("h", run.h);
  return r;
}

std::vector<ParamSpec> params(long n_default, double hfact_default) {
  std::vector<ParamSpec> ps = {
      integer_param("n", n_default, "particles per unit length on the left (left spacing 1/n)"),
      choice_param("preset", "sod", "Riemann problem: sod = Toro 1; toro2 123; toro3/4 blast waves; toro5 collision",
                   {"sod", "toro2", "toro3", "toro4", "toro5"}),
  };
  for (const std::string k : state_keys)
    ps.push_back({k, ParamSpec::Kind::Text, "preset",
                  k == "x0" ? "interface position (default: the domain's middle, Toro's 0.5)"
                            : "number overriding the preset (default: the preset's)"});
  ps.push_back({"domain", ParamSpec::Kind::Text, "0,1",
                "x_lo,x_hi of the tube in a scored snapshot (sphv score: default the file's box; sphv run's tube is [0, 1])"});
  ps.push_back(choice_param("ends", "open",
                            "the tube's ends in a scored snapshot: open (a window of an unbounded tube, particles outside "
                            "not scored), periodic (a second interface at the wrap), closed (walls or free ends)",
                            {"open", "periodic", "closed"}));
  auto add = [&](const std::vector<ParamSpec>& more) { ps.insert(ps.end(), more.begin(), more.end()); };
  add({choice_param("density", "summation", "density: summation (27) or continuity (29)/(33)",
                    {"summation", "continuity29", "continuity33"}),
       choice_param("euler", "23", "Euler form (22), (23), (25) with lambda, (26)", {"22", "23", "25", "26"}),
       choice_param("energy", "auto", "energy form; auto = the Euler form's partner (22-37, 23-41, 25-lambda, 26-42)",
                    {"auto", "37", "38", "40", "41", "42"}),
       real_param("lambda", 1.5, "lambda of (25)"),
       choice_param("integrator", "kdk", "kick-drift-kick, or the chapter's leapfrog of 9.3.2", {"kdk", "chapter"})});
  add(time_step_params());
  add({real_param("C_force", 0.25, "acceleration criterion factor", 0.0),
       real_param("C_energy", 0.25, "cooling criterion dt <= C_energy u / |du/dt| (0: off)", -1e-300),
       real_param("alpha", 1.0, "artificial viscosity alpha (45)", -1e-300),
       real_param("beta", 2.0, "artificial viscosity beta (45)", -1e-300),
       real_param("eps", 0.01, "epsilon of (46)", 0.0),
       choice_param("visc_h", "half", "h in mu_ij (46): half the support radius (Monaghan) or the full one",
                    {"half", "full"}),
       real_param("hfact", hfact_default, "initial support radius / particle spacing (50)", 0.0),
       choice_param("kernel", "cubic_spline",
                    "the kernel (sph/kernel/kernels.hpp); other than cubic_spline: 1D, with density=summation, "
                    "euler=23, energy=auto",
                    sph::kernel_names()),
       integer_param("max_steps", 200000, "step budget (ends with a verdict)")});
  ps.push_back(forms_or_scheme_param("forms: the density, Euler and energy forms above as a scene, h by (53); or a "
                                     "scheme (sph/schemes/) with its own forms and h by (50), and hfact, alpha, beta"));
  return ps;
}

// A variant's name as the catalogue lists it: the settings other than n, joined ("default").
std::string variant_key(const Params& p) {
  std::string k;
  for (const auto& kv : p.non_defaults())
    if (kv.rfind("n=", 0) != 0) k += (k.empty() ? "" : ",") + kv;
  return k.empty() ? "default" : k;
}

// Measured errors {L1_rho, L1_v, L1_p, L1_u} at the finest quick level of every variant the
// catalogue runs (1D n = 800; 2D and 3D below; one thread). The
// bound on each error at the finest level of a sweep is the measured value + 20 % (errors fall
// with n, so it holds on the standard levels too); a method change of the size the variants
// show (visc_h=full against half: +45 % in L1_rho) breaks it. Continuity (29) does not converge:
// it is gated to stay above half its measured value (a floor) and below the same + 20 %.
using Errors4 = std::array<double, 4>;
const char* const error_names[] = {"L1_rho", "L1_v", "L1_p", "L1_u"};
const std::map<std::string, Errors4> measured_1d = {
    {"default", {4.016e-3, 1.721e-2, 4.943e-3, 2.267e-2}},
    {"density=continuity33", {4.547e-3, 1.704e-2, 6.385e-3, 2.254e-2}},
    {"density=continuity29", {1.046e-1, 1.208e-1, 1.084e-1, 1.338e-1}},
    {"euler=26", {3.988e-3, 1.682e-2, 4.804e-3, 2.216e-2}},
    {"euler=25", {3.862e-3, 1.651e-2, 4.713e-3, 2.190e-2}},
    {"euler=22", {6.439e-3, 1.793e-2, 6.345e-3, 3.729e-2}},
    {"energy=38", {4.067e-3, 1.690e-2, 4.767e-3, 2.193e-2}},
    {"integrator=chapter", {4.009e-3, 1.720e-2, 4.934e-3, 2.266e-2}},
    {"visc_h=full", {5.808e-3, 2.907e-2, 7.025e-3, 3.435e-2}},
    {"scheme=gradh_switches", {6.206e-3, 1.796e-2, 5.922e-3, 2.773e-2}},
};
// 2D: n = 200 (hfact 2.4), 100 (hfact 6); 3D: n = 24 (hfact 2.4), 16 (hfact 4).
const std::map<std::string, Errors4> measured_2d = {{"default", {1.528e-2, 3.821e-2, 1.668e-2, 4.012e-2}},
                                                   {"hfact=6", {1.999e-2, 5.575e-2, 2.047e-2, 8.146e-2}}};
const std::map<std::string, Errors4> measured_3d = {{"default", {4.474e-2, 1.095e-1, 5.945e-2, 1.452e-1}},
                                                   {"hfact=4", {3.938e-2, 1.141e-1, 4.919e-2, 1.916e-1}}};
// L1_p_contact (1D only, tube_contact_error) at n = 800 likewise; euler=22's at n = 6400, the finest
// level of its every tier, where its error has grown (its known failure). {value, n}.
const std::map<std::string, std::pair<double, long>> measured_contact_1d = {
    {"default", {2.423e-2, 800}},   {"density=continuity33", {5.498e-2, 800}}, {"density=continuity29", {1.735, 800}},
    {"euler=26", {2.268e-2, 800}},  {"euler=25", {2.380e-2, 800}},             {"euler=22", {9.672e-2, 6400}},
    {"energy=38", {2.145e-2, 800}}, {"integrator=chapter", {2.423e-2, 800}},   {"visc_h=full", {2.475e-2, 800}},
    {"scheme=gradh_switches", {9.463e-3, 800}},
};
constexpr double bound_margin = 1.2, floor_fraction = 0.5;

const Errors4* measured(const Params& p, int dim) {
  const auto& table = dim == 1 ? measured_1d : dim == 2 ? measured_2d : measured_3d;
  const auto it = table.find(variant_key(p));
  return it == table.end() ? nullptr : &it->second;
}

// 2D/3D lattices at a support ratio where the kernel's lattice sums are off by more than 0.2 %
// (common/lattice_sums.hpp), on the initial lattice or on the lattice the shock compresses (there
// h from (50) shrinks by c^(1/D) and spans fewer spacings across the tube): the tube's errors then
// level off. Sod (c = 2.12): at hfact 2.4 the initial lattice's S1 is off by 0.9 % (2D), 1.8 %
// (3D); at 4 the initial sums are within 0.09 % but the compressed lattice's flux across is off by
// 1.75 % (2D), 0.46 % (3D), and L1_rho's local orders fall, 0.69 and 0.55 on n = 100..400 (2D);
// at 6 every sum is within 0.11 % and they rise, 0.73, 0.87, 0.95 on 50..400.
// 3D: the compressed lattice at hfact 4 is off by 0.47 % across, and the density and pressure
// errors bend away from first order late: local orders about 0.75 from 64 to 128, 0.68 and 0.70
// from 128 to 192. No affordable 3D level is asymptotic at any hfact (at 6, L1_rho is 4.7e-2,
// 4.9e-2, 4.4e-2, 3.2e-2 on n = 16, 24, 32, 48: the right state's support radius spans the
// plateau; docs/cases/sod.md), so 3D judges the initial lattice only, at 0.1 %, and keeps the
// former claim, provisional.
constexpr double lattice_tolerance = 2e-3;
bool lattice_floor(const Params& p, int dim) {
  if (dim == 1) return false;
  const double hfact = p.real("hfact");
  if (dim == 3) {
    const LatticeSums l = lattice_sums<3>(hfact);
    return std::max(std::abs(l.S0 - 1.0), std::abs(l.S1 - 1.0)) > 1e-3;
  }
  const LatticeSums l = lattice_sums<2>(hfact), lc = compressed_lattice_sums<2>(hfact, shock_compression(p));
  return std::max({std::abs(l.S0 - 1.0), std::abs(l.S1 - 1.0), std::abs(lc.S0 - 1.0), std::abs(lc.S1 - 1.0),
                   std::abs(lc.S1_across - 1.0)}) > lattice_tolerance;
}

// Per level: stable, or (timestep=chapter) unstable as predicted. Then a bound on each error at
// the finest level (a floor as well for (29)). Momentum and energy of the tube are not gated
// here: the boundary layers push on the tube ends (impulse (p_l - p_r) t); conservation is gated
// on an isolated periodic gas in tests/hydro.cpp.
std::vector<Check> tube_gates(const Sweep& s, int dim) {
  std::vector<Check> c;
  const Params p = find_case(s.case_name).parse(s.settings);
  const bool chapter_dt = p.text("timestep") == "chapter";
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const bool stable = s.runs[k].verdict == "ok" || s.runs[k].verdict == "stable";
    const std::string level = "n" + std::to_string(s.levels[k]);
    if (!chapter_dt) {
      c.push_back({level + "_stable", double(stable), 1.0, 1.0, "runs to t_end with a finite, positive state"});
    } else {
      // (43) ignores the sound speed: from rest it takes dt = eta^2 (errata), 36x the Courant
      // step at n = 400. Measured: the first step ends with a particle's h <= 0 at every level.
      c.push_back({level + "_unstable", double(!stable), 1.0, 1.0, "(43) from rest: dt = eta^2 >> Courant limit"});
    }
  }
  const Errors4* m = measured(p, dim);
  if (!m || s.runs.empty()) return c;
  const bool floor = p.text("density") == "continuity29";
  const auto& fine = s.runs.back();
  // {error, measured value, the level it was measured at}
  std::vector<std::tuple<std::string, double, std::string>> bounded;
  for (int e = 0; e < 4; ++e) bounded.emplace_back(error_names[e], (*m)[e], dim == 1 ? "800" : "the finest quick level");
  if (dim == 1) {
    const auto& [v, n] = measured_contact_1d.at(variant_key(p));
    bounded.emplace_back("L1_p_contact", v, std::to_string(n));
  }
  for (const auto& [name, v, at] : bounded) {
    if (!fine.errors.count(name)) continue;
    c.push_back({name, fine.errors.at(name), floor ? floor_fraction * v : 0.0, bound_margin * v,
                 floor ? "(29) does not converge: between half and 1.2x the measured " + std::to_string(v)
                       : "finest level: measured " + std::to_string(v) + " at n = " + at + " + 20 %",
                 Check::Kind::drift, name});
  }
  if (dim > 1 && !lattice_floor(p, dim) && s.runs.size() >= 2 && fine.errors.count("L1_rho") &&
      s.runs.front().errors.count("L1_rho"))
    // 2D at hfact 6, 3D at 4: the error must fall with resolution (measured finest / coarsest
    // level: 0.28 in 2D on 100..400, 0.71 in 3D on 16..32).
    c.push_back({"L1_rho_falls", fine.errors.at("L1_rho") / s.runs.front().errors.at("L1_rho"), 0.0, 0.9,
                 "finest / coarsest level: must fall with resolution (measured 0.28 in 2D, 0.71 in 3D)",
                 Check::Kind::verification, "L1_rho"});
  return c;
}

// A tube's L1 error sums the shock's and the contact's smearing over a few h (first order in h ~
// 1/n: width h times the jump) and the rarefaction's smooth error (faster): asymptotically first
// order, approached from below while the contact's start-up error (the wall-heating blip the
// first steps leave) still weighs. Theory bounds the order from below, not to a rate: the claim is
// "at least 0.74", Athena++'s regression gate for Sod (an error ratio <= 0.6 per doubling).
const char* const why_first_order =
    "shock and contact are smeared over a few h ~ 1/n, an O(1/n) L1 contribution each, and the smooth "
    "rarefaction converges faster: the order is at least the shock's and contact's, approached from below "
    "while the contact's start-up error weighs; gated as at least 0.74, Athena++'s error ratio <= 0.6 per doubling";

// The contact's pressure error (L1_p_contact): the exact pressure is p* across the contact, and
// the scheme's blip there spans a few h ~ 1/n at an amplitude that does not grow with n (without
// conduction it stays at the density jump's own size; with conduction it falls): over a window of
// fixed width, an O(1/n) error or less, approached from below while the start-up error weighs.
const char* const why_contact =
    "the contact's pressure blip spans a few h ~ 1/n at an amplitude that does not grow with n (max |p/p* - 1| "
    "{extra.contact_blip} at {levels}): over a window of fixed width an O(1/n) error or less; gated as at least "
    "0.74, Athena++'s error ratio <= 0.6 per doubling";

const char* const why_former =
    "shock and contact are smeared over a few h ~ 1/n, an O(1/n) L1 contribution each: first order, the "
    "former claim 1 +- 0.5 kept until the levels reach the asymptotic range";

OrderClaims first_order(const Params& p, int dim) {
  if (p.text("timestep") == "chapter") return {};  // unstable at every level: no errors
  // 3D: the affordable levels are pre-asymptotic (lattice_floor): the former first-order claim,
  // provisional under the acceptance rule.
  OrderClaim claim = dim < 3 ? at_least(0.74, why_first_order) : OrderClaim{1.0, 0.5, why_former};
  // A known failure's reason as the contact's own error shows it (L1_p_contact's row quotes its
  // numbers, not the tube's L1 errors of the other four rows).
  const char* contact_failure = nullptr;
  // (29) is the Eulerian rate d(rho)/dt + v . grad rho: wrong by v . grad rho wherever a
  // density gradient moves (the contact), an O(1) error that does not converge (order about 0):
  // the claim every tube makes fails, and the default summation (27)
  // on the same tube is the experiment that converges.
  if (p.text("density") == "continuity29") {
    claim = known_failure(claim,
                          "(29) is the Eulerian rate: wrong by v . grad rho at the moving contact, an O(1) error that "
                          "does not converge (L1_rho {L1_rho} at {levels}, order {order.L1_rho}); gated to stay above "
                          "a floor (half its measured value)",
                          "density=summation");
    contact_failure = "(29) is the Eulerian rate: wrong by v . grad rho at the moving contact, so the pressure there "
                      "departs from p* by an O(1) blip that does not shrink (max |p/p* - 1| {extra.contact_blip}; "
                      "L1_p_contact {L1_p_contact} at {levels}, order {order.L1_p_contact})";
  } else if (p.text("euler") == "22") {
    // (22) weighs p_j alone: the force of i on j is not that of j on i, momentum is not conserved,
    // and across the shock the discrete jump conditions are not the exact ones, an error at the
    // shock that does not vanish with h. Between contact and shock the same unbalanced forces
    // drive a velocity noise that grows with n: L1_v 3.27e-2, 1.79e-2, 9.11e-3, 5.79e-3, 8.32e-3,
    // 3.48e-2 at n = 400..12800, nearly all of the rise between x = 0.55 and 0.9 (ten times the
    // default's there at 6400). The symmetric (23) on the same tube is the experiment.
    claim = known_failure(claim,
                          "(22) is not antisymmetric in i and j: momentum is not conserved and the shock's discrete jump "
                          "conditions miss the exact ones, an error that does not vanish with h, and the unbalanced "
                          "forces drive a velocity noise between contact and shock that grows again at the finest "
                          "levels (L1_p {L1_p}, L1_u {L1_u}, L1_v {L1_v} at {levels}; orders {order.L1_p}, "
                          "{order.L1_u}, {order.L1_v})",
                          "euler=23");
    contact_failure = "(22) is not antisymmetric in i and j: the unbalanced forces that drive the velocity noise "
                      "between contact and shock raise the contact's pressure blip with n (max |p/p* - 1| "
                      "{extra.contact_blip}; L1_p_contact {L1_p_contact} at {levels}, order {order.L1_p_contact})";
  } else if (lattice_floor(p, dim)) {
    // The tube's lattices keep h/dx = hfact on either side and, behind the shock, a lattice
    // compressed along the tube whose sums across it are further off (lattice_floor): the errors
    // stop falling at a level set by hfact, not n. The variant at hfact 6 (every sum within
    // 0.11 %) converges.
    claim = known_failure(claim,
                          "fixed-h/dx lattice-sum floor: at this hfact the kernel's density sum on the initial lattice "
                          "is off by {extra.lattice_S0_minus_1}, the pressure force's momentum flux by "
                          "{extra.lattice_S1_minus_1}, and across the lattice the shock compresses "
                          "{extra.shock_compression} times by {extra.compressed_lattice_S1_across_minus_1}, whatever n; "
                          "L1_rho {L1_rho} at {levels}",
                          dim == 2 ? "hfact=6" : "hfact=4");
  }
  if (!measured(p, dim)) {
    if (find_case(dim == 1 ? "sod" : "sod" + std::to_string(dim) + "d").method_in_catalogue(p)) claim.unbounded = true;
    else claim = no_order("method settings outside the catalogue's variants: no claim measured for this method, only the verdict is gated");
  }
  OrderClaim contact = claim;
  if (contact.known_failure() && contact_failure) contact.why = contact_failure;
  else if (contact.at_least && !contact.known_failure()) contact.why = why_contact;
  return {{"L1_rho", claim}, {"L1_v", claim}, {"L1_p", claim}, {"L1_u", claim}, {"L1_p_contact", contact}};
}

Case make_case(int dim) {
  Case c;
  c.name = dim == 1 ? "sod" : "sod" + std::to_string(dim) + "d";
  c.summary = dim == 1 ? "Sod / Toro 1-5 shock tubes in 1D against the exact Riemann solver"
                       : "Sod shock tube, " + std::to_string(dim) + "D lattice periodic across, against the exact solver";
  c.n_counts = "particles per unit length on the left state (equal masses: the right has n (rho_r/rho_l)^(1/D))";
  c.tags = {"gate", "sweep"};
  // 1D: support radius 4 dx, where lattice sums are exact (errata); at 2.4 dx the kernel-sum
  // error (~2e-3 in rho) is a floor that stops convergence near n = 1600. 2D/3D: 2.4 dx
  // (Phantom's default, ~18 and ~58 neighbours).
  c.params = params(dim == 1 ? 400 : dim == 2 ? 100 : 32, dim == 1 ? 4.0 : 2.4);
  c.orders = [dim](const Params& p) { return first_order(p, dim); };
  // First order is the physics of a discontinuous solution: it holds whatever the gas, the states
  // and where the tube lies (and for any code: sweep --runner).
  c.claim_domain = {"preset", "rho_l", "v_l", "p_l", "rho_r", "v_r", "p_r", "gamma", "t_end", "x0", "domain", "ends"};
  c.error_defs = tube_error_defs;
  c.expects_unstable = [](const Params& p) { return p.text("timestep") == "chapter"; };
  c.validate = [dim](const Params& p) {
    problem(p);
    const std::string euler = p.text("euler"), energy = p.text("energy");
    if (p.text("kernel") != "cubic_spline" &&
        (dim > 1 || p.text("density") != "summation" || euler != "23" || energy != "auto"))
      throw InputError("kernel=" + p.text("kernel") + ": only the 1D tube (sod) runs kernels other than cubic_spline, "
                       "with density=summation, euler=23, energy=auto");
    if (p.text("scheme") != "forms" &&
        (p.text("density") != "summation" || euler != "23" || energy != "auto" || p.text("kernel") != "cubic_spline" ||
         p.text("visc_h") != "half" || p.real("eps") != 0.01))
      throw InputError("scheme=" + p.text("scheme") + " has its own forms: density, euler, energy, kernel, visc_h and "
                       "eps do not apply");
    if (dim > 1 && energy != "auto" && energy != sph::partner_energy(euler))
      throw InputError("energy=" + energy + " with euler=" + euler + ": mixed pairings are 1D only (sod); in " +
                       std::to_string(dim) + "D the energy form is the Euler form's partner (energy=auto)");
  };
  if (dim == 1) {
    // From n = 400: below it the contact's start-up error holds the local orders of L1_v and L1_u
    // under 0.8 (docs/cases/sod.md); 1D costs a few seconds at 3200.
    // scheme=gradh_switches (grad-h, the viscosity switch, conduction; h by (50)): L1_rho 1.16e-2,
    // 6.21e-3, 3.42e-3, 1.84e-3 at n = 400..3200 (fit 0.88), L1_v 0.91, L1_p 0.96, L1_u 0.85: first
    // order like the chapter's forms, its errors at n = 800 1.5 (rho), 1.0 (v), 1.2 (p), 1.2 (u)
    // times the default variant's.
    c.levels = {.quick = {400, 800, 1600}, .standard = {400, 800, 1600, 3200}, .full = {400, 800, 1600, 3200, 6400}};
    c.levels_for = [levels = c.levels](const Params& p) {
      Levels l = levels;
      // (22): its velocity error falls to n = 3200 and grows from there (first_order): every tier
      // reaches 6400 (5 to 7 s), where the known failure shows; at 12800 the errors exceed the
      // drift bounds measured at 800.
      if (p.text("euler") == "22") l.quick = {1600, 3200, 6400}, l.standard = l.full;
      // (29): flat at every level; at 6400 its density drift collapses the Courant step (200,000
      // steps reach t = 0.152), so the full tier keeps the standard's levels.
      if (p.text("density") == "continuity29") l.full = l.standard;
      return l;
    };
    c.variants = {{},
                  {"density=continuity33"},
                  {"density=continuity29"},
                  {"euler=26"},
                  {"euler=25"},
                  {"euler=22"},
                  {"energy=38"},
                  {"integrator=chapter"},
                  {"timestep=chapter"},
                  {"visc_h=full"},
                  {"scheme=gradh_switches"}};
    c.run = run<1>;
  } else if (dim == 2) {
    // Quick: the known failure at two levels (CI gates that it stays below the claim).
    c.levels = {.quick = {100, 200}, .standard = {100, 200, 400}, .full = {100, 200, 400, 800}};
    // hfact 6 is the smallest support whose lattices, initial and compressed, stay within 0.2 %
    // (lattice_floor; at 4 the density and pressure errors level off, docs/cases/sod.md). It
    // converges from n = 100 (local orders 0.79 to 1.0 from 200 to 400), where its L1_u and L1_v
    // still fall at 0.69 and 0.62 to n = 200: one level in quick (4 s), 100..400 in standard (70 s).
    c.variants = {{}, {"hfact=6"}};
    c.levels_for = [levels = c.levels](const Params& p) {
      Levels l = levels;
      if (p.real("hfact") == 6.0) l.quick = {100};
      return l;
    };
    c.run = run<2>;
  } else {
    // hfact 4 costs about ten times as much a particle (4.6x the neighbours, 4x the particles
    // across): one level in quick. Its standard levels reach n = 48: the right state's support
    // radius h_r = 2 hfact / n is 0.5 at n = 16, wider than the plateau between the fan and the
    // shock (0.46), and until h_r falls below the 0.062 between the shock and x = 1 the error ahead of
    // the shock samples a window of fixed width, so L1_v stalls from 16 to 24 and a fit over
    // 16..32 does not resolve its order; over 16..48 it does (docs/cases/sod.md).
    c.levels = {.quick = {16, 24}, .standard = {16, 24, 32}, .full = {16, 24, 32, 48}};
    c.variants = {{}, {"hfact=4"}};
    c.levels_for = [levels = c.levels](const Params& p) {
      Levels l = levels;
      if (p.real("hfact") == 4.0) l.quick = {16}, l.standard = l.full;
      return l;
    };
    c.run = run<3>;
  }
  c.gates = [dim](const Sweep& s) { return tube_gates(s, dim); };
  c.scorer = tube::scorer();
  c.ic = tube::initial_conditions(dim);
  return c;
}

const Registration reg1{make_case(1)};
const Registration reg2{make_case(2)};
const Registration reg3{make_case(3)};

}  // namespace
}  // namespace sphv::sod_case

namespace sphv {
TubeProblem tube_problem(const Params& p) { return sod_case::problem(p); }
std::map<std::string, std::pair<reference::GasState, reference::GasState>> tube_presets() {
  std::map<std::string, std::pair<reference::GasState, reference::GasState>> states;
  for (const auto& [name, preset] : sod_case::presets) states[name] = {preset.l, preset.r};
  return states;
}
}  // namespace sphv
