#pragma once
// The templated shock-tube simulation; included only by sod_tube_{1d,2d,3d}.cpp.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "sph/density/terms.hpp"
#include "sph/density/variable_h.hpp"
#include "sph/hydro/eos.hpp"
#include "sph/hydro/forms.hpp"
#include "sph/schemes/schemes.hpp"
#include "verification/cases/shock_tubes/tube.hpp"

namespace sphv {
namespace tube {

// Equal-mass particles, the density jump made by the spacing (9.3.1). Left spacing 1/n; in 2D/3D
// the tube is periodic across with a width of several support radii, the right side keeps the
// same width with its own (near-isotropic) lattice. The particles [0, active) reach beyond [0, 1]
// far enough that no wave reaches their ends before t_end; beyond them, boundary layers of
// 2.5 support radii continue the lattice and are held at the initial state, moving with the
// initial velocity (9.4.1: no free surface, no boundary density deficit).
template <int D>
struct Layout {
  sph::Particles<D> p, initial;
  sph::Box<D> box;
  std::size_t active = 0;
};

template <int D>
Layout<D> layout(const TubeProblem& pr, double hfact, long n, TubeRun& run) {
  const reference::RiemannSolution exact(pr.left, pr.right, pr.gamma, pr.x0);
  const double dxl = 1.0 / n, mass = pr.left.rho * std::pow(dxl, D);
  const double s = std::pow(pr.left.rho / pr.right.rho, 1.0 / D);  // isotropic spacing ratio R/L
  const int ntl = D == 1 ? 1 : static_cast<int>(std::ceil(2.5 * hfact * std::max(1.0, s)));
  const double width = ntl * dxl;
  const int ntr = D == 1 ? 1 : std::max(1, static_cast<int>(std::lround(ntl / s)));
  const double dyr = width / ntr, dxr = mass / (pr.right.rho * std::pow(dyr, D - 1));
  const double hl = hfact * dxl, hr = hfact * std::pow(mass / pr.right.rho, 1.0 / D);
  const double margin = 4.0 * std::max(hl, hr);
  const double a = std::min(0.0, pr.x0 + exact.slowest() * pr.t_end) - std::max(0.0, pr.left.u) * pr.t_end - margin;
  const double b = std::max(1.0, pr.x0 + exact.fastest() * pr.t_end) + std::max(0.0, -pr.right.u) * pr.t_end + margin;
  const long nl = static_cast<long>(std::ceil((pr.x0 - a) / dxl)), nr = static_cast<long>(std::ceil((b - pr.x0) / dxr));
  const long gl = static_cast<long>(std::ceil(2.5 * hl / dxl)), gr = static_cast<long>(std::ceil(2.5 * hr / dxr));
  long per_l = 1, per_r = 1;
  for (int d = 1; d < D; ++d) per_l *= ntl, per_r *= ntr;

  Layout<D> L;
  sph::Particles<D>& p = L.p;
  p.resize((nl + gl) * per_l + (nr + gr) * per_r);
  std::size_t k = 0;
  // Slabs [from, to) on one side of x0 (side = -1 left, +1 right).
  auto place = [&](long from, long to, double side, double dx, int nt, long per, const reference::GasState& st) {
    for (long i = from; i < to; ++i)
      for (long t = 0; t < per; ++t, ++k) {
        p.x[k][0] = pr.x0 + side * (i + 0.5) * dx;
        long rest = t;
        for (int d = 1; d < D; ++d) p.x[k][d] = (static_cast<double>(rest % nt) + 0.5) * (width / nt), rest /= nt;
        p.v[k][0] = st.u;
        p.m[k] = mass;
        p.rho[k] = st.rho;
        p.u[k] = st.p / ((pr.gamma - 1.0) * st.rho);
      }
  };
  place(0, nl, -1.0, dxl, ntl, per_l, pr.left);
  place(0, nr, +1.0, dxr, ntr, per_r, pr.right);
  L.active = k;
  place(nl, nl + gl, -1.0, dxl, ntl, per_l, pr.left);
  place(nr, nr + gr, +1.0, dxr, ntr, per_r, pr.right);
  sph::smoothing_length_from_density(p, hfact);  // (50)
  L.box.lo = sph::Vec<D>::Zero();
  L.box.hi = sph::Vec<D>::Constant(width);
  L.box.lo[0] = pr.x0 - (nl + gl) * dxl;
  L.box.hi[0] = pr.x0 + (nr + gr) * dxr;
  L.box.periodic.fill(true);
  L.box.periodic[0] = false;
  L.initial = p;
  run.box_lo = pr.x0 - nl * dxl;
  run.box_hi = pr.x0 + nr * dxr;
  run.width = D == 1 ? 0.0 : width;
  return L;
}

// Runs the particles to t_end by evolve(p, box, hooks) (a scene's or a scheme's evolve, returning
// its sph::HydroOutcome) with the boundary layers held, recording the conservation diagnostics of
// the active particles.
template <int D, class Evolve>
void advance(Evolve&& evolve, Layout<D>& L, TubeRun& run) {
  sph::Particles<D>& p = L.p;
  const std::size_t na = L.active;
  sph::Derivatives<D> at_rest;
  at_rest.reset(p.size());
  const sph::Totals<D> first = sph::totals(p, at_rest, 0, na);
  double pscale = first.momentum_scale;
  sph::HydroHooks<D> hooks;
  hooks.constrain = [&](sph::Particles<D>& q, double t) {  // after every step, at its end time t
    if (run.first_dt == 0.0) run.first_dt = t;
    for (std::size_t i = na; i < q.size(); ++i) {
      q.x[i] = L.initial.x[i] + t * L.initial.v[i];
      q.v[i] = L.initial.v[i];
      q.rho[i] = L.initial.rho[i];
      q.u[i] = L.initial.u[i];
      q.h[i] = L.initial.h[i];
    }
  };
  hooks.evaluated = [&](const sph::Particles<D>& q, const sph::Derivatives<D>& d) {
    const auto t = sph::totals(q, d, 0, na);
    if (t.rate_scale > 0.0) run.energy_rate = std::max(run.energy_rate, std::abs(t.energy_rate) / t.rate_scale);
  };
  hooks.stepped = [&](const sph::Particles<D>& q, const sph::Derivatives<D>& d, long, double) {
    const auto t = sph::totals(q, d, 0, na);
    pscale = std::max(pscale, t.momentum_scale);
    run.momentum_drift = std::max(run.momentum_drift, (t.momentum - first.momentum).norm() / pscale);
    run.mass_drift = std::max(run.mass_drift, std::abs(t.mass - first.mass) / first.mass);
    run.energy_drift = std::abs(t.energy - first.energy) / first.energy;
  };
  run.outcome = evolve(p, L.box, hooks);
}

// evolve for advance: the scene's, with the controls c.
template <int D, class Scene>
auto scene_evolve(Scene scene, const sph::HydroControls& c) {
  return [scene, &c](sph::Particles<D>& p, const sph::Box<D>& box, const sph::HydroHooks<D>& hooks) mutable {
    return sph::evolve(scene, p, box, c, hooks);
  };
}

template <int D, class F>
void with_density(const TubeMethod& m, F&& f) {
  using enum sph::ContinuityForm;
  if (m.density == "summation") f(sph::SummationDensity<D>{});
  else if (m.density == "continuity29") f(sph::ContinuityDensity<D, direct29>{});
  else if (m.density == "continuity33") f(sph::ContinuityDensity<D, difference33>{});
  else throw std::invalid_argument("unknown density method " + m.density);
}

}  // namespace tube

// The tube with kernel K: the cubic spline (6) with every runtime choice of forms; another
// kernel with the default forms only (summation (27), Euler (23) with energy (41)), one scene each
// (each scene costs compile time, and the forms are compared with the cubic spline).
template <int D, class K>
TubeRun simulate_tube_with(const TubeProblem& pr, const TubeMethod& m, long n) {
  TubeRun run;
  sph::HydroControls controls = m.controls;
  controls.t_end = pr.t_end;
  tube::Layout<D> L = tube::layout<D>(pr, m.hfact, n, run);
  const sph::ArtificialViscosity<D> visc{m.alpha, m.beta, m.eps, m.h_scale};
  const sph::EquationOfState<D, sph::IdealGas> eos{{pr.gamma}};
  // The runtime choice of forms is resolved here, once, into a scene type; "auto" pairs the
  // Euler form with its energy form. Every pairing in 1D (72 scenes); in 2D and 3D the chapter's
  // pairings only (12 scenes each: the mixed ones are studied in 1D, and each scene costs compile time).
  const std::string energy_form = m.energy == "auto" ? sph::partner_energy(m.euler) : m.energy;
  if constexpr (!std::is_same_v<K, sph::CubicSpline<D>>) {
    if (m.density != "summation" || m.euler != "23" || energy_form != "41")
      throw std::invalid_argument(std::string("kernel ") + K::name +
                                  ": the tube runs it with density=summation, euler=23, energy=auto only");
    using S = sph::Scene<D, sph::SummationDensity<D, K>, sph::EquationOfState<D, sph::IdealGas>,
                         sph::EulerSymmetric<D, sph::Lambda1>, sph::EnergySymmetric<D, sph::Lambda1>,
                         sph::ArtificialViscosity<D>, sph::SmoothingLengthRate<D>>;
    tube::advance<D>(tube::scene_evolve<D>(S{{{}, eos, {}, {}, visc, {}}}, controls), L, run);
  } else if (m.scheme != "forms") {
    // A scheme of the registry with its default forms (one type a scheme), h by (50): the
    // options' gamma, hfact, alpha and beta.
    sph::SchemeOptions o;
    o.gamma = pr.gamma, o.hfact = m.hfact, o.alpha = m.alpha, o.beta = m.beta;
    sph::with_default_scheme<D, K>(m.scheme, o, [&](auto& scheme) {
      tube::advance<D>([&](sph::Particles<D>& p, const sph::Box<D>& box, const sph::HydroHooks<D>& hooks) {
        return sph::evolve(scheme, p, box, controls, hooks);
      }, L, run);
    });
  } else {
    // The continuity equation starts from the summation density (27) of the initial particles,
    // not from the sharp jump: a sharp jump puts the first low-density particle in a runaway.
    if (m.density != "summation")
      sph::density_summation(L.p, sph::grid_search<D>(L.p.x, L.p.h, L.box), L.box);
    if (D > 1 && energy_form != sph::partner_energy(m.euler))
      throw std::invalid_argument("energy form " + energy_form + " with Euler form " + m.euler +
                                  ": mixed pairings are 1D only (energy=auto in 2D and 3D)");
    tube::with_density<D>(m, [&](auto density) {
      auto simulate = [&](auto euler, auto energy) {
        using S = sph::Scene<D, decltype(density), sph::EquationOfState<D, sph::IdealGas>, decltype(euler),
                             decltype(energy), sph::ArtificialViscosity<D>, sph::SmoothingLengthRate<D>>;
        tube::advance<D>(tube::scene_evolve<D>(S{{density, eos, euler, energy, visc, {}}}, controls), L, run);
      };
      if constexpr (D == 1)
        sph::with_hydro_forms<D>(m.euler, energy_form, m.lambda, simulate);
      else
        sph::with_euler_form<D>(m.euler, m.lambda, [&](auto euler) { simulate(euler, sph::partner_energy_term(euler)); });
    });
  }
  const sph::Particles<D>& p = L.p;
  run.active = L.active;
  for (std::size_t i = 0; i < p.size(); ++i) {
    run.x.push_back(p.x[i][0]);
    run.v.push_back(p.v[i][0]);
    run.rho.push_back(p.rho[i]);
    run.u.push_back(p.u[i]);
    run.p.push_back((pr.gamma - 1.0) * p.rho[i] * p.u[i]);
    run.m.push_back(p.m[i]);
    run.h.push_back(p.h[i]);
  }
  for (int d = 0; d < D; ++d) {
    run.position.emplace_back();
    for (std::size_t i = 0; i < p.size(); ++i) run.position.back().push_back(p.x[i][d]);
  }
  return run;
}

template <int D>
TubeRun simulate_tube(const TubeProblem& pr, const TubeMethod& m, long n) {
  if (m.kernel == sph::CubicSpline<D>::name) return simulate_tube_with<D, sph::CubicSpline<D>>(pr, m, n);
  if constexpr (D == 1) return simulate_tube_other_kernel(pr, m, n);
  else throw std::invalid_argument("kernel " + m.kernel + ": the " + std::to_string(D) + "D tube runs cubic_spline only");
}

}  // namespace sphv
