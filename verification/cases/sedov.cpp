// Case `sedov`: the Sedov-Taylor point blast in 2D and 3D. Energy E = 1 is put, as heat, into the
// particles within r_blast R of the centre of a uniform, nearly cold gas (rho0 = 1) in a periodic
// box; at t_end the shock should sit at R = xi_0 (E t^2 / rho0)^(1/(d+2)) = 0.3 (box half-width
// 0.5). Independent reference: reference/sedov (similarity ODEs integrated by GSL, xi_0 from the
// energy integral, checked against the published table in tests/extreme.cpp).
//
// Blast radius: a fixed fraction of R (r_blast = 1/4), not the initial h. Deposited over one
// kernel of the initial h, the blast sat on the same ~20 particles at every resolution; their
// volume cannot represent the hot, nearly empty centre, and they kept a resolution-independent
// excess of the energy as heat (measured, 2D n = 64: 0.30 E as heat within R/2 against 0.127 E
// exact; kinetic energy 0.237 E against 0.267 E). The profile lagged by 6.3, 4.8, 4.0% of R at
// n = 32, 64, 128 (best-fitting R) and the density L1 did not converge (0.277, 0.279, 0.253).
// With the blast on R/4 (the same particles at n = 32): lag 6.3, 2.5, 0.5%, kinetic energy
// 0.225, 0.262, 0.270 E. The blast's finite size is remembered at t_end; at these levels it is
// below the shock's smearing (the sweep's order says so).
#include <cmath>

#include "reference/sedov.hpp"
#include "verification/case.hpp"
#include "verification/cases/extreme_hydro.hpp"
#include "verification/cases/centre_param.hpp"
#include "verification/cases/radial_result.hpp"
#include "verification/cases/sedov_errors.hpp"
#include "verification/cases/sedov_setup.hpp"
#include "verification/sweep.hpp"

namespace sphv::sedov_case {
namespace {

using sedov::R_target;

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  extreme::Method m = extreme::method(prm);
  const reference::Sedov exact(D, m.gamma);
  const double E = prm.real("E"), rho0 = prm.real("rho0");
  if (radial::centre<D>(prm) != sph::Vec<D>::Zero())
    throw InputError("sedov: centre is for scoring snapshots (sphv score); sphv run puts the blast at the origin");
  m.controls.t_end = sedov::end_time(prm);
  const sph::Box<D> box = sedov::box<D>();
  // The blast in a cold gas (u_ambient: the similarity solution's, p0 / p_shock ~ 1e-6).
  sph::Particles<D> p = sedov::initial_particles<D>(prm, m.hfact);
  m.h_max = 0.45;  // below half the periodic box
  const double r_b = prm.real("r_blast") * R_target;
  double E0 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) E0 += p.m[i] * p.u[i];

  const sph::HydroOutcome out = extreme::evolve_gas(p, box, m);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"t_end", m.controls.t_end}, {"xi0", exact.xi0()},
             {"R_exact", exact.shock_radius(E, rho0, m.controls.t_end)}, {"dim", D}, {"r_blast", r_b}};
  if (r.verdict != "stable") return r;

  double E1 = 0.0, kinetic = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    kinetic += 0.5 * p.m[i] * p.v[i].squaredNorm();
    E1 += p.m[i] * (0.5 * p.v[i].squaredNorm() + p.u[i]);
  }
  sedov::measure<D>(r, p.x, p.v, p.m, p.rho, n, E, rho0, out.t, exact);
  r.extra["energy_drift"] = (E1 - E0) / E0;
  r.extra["kinetic_fraction"] = kinetic / E1;
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

Result run(const Params& p) { return p.integer("dim") == 2 ? run_dim<2>(p) : run_dim<3>(p); }

void validate(const Params& p) {
  const long d = p.integer("dim"), n = p.integer("n");
  if (d != 2 && d != 3) throw InputError("sedov: dim must be 2 or 3");
  if (n < 8) throw InputError("sedov: need n >= 8 particles per side");
  if (!(p.real("u_ambient") >= 0.0)) throw InputError("sedov: u_ambient must be >= 0");
  const double r_blast = p.real("r_blast");
  if (!(r_blast < 1.0)) throw InputError("sedov: r_blast must be below 1 (a fraction of the final shock radius)");
  // The lattice particles nearest the centre sit at sqrt(d) / (2 n) from it.
  if (r_blast * R_target <= std::sqrt(double(d)) / (2.0 * n))
    throw InputError("sedov: r_blast R = " + std::to_string(r_blast * R_target) +
                     " holds no particle: raise r_blast or n");
}

// Measured L1_rho at the finest quick level of each catalogue variant (2D n = 32, 3D n = 16; one
// thread, the drift baseline's values): default 0.2772, dim=3 0.3059, gamma=1.4 0.3966,
// energy=41 0.2829. The bound at a sweep's finest level is that + 20 % (2D: the error falls with n,
// 0.277, 0.203, 0.112 at n = 32, 64, 128, so it holds on the standard levels; 3D: 0.306, 0.341 at
// n = 16, 24, it does not fall yet, and the bound is gated at the quick level only).
double l1_measured(const Params& p) {
  if (p.integer("dim") == 3) return 0.3059;
  if (p.real("gamma") == 1.4) return 0.3966;
  return p.text("energy") == "41" ? 0.2829 : 0.2772;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c = radial::per_level(s, [](const std::string& level, const Result& r, std::vector<Check>& c) {
    // Measured |R_front - R| / R: 2D 1.9%, 1.9%, 0.4% (n = 32, 64, 128); 3D 9.2% (n=16, blast on
    // 8 particles). Tolerances: 2D 6% (margin 3), 3D 12% (margin 1.3).
    const double tol = r.extra.value("dim", 2) == 3 ? 0.12 : 0.06;
    c.push_back({level + "_shock_radius", r.errors.at("shock_radius"), 0.0, tol,
                 "R_front within tol of xi_0 (E t^2/rho)^(1/(d+2)) (measured, margin >= 1.3)", Check::Kind::verification,
                 "shock_radius"});
  });
  // 2D: the finest level; 3D: the quick level n = 16 (the error does not fall yet, see above).
  const Params p = find_case(s.case_name).parse(s.settings);
  const bool d3 = p.integer("dim") == 3;
  for (std::size_t k = 0; k < s.runs.size(); ++k) {
    const bool gated = d3 ? s.levels[k] == 16 : k + 1 == s.runs.size();
    if (!gated || !s.runs[k].errors.count("L1_rho")) continue;
    const double m = l1_measured(p);
    c.push_back({"n" + std::to_string(s.levels[k]) + "_L1_rho", s.runs[k].errors.at("L1_rho"), 0.0, 1.2 * m,
                 "measured " + std::to_string(m) + " at the quick level + 20 %", Check::Kind::verification, "L1_rho"});
  }
  return c;
}

// 2D, density L1 (theory 1 once the shock's smearing over ~h dominates). Measured at n = 32, 64,
// 128: gamma 5/3 with (38) 0.277, 0.203, 0.112 (local orders 0.45, 0.86; fit 0.65); gamma 1.4
// 0.397, 0.330, 0.213 (0.27, 0.63; fit 0.45); (41) 0.283, 0.202, 0.109 (0.49, 0.88; fit 0.69).
// With the blast on the initial kernel it was 0.277, 0.279, 0.253 (orders -0.01, 0.14): a band
// that admits that must not be. Band 0.6 around 1 (pre-asymptotic: the local order rises towards
// 1; n = 32 holds the blast's R/4 on 2.4 spacings), plus 2 se of the fit. The shock radius error
// is a few % and not monotone in n (1.9, 1.9, 0.4 %): bounded, no order claimed.
// 3D at n = 16, 24 (0.306, 0.341): pre-asymptotic, the blast on 8 and 32 particles: no order.
OrderClaims sedov_orders(const Params& p) {
  const OrderClaim radius = no_order("the front position error is a few per cent and not monotone on the affordable "
                                     "levels (2D 1.9, 1.9, 0.4 % at n = 32, 64, 128): bounded at every level");
  if (p.integer("dim") == 3)
    return {{"shock_radius", radius},
            {"L1_rho", no_order("3D pre-asymptotic: L1 0.306, 0.341 at n = 16, 24 (the blast on 8 and 32 particles); "
                                "bounded at the quick level, the full tier (n up to 48) looks for the order")}};
  return {{"shock_radius", radius},
          {"L1_rho", {1.0, 0.6, "a shock smeared over a few h: L1 first order in h at fixed hfact; pre-asymptotic "
                                "on 32..128 (measured fits 0.45-0.69, local orders rising towards 1)"}}};
}

// Cost (wall, one thread, loaded machine): 2D n = 32 ~4 s, 64 ~8 s, 128 ~60 s (steps ~ n, particles
// ~ n^2); 256 ~ 8 min (estimated). Quick: one level (the L1 bound and the front); standard: the
// order on three levels; full adds 256.
const Levels levels = {.quick = {32}, .standard = {32, 64, 128}, .full = {32, 64, 128, 256}};

const Registration reg{Case{
    .name = "sedov",
    .summary = "Sedov-Taylor blast (2D/3D): shock radius and density profile against the similarity solution",
    .n_counts = "particles per side of the periodic unit box",
    .tags = {"gate", "extreme", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 32, "particles per side"),
                                   integer_param("dim", 2, "dimension 2 or 3"),
                                   real_param("u_ambient", 1e-6, "specific internal energy of the ambient gas"),
                                   real_param("r_blast", 0.25, "radius of the blast's heat deposit / R(t_end)", 0.0),
                                   real_param("E", 1.0, "blast energy", 0.0),
                                   real_param("rho0", 1.0, "ambient density", 0.0),
                                   ParamSpec{"t", ParamSpec::Kind::Real, "0", "end time; 0: when the shock reaches R = 0.3",
                                             std::nullopt, 0.0},
                                   radial::centre_param()};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = levels,
    .orders = sedov_orders,
    .error_defs = sedov::error_defs,
    .variants = {{}, {"dim=3"}, {"gamma=1.4"}, {"energy=41"}},
    .levels_for = [](const Params& p) {
      // 3D: n = 16 ~25 s (4096 particles), 24 ~2 min, 32 ~6 min, 48 ~40 min (estimated ~n^4). No
      // order is claimed (pre-asymptotic), so standard stays at the quick level and full carries
      // the resolutions that may show one.
      if (p.integer("dim") == 3) return Levels{.quick = {16}, .standard = {16}, .full = {16, 24, 32, 48}};
      return levels;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::sedov_case
