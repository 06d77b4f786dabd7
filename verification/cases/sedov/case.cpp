// Case `sedov`: the Sedov-Taylor point blast in 2D and 3D. Energy E = 1 is put, as heat, into the
// particles within r_blast R of the centre of a uniform, nearly cold gas (rho0 = 1) in a periodic
// box; at t_end the shock should sit at R = xi_0 (E t^2 / rho0)^(1/(d+2)) = 0.3 (box half-width
// 0.5). Independent references: reference/sedov (similarity ODEs integrated by GSL, xi_0 from the
// energy integral, checked against the published table in tests/extreme.cpp) and
// reference/blast_lagrangian (the blast from the run's own deposit in 1D, which converges to the
// similarity solution as the deposit shrinks: tests/blast_reference.cpp).
//
// Blast radius: a fixed fraction of R (r_blast = 1/4), not the initial h. Deposited over one
// kernel of the initial h, the blast would sit on the same ~20 particles at every resolution;
// their volume cannot represent the hot, nearly empty centre, they keep a resolution-independent
// excess of the energy as heat, the profile lags the similarity solution by a few per cent of R
// at every n and the density L1 does not converge. On R/4 (the same particles at n = 32) the
// deposit holds more particles at each finer level, and the lag and the missing kinetic energy
// fall with n (docs/cases/sedov.md). The blast's finite size is remembered at t_end: L1_rho_deposit
// measures the density against the blast the run poses (sedov/deposit.hpp).
#include <cmath>
#include <string>

#include "reference/sedov.hpp"
#include "sph/kernel/kernels.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/extreme_hydro.hpp"
#include "verification/cases/common/centre_param.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/cases/sedov/deposit.hpp"
#include "verification/cases/sedov/errors.hpp"
#include "verification/cases/sedov/snapshots.hpp"
#include "verification/cases/sedov/setup.hpp"
#include "verification/harness/sweep.hpp"

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
  if (prm.real("h_support") != 1.0)
    throw InputError("sedov: h_support is for scoring snapshots (sphv score); sphv's h is the kernel's support");
  m.controls.t_end = sedov::end_time(prm);
  const sph::Box<D> box = sedov::box<D>();
  // The blast in a cold gas (u_ambient: the similarity solution's, p0 / p_shock ~ 1e-6).
  sph::Particles<D> p = sedov::initial_particles<D>(prm, m.hfact);
  m.h_max = 0.45;  // below half the periodic box
  const double r_b = prm.real("r_blast") * R_target;
  double E0 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) E0 += p.m[i] * p.u[i];

  const std::string kernel = prm.text("kernel");
  const sph::HydroOutcome out = extreme::evolve_gas_kernel<D>(kernel, p, box, m);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"t_end", m.controls.t_end}, {"xi0", exact.xi0()},
             {"R_exact", exact.shock_radius(E, rho0, m.controls.t_end)}, {"dim", D}, {"r_blast", r_b},
             {"blast_spacings", r_b * n}};
  if (r.verdict != "stable") return r;

  double E1 = 0.0, kinetic = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    kinetic += 0.5 * p.m[i] * p.v[i].squaredNorm();
    E1 += p.m[i] * (0.5 * p.v[i].squaredNorm() + p.u[i]);
  }
  // The reference density is smoothed with the run's kernel (sedov/smoothed.hpp).
  sph::with_kernel<D>(kernel, [&](auto k) {
    sedov::measure<D, decltype(k)>(r, p.x, p.v, p.m, p.rho, p.h, 1.0, n, E, rho0, out.t, exact);
  });
  sedov::measure_deposit<D>(r, p.x, p.m, p.rho, m.gamma, E, rho0, prm.real("u_ambient"), r_b, out.t, exact);
  r.extra["energy_drift"] = (E1 - E0) / E0;
  r.extra["kinetic_fraction"] = kinetic / E1;
  r.extra["kinetic_fraction_exact"] = sedov::kinetic_share(exact, D);
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
  if (p.text("kernel") != "cubic_spline" && (p.text("hmode") != "iterate50" || p.text("energy") != "38"))
    throw InputError("sedov: kernel=" + p.text("kernel") + " runs with hmode=iterate50, energy=38 only");
  if (p.text("kernel") != "cubic_spline" && p.text("scheme") != sph::ChapterScheme::name)
    throw InputError("sedov: kernel=" + p.text("kernel") + " runs with scheme=" + sph::ChapterScheme::name + " only");
  if (r_blast * R_target <= std::sqrt(double(d)) / (2.0 * n))
    throw InputError("sedov: r_blast R = " + std::to_string(r_blast * R_target) +
                     " holds no particle: raise r_blast or n");
}

// L1_rho measured at the finest quick level of each catalogue variant (2D n = 96; 3D n = 24 at
// r_blast 1/4, n = 32 at 1/2; one thread). The bound at a sweep's finest level is that + 20 %: no
// variant's error grows beyond its finest quick level on the standard and full levels (3D at
// r_blast 1/4: 0.3187 at n = 32, 0.2565 at 48).
double l1_measured(const Params& p) {
  if (p.integer("dim") == 3) return p.real("r_blast") == 0.5 ? 0.2514 : 0.3207;
  if (p.text("scheme") != sph::ChapterScheme::name) return 0.1500;  // gradh_switches
  if (p.real("gamma") == 1.4) return 0.2498;
  return p.text("energy") == "41" ? 0.1367 : 0.1468;
}

// L1_rho_deposit likewise (the same runs; docs/cases/sedov.md).
double l1_deposit_measured(const Params& p) {
  if (p.integer("dim") == 3) return p.real("r_blast") == 0.5 ? 0.2585 : 0.3068;
  if (p.text("scheme") != sph::ChapterScheme::name) return 0.1656;  // gradh_switches
  if (p.real("gamma") == 1.4) return 0.2226;
  return p.text("energy") == "41" ? 0.1318 : 0.1350;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c = radial::per_level(s, [](const std::string& level, const Result& r, std::vector<Check>& c) {
    // |R_front - R_front(rho_h)| / R, measured (one thread) at most 5.6 % in 2D (gamma 1.4,
    // n = 32) and 6.1 % in 3D (n = 32; the front lags more at each finer level, see the claims).
    // Tolerances: 2D 8 %, 3D 10 % (margins 1.4 and 1.6 over those).
    if (!r.errors.count("shock_radius")) return;
    const double tol = r.extra.value("dim", 2) == 3 ? 0.10 : 0.08;
    c.push_back({level + "_shock_radius", r.errors.at("shock_radius"), 0.0, tol,
                 "R_front within tol of the kernel-smoothed exact front (measured, margin stated in sedov.cpp)",
                 Check::Kind::drift, "shock_radius"});
  });
  // The finest level of the sweep.
  const Params p = find_case(s.case_name).parse(s.settings);
  for (const auto& [error, m] :
       {std::pair{"L1_rho", l1_measured(p)}, std::pair{"L1_rho_deposit", l1_deposit_measured(p)}})
    if (!s.runs.empty() && s.runs.back().errors.count(error))
      c.push_back({"n" + std::to_string(s.levels.back()) + "_" + error, s.runs.back().errors.at(error), 0.0, 1.2 * m,
                   "measured " + std::to_string(m) + " at the finest quick level + 20 %", Check::Kind::drift, error});
  return c;
}

// The density's L1 against the point blast has the similarity solution as its limit only as the
// deposit shrinks: at a fixed r_blast the runs tend to the blast they pose, whose 1D solution
// (sedov/deposit.hpp) differs from the similarity solution by the deposit's memory, in L1_rho's
// norm 0.0365, 0.0376, 0.0387 on zones R/600, R/1200, R/2400 wide (2D, R/4), 0.088 (gamma 1.4),
// 0.065 (3D, R/2). So L1_rho claims no order, and L1_rho_deposit, the same norm against that
// solution, carries the claim: first order in h ~ 1/n, the shock smeared over a few h. 2D on 48..256
// (docs/cases/sedov.md): its local orders 0.93, 0.90, 0.90, 0.58 (L1_rho's 0.96, 0.78, 0.95,
// 0.45), at gamma 1.4 0.59, 0.94, 0.65, 0.85 (L1_rho's 0.60, 0.67, 0.49, 0.62: the memory is
// larger behind the 6-fold compressed spike); the particles inside 0.8 R follow the deposit's
// solution, not the similarity solution (n = 256: mean rho 0.044 at 0.1 R, the deposit's 0.045,
// the similarity solution's 0.003). From 128 to 256 the order bends at hfact 2.4 and not at 4
// (docs/cases/sedov.md), as the tubes' do where the compressed lattice's sums are off.
// shock_radius is the sum of two lags behind the smoothed exact front, the shock's width beyond
// the kernel's (first order in h) and the blast's memory (falling faster than h while the deposit
// holds more particles): both trail the front, so the sum's local orders lie at or above 1 and
// tend to 1, which theory gives only as a bound ("at least 1"). In 3D the same levels are
// pre-asymptotic (the former windows 1 +- 0.8 and 1 +- 0.75 stay, so the rows read provisional).
// 3D: with the heat on R/4 the deposit spans 1.2, 1.8, 2.4 lattice spacings at n = 16, 24, 32
// (2D's coarsest level, n = 32, already has 2.4), and the hot particles keep the heat: the kinetic
// share of the energy stays below the exact 0.283 without rising, the front trails the
// kernel-smoothed exact front further at each level and the density's L1 does not fall; from
// n = 48 (3.6 spacings) the share rises and both errors fall. The same levels with the heat on
// R/2 (2.4-4.8 spacings) converge (docs/cases/sedov.md); beyond them the front's offset keeps
// falling and the density's L1 levels off (n = 40..64 in docs/cases/sedov.md). A smaller
// Courant number (0.15) changes nothing (the time step is not the cause), and the wider support
// hfact 4 does not converge either. So 3D at R/4 is a known failure, with the deposit on R/2 as
// the variant that converges.
//
// scheme=gradh_switches (2D, gamma 5/3; grad-h, the Cullen & Dehnen switch, conduction) on n = 48,
// 64, 96, 128: L1_rho 0.2773, 0.2141, 0.1500, 0.1170, local orders 0.90, 0.88, 0.86, fit 0.88 +-
// 0.005 (the default's 0.2667, 0.2024, 0.1472, 0.1120); shock_radius 0.0468, 0.0349, 0.0183,
// 0.0143, local orders 1.01, 1.60, 0.87, fit 1.27 +- 0.10 (the default's 0.0367 .. 0.0054, fit
// 1.93). Its front runs ahead of the smoothed exact front at every level (the default's trails):
// the conduction (Price 2008's signal speed sqrt(|p_i - p_j| / rho), large across the shock)
// carries the blast's heat into the cold gas ahead of it. Without the conduction (a build made for
// the test) the front still leads, by 0.0180, 0.0126, 0.0057, 0.0041 (local orders 1.24, 1.98,
// 1.12), and L1_rho is 0.198 .. 0.092; the conduction's share of the offset, 0.029, 0.022,
// 0.013, 0.010, falls at first order (0.96, 1.37, 0.80). Both parts lead, so as for the default
// the sum's order is at least 1; the conduction's heated foot is what makes the front's offset
// 2.6 times the default's at n = 128.
OrderClaims sedov_orders(const Params& p) {
  const OrderClaim radius{1.0, 0.8, "the front's offset from the kernel-smoothed exact front: the shock's width "
                                    "beyond the kernel's and the blast's memory, first order in h ~ 1/n (faster "
                                    "while the blast's memory fades)"};
  const OrderClaim l1_3d{1.0, 0.75, "a shock smeared over a few h: L1 against the blast the run poses first order in "
                                    "h at fixed hfact; on the affordable 3D levels its local orders stay below 1 "
                                    "(docs/cases/sedov.md)"};
  const OrderClaim l1_2d{1.0, 0.3, "a shock smeared over a few h: L1 against the blast the run poses (its finite "
                                   "deposit) first order in h at fixed hfact, from n = 48, where the deposit spans "
                                   "{extra.blast_spacings} spacings at {levels}"};
  // Against the point blast the runs' limit at a fixed r_blast is the deposit's memory, not 0.
  const OrderClaim point = no_order("the point blast is the limit only as the deposit shrinks: at a fixed r_blast the "
                                    "runs tend to the blast they pose, whose solution differs from the similarity "
                                    "solution by {extra.deposit_memory} in this norm at {levels}, so this error tends "
                                    "to about that, not to 0; L1_rho_deposit carries the order");
  const OrderClaim radius_2d = at_least(1.0, "the front's offset from the kernel-smoothed exact front "
                                             "({extra.front_offset} of R at {levels}): the shock's width beyond the "
                                             "kernel's, first order in h ~ 1/n, and the blast's memory, fading faster "
                                             "than h; both trail the front, so the order is at least 1");
  if (p.integer("dim") == 2 && p.text("scheme") != sph::ChapterScheme::name && p.real("gamma") != 1.4)
    return {{"shock_radius", at_least(1.0, "the front's offset ahead of the kernel-smoothed exact front "
                                           "({extra.front_offset} of R at {levels}): the conduction's heated foot, "
                                           "whose width is first order in h ~ 1/n, and the rest of the shock's width, "
                                           "first order or faster; both lead, so the order is at least 1")},
            {"L1_rho", point},
            {"L1_rho_deposit", l1_2d}};
  if (p.integer("dim") == 2) return {{"shock_radius", radius_2d}, {"L1_rho", point}, {"L1_rho_deposit", l1_2d}};
  if (p.real("r_blast") == 0.25) {
    const std::string why = "the blast's heat on R/4 spans {extra.blast_spacings} lattice spacings at {levels}: the hot "
                            "particles keep it, the kinetic share of the energy is {extra.kinetic_fraction} (exact: "
                            "{extra.kinetic_fraction_exact}), the front's offset {extra.front_offset} and "
                            "L1_rho_deposit {L1_rho_deposit}";
    return {{"shock_radius", known_failure(radius.expected, radius.band, why, "dim=3,r_blast=0.5")},
            {"L1_rho", point},
            {"L1_rho_deposit", known_failure(l1_3d.expected, l1_3d.band, why, "dim=3,r_blast=0.5")}};
  }
  return {{"shock_radius", radius}, {"L1_rho", point}, {"L1_rho_deposit", l1_3d}};
}

// Cost grows as n^3 (steps ~ n, particles ~ n^2; times: docs/cases/sedov.md). From n = 48 (see
// the claims). Quick: two levels a factor 2 apart (the order claims are gated in CI); standard:
// four; full adds 256.
const Levels levels = {.quick = {48, 96}, .standard = {48, 64, 96, 128}, .full = {48, 64, 96, 128, 256}};

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
                                   radial::centre_param(),
                                   real_param("h_support", 1.0,
                                              "kernel support / the scored snapshot's h (sphv and SWIFT files 1: "
                                              "the SWIFT reader converts; SPH-EXA 2)",
                                              0.0)};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      ps.push_back(choice_param("kernel", "cubic_spline",
                                "the kernel of the run and of the smoothed reference (sph/kernel/kernels.hpp; the "
                                "blast's deposit keeps the cubic's weights); others with hmode=iterate50, energy=38",
                                sph::kernel_names()));
      return ps;
    }(),
    .levels = levels,
    .orders = sedov_orders,
    .error_defs = [] {
      auto defs = sedov::error_defs;
      defs.emplace("L1_rho_deposit", sedov::deposit_error_def);
      return defs;
    }(),
    .variants = {{}, {"dim=3"}, {"dim=3", "r_blast=0.5"}, {"gamma=1.4"}, {"energy=41"}, {"scheme=gradh_switches"}},
    .levels_for = [](const Params& p) {
      // 3D (cost ~ n^4; times: docs/cases/sedov.md). Quick: two levels each, so that CI gates the
      // known failure (16, 24) and its experiment; standard: three; full adds 48. The heat on R/2
      // starts at n = 24, where it spans 3.6 spacings, as 2D's levels start at n = 48 (at n = 16,
      // 2.4 spacings, the front's offset is smaller than at 24: 0.0233, 0.0293).
      if (p.integer("dim") == 3) {
        if (p.real("r_blast") == 0.5) return Levels{.quick = {24, 32}, .standard = {24, 32, 40}, .full = {24, 32, 40, 48}};
        return Levels{.quick = {16, 24}, .standard = {16, 24, 32}, .full = {16, 24, 32, 48}};
      }
      return levels;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
    .scorer = sedov::scorer(),
    .ic = sedov::initial_conditions,
}};

}  // namespace
}  // namespace sphv::sedov_case
