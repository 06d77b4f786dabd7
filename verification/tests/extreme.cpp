// References and gates of the extreme-case catalogue (sedov, noh, strong tubes, stability maps).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <omp.h>

#include "reference/noh.hpp"
#include "reference/sedov.hpp"
#include "verification/cases/sedov/errors.hpp"
#include "verification/harness/sweep.hpp"

namespace {
// One thread (see gates.cpp): results do not depend on the thread count.
sphv::Sweep sweep_one_thread(const sphv::Case& c, const std::vector<long>& levels, const std::vector<std::string>& settings) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  sphv::Sweep s = sphv::run_sweep(c, levels, settings);
  omp_set_num_threads(before);
  return s;
}
}  // namespace

TEST_CASE("sedov reference: xi_0 against the published table", "[reference][sedov]") {
  // /work/shared/spec/reference-values.md (Sedov-Taylor table): 4 significant digits asked,
  // tolerance half a unit in the 4th digit of the table's rounding (1D values have 4 digits).
  struct Row {
    int d;
    double gamma, xi0;
  };
  for (const Row row : {Row{3, 1.4, 1.03278}, Row{2, 1.4, 1.00402}, Row{1, 1.4, 0.9754}, Row{3, 5.0 / 3.0, 1.15167},
                        Row{2, 5.0 / 3.0, 1.15379}, Row{1, 5.0 / 3.0, 1.1837}}) {
    const reference::Sedov s(row.d, row.gamma);
    INFO("d = " << row.d << ", gamma = " << row.gamma << ": xi_0 = " << s.xi0());
    CHECK(std::abs(s.xi0() - row.xi0) < 5e-5 * row.xi0);
  }
}

TEST_CASE("sedov: the exact kinetic share and the thermal share add up to the blast's energy", "[reference][sedov]") {
  // The thermal share sigma_d alpha^2 xi_0^(d+2) int_0^1 h / (gamma - 1) xi^(d-1) dxi, summed here
  // on its own grid (midpoint, 2 10^5 cells): with the kinetic share it must give the energy
  // integral's 1, to the tabulation's accuracy (1e-4: the profiles are linear between points).
  for (const int d : {2, 3})
    for (const double gamma : {1.4, 5.0 / 3.0}) {
      const reference::Sedov s(d, gamma);
      const double sigma = d == 2 ? 2.0 * M_PI : 4.0 * M_PI, alpha = 2.0 / (d + 2);
      double thermal = 0.0;
      for (int k = 0; k < 200000; ++k) {
        const double xi = (k + 0.5) / 200000;
        thermal += s.h(xi) / (gamma - 1.0) * std::pow(xi, d - 1) / 200000;
      }
      thermal *= sigma * alpha * alpha * std::pow(s.xi0(), d + 2);
      const double kinetic = sphv::sedov::kinetic_share(s, d);
      INFO("d = " << d << ", gamma = " << gamma << ": kinetic " << kinetic << ", thermal " << thermal);
      CHECK(kinetic > 0.1);
      CHECK(std::abs(kinetic + thermal - 1.0) < 1e-4);
    }
}

TEST_CASE("sedov reference: jump conditions and centre behaviour", "[reference][sedov]") {
  for (int d = 1; d <= 3; ++d) {
    const double gamma = 5.0 / 3.0;
    const reference::Sedov s(d, gamma);
    // Strong-shock density jump (gamma + 1)/(gamma - 1) = 4 at xi = 1; ambient outside.
    CHECK(s.g(1.0) == Approx(4.0).epsilon(1e-12));
    CHECK(s.g(1.01) == 1.0);
    CHECK(s.h(1.01) == 0.0);
    // Near the centre v -> U xi / gamma (homologous), density -> 0, pressure finite.
    CHECK(s.f(1e-3) == Approx(1e-3 / gamma).epsilon(1e-3));
    CHECK(s.g(1e-2) < 1e-2);
    CHECK(s.h(0.0) > 0.1);
    // Energy integral recomputed on the tabulated profiles by the trapezoidal rule.
    const int N = 20000;
    double I = 0.0;
    for (int k = 0; k <= N; ++k) {
      const double xi = static_cast<double>(k) / N, w = (k == 0 || k == N) ? 0.5 : 1.0;
      I += w * std::pow(xi, d - 1) * (0.5 * s.g(xi) * s.f(xi) * s.f(xi) + s.h(xi) / (gamma - 1.0)) / N;
    }
    const double sigma = d == 1 ? 2.0 : d == 2 ? 2.0 * M_PI : 4.0 * M_PI, alpha = 2.0 / (d + 2.0);
    CHECK(sigma * alpha * alpha * std::pow(s.xi0(), d + 2) * I == Approx(1.0).epsilon(1e-4));
  }
  // Physical scaling R = xi_0 (E t^2 / rho)^(1/(d+2)).
  const reference::Sedov s3(3, 1.4);
  CHECK(s3.shock_radius(1.0, 1.0, 1.0) == Approx(1.03278).epsilon(1e-5));
  CHECK(s3.shock_radius(8.0, 2.0, 0.5) == Approx(1.032777 * std::pow(1.0, 0.2)).epsilon(1e-5));
}

TEST_CASE("noh reference: published post-shock states", "[reference][noh]") {
  // reference-values.md: gamma = 5/3, rho0 = 1, u0 = 1: 4, 16, 64; shock speed 1/3; p = rho/3.
  const double expected[] = {4.0, 16.0, 64.0};
  for (int d = 1; d <= 3; ++d) {
    const reference::Noh noh(d, 5.0 / 3.0);
    CHECK(noh.post_shock_density() == Approx(expected[d - 1]));
    CHECK(noh.shock_speed() == Approx(1.0 / 3.0));
    CHECK(noh.post_shock_pressure() == Approx(expected[d - 1] / 3.0));
    const auto in = noh.at(0.1, 0.6), out = noh.at(0.6, 0.6);
    CHECK(in.rho == Approx(expected[d - 1]));
    CHECK(in.v == 0.0);
    CHECK(out.rho == Approx(std::pow(2.0, d - 1)));
    CHECK(out.v == -1.0);
    CHECK(out.p == 0.0);
  }
}

TEST_CASE("sedov: the harness gates the density L1 and shock-radius orders (2D, n = 48, 96)", "[extreme][sedov]") {
  // The quick levels, so the harness adds the order checks of the claims (~5 s): L1_rho_deposit
  // 1 +- 0.3 (measured 0.91) and shock_radius at least 1 (measured 1.96) verify; L1_rho, against
  // the point blast, claims no order (its limit is the deposit's memory, sedov/deposit.hpp).
  const auto s = sweep_one_thread(sphv::find_case("sedov"), {48, 96}, {});
  REQUIRE(s.observed_order.count("L1_rho_deposit") == 1);
  for (const auto& ch : s.checks) {
    INFO(ch.name << " = " << ch.value << " in [" << ch.lo << ", " << ch.hi << "]: " << ch.why);
    CHECK(ch.pass());
  }
  for (const char* order : {"order_L1_rho_deposit", "order_shock_radius"})
    CHECK(std::any_of(s.checks.begin(), s.checks.end(), [&](const sphv::Check& c) { return c.name == order; }));
  for (const auto& r : s.rows) {
    INFO(r.error << ": " << r.why);
    CHECK(r.outcome == (r.error == "L1_rho" ? "no order claimed" : "verified"));
  }
}
