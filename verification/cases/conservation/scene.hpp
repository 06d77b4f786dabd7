#pragma once
// Shared set-up of the conservation cases (conservation*.cpp): two colliding gas blobs with free
// surfaces, the invariants of 9.5 and a fixed-step run of any scene type.
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <Eigen/Dense>

#include "sph/core/verdict.hpp"
#include "sph/density/summation.hpp"
#include "sph/density/variable_h.hpp"
#include "sph/hydro/evolve.hpp"
#include "sph/search/grid_search.hpp"

namespace sphv::conservation {

// Two blobs of radius 1/2 on jittered lattices (n points per diameter), centres offset across
// the line of approach so that they collide off-axis; each spins at its own rate about its own
// axis, the second blob is twice as dense, masses vary by +-30 % per particle, velocities carry
// a random part and u varies by +-30 %. No symmetry is left that could cancel an error. The
// support radius follows (50) from the summation density (27): h_i = hfact (m_i / rho_i)^(1/D).
template <int D>
sph::Particles<D> colliding_blobs(long n, double hfact, std::uint64_t seed = 11) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const double R = 0.5, dx = 2.0 * R / n;
  sph::Particles<D> p;
  for (int b = 0; b < 2; ++b) {
    const double s = b == 0 ? -1.0 : 1.0, rho0 = b == 0 ? 1.0 : 2.0;
    sph::Vec<D> centre = sph::Vec<D>::Zero(), bulk = sph::Vec<D>::Zero();
    centre[0] = 0.6 * s, centre[1] = -0.17 * s, bulk[0] = -0.5 * s, bulk[1] = 0.08 * s;
    if constexpr (D == 3) centre[2] = 0.11 * s, bulk[2] = -0.05 * s;
    Eigen::Vector3d omega = b == 0 ? Eigen::Vector3d(0.3, -0.4, 1.5) : Eigen::Vector3d(-0.5, 0.2, -2.0);
    if constexpr (D == 2) omega.head<2>().setZero();
    const long k = n / 2 + 1;
    long idx[3] = {-k, -k, -k};
    for (;;) {
      sph::Vec<D> off;
      for (int d = 0; d < D; ++d) off[d] = (idx[d] + 0.5 + 0.2 * U(rng)) * dx;
      if (off.norm() < R) {
        Eigen::Vector3d r3 = Eigen::Vector3d::Zero();
        r3.head<D>() = off;
        const Eigen::Vector3d spin = omega.cross(r3);
        sph::Vec<D> v = bulk + spin.head<D>();
        for (int d = 0; d < D; ++d) v[d] += 0.15 * U(rng);
        p.x.push_back(centre + off);
        p.v.push_back(v);
        p.m.push_back(rho0 * std::pow(dx, D) * (1.0 + 0.3 * U(rng)));
        p.u.push_back(1.0 + 0.3 * U(rng));
        p.h.push_back(hfact * dx);
      }
      int d = 0;
      while (d < D && ++idx[d] > k) idx[d++] = -k;
      if (d == D) break;
    }
  }
  const std::size_t N = p.x.size();
  p.rho.assign(N, 0.0), p.p.assign(N, 0.0), p.c.assign(N, 0.0);
  const sph::Box<D> open = sph::unit_box<D>(false);
  for (int pass = 0; pass < 2; ++pass) {  // (27) then (50), twice: h consistent with rho
    sph::density_summation(p, sph::grid_search<D>(p.x, p.h, open), open);
    sph::smoothing_length_from_density(p, hfact);
  }
  sph::density_summation(p, sph::grid_search<D>(p.x, p.h, open), open);
  return p;
}

// Linear momentum P = sum m_i v_i, angular momentum L = sum m_i r_i x v_i (about the origin, as
// a 3-vector; in 2D only its z component is non-zero), and the scales the drifts are measured
// against. With zero net momentum |P| itself is no scale; we use
//   momentum drift  |P(t) - P(0)| / sum_i m_i |v_i(0)|,
//   angular drift   |L(t) - L(0)| / sum_i m_i |r_i(0) x v_i(0)|,
// i.e. the change relative to the largest |P| or |L| the particles could carry. The energy
// drift is |E(t) - E(0)| / E(0) with E > 0 (kinetic plus internal).
struct Invariants {
  Eigen::Vector3d P = Eigen::Vector3d::Zero(), L = Eigen::Vector3d::Zero();
  double P_scale = 0.0, L_scale = 0.0;
};
template <int D>
Invariants invariants(const sph::Particles<D>& p) {
  Invariants s;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Eigen::Vector3d r = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
    r.head<D>() = p.x[i], v.head<D>() = p.v[i];
    const Eigen::Vector3d l = p.m[i] * r.cross(v);
    s.P += p.m[i] * v, s.L += l;
    s.P_scale += p.m[i] * v.norm(), s.L_scale += l.norm();
  }
  return s;
}

// What a run saw: the drift of P, L and E after every step (relative, as above), the largest
// semi-discrete energy-rate residual |dE/dt| / sum_i m_i (|v_i . a_i| + |du_i/dt|) of (96) over
// all derivative evaluations, and the verdict.
struct Drifts {
  std::vector<double> t, momentum, angular, energy;
  double energy_rate = 0.0;
  std::string verdict = "ok";
  double max_of(const std::vector<double>& v) const {
    double m = 0.0;
    for (double x : v) m = std::max(m, x);
    return m;
  }
};

// Total energy of a state; the default is kinetic plus internal, sum m_i (v_i^2/2 + u_i).
template <int D>
using EnergyOf = std::function<double(const sph::Particles<D>&)>;
template <int D>
double kinetic_plus_internal(const sph::Particles<D>& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e += p.m[i] * (0.5 * p.v[i].squaredNorm() + p.u[i]);
  return e;
}

// Advances a scene, given by its rates, by `steps` fixed steps of dt (a fixed step, so that the
// energy error can be measured against dt) with free boundaries, recording the drifts. Ends with a
// verdict, never throws on a blow-up. Compiled once per dimension, not once per scene type.
template <int D>
Drifts run_fixed_steps_of(const sph::SceneRates<D>& rates, sph::Particles<D>& p, sph::IntegratorKind integrator,
                          double dt, long steps, const EnergyOf<D>& energy) {
  const sph::Box<D> open = sph::unit_box<D>(false);
  Drifts out;
  auto derivs = [&](sph::Particles<D>& q, sph::Derivatives<D>& d) {
    rates(q, sph::Neighbourhood<D>{sph::grid_search<D>(q.x, q.h, open), open}, d);
    const auto t = sph::totals(q, d, 0, q.size());
    if (t.rate_scale > 0.0) out.energy_rate = std::max(out.energy_rate, std::abs(t.energy_rate) / t.rate_scale);
  };
  const Invariants first = invariants(p);
  double E0 = 0.0;
  auto record = [&](long step) {
    const Invariants now = invariants(p);
    out.t.push_back(step * dt);
    out.momentum.push_back((now.P - first.P).norm() / first.P_scale);
    out.angular.push_back((now.L - first.L).norm() / first.L_scale);
    out.energy.push_back(std::abs(energy(p) - E0) / E0);
  };
  sph::Derivatives<D> d, at_t;
  try {
    derivs(p, d);  // sets p, c (and rho for summation) of the initial state
    E0 = energy(p);
    record(0);
    for (long s = 1; s <= steps; ++s) {
      if (integrator == sph::IntegratorKind::kdk) sph::kdk_leapfrog_step(p, d, at_t, dt, derivs);
      else sph::chapter_leapfrog_step(p, d, dt, derivs);
      if (auto b = sph::first_bad(p)) {
        out.verdict = sph::unstable_verdict(s, s * dt, *b);
        return out;
      }
      record(s);
    }
  } catch (const std::invalid_argument& e) {  // grid search refused a support radius
    out.verdict = std::string("unstable: ") + e.what();
  }
  return out;
}

template <int D, class... Terms>
Drifts run_fixed_steps(sph::Scene<D, Terms...> scene, sph::Particles<D>& p, sph::IntegratorKind integrator,
                       double dt, long steps,
                       const std::type_identity_t<EnergyOf<D>>& energy = kinetic_plus_internal<D>) {
  auto rates = [&](sph::Particles<D>& q, const sph::Neighbourhood<D>& nb, sph::Derivatives<D>& d) {
    scene.derivatives(q, nb, d);
  };
  return run_fixed_steps_of<D>(rates, p, integrator, dt, steps, energy);
}

}  // namespace sphv::conservation
