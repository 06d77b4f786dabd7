// The exact Riemann solver (reference/riemann) against Toro's published tables 4.2/4.3 and
// the Sod wave speeds of /work/shared/spec/reference-values.md.
#include <catch2/catch.hpp>

#include <cmath>
#include <algorithm>
#include <string>

#include "reference/riemann.hpp"

using reference::GasState;
using reference::RiemannSolution;

namespace {

// A published value is exact to half a unit in its last printed digit; that half unit is
// the tolerance (0.30313 -> 5e-6), so the check is "agrees to every digit Toro prints".
// Test 5's input states are themselves Toro's 6-digit results of tests 3 and 4; their rounding
// (relative 1e-6) moves p* and u* by up to 3e-6 relatively, so its values are held to 5
// significant digits (the requirement) rather than to every printed digit.
struct Published {
  double value, tol;
  Published(const char* text, int max_digits = 6) : value(std::stod(text)) {
    const std::string t(text);
    const auto dot = t.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(t.size() - dot - 1);
    tol = 0.5 * std::pow(10.0, -decimals);
    const int e = static_cast<int>(std::floor(std::log10(std::abs(value) + 1e-300)));
    if (value != 0.0) tol = std::max(tol, 0.5 * std::pow(10.0, e - max_digits + 1));
  }
};

struct Row {
  const char* name;
  GasState l, r;
  Published p_star, u_star, rho_l, rho_r;
};

// Toro tables 4.1-4.3 (gamma = 1.4), as printed: 5 or 6 significant digits, except test 2
// whose p* = 0.00189 has 3 and rho* = 0.02185 has 4.
const Row rows[] = {
    {"1 (Sod)", {1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, "0.30313", "0.92745", "0.42632", "0.26557"},
    {"2 (123)", {1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, "0.00189", "0.0", "0.02185", "0.02185"},
    {"3 (left blast)", {1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, "460.894", "19.5975", "0.57506", "5.99924"},
    {"4 (right blast)", {1.0, 0.0, 0.01}, {1.0, 0.0, 100.0}, "46.0950", "-6.19633", "5.99242", "0.57511"},
    {"5 (collision)", {5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, {"1691.64", 5}, {"8.68975", 5}, {"14.2823", 5},
     {"31.0426", 5}},
};

}  // namespace

TEST_CASE("exact Riemann solver reproduces Toro's star states", "[riemann]") {
  for (const auto& row : rows) {
    INFO("Toro test " << row.name);
    const RiemannSolution s(row.l, row.r, 1.4);
    auto agrees = [](double computed, const Published& p) {
      INFO("computed " << computed << ", published " << p.value << " +- " << p.tol);
      CHECK(std::abs(computed - p.value) <= p.tol);
    };
    agrees(s.p_star(), row.p_star);
    if (row.u_star.value == 0.0) CHECK(std::abs(s.u_star()) <= 1e-12);  // symmetric data: u* = 0 exactly
    else agrees(s.u_star(), row.u_star);
    agrees(s.rho_star_left(), row.rho_l);
    agrees(s.rho_star_right(), row.rho_r);
  }
}

TEST_CASE("exact Riemann solver: Sod wave speeds and sampled profile", "[riemann]") {
  const RiemannSolution s({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4, 0.5);
  CHECK(std::abs(s.right_head() - 1.75216) <= 5e-6);
  CHECK(std::abs(s.left_head() - -1.18322) <= 5e-6);
  CHECK(std::abs(s.left_tail() - -0.07027) <= 5e-6);
  const double t = 0.25;
  // Undisturbed states outside the waves, star states between them.
  CHECK(s.sample(0.1, t).rho == 1.0);
  CHECK(s.sample(0.99, t).p == 0.1);
  const auto mid_l = s.sample(0.5 + 0.5 * (s.left_tail() + s.u_star()) * t, t);
  CHECK(mid_l.rho == Approx(s.rho_star_left()).epsilon(1e-14));
  CHECK(mid_l.p == Approx(s.p_star()).epsilon(1e-14));
  const auto mid_r = s.sample(0.5 + 0.5 * (s.u_star() + s.right_head()) * t, t);
  CHECK(mid_r.rho == Approx(s.rho_star_right()).epsilon(1e-14));
  CHECK(mid_r.e == Approx(s.p_star() / (0.4 * s.rho_star_right())).epsilon(1e-14));
  // The fan is continuous at its head and tail, and isentropic inside (p / rho^gamma = const).
  const double eps = 1e-9;
  CHECK(s.sample(0.5 + (s.left_head() + eps) * t, t).rho == Approx(1.0).epsilon(1e-8));
  CHECK(s.sample(0.5 + (s.left_tail() - eps) * t, t).p == Approx(s.p_star()).epsilon(1e-8));
  const auto fan = s.sample(0.5 + 0.5 * (s.left_head() + s.left_tail()) * t, t);
  CHECK(fan.p / std::pow(fan.rho, 1.4) == Approx(1.0).epsilon(1e-13));
  // Rankine-Hugoniot mass flux across the shock: rho_R (S - u_R) = rho*R (S - u*).
  CHECK(0.125 * s.right_head() == Approx(s.rho_star_right() * (s.right_head() - s.u_star())).epsilon(1e-13));
}

TEST_CASE("exact Riemann solver refuses invalid data and vacuum", "[riemann]") {
  using reference::RiemannError;
  CHECK_THROWS_AS(RiemannSolution({1, 0, 1}, {1, 0, 1}, 1.0), RiemannError);
  CHECK_THROWS_AS(RiemannSolution({-1, 0, 1}, {1, 0, 1}, 1.4), RiemannError);
  CHECK_THROWS_AS(RiemannSolution({1, 0, 1}, {1, 0, -1}, 1.4), RiemannError);
  CHECK_THROWS_AS(RiemannSolution({1, -10, 0.4}, {1, 10, 0.4}, 1.4), RiemannError);  // vacuum
}
