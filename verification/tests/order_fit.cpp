// The observed order's fit and the grid convergence index (verification/harness/sweep.cpp) against known
// answers: data built with a known slope and known residuals, whose least-squares slope and
// standard error follow in closed form (the standard error sets the width of every order band the
// report shows), and a functional with a known limit, whose GCI follows in closed form.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "verification/harness/sweep.hpp"

namespace {

// err_k = C n_k^-p exp(r_k) on n_k = n0 2^k, k = 0..4. The residuals r = eps (1, -2, 0, 2, -1)
// sum to zero and are orthogonal to log n_k - mean (which is ln 2 (k - 2)), so the least-squares
// line through (log n, log err) is exactly log C - p log n with residuals r, and
//   se(slope)^2 = [sum r^2 / (N - 2)] / sum (x - mean x)^2 = [10 eps^2 / 3] / [10 (ln 2)^2],
//   se(slope) = eps / (sqrt(3) ln 2),
// while the intercept's variance, [sum r^2 / (N - 2)] (1/N + mean(x)^2 / sum (x - mean x)^2),
// grows with n0 (mean x = log n0 + 2 ln 2): its square root is 1.7, 4.7, 7.4 times the slope's at
// n0 = 1, 25, 400.
struct Data {
  std::vector<double> n, err;
};
Data known_residuals(double n0, double C, double p, double eps) {
  const double r[] = {1.0, -2.0, 0.0, 2.0, -1.0};
  Data d;
  for (int k = 0; k < 5; ++k) {
    d.n.push_back(n0 * std::pow(2.0, k));
    d.err.push_back(C * std::pow(d.n.back(), -p) * std::exp(eps * r[k]));
  }
  return d;
}

}  // namespace

TEST_CASE("order fit: slope and standard error equal the closed-form least squares (known answer)", "[sweep]") {
  for (const double n0 : {1.0, 25.0, 400.0}) {
    for (const double eps : {0.0, 0.01, 0.2}) {
      const double p = 1.7;
      const Data d = known_residuals(n0, 3.0, p, eps);
      const sphv::Order o = sphv::observed_order(d.n, d.err);
      const double se = eps / (std::sqrt(3.0) * std::log(2.0));
      INFO("n0 " << n0 << ", eps " << eps << ": order " << o.p << " +- " << o.se << ", closed form " << p << " +- " << se);
      // Round-off of logs and sums of five O(10) numbers: 1e-12 absolute.
      CHECK(std::abs(o.p - p) <= 1e-12);
      CHECK(std::abs(o.se - se) <= 1e-12);
    }
  }
}

TEST_CASE("order fit: a general set of five points against the normal equations by hand (known answer)", "[sweep]") {
  const std::vector<double> n = {16, 32, 64, 128, 256}, err = {0.21, 0.062, 0.019, 0.0043, 0.0013};
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) mx += std::log(n[k]) / 5.0, my += std::log(err[k]) / 5.0;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    sxx += (std::log(n[k]) - mx) * (std::log(n[k]) - mx);
    sxy += (std::log(n[k]) - mx) * (std::log(err[k]) - my);
  }
  const double slope = sxy / sxx, intercept = my - slope * mx;
  double ssr = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) ssr += std::pow(std::log(err[k]) - intercept - slope * std::log(n[k]), 2);
  const double se = std::sqrt(ssr / 3.0 / sxx);
  const sphv::Order o = sphv::observed_order(n, err);
  INFO("fit " << o.p << " +- " << o.se << ", by hand " << -slope << " +- " << se);
  CHECK(o.p == Approx(-slope).epsilon(1e-12));
  CHECK(o.se == Approx(se).epsilon(1e-10));  // se is a difference of near sums: a few digits less
  // Below three points there is no residual to estimate the scatter from: se is not a number.
  CHECK(std::isnan(sphv::observed_order({16, 32}, {0.21, 0.062}).se));
}

// Roache's grid convergence index on a functional with a known limit: f(n) = A + C n^-p exactly.
// Then f1 - f2 = C n1^-p (1 - r^p) on the finest pair (n1 = r n2), so |f1 - f2| / (r^p - 1) is
// |f1 - A|, the finest level's true error, and
//   GCI = Fs |f1 - f2| / (|f1| (r^p - 1)) = Fs |f1 - A| / |f1|,
// with p observed from three levels at a constant ratio (Fs = 1.25), or the claimed order with two
// (Fs = 3; exact when the claim is p). The claimed order differs from p here, so a GCI that took it
// in place of the observed order with three levels would not give this answer.
TEST_CASE("grid convergence index of f = A + C n^-p equals Fs |f1 - A| / |f1| (known answer)", "[sweep]") {
  const double A = 2.0, C = -0.7, p = 1.6;
  auto f = [&](double n) { return A + C * std::pow(n, -p); };
  const std::vector<double> n3 = {20, 40, 80}, f3 = {f(20), f(40), f(80)};
  const auto g3 = sphv::grid_convergence_index(n3, f3, 2.0);
  REQUIRE(g3);
  const double true_rel = std::abs(f(80) - A) / std::abs(f(80));
  INFO("three levels: order " << g3->order << ", Fs " << g3->safety << ", GCI " << g3->gci << "; known " << 1.25 * true_rel);
  CHECK(std::abs(g3->order - p) <= 1e-9);  // logs of differences of O(1) values: round-off 1e-12
  CHECK(g3->safety == 1.25);
  CHECK(g3->gci == Approx(1.25 * true_rel).epsilon(1e-9));
  const auto g2 = sphv::grid_convergence_index({40, 80}, {f(40), f(80)}, p);
  REQUIRE(g2);
  INFO("two levels, claimed order p: GCI " << g2->gci << "; known " << 3.0 * true_rel);
  CHECK(g2->safety == 3.0);
  CHECK(g2->gci == Approx(3.0 * true_rel).epsilon(1e-12));
}
