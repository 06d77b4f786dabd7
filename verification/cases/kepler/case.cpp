// Case `kepler`: test particles orbiting a point mass, external gravity (75)-(77) as a scene
// term, integrated with the chapter's leapfrog (9.3.2 as written) and kick-drift-kick.
// (a) one particle on an eccentric Kepler orbit (e = 0.5, eps = 0) against Kepler's equation;
// (b) a ring of test particles on circular orbits about a softened point mass (eps = 0.1)
//     against the analytic circular period 2 pi r / v_c(r). G M = 1, a = 1: period 2 pi.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/potentials.hpp"
#include "sph/gravity/point_mass.hpp"
#include "sph/time/leapfrog.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/common/measured_bound.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::kepler_case {
namespace {

using V3 = sph::Vec<3>;
using GravityScene = sph::Scene<3, sph::PointMassGravity<3>>;
constexpr double two_pi = 2.0 * std::numbers::pi;

// What an integration measured per particle.
struct Track {
  std::vector<double> max_energy_error;  // max_t |E - E0| / |E0|
  std::vector<double> max_L_error;       // max_t |L_z - L_z0| / |L_z0|
  std::vector<double> angle;             // unwrapped polar angle travelled
  std::vector<double> first_orbit, last_orbit;  // max energy error in the first and last orbit
  Series energy_history;                 // particle 0: relative energy error against t / T
  std::vector<V3> x_final;
};

enum class Scheme { chapter, kdk };

// Integrates for `orbits` periods of 2 pi with n steps each.
Track integrate(sph::Particles<3> p, double eps, long n, long orbits, Scheme scheme) {
  GravityScene scene;
  scene.term<sph::PointMassGravity<3>>().eps = eps;
  const auto& g = scene.term<sph::PointMassGravity<3>>();
  sph::NeighbourList none;
  none.offset.assign(p.size() + 1, 0);
  const auto box = sph::unit_box<3>(false);
  const sph::Neighbourhood<3> nb{none, box};
  sph::Derivatives<3> d, at_t;
  auto derivs = [&](sph::Particles<3>& q, sph::Derivatives<3>& dd) { scene.derivatives(q, nb, dd); };
  derivs(p, d);
  const std::size_t np = p.size();
  auto energy = [&](std::size_t i) { return 0.5 * p.v[i].squaredNorm() + g.potential(p.x[i]); };
  auto Lz = [&](std::size_t i) { return p.x[i][0] * p.v[i][1] - p.x[i][1] * p.v[i][0]; };
  std::vector<double> E0(np), L0(np), prev(np);
  Track tr{std::vector<double>(np), std::vector<double>(np), std::vector<double>(np), std::vector<double>(np),
           std::vector<double>(np), {scheme == Scheme::kdk ? "kick-drift-kick" : "chapter's leapfrog", {}, {}, "line"}};
  for (std::size_t i = 0; i < np; ++i) E0[i] = energy(i), L0[i] = Lz(i), prev[i] = std::atan2(p.x[i][1], p.x[i][0]);
  const double dt = two_pi / n;
  const long steps = n * orbits;
  for (long s = 1; s <= steps; ++s) {
    if (scheme == Scheme::kdk) sph::kdk_leapfrog_step(p, d, at_t, dt, derivs);
    else sph::chapter_leapfrog_step(p, d, dt, derivs);
    for (std::size_t i = 0; i < np; ++i) {
      const double de = std::abs(energy(i) - E0[i]) / std::abs(E0[i]);
      tr.max_energy_error[i] = std::max(tr.max_energy_error[i], de);
      if (s <= n) tr.first_orbit[i] = std::max(tr.first_orbit[i], de);
      if (s > steps - n) tr.last_orbit[i] = std::max(tr.last_orbit[i], de);
      tr.max_L_error[i] = std::max(tr.max_L_error[i], std::abs(Lz(i) - L0[i]) / std::abs(L0[i]));
      const double phi = std::atan2(p.x[i][1], p.x[i][0]);
      tr.angle[i] += std::remainder(phi - prev[i], two_pi);
      prev[i] = phi;
      if (i == 0 && (s % std::max(1L, steps / 2000) == 0))
        tr.energy_history.x.push_back(s * dt / two_pi), tr.energy_history.y.push_back(std::max(de, 1e-17));
    }
  }
  tr.x_final = p.x;
  return tr;
}

sph::Particles<3> eccentric_orbit(double e) {
  sph::Particles<3> p;
  p.resize(1);
  p.m[0] = 1.0;
  p.x[0] = V3(1.0 - e, 0.0, 0.0);  // pericentre, a = 1
  p.v[0] = V3(0.0, std::sqrt((1.0 + e) / (1.0 - e)), 0.0);
  return p;
}

// Ring of test particles on circular orbits of radii 0.3 .. 2, at spread-out angles.
sph::Particles<3> ring(double eps, int count) {
  sph::Particles<3> p;
  p.resize(count);
  for (int k = 0; k < count; ++k) {
    const double r = 0.3 * std::pow(2.0 / 0.3, double(k) / (count - 1)), ang = k * 2.39996;  // golden angle
    const double vc = reference::softened_circular_speed(r, 1.0, eps);
    p.m[k] = 1.0;
    p.x[k] = V3(r * std::cos(ang), r * std::sin(ang), 0.0);
    p.v[k] = V3(-vc * std::sin(ang), vc * std::cos(ang), 0.0);
  }
  return p;
}

double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

Result run(const Params& p) {
  const long n = p.integer("n"), orbits = p.integer("orbits");
  const double e = p.real("e"), eps = p.real("eps_ring");
  constexpr int ring_count = 16;
  Result r;
  r.n_particles = 1 + ring_count;
  Figure fe{"energy_history", "Energy error of the eccentric orbit (e = " + std::to_string(e) + "), n = " +
                std::to_string(n) + " steps per orbit", "time / orbital period", "|E - E0| / |E0|", "linear", "log", {}};
  Figure fp{"ring_period", "Period error of circular orbits about a softened point mass (eps = " +
                std::to_string(eps) + ")", "orbit radius / eps", "|T_num - T| / T", "log", "log", {}};
  const auto ref = reference::kepler_orbit(two_pi * orbits, 1.0, 1.0, e);
  const auto rp = ring(eps, ring_count);
  for (const auto scheme : {Scheme::chapter, Scheme::kdk}) {
    const std::string tag = scheme == Scheme::kdk ? "kdk" : "chapter";
    const Track a = integrate(eccentric_orbit(e), 0.0, n, orbits, scheme);
    const Track b = integrate(rp, eps, n, orbits, scheme);
    const V3 xk(ref.x[0], ref.x[1], 0.0);
    r.errors["energy_" + tag] = a.max_energy_error[0];
    r.errors["position_" + tag] = (a.x_final[0] - xk).norm();  // a = 1
    r.errors["ring_energy_" + tag] = max_of(b.max_energy_error);
    Series ps{a.energy_history.label, {}, {}, "line"};
    double worst_period = 0.0;
    for (int k = 0; k < ring_count; ++k) {
      const double rad = rp.x[k].norm();
      const double T = two_pi * rad / reference::softened_circular_speed(rad, 1.0, eps);
      const double Tnum = two_pi * (two_pi * orbits) / b.angle[k];
      ps.x.push_back(rad / eps), ps.y.push_back(std::max(std::abs(Tnum - T) / T, 1e-17));
      worst_period = std::max(worst_period, std::abs(Tnum - T) / T);
    }
    r.errors["ring_period_" + tag] = worst_period;
    r.extra["L_error_" + tag] = std::max(a.max_L_error[0], max_of(b.max_L_error));
    // Secular drift: energy error in the last orbit over that in the first (about 1 when bounded).
    r.extra["drift_ratio_" + tag] = a.last_orbit[0] / a.first_orbit[0];
    r.extra["ring_drift_ratio_" + tag] = max_of(b.last_orbit) / max_of(b.first_orbit);
    fe.series.push_back(a.energy_history);
    fp.series.push_back(ps);
  }
  r.figures = {fe, fp};
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const auto& x = s.runs.back().extra;
  for (const std::string tag : {"chapter", "kdk"}) {
    // Central force: both schemes kick along r and drift along v, so L_z is conserved to
    // round-off (about 1e-16 per step, 1e4 steps: < 1e-11 with margin).
    c.push_back({"L_" + tag, x.at("L_error_" + tag), 0.0, 1e-11, "central force: L exact up to round-off"});
    // Symplectic: the energy error oscillates without secular growth. A drift of one orbit's
    // error per orbit would give a ratio of about the number of orbits (10).
    c.push_back({"drift_" + tag, x.at("drift_ratio_" + tag), 0.0, 1.5, "symplectic: bounded energy error"});
    c.push_back({"ring_drift_" + tag, x.at("ring_drift_ratio_" + tag), 0.0, 1.5, "symplectic: bounded energy error"});
  }
  // Bounds: the errors measured at n = 1024 (Release build on x86-64; deterministic, no random
  // input) times 1.5, carried to the finest level by the claimed order (common/measured_bound.hpp). The
  // errors over 128..2048 lie within 14 % of that power law (position with KDK at n = 128, near
  // saturation, below it) and at most 1 % above it; an error constant 1.5x larger, or an order
  // lost, fails.
  const std::pair<const char*, double> measured_1024[] = {
      {"energy_chapter", 2.417e-05},      {"energy_kdk", 1.023e-04},          {"position_chapter", 4.579e-03},
      {"position_kdk", 1.687e-02},        {"ring_energy_chapter", 2.730e-08}, {"ring_energy_kdk", 2.228e-07},
      {"ring_period_chapter", 2.592e-04}, {"ring_period_kdk", 2.588e-04}};
  for (const auto& [e, v] : measured_1024)
    c.push_back(measured_bound(s, e, v, 1024, 1.5));
  return c;
}

const Registration reg{Case{
    .name = "kepler",
    .summary = "orbits about a (softened) point mass: energy, L, period error of both leapfrogs",
    .n_counts = "time steps per orbital period 2 pi (G M = 1, a = 1)",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 128, "steps per orbit"), integer_param("orbits", 10, "orbital periods integrated"),
               real_param("e", 0.5, "eccentricity of the single orbit (0 <= e < 1)", std::nullopt),
               real_param("eps_ring", 0.1, "softening length (77) for the ring of circular orbits", 0.0)},
    // From 128 steps per orbit: at 64 the KDK phase error after 10 orbits is O(1) (position error
    // saturates at the orbit's diameter). Full adds 4096 and 8192 (the ring's dt^4 energy error
    // there, ~7e-12, still 100x above the round-off of 8e4 steps; CPU times: docs/cases/kepler.md).
    .levels = {.quick = {128, 256, 512, 1024},
               .standard = {128, 256, 512, 1024, 2048},
               .full = {128, 256, 512, 1024, 2048, 4096, 8192}},
    // Both schemes are second order (9.3.2; errata). Measured orders over 128..1024 and 128..2048:
    // 1.93-2.005 (position with KDK 1.93 +- 0.03, pre-asymptotic at 128), the others within 0.01
    // of 2 and 3.97-3.99 for the ring energy. Band +-0.15 (twice the largest departure measured):
    // a first-order slip fails it.
    .orders = [](const Params&) {
      OrderClaims o;
      for (const std::string t : {"chapter", "kdk"}) {
        for (const std::string e : {"energy_", "position_", "ring_period_"})
          o[e + t] = {2.0, 0.15, "both leapfrog forms of 9.3.2 are second-order symplectic schemes"};
        // On a circular orbit the dt^2 term of the scheme's modified energy is constant along the
        // orbit, so the energy error falls as dt^4 (measured 3.97-3.99).
        o["ring_energy_" + t] = {4.0, 0.15, "circular orbits: the dt^2 term of the modified energy is constant on a circle"};
      }
      return o;
    },
    .error_defs = [] {
      std::map<std::string, std::string> d;
      for (const std::string t : {"chapter", "kdk"}) {
        const std::string by = t == "kdk" ? " (kick-drift-kick)" : " (the chapter's leapfrog)";
        d["energy_" + t] = "max over the run of |E(t) - E(0)| / |E(0)|, single orbit of eccentricity e" + by;
        d["position_" + t] = "|x(t_end) - x_Kepler(t_end)| / a after the given orbits (Kepler's equation)" + by;
        d["ring_energy_" + t] = "max over the ring's circular orbits and the run of |E(t) - E(0)| / |E(0)|" + by;
        d["ring_period_" + t] = "max over the ring of |T_measured - T_exact| / T_exact, softened point mass (77)" + by;
      }
      return d;
    }(),
    .validate = [](const Params& p) {
      if (!(p.real("e") >= 0.0 && p.real("e") < 0.95)) throw InputError("parameter e must be in [0, 0.95)");
    },
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::kepler_case
