// The shock tubes (sod, sod2d, sod3d) and other codes' files: the scorer of `sphv score` and the
// initial conditions of `sphv ic`.
#include "verification/cases/shock_tubes/snapshots.hpp"

#include <cmath>

#include "verification/cases/shock_tubes/errors.hpp"
#include "verification/cases/shock_tubes/simulate.hpp"
#include "verification/snapshot/ic_layout.hpp"
#include "verification/snapshot/score_columns.hpp"

namespace sphv::sod_snapshots_case {
namespace {

using namespace snapshot_columns;
using namespace ic_layout;

// The tube's domain as text: "[0, 2], periodic".
std::string domain_text(const TubeProblem& pr) {
  return "[" + shortest(pr.x_lo) + ", " + shortest(pr.x_hi) + "], " + pr.ends;
}

// A periodic or closed tube scores every particle (one outside it fails the verdict) up to the
// time its exact solution holds; an open one is a window of an unbounded tube.
Result score_tube(const Params& prm, const Snapshot& s) {
  const TubeProblem pr = tube_problem(prm);
  const std::string who = "the shock tube";
  positive(s, "rho", who);
  positive(s, "m", who);
  const TubeExact exact(pr);
  const std::string f = s.path.string(), domain = domain_text(pr);
  if (pr.t_end > exact.valid_until())
    throw InputError(f + ": at t = " + shortest(pr.t_end) + " the exact solution no longer holds on the tube " + domain +
                     ": " + (pr.ends == "periodic" ? "the waves from x0 and from the periodic wrap meet" : "the first wave from x0 reaches an end") +
                     " at t = " + shortest(exact.valid_until()));
  Result r;
  std::size_t outside = 0;
  r.errors = tube_l1_errors(s.at("x", who), s.at("vx", who), s.at("rho", who), pressure(s, pr.gamma, who),
                            internal_energy(s, pr.gamma, who), s.at("m", who), s.size(), exact, pr.t_end, &outside);
  if (outside == s.size())
    throw InputError(f + ": no particle lies in the tube's domain " + domain + " (--set domain=x_lo,x_hi)");
  r.extra["particles_scored"] = s.size() - outside;
  r.extra["window"] = "the domain " + domain + (outside > 0 && pr.ends == "open" ? ": the rest lie outside it, not scored" : "");
  r.extra["x0"] = pr.x0;
  r.extra["gamma"] = pr.gamma;
  if (std::isfinite(exact.valid_until())) r.extra["exact_until"] = exact.valid_until();
  if (outside > 0 && pr.ends != "open")
    r.verdict = std::to_string(outside) + " of " + std::to_string(s.size()) + " particles outside the domain " + domain;
  return r;
}

double tube_t_end(const Params& p) { return tube_problem(p).t_end; }
double tube_gamma(const Params& p) { return tube_problem(p).gamma; }

// The shock tube as SWIFT's SodShock examples lay it out: periodic on [0, 2] along x, the left
// state on [0, 1), the right state on [1, 2), so the interfaces lie at x = 1 and at the wrap
// x = 0 = 2 and no boundary layer is needed. The left spacing is 1/n; in 2D/3D the tube is
// periodic across with tube::layout's width and lattices. Each side's spacing along x divides its
// unit length and its particle mass makes its density exact (the masses of the two sides agree
// when the counts divide, as in makeIC.py).
template <int D>
InitialState periodic_tube(const Params& prm) {
  const TubeProblem pr = tube_problem(prm);
  if (pr.x0 != 0.5)
    throw InputError("x0 = " + prm.text("x0") + ": the periodic tube of SWIFT's layout has its interfaces at x = 1 "
                     "and at the wrap of [0, 2], the tube [0, 1]'s x0 = 0.5 moved to its middle");
  const long n = prm.integer("n");
  const double hfact = prm.real("hfact"), dxl = 1.0 / n;
  const double s = std::pow(pr.left.rho / pr.right.rho, 1.0 / D);  // isotropic spacing ratio R/L
  const int ntl = D == 1 ? 1 : static_cast<int>(std::ceil(2.5 * hfact * std::max(1.0, s)));
  const int ntr = D == 1 ? 1 : std::max(1, static_cast<int>(std::lround(ntl / s)));
  const double width = ntl * dxl, mass = pr.left.rho * std::pow(dxl, D);
  const long nr = std::max(1L, std::lround(pr.right.rho * std::pow(width / ntr, D - 1) / mass));
  auto per_slab = [](int nt) {
    long per = 1;
    for (int d = 1; d < D; ++d) per *= nt;
    return per;
  };
  sph::Particles<D> p;
  p.resize(n * per_slab(ntl) + nr * per_slab(ntr));
  std::size_t k = 0;
  auto place = [&](double from, long count, int nt, const reference::GasState& st) {
    const double dx = 1.0 / count, dy = width / nt;
    for (long i = 0; i < count; ++i)
      for (long t = 0; t < per_slab(nt); ++t, ++k) {
        p.x[k][0] = from + (i + 0.5) * dx;
        for (long d = 1, rest = t; d < D; ++d, rest /= nt) p.x[k][d] = (static_cast<double>(rest % nt) + 0.5) * dy;
        p.v[k][0] = st.u;
        p.m[k] = st.rho * dx * std::pow(dy, D - 1);
        p.rho[k] = st.rho;
        p.u[k] = st.p / ((pr.gamma - 1.0) * st.rho);
      }
  };
  place(0.0, n, ntl, pr.left);
  place(1.0, nr, ntr, pr.right);
  sph::smoothing_length_from_density(p, hfact);  // (50)
  return {at_start(p, pr.gamma), {{2.0, D == 1 ? 2.0 : width, D == 1 ? 2.0 : width}, pr.gamma}};
}

// The shock tube exactly as sod/sod2d/sod3d lay it out (tube::layout): the active particles and,
// beyond them, the boundary layers sphv holds at the initial state (a code without such layers
// may drop them; only 0 <= x <= 1 is scored). SWIFT's layout: periodic_tube.
template <int D>
InitialState tube_ic(const Params& p, IcLayout layout) {
  if (layout == IcLayout::swift) return periodic_tube<D>(p);
  const TubeProblem pr = tube_problem(p);
  TubeRun run;
  return {at_start(tube::layout<D>(pr, p.real("hfact"), p.integer("n"), run).p, pr.gamma), {{}, pr.gamma}};
}

}  // namespace
}  // namespace sphv::sod_snapshots_case

namespace sphv::tube {

Scorer scorer() { return {"t_end", sod_snapshots_case::score_tube, sod_snapshots_case::tube_t_end, Resolution::none, sod_snapshots_case::tube_gamma}; }

InitialConditions initial_conditions(int dim) {
  switch (dim) {
    case 1: return sod_snapshots_case::tube_ic<1>;
    case 2: return sod_snapshots_case::tube_ic<2>;
    default: return sod_snapshots_case::tube_ic<3>;
  }
}

}  // namespace sphv::tube
