#pragma once
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "sph/gravity/plummer.hpp"
#include "sph/search/tree.hpp"

namespace sph {

// Self-gravity with the Barnes-Hut tree (9.4.7), 3D, Plummer softening eps (the same as
// add_plummer and the direct sum), units of G given.
enum class Multipole { monopole, quadrupole };
// plain: accept a node when d / r < theta (89), r = |r_i - r_CM|. Unbounded errors above
// theta = 1/sqrt(3) when r_CM sits near the edge of the cell (Salmon & Warren 1994).
// robust: accept when r > d / theta + delta, delta = |r_CM - centre of the cell| (Barnes 1994),
// and never accept the cell that contains r_i: every accepted cell lies outside the sphere of
// radius d / theta about its centre.
enum class Opening { plain, robust };

struct GravityOptions {
  double theta = 0.5;
  double eps = 0.0;
  double G = 1.0;
  Multipole multipole = Multipole::quadrupole;
  Opening opening = Opening::robust;
};

// Accelerations, potentials and the work done per target (particle-particle plus
// particle-node interactions).
struct GravityField {
  std::vector<Vec<3>> a;
  std::vector<double> phi;
  std::vector<long> interactions;
};

namespace detail {

// Potential and acceleration of a node at y = r - r_CM, expanded about its centre of mass
// ((81) with the dipole (86) zero) as a Taylor series of the softened Green's function
// g = (|y|^2 + eps^2)^(-1/2): phi = -G [M g + 1/2 S_ab d_a d_b g]. With eps = 0 the second term
// is (81)'s -G Q_ab y_a y_b / (2 r^5), Q = 3 S - tr(S) I (84). a = -grad phi, so the quadrupole
// enters the force.
template <Multipole M>
inline void add_node(const Tree<3>::Node& nd, const Vec<3>& y, double G, double eps2, Vec<3>& a,
                     double& phi) {
  const double s2 = y.squaredNorm() + eps2, inv = 1.0 / std::sqrt(s2), inv2 = inv * inv;
  const double inv3 = inv * inv2;
  phi -= G * nd.mass * inv;
  a -= (G * nd.mass * inv3) * y;
  if constexpr (M == Multipole::quadrupole) {
    const Vec<3> Sy = nd.S * y;
    const double ySy = y.dot(Sy), tr = nd.S.trace(), inv5 = inv3 * inv2;
    phi -= 0.5 * G * (3.0 * ySy * inv5 - tr * inv3);
    a += G * inv5 * (3.0 * Sy + (1.5 * tr - 7.5 * ySy * inv2) * y);
  }
}

// Squared distance from the centre of mass beyond which a node is accepted:
// plain (d / theta)^2, robust (d / theta + delta)^2.
template <Opening O>
std::vector<double> critical_radius2(const Tree<3>& t, double theta) {
  std::vector<double> rc2(t.nodes.size());
  for (std::size_t k = 0; k < rc2.size(); ++k) {
    const auto& nd = t.nodes[k];
    double rc = nd.size / theta;
    if constexpr (O == Opening::robust) rc += (nd.com - nd.centre).norm();
    rc2[k] = rc * rc;
  }
  return rc2;
}

template <Opening O>
inline bool accept(const Tree<3>::Node& nd, double rc2, const Vec<3>& r) {
  if ((r - nd.com).squaredNorm() <= rc2) return false;
  if constexpr (O == Opening::robust) return !((r - nd.centre).cwiseAbs().array() <= 0.5 * nd.size).all();
  return true;
}

// Field at point r from all particles except `self` (-1 for a point that is no particle).
// xs, ms: positions and masses in tree order (leaf particles contiguous in memory).
template <Multipole M, Opening O>
void walk(const Tree<3>& t, const std::vector<Vec<3>>& xs, const std::vector<double>& ms,
          const GravityOptions& o, const std::vector<double>& rc2, const Vec<3>& r, long self,
          std::vector<int>& stack, Vec<3>& a,
          double& phi, long& count) {
  const double eps2 = o.eps * o.eps;
  a.setZero();
  phi = 0.0;
  count = 0;
  if (t.nodes.empty()) return;
  stack.assign(1, 0);
  while (!stack.empty()) {
    const int k = stack.back();
    const auto& nd = t.nodes[k];
    stack.pop_back();
    if (nd.leaf()) {
      for (int q = nd.begin; q < nd.end; ++q) {
        if (t.order[q] == self) continue;
        add_plummer<3>(r - xs[q], o.G * ms[q], eps2, a, phi);
        ++count;
      }
    } else if (accept<O>(nd, rc2[k], r)) {
      add_node<M>(nd, r - nd.com, o.G, eps2, a, phi);
      ++count;
    } else {
      for (int c = 0; c < nd.n_children; ++c) stack.push_back(nd.first_child + c);
    }
  }
}

template <Multipole M, Opening O>
GravityField field(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                   const GravityOptions& o, const std::vector<Vec<3>>& targets, bool at_particles) {
  const std::size_t n = targets.size();
  GravityField f{std::vector<Vec<3>>(n), std::vector<double>(n), std::vector<long>(n)};
  const std::vector<double> rc2 = critical_radius2<O>(t, o.theta);
  std::vector<Vec<3>> xs(t.order.size());
  std::vector<double> ms(t.order.size());
  for (std::size_t q = 0; q < xs.size(); ++q) xs[q] = x[t.order[q]], ms[q] = m[t.order[q]];
#pragma omp parallel
  {
    std::vector<int> stack;
#pragma omp for schedule(dynamic, 64)
    for (std::size_t k = 0; k < n; ++k) {
      // Particles are visited in tree order: consecutive walks touch the same nodes (cache).
      const std::size_t i = at_particles ? static_cast<std::size_t>(t.order[k]) : k;
      walk<M, O>(t, xs, ms, o, rc2, targets[i], at_particles ? static_cast<long>(i) : -1L, stack, f.a[i], f.phi[i],
                 f.interactions[i]);
    }
  }
  return f;
}

}  // namespace detail

// Gravity at `targets`; at_particles: the targets are the particles x themselves (each skips
// its own mass). The method choice is dispatched once, outside the walks
// (sph/gravity/tree_gravity.cpp: the four walks are compiled there once).
GravityField tree_gravity_at(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                             const GravityOptions& o, const std::vector<Vec<3>>& targets, bool at_particles = false);

// Gravity at every particle from all the others.
inline GravityField tree_gravity(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                                 const GravityOptions& o) {
  return tree_gravity_at(t, x, m, o, x, true);
}

}  // namespace sph
