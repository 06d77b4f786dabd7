// Case `sedov`: the Sedov-Taylor point blast in 2D and 3D. Energy E = 1 is put into the
// particles within one support radius of the centre of a uniform, nearly cold gas (rho0 = 1) in
// a periodic box; at t_end the shock should sit at R = xi_0 (E t^2 / rho0)^(1/(d+2)) = 0.3 (box
// half-width 0.5). Independent reference: reference/sedov (similarity ODEs integrated by GSL,
// xi_0 from the energy integral, checked against the published table in tests/extreme.cpp).
#include <cmath>

#include "reference/sedov.hpp"
#include "verification/case.hpp"
#include "verification/cases/extreme_hydro.hpp"
#include "verification/sweep.hpp"

namespace sphv {
namespace {

constexpr double R_target = 0.3;

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  extreme::Method m = extreme::method(prm);
  const reference::Sedov exact(D, m.gamma);
  const double E = 1.0, rho0 = 1.0;
  m.controls.t_end = std::sqrt(std::pow(R_target / exact.xi0(), D + 2) * rho0 / E);
  sph::Box<D> box = sph::unit_box<D>(true);
  box.lo = sph::Vec<D>::Constant(-0.5);
  box.hi = sph::Vec<D>::Constant(0.5);
  sph::Particles<D> p = sph::lattice<D>(n, box, rho0, m.hfact);
  m.h_max = 0.45;  // below half the periodic box
  // Blast: E shared by kernel weight among the particles within h0 of the centre; the rest has
  // a thermal energy u_ambient (the similarity solution's cold gas, p0 / p_shock ~ 1e-6).
  const double h0 = p.h[0];
  double wsum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) wsum += p.m[i] * sph::CubicSpline<D>::W(p.x[i].norm(), h0);
  for (std::size_t i = 0; i < p.size(); ++i)
    p.u[i] = prm.real("u_ambient") + E * sph::CubicSpline<D>::W(p.x[i].norm(), h0) / wsum;
  double E0 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) E0 += p.m[i] * p.u[i];

  const sph::HydroOutcome out = extreme::evolve_gas(p, box, m);
  Result r;
  r.n_particles = p.size();
  r.verdict = out.verdict == "ok" ? "stable" : out.verdict;
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"t_end", m.controls.t_end}, {"xi0", exact.xi0()},
             {"R_exact", exact.shock_radius(E, rho0, m.controls.t_end)}, {"dim", D}};
  if (out.verdict != "ok") return r;

  double E1 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) E1 += p.m[i] * (0.5 * p.v[i].squaredNorm() + p.u[i]);
  const double R = exact.shock_radius(E, rho0, out.t), dx = 1.0 / n;
  const std::vector<double> rad = extreme::radii(p);
  // Shock radius: where the density profile (binned at half the spacing) rises, coming from
  // outside, to half-way between the ambient density and its peak. SPH smooths the jump over a
  // few h; the half-rise point of a symmetrically smoothed jump is the jump, while the smoothed
  // peak trails it by about half a kernel width.
  const extreme::Profile prof = extreme::radial_profile(rad, p.rho, 0.5, 2 * n);
  const auto peak = std::max_element(prof.mean.begin(), prof.mean.end()) - prof.mean.begin();
  const double half = 0.5 * (rho0 + prof.mean[peak]);
  double R_front = prof.r[peak];
  for (auto k = static_cast<std::size_t>(peak); k + 1 < prof.r.size(); ++k)
    if (prof.mean[k] >= half && prof.mean[k + 1] < half) {
      R_front = prof.r[k] + (prof.r[k + 1] - prof.r[k]) * (prof.mean[k] - half) / (prof.mean[k] - prof.mean[k + 1]);
      break;
    }
  const double R_peak = prof.r[peak];
  // L1 density error, volume-weighted, over the ball r < 1.2 R (shocked gas and some ambient).
  double vol = 0.0, l1 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (rad[i] < 1.2 * R) {
      const double w = p.m[i] / p.rho[i];
      vol += w;
      l1 += w * std::abs(p.rho[i] - exact.density(rad[i], E, rho0, out.t));
    }
  r.errors = {{"shock_radius", std::abs(R_front - R) / R}, {"L1_rho", l1 / vol / rho0}};
  r.functionals = {{"R_front", R_front}, {"rho_peak", prof.mean[peak]}};
  r.extra["R_front"] = R_front;
  r.extra["R_peak"] = R_peak;
  r.extra["rho_peak_binned"] = prof.mean[peak];
  r.extra["rho_peak_exact"] = exact.g(1.0) * rho0;
  r.extra["energy_drift"] = (E1 - E0) / E0;
  r.extra["bin_width"] = 0.5 * dx;

  Series pts{"SPH particles", {}, {}, "points"}, line{"Sedov-Taylor (similarity solution)", {}, {}, "line"};
  const std::size_t stride = std::max<std::size_t>(1, p.size() / 4000);
  for (std::size_t i = 0; i < p.size(); i += stride)
    if (rad[i] < 1.5 * R) pts.x.push_back(rad[i] / R), pts.y.push_back(p.rho[i] / rho0);
  for (int k = 0; k <= 600; ++k) {
    const double xi = 1.5 * k / 600.0;
    line.x.push_back(xi), line.y.push_back(exact.g(xi));
  }
  r.figures.push_back({"profile_rho", "Sedov " + std::to_string(D) + "D, n = " + std::to_string(n) + ": density at t = " +
                                          std::to_string(out.t),
                       "r / R(t)", "rho / rho0", "linear", "linear", {pts, line}});
  Series vp{"SPH particles", {}, {}, "points"}, vl{"Sedov-Taylor", {}, {}, "line"};
  const double U = exact.shock_speed(E, rho0, out.t);
  for (std::size_t i = 0; i < p.size(); i += stride)
    if (rad[i] < 1.5 * R) vp.x.push_back(rad[i] / R), vp.y.push_back(p.v[i].dot(p.x[i]) / std::max(rad[i], 1e-300) / U);
  for (int k = 0; k <= 600; ++k) {
    const double xi = 1.5 * k / 600.0;
    vl.x.push_back(xi), vl.y.push_back(exact.f(xi));
  }
  r.figures.push_back({"profile_v", "Sedov " + std::to_string(D) + "D: radial velocity", "r / R(t)",
                       "v_r / (dR/dt)", "linear", "linear", {vp, vl}});
  r.particles = extreme::particle_table(p);
  return r;
}

Result run(const Params& p) { return p.integer("dim") == 2 ? run_dim<2>(p) : run_dim<3>(p); }

void validate(const Params& p) {
  if (p.integer("dim") != 2 && p.integer("dim") != 3) throw InputError("sedov: dim must be 2 or 3");
  if (p.integer("n") < 8) throw InputError("sedov: need n >= 8 particles per side");
  if (!(p.real("u_ambient") >= 0.0)) throw InputError("sedov: u_ambient must be >= 0");
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const auto& r = s.runs[k];
    const std::string level = "n" + std::to_string(s.levels[k]);
    c.push_back({level + "_stable", double(r.verdict == "stable"), 1.0, 1.0, "runs to t_end with a finite, positive state"});
    if (r.verdict != "stable") continue;
    // Measured |R_front - R| / R: 2D 1.9% (n=32), 3.7% (n=64); 3D 8.4% (n=16, h0 = R/2), 1.9%
    // (n=24). Tolerances: 2D 6%, 3D 12% (margin about 1.5 over the worst measured).
    const double tol = r.extra.value("dim", 2) == 3 ? 0.12 : 0.06;
    c.push_back({level + "_shock_radius", r.errors.at("shock_radius"), 0.0, tol,
                 "R_front within tol of xi_0 (E t^2/rho)^(1/(d+2)) (measured, margin ~1.5)"});
  }
  return c;
}

const Registration reg{Case{
    .name = "sedov",
    .summary = "Sedov-Taylor blast (2D/3D): shock radius and density profile against the similarity solution",
    .n_counts = "particles per side of the periodic unit box",
    .tags = {"gate", "extreme", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 32, "particles per side"),
                                   integer_param("dim", 2, "dimension 2 or 3"),
                                   real_param("u_ambient", 1e-6, "specific internal energy of the ambient gas")};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = {32, 64, 128},
    .gate_levels = {32},
    .expected_order = [](const Params&) { return std::map<std::string, double>{{"shock_radius", 1.0}, {"L1_rho", 1.0}}; },
    .expected_why = "a shock smeared over a few h: errors first order in h at fixed hfact",
    .variants = {{}, {"dim=3"}, {"gamma=1.4"}, {"energy=41"}},
    .levels_for = [](const Params& p, std::vector<long> l) {
      // 2D 32, 64, 128; 3D 16, 24, 32 (the gate's 32 maps to 16).
      if (p.integer("dim") == 3) for (auto& v : l) v = v == 32 ? 16 : v == 64 ? 24 : 32;
      return l;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv
