// Case `noh`: Noh's implosion in 1D, 2D and 3D (planar, cylindrical, spherical). Cold gas
// (gamma = 5/3, rho0 = 1, u ~ 0) falls at unit speed onto the centre; a shock leaves it at speed
// 1/3 with density 4^d behind it and the gas at rest. Independent reference: reference/noh (the
// exact solution). Wall heating (Noh 1987): every method overheats and underdensifies the gas
// at the centre; it is measured, not gated, and the density gate looks away from it.
#include <algorithm>
#include <cmath>

#include "reference/noh.hpp"
#include "verification/case.hpp"
#include "verification/cases/extreme_hydro.hpp"
#include "verification/cases/centre_param.hpp"
#include "verification/cases/noh_errors.hpp"
#include "verification/cases/noh_setup.hpp"
#include "verification/cases/radial_result.hpp"
#include "verification/sweep.hpp"

namespace sphv::noh_case {
namespace {

template <int D>
Result run_dim(const Params& prm) {
  const int n = static_cast<int>(prm.integer("n"));
  extreme::Method m = extreme::method(prm);
  const double t_end = prm.real("t_end");
  m.controls.t_end = t_end;
  if (radial::centre<D>(prm) != sph::Vec<D>::Zero())
    throw InputError("noh: centre is for scoring snapshots (sphv score); sphv run puts the centre at the origin");
  const reference::Noh exact(D, m.gamma);
  auto [box, p, R0] = noh::initial<D>(prm, m.hfact);
  const double h0 = m.hfact * (1.0 / n);  // as noh::initial computes it
  // The free surface's self-density floor (49): h at most 3 h0 (its density is never used).
  m.h_max = 3.0 * h0;

  const sph::HydroOutcome out = extreme::evolve_gas(p, box, m);
  Result r = radial::start(p.size(), out);
  r.extra = {{"steps", out.steps}, {"t_reached", out.t}, {"rho_post_exact", exact.post_shock_density()}, {"R0", R0},
             {"shock_radius_exact", exact.shock_radius(out.t)}};
  if (r.verdict != "stable") return r;

  noh::measure<D>(r, p.x, p.v, p.m, p.rho, p.u, out.t, m.gamma, n);
  r.particles = extreme::particle_table(p, m.gamma);
  return r;
}

Result run(const Params& p) {
  noh::check_size(p);
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
    // 3D at n = 10: no post-shock plateau and no front (binned peak ~12 against 64; the run reports
    // neither error, and the swept mass above is the gated measure of the shock). 1D/2D: the front
    // must be found.
    if (d == 3) return;
    c.push_back({level + "_shock_front_found", r.extra.value("shock_front_found", false) ? 1.0 : 0.0, 1.0, 1.0,
                 "the binned density rises through the midpoint of the post- and pre-shock values",
                 Check::Kind::verification, "shock_speed"});
    if (!r.errors.count("rho_post")) return;
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

// Measured in 1D (one thread): n = 200, 400: rho_post 0.01321, 0.01329; shock_speed 0.0419,
// 0.0407; swept_mass 0.006249, 0.006249. None converges: wall heating (Noh 1987) leaves the centre
// hot and underdense whatever the resolution (the start-up collision's entropy excess), so the
// plateau sits 1.3 % low and the front 4 % ahead, in every method without an explicit heat
// conduction term. The errors are floors, bounded at every level (gates above).
OrderClaims noh_orders(const Params& p) {
  const std::string floor = "wall heating (Noh 1987): the start-up collision's entropy excess at the centre does not "
                            "shrink with resolution; measured 1D n = 200, 400: rho_post 1.32 %, 1.33 %, shock_speed "
                            "4.2 %, 4.1 %, swept_mass 0.62 %, 0.62 %: floors, bounded at every level";
  if (p.integer("dim") == 3)
    return {{"swept_mass", no_order("3D pre-asymptotic: at n = 10 the shock radius is 0.8 initial h, no post-shock "
                                    "plateau or front exists (rho_post, shock_speed are not reported); the swept mass "
                                    "is bounded")},
            {"rho_post", no_order(floor)}, {"shock_speed", no_order(floor)}};
  return {{"rho_post", no_order(floor)}, {"shock_speed", no_order(floor)}, {"swept_mass", no_order(floor)}};
}

// Cost (CPU, one thread): 1D n = 400 2 s; 2D n = 50 ~10 s; 3D n = 10 ~25 s (5k particles). 3D
// claims no order, so its standard tier stays at the quick level; full adds n = 14, 20 (~3, ~15
// min, estimated ~n^4; n = 28 would need max_particles above 8e4). Full in 1D/2D is the standard
// tier: the errors are floors, and 2D n = 141 would pass the 5e4 particle cap.
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
                                   real_param("max_particles", 5e4, "refuse runs with more particles than this", 0.0),
                                   radial::centre_param()};
      for (auto& q : extreme::method_params(5.0 / 3.0, 2.4)) ps.push_back(q);
      return ps;
    }(),
    .levels = levels,
    .orders = noh_orders,
    .error_defs = noh::error_defs,
    .variants = {{}, {"dim=2"}, {"dim=3"}},
    .levels_for = [](const Params& p) {
      // 1D 200, 400, 800; 2D 50, 71, 100; 3D 10 (full 10, 14, 20).
      const long d = p.integer("dim");
      if (d == 3) return Levels{.quick = {10}, .standard = {10}, .full = {10, 14, 20}};
      Levels l = levels;
      for (auto* v : {&l.quick, &l.standard, &l.full})
        for (auto& n : *v) n = d == 1 ? n : static_cast<long>(std::lround(50.0 * std::sqrt(n / 200.0)));
      return l;
    },
    .validate = validate,
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::noh_case
