// Case `gravity_analytic`: potential and force of N random particles drawn from a homogeneous
// sphere (inside and outside) or a Plummer sphere, by the direct sum and by the tree
// (quadrupole, theta = 0.5), against the analytic fields (reference/potentials). eps = 0; the
// fields are evaluated at probe points that are not particles.
// Sampling theory gives the reference behaviour: the potential and the force outside the sphere
// are means of N independent terms of finite variance, so their errors are Gaussian with the
// standard error s / sqrt(N) (s from the sample: z-scores must look standard normal) and fall as
// N^-1/2. Inside the mass the force variance is infinite (1/r^4 is not integrable): the nearest
// particles dominate (Holtsmark), the typical error is G m / d_nn^2 ~ N^-1/3.
#include <cmath>
#include <random>

#include "reference/direct_sum.hpp"
#include "reference/potentials.hpp"
#include "sph/gravity/tree_gravity.hpp"
#include "verification/harness/case.hpp"
#include "verification/cases/gravity/compare.hpp"
#include "verification/cases/gravity/models.hpp"
#include "verification/cases/common/measured_bound.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::gravity_analytic_case {
namespace {

using namespace gravity;
using V3 = sph::Vec<3>;
constexpr int realisations = 4;
constexpr int probes_per_region = 100;

struct Probe {
  V3 x;
  int region;  // 0: inside the mass (uniform r < 0.9; Plummer all), 1: outside (uniform r > 1.2)
};

std::vector<Probe> make_probes(bool uniform) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Probe> p;
  for (int k = 0; k < probes_per_region; ++k) p.push_back({(0.1 + 0.8 * u(rng)) * random_direction(rng), 0});
  for (int k = 0; k < probes_per_region; ++k)
    p.push_back({(uniform ? 1.2 + 1.8 * u(rng) : 1.0 + 2.0 * u(rng)) * random_direction(rng), uniform ? 1 : 0});
  return p;
}

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s / v.size());
}

Result run(const Params& p) {
  const long n = p.integer("n");
  const bool uniform = p.text("model") == "uniform";
  const auto probes = make_probes(uniform);
  std::vector<V3> px;
  for (const auto& q : probes) px.push_back(q.x);
  const Columns pc = columns(px);
  auto phi_exact = [&](double r) { return uniform ? reference::uniform_sphere_phi(r, 1, 1) : reference::plummer_phi(r, 1, 1); };
  auto g_exact = [&](double r) { return uniform ? reference::uniform_sphere_g(r, 1, 1) : reference::plummer_g(r, 1, 1); };

  // Per probe and realisation: relative errors and z-scores of the direct sum and of the tree.
  std::vector<double> phi_d, phi_t, gin_d, gin_t, gout_d, gout_t, z_phi, z_gout, z_phi_t, z_gout_t;
  for (int k = 0; k < realisations; ++k) {
    const auto s = uniform ? uniform_sphere(n, 1000 + k) : plummer_sphere(n, 1000 + k);
    const Columns c = columns(s.x);
    const auto d = reference::direct_sum_at(c.x, c.y, c.z, s.m, 1.0, 0.0, pc.x, pc.y, pc.z);
    const auto t = sph::tree_gravity_at(sph::build_tree<3>(s.x, s.m), s.x, s.m, {.theta = 0.5}, px);
    for (std::size_t q = 0; q < probes.size(); ++q) {
      const double r = probes[q].x.norm();
      const V3 rhat = probes[q].x / r, ge = g_exact(r) * rhat;
      const V3 gd(d.ax[q], d.ay[q], d.az[q]);
      phi_d.push_back((d.phi[q] - phi_exact(r)) / std::abs(phi_exact(r)));
      phi_t.push_back((t.phi[q] - phi_exact(r)) / std::abs(phi_exact(r)));
      (probes[q].region == 0 ? gin_d : gout_d).push_back((gd - ge).norm() / ge.norm());
      (probes[q].region == 0 ? gin_t : gout_t).push_back((t.a[q] - ge).norm() / ge.norm());
      // Standard errors from the sample: per-particle terms of phi and of the radial force,
      // -G M / |r - r_j| and -G M (r - r_j).rhat / |r - r_j|^3 (m_j = M / N).
      double s1 = 0, s2 = 0, f1 = 0, f2 = 0;
      for (long j = 0; j < n; ++j) {
        const V3 dr = probes[q].x - s.x[j];
        const double inv = 1.0 / dr.norm(), a = -inv, b = -dr.dot(rhat) * inv * inv * inv;
        s1 += a, s2 += a * a, f1 += b, f2 += b * b;
      }
      const double se_phi = std::sqrt((s2 / n - (s1 / n) * (s1 / n)) / (n - 1.0));
      z_phi.push_back((d.phi[q] - phi_exact(r)) / se_phi);
      z_phi_t.push_back((t.phi[q] - phi_exact(r)) / se_phi);
      if (probes[q].region == 1) {
        const double se_g = std::sqrt((f2 / n - (f1 / n) * (f1 / n)) / (n - 1.0));
        z_gout.push_back((gd.dot(rhat) - g_exact(r)) / se_g);
        z_gout_t.push_back((t.a[q].dot(rhat) - g_exact(r)) / se_g);
      }
    }
  }
  Result r;
  r.n_particles = n;
  auto median_abs = [](const std::vector<double>& v) { return percentiles(v).p50; };
  r.errors = {{"phi_direct", rms(phi_d)}, {"phi_tree", rms(phi_t)}, {"g_in_direct", median_abs(gin_d)},
              {"g_in_tree", median_abs(gin_t)}};
  if (uniform) r.errors["g_out_direct"] = rms(gout_d), r.errors["g_out_tree"] = rms(gout_t);
  auto max_abs = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double z : v) m = std::max(m, std::abs(z));
    return m;
  };
  r.extra = {{"realisations", realisations}, {"probes", probes.size()}};
  for (const auto& [name, z] : {std::pair{"phi", &z_phi}, {"g_out", &z_gout}, {"phi_tree", &z_phi_t}, {"g_out_tree", &z_gout_t}}) {
    r.extra["rms_z_" + std::string(name)] = z->empty() ? nlohmann::json() : nlohmann::json(rms(*z));
    r.extra["max_abs_z_" + std::string(name)] = z->empty() ? nlohmann::json() : nlohmann::json(max_abs(*z));
  }
  // Profile of the first realisation's potential: direct sum and analytic against radius.
  Figure f{"potential_profile", std::string(uniform ? "Homogeneous" : "Plummer") + " sphere: potential at probes, N = " +
               std::to_string(n), "radius r", "potential phi (G = M = 1)", "linear", "linear", {}};
  Series sd{"direct sum", {}, {}, "points"}, st{"tree (quadrupole, theta 0.5)", {}, {}, "points"}, sa{"analytic", {}, {}, "line"};
  for (std::size_t q = 0; q < probes.size(); ++q) {
    const double rr = probes[q].x.norm();
    sd.x.push_back(rr), sd.y.push_back(phi_exact(rr) + phi_d[q] * std::abs(phi_exact(rr)));
    st.x.push_back(rr), st.y.push_back(phi_exact(rr) + phi_t[q] * std::abs(phi_exact(rr)));
  }
  for (int k = 0; k <= 100; ++k) sa.x.push_back(0.03 * k), sa.y.push_back(phi_exact(0.03 * k));
  f.series = {sa, sd, st};
  r.figures = {f};
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const auto v = Check::Kind::verification;
  // z-scores against the analytic fields: standard normal when the code and the formulas agree
  // (G, masses, signs). rms in [0.7, 1.3]: 800 correlated samples; max below 5 (800 normal
  // samples exceed 5 with probability 5e-4). The tree (quadrupole, theta 0.5) is held to the same
  // test: its own error adds in quadrature to the sampling error, rms z_tree = sqrt(1 + (e_tree /
  // se)^2) times the direct sum's. Its own error at the exterior probes, ~8e-4 (g_out_tree^2 -
  // g_out_direct^2 at N = 256000), is a third of the standard error at N = 64000 (rms z inflated
  // by 5 %) but 0.6 of it at 256000, where the tree's z-scores leave the bounds
  // (docs/cases/gravity.md). So the exterior-force z-test of the tree runs up to N = 64000; beyond
  // it the tree's own error is not negligible and only its bound holds.
  // A tree without the quadrupole term fails it at N = 64000 (measured rms 1.36, max 5.9).
  const std::pair<const char*, const char*> zs[] = {
      {"phi", "phi_direct"}, {"g_out", "g_out_direct"}, {"phi_tree", "phi_tree"}, {"g_out_tree", "g_out_tree"}};
  for (const auto& r : s.runs) {
    const std::string at = "_n" + std::to_string(r.params.value("n", 0L));
    for (const auto& [z, e] : zs) {
      if (r.extra.at("rms_z_" + std::string(z)).is_null()) continue;
      if (std::string(z) == "g_out_tree" && r.params.value("n", 0L) > 64000) continue;
      c.push_back({"rms_z_" + std::string(z) + at, r.extra.at("rms_z_" + std::string(z)), 0.7, 1.3, "z ~ N(0, 1)", v, e});
      c.push_back({"max_z_" + std::string(z) + at, r.extra.at("max_abs_z_" + std::string(z)), 0.0, 5.0, "z ~ N(0, 1)", v, e});
    }
  }
  // Bounds on every error at the finest level: measured at N = 64000 (fixed seeds), carried by
  // the claimed order (common/measured_bound.hpp), margin 1.5. The largest ratio of an error at another
  // level (1000..256000) to the measurement carried there is 1.25 (phi at N = 16000: sampling
  // scatter of four realisations; g_out_tree at 256000: 1.20 from the tree's own error floor).
  const bool uniform = s.runs.back().params.value("model", "uniform") == "uniform";
  const std::vector<std::pair<std::string, double>> measured =
      uniform ? std::vector<std::pair<std::string, double>>{{"phi_direct", 1.778e-3},  {"phi_tree", 1.774e-3},
                                                            {"g_in_direct", 1.110e-1}, {"g_in_tree", 1.116e-1},
                                                            {"g_out_direct", 2.553e-3}, {"g_out_tree", 2.667e-3}}
              : std::vector<std::pair<std::string, double>>{{"phi_direct", 2.553e-3}, {"phi_tree", 2.554e-3},
                                                            {"g_in_direct", 4.361e-2}, {"g_in_tree", 4.350e-2}};
  for (const auto& [e, m] : measured) c.push_back(measured_bound(s, e, m, 64000, 1.5));
  return c;
}

const Registration reg{Case{
    .name = "gravity_analytic",
    .summary = "direct sum and tree against analytic sphere potentials and forces (sampling theory)",
    .n_counts = "number of particles N drawn from the model",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 4000, "number of particles", 1.0),
               choice_param("model", "uniform", "mass model", {"uniform", "plummer"})},
    // Full: the same range at ratio 2, a denser fit (CPU times: docs/cases/gravity.md).
    // Not beyond 2.6e5: there the sampling error of the exterior force (~1.4e-3) meets the tree's
    // own error at theta 0.5 (~8e-4), and g_out_tree stops falling as N^-1/2.
    .levels = {.quick = {1000, 4000, 16000, 64000},
               .standard = {1000, 4000, 16000, 64000, 256000},
               .full = {1000, 2000, 4000, 8000, 16000, 32000, 64000, 128000, 256000}},
    // Orders in N from sampling theory (see the file comment). Measured over 1000..256000: 0.31
    // and 0.335 (g_in, claim 1/3), 0.456-0.517 (phi, g_out), se 0.007-0.04: four realisations per
    // level leave a statistical scatter of up to 25 % per level; band +-0.15.
    .orders = [](const Params& p) {
      const OrderClaim half{0.5, 0.15, "random sampling: potential and exterior force errors ~N^-1/2 (finite variance)"};
      const OrderClaim third{1.0 / 3.0, 0.15, "random sampling: force inside the mass ~N^-1/3 (nearest neighbour, "
                                              "Holtsmark dominated)"};
      OrderClaims o{{"phi_direct", half}, {"phi_tree", half}, {"g_in_direct", third}, {"g_in_tree", third}};
      if (p.text("model") == "uniform") o["g_out_direct"] = half, o["g_out_tree"] = half;
      return o;
    },
    .error_defs = {{"phi_direct", "rms over probes and realisations of (phi_direct - phi_exact) / |phi_exact|"},
                   {"phi_tree", "rms over probes and realisations of (phi_tree - phi_exact) / |phi_exact| (quadrupole, theta 0.5)"},
                   {"g_in_direct", "median over probes inside the mass of |g_direct - g_exact| / |g_exact|"},
                   {"g_in_tree", "median over probes inside the mass of |g_tree - g_exact| / |g_exact|"},
                   {"g_out_direct", "rms over probes outside the sphere of |g_direct - g_exact| / |g_exact|"},
                   {"g_out_tree", "rms over probes outside the sphere of |g_tree - g_exact| / |g_exact|"}},
    .variants = {{}, {"model=plummer"}},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::gravity_analytic_case
