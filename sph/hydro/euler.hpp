#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "sph/hydro/scene.hpp"

namespace sph {

// Symmetric pressure factor of (25): P_ij = p_j / (rho_i^(2-l) rho_j^l) + p_i / (rho_i^l rho_j^(2-l)),
// symmetric in i and j. lambda = 1 gives (23), lambda = 2 gives (26); both are specialised so
// that they cost no pow(). factor(p, i, j): the P_ij of particles i and j.
struct Lambda1 {  // (23): (p_i + p_j) / (rho_i rho_j)
  template <int D>
  double factor(const Particles<D>& p, std::size_t i, std::size_t j) const {
    return (p.p[i] + p.p[j]) / (p.rho[i] * p.rho[j]);
  }
};
struct Lambda2 {  // (26): p_i / rho_i^2 + p_j / rho_j^2
  template <int D>
  double factor(const Particles<D>& p, std::size_t i, std::size_t j) const {
    return p.p[i] / (p.rho[i] * p.rho[i]) + p.p[j] / (p.rho[j] * p.rho[j]);
  }
};
// (25) with any lambda. The pair loop reads rho^lambda and rho^(2 - lambda) of each end from
// arrays that prepare() fills once an evaluation: two pow() a particle instead of four a pair.
struct LambdaGeneral {
  double lambda = 1.5;
  std::vector<double> rho_l, rho_2l;  // rho_i^lambda, rho_i^(2 - lambda) at the last prepare()
  template <int D>
  void prepare(const Particles<D>& p) {
    const std::size_t n = p.size();
    rho_l.resize(n), rho_2l.resize(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) rho_l[i] = std::pow(p.rho[i], lambda), rho_2l[i] = std::pow(p.rho[i], 2.0 - lambda);
  }
  template <int D>
  double factor(const Particles<D>& p, std::size_t i, std::size_t j) const {
    return p.p[j] / (rho_2l[i] * rho_l[j]) + p.p[i] / (rho_l[i] * rho_2l[j]);
  }
};

// A symmetric form's per-particle work before the pair loop: LambdaGeneral's powers.
template <class Lambda, int D>
void prepare_lambda(Lambda& lambda, const Particles<D>& p) {
  if constexpr (requires { lambda.template prepare<D>(p); }) lambda.template prepare<D>(p);
}

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
  void prepare(Particles<D>& p, const Neighbourhood<D>&) { prepare_lambda(lambda, p); }
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    s.dvdt -= (p.m[q.j] * lambda.factor(p, q.i, q.j)) * q.gradW;
  }
};

}  // namespace sph
