// Gates and input checks of the conduction cases (laplacian, heat, heat_stability, heat_stiff).
#include <catch2/catch.hpp>

#include <cmath>

#include "reference/cvode.hpp"
#include "verification/sweep.hpp"

TEST_CASE("heat: bad input is refused", "[heat][input]") {
  const auto& c = sphv::find_case("heat");
  CHECK_THROWS_AS(c.parse({"K=-1"}), sphv::InputError);
  CHECK_THROWS_AS(c.parse({"solver=lu"}), sphv::InputError);
  CHECK_THROWS_AS(c.parse({"form=sixth"}), sphv::InputError);
  CHECK_THROWS_AS(c.parse({"n=4"}), sphv::InputError);  // support radius above half the box
  CHECK_THROWS_AS(sphv::find_case("laplacian").parse({"dim=4"}), sphv::InputError);
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
