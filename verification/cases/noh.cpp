// Case `noh`: Noh's implosion in 1D, 2D and 3D (planar, cylindrical, spherical). Cold gas
// (gamma = 5/3, rho0 = 1, u ~ 0) falls at unit speed onto the centre; a shock leaves it at speed
// 1/3 with density 4^d behind it and the gas at rest. Independent reference: reference/noh (the
// exact solution). Wall heating (Noh 1987): every method overheats and underdensifies the gas
// at the centre; it is measured, not gated, and the density gate looks away from it.
#include <cmath>

#include "reference/noh.hpp"
#include "verification/case.hpp"
#include "verification/cases/extreme_hydro.hpp"
#include "verification/cases/radial_result.hpp"
#include "verification/sweep.hpp"

namespace sphv {
namespace {

// Gas out to R0. The gas that meets the shock by t_end started within R_s + t_end = 4 t_end / 3;
// the shock runs ahead of R_s by up to ~5% in 1D/2D (measured), so a margin of 10% of that, plus
// one initial support radius for the neighbourhood of the last gas that matters. (A bare 3 h0 is
// 0.7 of the radius at the 3D gate size, n = 10, and tripled its particles.)
double gas_radius(double t_end, double h0) { return 1.1 * 4.0 / 3.0 * t_end + h0; }

// Volume of the d-ball of radius r.
double ball_volume(int d, double r) { return (d == 1 ? 2.0 : d == 2 ? M_PI : 4.0 / 3.0 * M_PI) * std::pow(r, d); }

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  extreme::Method m = extreme::method(prm);
  const double t_end = prm.real("t_end");
  m.controls.t_end = t_end;
  const reference::Noh exact(D, m.gamma);
  const double dx = 1.0 / n, h0 = m.hfact * dx;
  const double R0 = gas_radius(t_end, h0);
  const int k = static_cast<int>(std::ceil(R0 / dx));
  sph::Box<D> box = sph::unit_box<D>(false);
  box.lo = sph::Vec<D>::Constant(-(k + 1) * dx);
  box.hi = sph::Vec<D>::Constant((k + 1) * dx);
  sph::Particles<D> all = sph::lattice<D>(2 * k, sph::Box<D>{box.lo + sph::Vec<D>::Constant(dx), box.hi - sph::Vec<D>::Constant(dx), box.periodic}, 1.0, m.hfact);
  sph::Particles<D> p;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all.x[i].norm() < R0) {
      const double r = all.x[i].norm();
      p.x.push_back(all.x[i]);
      p.v.push_back(-all.x[i] / r);  // unit inflow
      p.m.push_back(all.m[i]);
      p.rho.push_back(1.0);
      p.p.push_back(0.0);
      p.c.push_back(0.0);
      p.u.push_back(prm.real("u_cold"));
      p.h.push_back(h0);
    }
  // The free surface's self-density floor (49): h at most 3 h0 (its density is never used).
  m.h_max = 3.0 * h0;

  const sph::HydroOutcome out = extreme::evolve_gas(p, box, m);
  Result r = radial::start(p.size(), out);
  const double rho_post = exact.post_shock_density(), Rs = exact.shock_radius(out.t);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"rho_post_exact", rho_post}, {"R0", R0},
             {"shock_radius_exact", Rs}};
  if (r.verdict != "stable") return r;

  const std::vector<double> rad = extreme::radii(p);
  // Post-shock density away from the wall-heated centre and from the smeared shock: the mean
  // over particles with R_s / 4 < r < 3 R_s / 4.
  double sum = 0.0, cnt = 0.0, rho_c = 0.0, u_c = 0.0, cnt_c = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (rad[i] > 0.25 * Rs && rad[i] < 0.75 * Rs) sum += p.rho[i], ++cnt;
    if (rad[i] < 0.1 * Rs) rho_c += p.rho[i], u_c += p.u[i], ++cnt_c;
  }
  const double rho_mid = cnt > 0 ? sum / cnt : 0.0;
  // Swept mass: the gas brought to rest (radial velocity above -1/2, half-way from the inflow to
  // rest) against rho0 vol(R_s + t), all the gas that started inside R_s + u0 t.
  double swept = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.v[i].dot(p.x[i]) > -0.5 * rad[i]) swept += p.m[i];
  const double swept_exact = ball_volume(D, Rs + out.t);
  // Shock position: the radius where the binned density falls, going outwards, through the
  // midpoint of the exact post-shock and pre-shock (4^(d-1) rho0 for gamma = 5/3) values.
  const double pre = exact.at(Rs * 1.0001, out.t).rho;
  const extreme::Profile prof = extreme::radial_profile(rad, p.rho, 2.0 * Rs, 40);
  const double R_front = radial::falling_through(prof, 0.5 * (rho_post + pre), 0.25 * Rs, 0.0);
  r.errors = {{"rho_post", std::abs(rho_mid - rho_post) / rho_post},
              {"shock_speed", std::abs(R_front / out.t - exact.shock_speed()) / exact.shock_speed()},
              {"swept_mass", std::abs(swept - swept_exact) / swept_exact}};
  r.functionals = {{"rho_post", rho_mid}, {"shock_speed", R_front / out.t}, {"swept_mass", swept}};
  r.extra["rho_post_measured"] = rho_mid;
  r.extra["shock_speed_measured"] = R_front / out.t;
  r.extra["particles_in_window"] = cnt;
  // Wall heating: density deficit and excess internal energy within R_s / 10 of the centre
  // (exact: rho_post and u = u0^2 / 2).
  r.extra["wall_rho_ratio"] = cnt_c > 0 ? rho_c / cnt_c / rho_post : 0.0;
  r.extra["wall_u_ratio"] = cnt_c > 0 ? u_c / cnt_c / 0.5 : 0.0;
  r.extra["wall_particles"] = cnt_c;

  const std::string dim = std::to_string(D) + "D";
  r.figures.push_back(radial::profile_figure(
      "profile_rho", "Noh " + dim + ", n = " + std::to_string(n) + ": density at t = " + std::to_string(out.t),
      "radius r", "density rho", rad, p.rho, 3.0 * Rs, 1.0, "exact (Noh)",
      [&](double x) { return exact.at(x, out.t).rho; }));
  r.figures.push_back(radial::profile_figure(
      "profile_u", "Noh " + dim + ": specific internal energy (wall heating at r = 0)", "radius r", "u", rad, p.u,
      3.0 * Rs, 1.0, "exact (Noh)", [&](double x) {
        const reference::NohState e = exact.at(x, out.t);
        return e.p / ((m.gamma - 1.0) * e.rho);
      }));
  r.particles = extreme::particle_table(p);
  return r;
}

Result run(const Params& p) {
  const long dim = p.integer("dim"), n = p.integer("n");
  const double t_end = p.real("t_end"), hfact = p.real("hfact");
  // n counts per unit length in every dimension: the 1D default (200) means ~1e5 particles in
  // 2D and ~2e7 in 3D. The finest sweep levels (2D n=100, 3D n=20) have <= 3.4e4. Runs above
  // max_particles are refused (raise it on purpose for a larger run). Checked here, not in
  // validate: a variant's settings are validated with the default n before its levels.
  const double N = ball_volume(static_cast<int>(dim), gas_radius(t_end, hfact / n)) * std::pow(double(n), dim);  // particles
  const double cap = p.real("max_particles");
  if (N > cap)
    throw InputError("noh: n = " + std::to_string(n) + " in " + std::to_string(dim) + "D means ~" +
                     std::to_string(static_cast<long>(N)) + " particles (max_particles " +
                     std::to_string(static_cast<long>(cap)) +
                     "); n counts per unit length: use n ~ 50 in 2D, 10-20 in 3D, or raise max_particles");
  return by_dimension(p, [&](auto d) { return run_dim<d>(p); });
}

void validate(const Params& p) {
  const long d = p.integer("dim"), n = p.integer("n");
  const double t_end = p.real("t_end"), hfact = p.real("hfact");
  if (d < 1 || d > 3) throw InputError("noh: dim must be 1, 2 or 3");
  if (!(t_end > 0.0)) throw InputError("noh: t_end must be > 0");
  if (!(p.real("u_cold") >= 0.0)) throw InputError("noh: u_cold must be >= 0");
  // Behind the shock the spacing, and so h, is a quarter of the initial one (density 4^d): ask
  // for three post-shock support radii inside R_s = t_end / 3, else there is no post-shock state.
  if (hfact * 2.25 > n * t_end)
    throw InputError("noh: resolution too coarse: need n t_end >= 2.25 hfact (three post-shock h inside the shock)");
}

std::vector<Check> gates(const Sweep& s) {
  const Params prm = find_case(s.case_name).parse(s.settings);
  const long d = prm.integer("dim");
  return radial::per_level(s, [&](const std::string& level, const Result& r, std::vector<Check>& c) {
    // Swept mass (the gas brought to rest, an integral measure of the shock's position). Measured
    // at the gate levels: 1D n=200 0.6%, 2D n=50 2.7%, 3D n=10 45% (n=14: 31%; the 3D gate level has
    // R_s = 0.8 h0: the shock is a few post-shock h thick and runs ahead). Tolerances: margin ~1.3-2.
    const double tol_swept = d == 1 ? 0.015 : d == 2 ? 0.05 : 0.6;
    c.push_back({level + "_swept_mass", r.errors.at("swept_mass"), 0.0, tol_swept,
                 "mass brought to rest vs rho0 vol(4 t / 3) (measured, margin >= 1.3)", Check::Kind::verification,
                 "swept_mass"});
    if (d == 3) return;  // at 3D gate sizes there is no post-shock plateau (peak 12 against 64 at n=10)
    // Measured post-shock density errors at the gate level: 1D n=200 1.3% (also 1.3% at n=400: the
    // deficit is the entropy excess of the start-up collision, not resolution), 2D n=50 7.7%;
    // tolerances about twice that.
    c.push_back({level + "_rho_post", r.errors.at("rho_post"), 0.0, d == 1 ? 0.03 : 0.15,
                 "post-shock density 4^d away from the wall (measured error, margin 2)", Check::Kind::verification,
                 "rho_post"});
    // Measured: the shock runs ahead by 4.2% (1D n=200), 5.4% (2D n=50): the wall-heated centre
    // holds less mass, so the shock sits further out. Tolerance 10% (margin ~2).
    c.push_back({level + "_shock_speed", r.errors.at("shock_speed"), 0.0, 0.1,
                 "shock speed 1/3 within 10% (measured, margin 2)", Check::Kind::verification, "shock_speed"});
  });
}

const Levels levels = {.quick = {200}, .standard = {200, 400, 800}, .full = {200, 400, 800}};

const Registration reg{Case{
    .name = "noh",
    .summary = "Noh implosion (1D/2D/3D): post-shock density 4^d and shock speed 1/3 against the exact solution",
    .n_counts = "particles per unit length of the initial lattice",
    .tags = {"gate", "extreme", "sweep"},
    .params = [] {
      std::vector<ParamSpec> ps = {integer_param("n", 200, "particles per unit length (a 1D size: use ~50 in 2D, 10-20 in 3D)"),
                                   integer_param("dim", 1, "dimension 1, 2 or 3"),
                                   real_param("t_end", 0.6, "end time (shock at t_end / 3)", 0.0),
                                   real_param("u_cold", 1e-6, "specific internal energy of the inflowing gas"),
                                   real_param("max_particles", 5e4, "refuse runs with more particles than this", 0.0)};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = levels,
    .orders = [](const Params&) {
      const OrderClaim first{1.0, 0.5, "shock-limited: first order in h at fixed hfact"};
      return OrderClaims{{"rho_post", first}, {"shock_speed", first}, {"swept_mass", first}};
    },
    .error_defs = {{"rho_post", "|mean rho over particles with R_s/4 < r < 3 R_s/4 - 4^d| / 4^d at t_end (exact post-shock density)"},
                   {"shock_speed", "|R_front / t - 1/3| / (1/3), R_front where the binned density falls through the "
                                   "midpoint of the exact post- and pre-shock densities"},
                   {"swept_mass", "|m(v_r > -1/2) - rho0 vol(R_s + t)| / (rho0 vol(R_s + t)): gas brought to rest"}},
    .variants = {{}, {"dim=2"}, {"dim=3"}},
    .levels_for = [](const Params& p) {
      // 1D 200, 400, 800; 2D 50, 71, 100; 3D 10, 14, 20 (a 3D run at n = 10 has ~5k particles,
      // ~40 s on one loaded core).
      const long d = p.integer("dim");
      Levels l = levels;
      for (auto* v : {&l.quick, &l.standard, &l.full})
        for (auto& n : *v) n = d == 1 ? n : static_cast<long>(std::lround((d == 2 ? 50.0 : 10.0) * std::sqrt(n / 200.0)));
      return l;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv
