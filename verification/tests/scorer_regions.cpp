// The scorers' weights against errors known by construction: an error is summed and normalised
// over the same particles (a tube's domain, not the particles beside it), and a particle's cell
// is sized from its phase's exact density, not from the density column (the SPH estimate, smeared
// across an interface).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>
#include <string>

#include "reference/riemann.hpp"
#include "verification/cases/square/errors.hpp"
#include "verification/cases/square/setup.hpp"
#include "verification/commands/score.hpp"
#include "verification/snapshot/snapshot.hpp"

using namespace sphv;

// Sod's exact solution at t = 0.25 on 400 equal-volume particles of the open tube's domain
// [0, 1] (m = rho dx, so every weight m/rho is dx), every velocity raised by delta = 1e-3, and 100
// more particles beyond it on (1, 1.25] (the right state, 10 times too dense: outside the
// domain, not scored). The volume-weighted L1 of a constant offset over the domain is the offset
// itself: L1_v = delta, whatever the particles outside weigh; the other errors are 0.
TEST_CASE("score: a tube's L1 is normalised by its domain's volume, not the particles beside it (known answer)",
          "[score]") {
  const reference::GasState left{1.0, 0.0, 1.0}, right{0.125, 0.0, 0.1};
  const double gamma = 1.4, t = 0.25, delta = 1e-3, dx = 1.0 / 400;
  const reference::RiemannSolution exact(left, right, gamma, 0.5);
  Snapshot s;
  s.format = "csv";
  s.dim = 1;
  s.time = t;
  for (const std::string name : {"x", "vx", "rho", "m", "p"}) s.taken_from[name] = name;
  auto add = [&](double x, double rho, double v, double p) {
    s.columns["x"].push_back(x), s.columns["vx"].push_back(v), s.columns["rho"].push_back(rho);
    s.columns["p"].push_back(p), s.columns["m"].push_back(rho * dx);
  };
  for (int i = 0; i < 400; ++i) {
    const double x = (i + 0.5) * dx;
    const auto e = exact.sample(x, t);
    add(x, e.rho, e.u + delta, e.p);
  }
  for (int i = 0; i < 100; ++i) add(1.0 + (i + 0.5) * dx, 10.0 * right.rho, 0.0, right.p);
  const Result r = score_snapshot(find_case("sod"), {"preset=sod", "gamma=1.4", "t_end=0.25", "domain=0,1", "ends=open"}, s);
  REQUIRE(r.errors.count("L1_v") == 1);
  // sum_i dx delta / sum_i dx over the domain: delta up to round-off (1e-9 leaves room for the sums
  // of 400 terms; the domain share that the wrong normalisation would bring is 0.8).
  CHECK(r.errors.at("L1_v") == Approx(delta).epsilon(1e-9));
  for (const char* e : {"L1_rho", "L1_p", "L1_u"}) {
    INFO(e);
    CHECK(r.errors.at(e) <= 1e-12);  // round-off of u = p / ((gamma - 1) rho) only
  }
}

// The isobaric square at t = 0 (square/setup.hpp: two lattices, each phase's masses making its
// density exact): its misfit is 0 by definition, every particle's cell (m / rho_phase)^(1/d)
// lying on its own side of the edge (square/errors.hpp). The density column given to the scorer
// is smeared across the edge, as an SPH density is (the mean of the two phases within one light
// spacing of its faces' planes); the cells must not follow it.
TEST_CASE("square: the exact initial square's misfit is zero with a smeared density column (known answer)", "[score]") {
  for (const char* dim : {"dim=2", "dim=3"}) {
    INFO(dim);
    const Params prm = find_case("square").parse({"n=16", dim});
    const reference::IsobaricSquare sq = square::problem(prm);
    Result r;
    auto one = [&](auto d) {
      constexpr int D = decltype(d)::value;
      sph::Particles<D> p = square::initial_particles<D>(prm);
      std::vector<double> rho = p.rho;
      for (std::size_t i = 0; i < p.size(); ++i) {
        double edge = 1.0;  // distance to the nearest plane of the square's faces, x_k = 1/4 or 3/4
        for (int k = 0; k < D; ++k) edge = std::min(edge, std::abs(std::abs(p.x[i][k] - 0.5) - 0.25));
        if (edge < 1.0 / 16) rho[i] = 0.5 * (sq.rho_in() + sq.rho_out());
      }
      square::measure<D>(r, p.x, p.v, p.m, rho, p.u, square::phase_by_u(p.u, sq, prm.real("gamma")), 0.0, sq,
                         prm.real("gamma"), prm.integer("n"));
    };
    if (std::string(dim) == "dim=2") one(std::integral_constant<int, 2>{});
    else one(std::integral_constant<int, 3>{});
    REQUIRE(r.errors.count("misfit") == 1);
    CHECK(r.errors.at("misfit") <= 1e-12);  // 0 by definition; the bound is round-off in the cells' overlaps
    CHECK(r.errors.at("v_rms") <= 1e-12);
  }
}
