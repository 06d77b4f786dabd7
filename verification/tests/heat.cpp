// Gates and input checks of the conduction cases (laplacian, heat, heat_stability, heat_stiff).
#include <catch2/catch.hpp>

#include <cmath>

#include "reference/cvode.hpp"
#include "sph/conduction/conduction.hpp"
#include "sph/core/lattice.hpp"
#include "sph/density/summation.hpp"
#include "sph/density/variable_h.hpp"
#include "sph/search/grid_search.hpp"
#include "verification/harness/sweep.hpp"

TEST_CASE("heat: bad input is refused", "[heat][input]") {
  const auto& c = sphv::find_case("heat");
  CHECK_THROWS_AS(c.parse({"K=-1"}), sphv::InputError);
  CHECK_THROWS_AS(c.parse({"solver=lu"}), sphv::InputError);
  CHECK_THROWS_AS(c.parse({"form=sixth"}), sphv::InputError);
  CHECK_THROWS_AS(c.parse({"n=4"}), sphv::InputError);  // support radius above half the box
  CHECK_THROWS_AS(sphv::find_case("laplacian").parse({"dim=4"}), sphv::InputError);
  // h/dx growing with n: h must still fall with n.
  CHECK_THROWS_AS(sphv::find_case("laplacian").parse({"hgrow=1"}), sphv::InputError);
  CHECK_THROWS_AS(sphv::find_case("laplacian").parse({"hgrow=-0.5"}), sphv::InputError);
  CHECK_NOTHROW(sphv::find_case("laplacian").parse({"hgrow=0.5", "n=64"}));
}

TEST_CASE("heat: an unstable explicit run ends with a verdict, not a NaN", "[heat][extreme]") {
  const auto& c = sphv::find_case("heat");
  // courant 1 is ten times the forward Euler bound (0.094 at hfact 4 in 1D).
  const auto r = sphv::run_case(c, c.parse({"n=16", "courant=1"}));
  CHECK(r.verdict.rfind("heun unstable", 0) == 0);
  CHECK(r.errors.count("time_euler") == 0);
  for (const auto& [k, v] : r.errors) CHECK(std::isfinite(v));
}

TEST_CASE("cvode driver: exponential decay and stats", "[heat][cvode]") {
  for (auto solver : {reference::LinearSolver::Spgmr, reference::LinearSolver::Band, reference::LinearSolver::Dense}) {
    reference::CvodeOptions o;
    o.rtol = 1e-10;
    o.atol = 1e-14;
    o.solver = solver;
    o.bandwidth = 1;
    // y_i' = -lambda_i y_i with lambda from 1 to 1e4: stiff, exact solution exp(-lambda t).
    const std::vector<double> lam = {1.0, 10.0, 1e2, 1e3, 1e4};
    auto f = [&](double, const std::vector<double>& y, std::vector<double>& yd) {
      for (std::size_t i = 0; i < y.size(); ++i) yd[i] = -lam[i] * y[i];
    };
    const auto r = reference::cvode_integrate(f, std::vector<double>(lam.size(), 1.0), 0.0, {0.5, 1.0}, o);
    REQUIRE(r.ok);
    REQUIRE(r.y.size() == 2);
    // Tolerance: rtol 1e-10 per step, global error a few hundred times that.
    CHECK(std::abs(r.y[1][0] - std::exp(-1.0)) < 1e-7);
    CHECK(std::abs(r.y[0][1] - std::exp(-5.0)) < 1e-7);
    CHECK(r.stats.steps > 0);
    CHECK(r.stats.rhs_evals >= r.stats.steps);
  }
  CHECK_THROWS_AS(reference::linear_solver_from_name("gmres2"), std::invalid_argument);
}

// The conduction terms against a direct sum of the chapter's formulas over all pairs, on a gas
// whose density is far from uniform (masses vary by a factor 3, positions jittered, h from (50)):
// forms that agree on uniform density (V_j = m_j / rho_j or m_j / rho_i, the weights of (56)/(58))
// differ here at first order. The sums below are written out from (69) and (56)-(59) (kernel
// gradient at h_ij = (h_i + h_j) / 2, errata); tolerance 1e-12 of each sum's scale (round-off).
TEST_CASE("conduction terms equal a direct sum of (69) and (56)-(59) on a non-uniform gas", "[heat]") {
  constexpr int D = 2;
  const sph::Box<D> box = sph::unit_box<D>(false);
  auto p = sph::lattice<D>(14, box, 1.0, 2.4, 0.2, 11);
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    p.m[i] *= 1.0 + 2.0 * p.x[i][0] * p.x[i][0];  // density rising threefold along x
    p.u[i] = 1.0 + std::sin(3.0 * p.x[i][0]) * std::cos(2.0 * p.x[i][1]);
  }
  sph::density_summation(p, sph::grid_search<D>(p.x, p.h, box), box);
  sph::smoothing_length_from_density(p, 2.4);  // (50): h varies with the density
  const auto nl = sph::grid_search<D>(p.x, p.h, box);
  sph::density_summation(p, nl, box);
  const sph::ConductionParams k{0.7, 1.3};
  auto gradW = [&](std::size_t i, std::size_t j) {
    const sph::Vec<D> rij = p.x[i] - p.x[j];
    return sph::CubicSpline<D>::gradW(rij, rij.norm(), 0.5 * (p.h[i] + p.h[j]));
  };
  auto T = [&](std::size_t i) { return p.u[i] / k.c_v; };
  // (69): du_i/dt = K / rho_i sum_j (m_j / rho_j) 2 (T_i - T_j) r_ij . grad_i W_ij / |r_ij|^2.
  std::vector<double> brookshaw(n, 0.0), scale(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const sph::Vec<D> rij = p.x[i] - p.x[j];
      const double term = k.K / p.rho[i] * (p.m[j] / p.rho[j]) * 2.0 * (T(i) - T(j)) * rij.dot(gradW(i, j)) / rij.squaredNorm();
      brookshaw[i] += term, scale[i] += std::abs(term);
    }
  // (56)/(58): G_i = rho_i sum_j m_j (T_i / rho_i^2 + T_j / rho_j^2) grad_i W_ij, then
  // du_i/dt = K / rho_i rho_i sum_j m_j (G_i / rho_i^2 + G_j / rho_j^2) . grad_i W_ij;
  // (57)/(59): G_i = 1 / rho_i sum_j m_j (T_j - T_i) grad_i W_ij, then
  // du_i/dt = K / rho_i 1 / rho_i sum_j m_j (G_j - G_i) . grad_i W_ij.
  std::vector<sph::Vec<D>> Gs(n, sph::Vec<D>::Zero()), Gd(n, sph::Vec<D>::Zero());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      Gs[i] += p.m[j] * (T(i) / (p.rho[i] * p.rho[i]) + T(j) / (p.rho[j] * p.rho[j])) * gradW(i, j);
      Gd[i] += p.m[j] * (T(j) - T(i)) * gradW(i, j);
    }
    Gs[i] *= p.rho[i], Gd[i] /= p.rho[i];
  }
  std::vector<double> symmetric(n, 0.0), difference(n, 0.0), scale_s(n, 0.0), scale_d(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double ts = k.K * p.m[j] * (Gs[i] / (p.rho[i] * p.rho[i]) + Gs[j] / (p.rho[j] * p.rho[j])).dot(gradW(i, j));
      const double td = k.K / (p.rho[i] * p.rho[i]) * p.m[j] * (Gd[j] - Gd[i]).dot(gradW(i, j));
      symmetric[i] += ts, scale_s[i] += std::abs(ts);
      difference[i] += td, scale_d[i] += std::abs(td);
    }
  auto rates = [&](auto term) {
    sph::Scene<D, decltype(term)> scene{{term}};
    sph::Derivatives<D> d;
    scene.derivatives(p, sph::Neighbourhood<D>{nl, box}, d);
    return d.dudt;
  };
  const auto b = rates(sph::BrookshawConduction<D>{k});
  const auto s = rates(sph::TwoPassConduction<D, sph::SymmetricForm>{k, {}});
  const auto df = rates(sph::TwoPassConduction<D, sph::DifferenceForm>{k, {}});
  double worst_b = 0.0, worst_s = 0.0, worst_d = 0.0, rho_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    worst_b = std::max(worst_b, std::abs(b[i] - brookshaw[i]) / scale[i]);
    worst_s = std::max(worst_s, std::abs(s[i] - symmetric[i]) / scale_s[i]);
    worst_d = std::max(worst_d, std::abs(df[i] - difference[i]) / scale_d[i]);
    rho_max = std::max(rho_max, p.rho[i]);
  }
  INFO("max relative difference: (69) " << worst_b << ", (56)/(58) " << worst_s << ", (57)/(59) " << worst_d);
  CHECK(worst_b <= 1e-12);
  CHECK(worst_s <= 1e-12);
  CHECK(worst_d <= 1e-12);
  // The gas is non-uniform indeed: rho spans more than a factor 2 (else the check is blind to V_j).
  double rho_min = rho_max;
  for (std::size_t i = 0; i < n; ++i) rho_min = std::min(rho_min, p.rho[i]);
  CHECK(rho_max / rho_min > 2.0);
}
