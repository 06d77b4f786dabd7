// Case `conservation_gradh`: density by continuity against summation, and the energy error of the
// neglected grad-h terms (9.4.4, errata). A polytropic gas (35), p = K rho^gamma, with Euler form
// (26) has the total energy E = sum_i m_i (v_i^2/2 + K rho_i^(gamma-1)/(gamma-1)) with no energy
// equation: dE/dt = sum_i m_i (v_i . a_i + p_i/rho_i^2 drho_i/dt), which (97)-(104) make zero
// whenever drho_i/dt = sum_j m_j v_ij . grad_i W_ij. That holds for
//   - summation (27) with fixed support radii (the exact time derivative of the sum),
//   - continuity (33) with fixed or variable radii (it is the rate the integrator uses),
// so their E changes only by the leapfrog's O(dt^2). It fails for
//   - summation with variable radii (53): the sum's true rate has the neglected term
//     sum_j m_j dW_ij/dh_ij dh_ij/dt (the grad-h term), an O(1) error in dt;
//   - continuity (29): it differs from (33) by v_i . sum_j m_j grad_i W_ij, non-zero at a free
//     surface.
// Continuity (33) tracks the summation density at fixed radii to O(dt^2); with variable radii it
// drifts from it by the grad-h term. Reference: the exact invariance of E and, for the density,
// the summation (27) at the final positions.
#include <cmath>
#include <limits>
#include <map>

#include "sph/density/terms.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/euler.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/conservation/scene.hpp"
#include "verification/cases/common/measured_bound.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::conservation_gradh_case {
namespace {

constexpr int D = 2;
const sph::Polytropic gas{1.0, 2.0};  // K = 1, gamma = 2: c ~ 1.4 .. 2.8 in the blobs

double polytropic_energy(const sph::Particles<D>& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    e += p.m[i] * (0.5 * p.v[i].squaredNorm() + gas.K * std::pow(p.rho[i], gas.gamma - 1.0) / (gas.gamma - 1.0));
  return e;
}

// Largest |rho_i - (27)_i| / (27)_i at the particles' positions and radii.
double deviation_from_summation(const sph::Particles<D>& p) {
  sph::Particles<D> q = p;
  const auto open = sph::unit_box<D>(false);
  sph::density_summation(q, sph::grid_search<D>(q.x, q.h, open), open);
  double dev = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) dev = std::max(dev, std::abs(p.rho[i] - q.rho[i]) / q.rho[i]);
  return dev;
}

struct Outcome {
  double energy = 0.0, rho = 0.0;
  std::vector<double> t, energy_t;
  std::string verdict;
};

template <class Density, class... Extra>
Outcome evolve(const sph::Particles<D>& initial, double dt, long steps) {
  sph::Particles<D> p = initial;
  sph::Scene<D, Density, sph::EquationOfState<D, sph::Polytropic>, sph::EulerSymmetric<D, sph::Lambda2>, Extra...>
      scene{{Density{}, sph::EquationOfState<D, sph::Polytropic>{gas}, {}, Extra{}...}};
  const auto d = conservation::run_fixed_steps(scene, p, sph::IntegratorKind::kdk, dt, steps, polytropic_energy);
  return {d.max_of(d.energy), deviation_from_summation(p), d.t, d.energy, d.verdict};
}

// Fixed radii, then variable radii (53), with the density method of the run.
template <class Density>
std::pair<Outcome, Outcome> both_radii(const sph::Particles<D>& initial, double dt, long steps) {
  return {evolve<Density>(initial, dt, steps), evolve<Density, sph::SmoothingLengthRate<D>>(initial, dt, steps)};
}

Result run(const Params& p) {
  using enum sph::ContinuityForm;
  const double dt = 1.0 / p.integer("n");
  const long steps = std::lround(p.real("t_end") / dt);
  const std::string density = p.text("density");
  const auto initial = conservation::colliding_blobs<D>(p.integer("res"), 2.4);
  const auto [fixed, variable] = density == "summation"      ? both_radii<sph::SummationDensity<D>>(initial, dt, steps)
                                 : density == "continuity33" ? both_radii<sph::ContinuityDensity<D, difference33>>(initial, dt, steps)
                                                             : both_radii<sph::ContinuityDensity<D, direct29>>(initial, dt, steps);
  Result r;
  r.n_particles = initial.size();
  r.verdict = fixed.verdict != "ok" ? "fixed h: " + fixed.verdict
              : variable.verdict != "ok" ? "variable h: " + variable.verdict
                                         : "ok";
  r.errors = {{"energy_fixed_h", fixed.energy}, {"energy_variable_h", variable.energy}};
  if (density != "summation") r.errors["rho_fixed_h"] = fixed.rho, r.errors["rho_variable_h"] = variable.rho;
  r.extra = {{"dt", dt}, {"steps", steps}, {"grad_h_energy_error", variable.energy - fixed.energy}};
  Figure f{"energy_time", "Energy error, " + density + " density, dt = 1/" + std::to_string(p.integer("n")), "time t",
           "|E(t) - E(0)| / E(0)", "linear", "log", {}};
  for (const auto& [label, o] : {std::pair{"fixed h", &fixed}, std::pair{"variable h (53)", &variable}}) {
    Series s{label, {}, {}, "line"};
    for (std::size_t k = 1; k < o->t.size(); ++k) s.x.push_back(o->t[k]), s.y.push_back(std::max(o->energy_t[k], 1e-18));
    f.series.push_back(s);
  }
  r.figures = {f};
  return r;
}

// Order 2 (leapfrog, as conservation_dt: band +-0.3 around 2, measured 1.85-2.00) where drho/dt
// is the rate the energy proof (97)-(104) needs; order 0 (band +-0.3) where a semi-discrete term
// is missing (grad-h with variable h, (29) at a free surface): that error does not shrink with dt.
OrderClaims orders(const Params& p) {
  const OrderClaim two{2.0, 0.3, "semi-discrete invariant: only the O(dt^2) leapfrog error"};
  // A semi-discrete error has no limit as dt -> 0: no order is claimed; the gates check that it
  // is present and does not change with dt.
  const OrderClaim zero = no_order("semi-discrete error (grad-h or (29)), independent of dt: no limit as dt goes to "
                                   "zero; gated to be present and to keep its size at every dt");
  const std::string d = p.text("density");
  if (d == "summation") return {{"energy_fixed_h", two}, {"energy_variable_h", zero}};
  if (d == "continuity33") return {{"energy_fixed_h", two}, {"energy_variable_h", two}, {"rho_fixed_h", two}, {"rho_variable_h", zero}};
  return {{"energy_fixed_h", zero}, {"energy_variable_h", zero}, {"rho_fixed_h", zero}, {"rho_variable_h", zero}};
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  for (const auto& r : s.runs)
    c.push_back({"verdict_n" + std::to_string(r.params.value("n", 0L)), r.verdict == "ok" ? 1.0 : 0.0, 1.0, 1.0,
                 r.verdict});
  for (const auto& [name, claim] : s.claims)
    if (!claim.claimed()) {
      // Measured >= 2.4e-2 (grad-h energy) and >= 0.7 (densities) at every dt: 1e-3 is a margin
      // of 20 and still 1e13 above round-off, so an error that vanished would fail here.
      c.push_back({name + "_present", s.runs.back().errors.at(name), 1e-3, std::numeric_limits<double>::infinity(),
                   "the missing semi-discrete term must be visible", Check::Kind::verification, name});
      // Independent of dt: its fitted order in dt within 0 +- 0.3 (measured: it changes by less
      // than 0.5 % over dt = 1/200 .. 1/1600, an order below 0.003).
      if (const auto o = s.observed_order.find(name); o != s.observed_order.end())
        c.push_back({name + "_independent_of_dt", o->second.p, -0.3, 0.3, "semi-discrete: the error keeps its size as dt falls",
                     Check::Kind::verification, name});
    }
  // Upper bounds: every error measured at dt = 1/1600 (deterministic set-up, seed 11) times 1.5,
  // carried to the finest level by its claimed order (dt^2, or none for the semi-discrete errors,
  // which change by less than 0.5 % over dt = 1/200 .. 1/1600). Over 1/200 .. 1/1600 no error
  // lies above that line (the dt^2 errors fall at local orders 1.85-2.0, so the coarser ones lie
  // up to 27 % below it). A variant not measured here has no bound: its rows fail.
  static const std::map<std::string, std::map<std::string, double>> measured_1600 = {
      {"default", {{"energy_fixed_h", 2.373e-06}, {"energy_variable_h", 2.359e-02}}},
      {"density=continuity33",
       {{"energy_fixed_h", 3.342e-06}, {"energy_variable_h", 3.477e-06}, {"rho_fixed_h", 6.461e-05}, {"rho_variable_h", 7.370e-01}}},
      {"density=continuity29",
       {{"energy_fixed_h", 1.801e-01}, {"energy_variable_h", 1.829e-01}, {"rho_fixed_h", 3.702}, {"rho_variable_h", 5.465}}}};
  if (const auto m = measured_1600.find(s.variant()); m != measured_1600.end())
    for (const auto& [name, v] : m->second) c.push_back(measured_bound(s, name, v, 1600, 1.5));
  return c;
}

const Registration reg{Case{
    .name = "conservation_gradh",
    .summary = "continuity against summation density, and the energy error of the neglected grad-h terms (9.4.4)",
    .n_counts = "time steps per unit time (dt = 1/n)",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 400, "time steps per unit time"),
               choice_param("density", "summation", "density method", {"summation", "continuity33", "continuity29"}),
               integer_param("res", 12, "particles per blob diameter"),
               real_param("t_end", 0.2, "end time", 0.0)},
    // Full adds dt = 1/3200 (CPU times: docs/cases/conservation.md).
    .levels = {.quick = {400, 800, 1600}, .standard = {200, 400, 800, 1600}, .full = {200, 400, 800, 1600, 3200}},
    .orders = orders,
    .error_defs = {{"energy_fixed_h", "largest |E(t) - E(0)| / E(0) over the run, fixed smoothing lengths"},
                   {"energy_variable_h", "largest |E(t) - E(0)| / E(0) over the run, h by (53) without grad-h terms"},
                   {"rho_fixed_h", "max_i |rho_i - rho_i(27)| / rho_i(27) at t_end: evolved density against the summation, fixed h"},
                   {"rho_variable_h", "max_i |rho_i - rho_i(27)| / rho_i(27) at t_end: evolved density against the summation, h by (53)"}},
    .variants = {{}, {"density=continuity33"}, {"density=continuity29"}},
    .validate = [](const Params& p) {
      if (p.integer("n") * p.real("t_end") < 1.0) throw InputError("conservation_gradh: t_end * n must be at least one step");
      if (p.integer("res") < 4) throw InputError("conservation_gradh: res must be at least 4 particles per diameter");
    },
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::conservation_gradh_case
