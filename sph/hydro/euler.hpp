#pragma once
#include <cmath>

#include "sph/hydro/scene.hpp"

namespace sph {

// Symmetric pressure factor of (25): P_ij = p_j / (rho_i^(2-l) rho_j^l) + p_i / (rho_i^l rho_j^(2-l)),
// symmetric in i and j. lambda = 1 gives (23), lambda = 2 gives (26); both are specialised so
// that they cost no pow().
struct Lambda1 {  // (23): (p_i + p_j) / (rho_i rho_j)
  double factor(double pi, double pj, double ri, double rj) const { return (pi + pj) / (ri * rj); }
};
struct Lambda2 {  // (26): p_i / rho_i^2 + p_j / rho_j^2
  double factor(double pi, double pj, double ri, double rj) const { return pi / (ri * ri) + pj / (rj * rj); }
};
struct LambdaGeneral {  // (25) with any lambda
  double lambda = 1.5;
  double factor(double pi, double pj, double ri, double rj) const {
    return pj / (std::pow(ri, 2.0 - lambda) * std::pow(rj, lambda)) +
           pi / (std::pow(ri, lambda) * std::pow(rj, 2.0 - lambda));
  }
};

// Euler equation, direct form (22): dv_i/dt = -1/rho_i sum_j m_j / rho_j p_j grad_i W_ij.
// Not antisymmetric in i, j: momentum is not conserved.
template <int D>
struct EulerDirect {
  static constexpr Writes writes{.dvdt = true};
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    s.dvdt -= (p.m[q.j] * p.p[q.j] / (p.rho[q.i] * p.rho[q.j])) * q.gradW;
  }
};

// Euler equation, symmetric forms (23), (25), (26): dv_i/dt = -sum_j m_j P_ij grad_i W_ij.
template <int D, class Lambda>
struct EulerSymmetric {
  static constexpr Writes writes{.dvdt = true};
  Lambda lambda{};
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    s.dvdt -= (p.m[q.j] * lambda.factor(p.p[q.i], p.p[q.j], p.rho[q.i], p.rho[q.j])) * q.gradW;
  }
};

}  // namespace sph
