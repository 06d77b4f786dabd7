// square and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/cases/square/snapshots.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "verification/cases/square/errors.hpp"
#include "verification/cases/square/setup.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/problem_check.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::square_snapshots_case {
namespace {

using namespace snapshot_columns;

// The square is isobaric: the particles' median pressure is p0 within 5 % at every time (the
// density sum's error across the step, where the pressure blips, touches a few particles, not the
// median). A gas of another gamma (u written for it) or p0 is off by tens of %.
void check_pressure(Result& r, const Snapshot& s, const reference::IsobaricSquare& sq, double gamma) {
  std::vector<double> p = pressure(s, gamma, "square");
  std::nth_element(p.begin(), p.begin() + p.size() / 2, p.end());
  const double median = p[p.size() / 2];
  const std::vector<StateCheck> checks = {
      {"the gas (" + std::to_string(s.size()) + " particles)", "median p", median, sq.pressure(), sq.pressure(), 0.05}};
  apply_problem_check(r, checks, "gamma or p0: the median pressure is " + problem_check::number(median) + ", p0 = " +
                                     problem_check::number(sq.pressure()) + " at gamma " + problem_check::number(gamma) +
                                     " (--set p0=P or gamma=G; SWIFT's gamma is fixed when it is built: --with-adiabatic-index)");
}

// The square in the periodic unit box [0, 1)^d of sphv's and SWIFT's layout: a file that states
// another box is refused (the reference's square of side 1/2 and its speeds are in units of the
// box's side). The phases are read from u (square/errors.hpp), or from p / rho where u is absent.
Result score_square(const Params& prm, const Snapshot& s) {
  const std::string who = "square";
  positive(s, "rho", who);
  positive(s, "m", who);
  if (const auto box = s.stated.find("box"); box != s.stated.end())
    for (double side : box->second.value)
      if (side != 0.0 && std::abs(side - 1.0) > 1e-12)
        throw InputError(s.path.string() + ": square scores the periodic unit box [0, 1)^d, the file's box (" +
                         box->second.from + ") has a side " + std::to_string(side) + " (rescale the snapshot)");
  if (s.dim != prm.integer("dim"))
    throw InputError(s.path.string() + ": the file has " + std::to_string(s.dim) + " coordinate(s), dim = " +
                     prm.text("dim") + " (set dim=" + std::to_string(s.dim) + ")");
  const reference::IsobaricSquare sq = square::problem(prm);
  Result r;
  const auto u = internal_energy(s, prm.real("gamma"), who);
  auto one = [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    auto x = vectors<D>(s, "", who);
    for (auto& xi : x)
      for (int d = 0; d < D; ++d) xi[d] -= std::floor(xi[d]);  // into [0, 1)
    square::measure<D>(r, x, vectors<D>(s, "v", who), s.at("m", who), s.at("rho", who), u,
                       square::phase_by_u(u, sq, prm.real("gamma")), prm.real("t_end"), sq, prm.real("gamma"),
                       prm.integer("n"));
  };
  if (s.dim == 2) one(std::integral_constant<int, 2>{});
  else one(std::integral_constant<int, 3>{});
  check_pressure(r, s, sq, prm.real("gamma"));
  return r;
}

}  // namespace
}  // namespace sphv::square_snapshots_case

namespace sphv::square {

Scorer scorer() {
  return {"t_end", square_snapshots_case::score_square, snapshot_columns::real_t_end, Resolution::none,
          snapshot_columns::real_gamma};
}

// The square's particles in the periodic unit box [0, 1)^d (square/setup.hpp: equal masses on
// two lattices, or one lattice), rho and u exact; the unit box is SWIFT's layout too.
InitialState initial_conditions(const Params& p, IcLayout layout) {
  auto one = [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return ic_layout::placed(ic_layout::at_start(initial_particles<D>(p), p.real("gamma")), p.real("gamma"), layout,
                             0.0, 1.0);
  };
  if (p.integer("dim") == 2) return one(std::integral_constant<int, 2>{});
  return one(std::integral_constant<int, 3>{});
}

}  // namespace sphv::square
