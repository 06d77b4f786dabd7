#pragma once
#include <vector>

#include <Eigen/Core>

#include "sph/core/particles.hpp"
#include "sph/hydro/pairs.hpp"
#include "sph/hydro/scene.hpp"
#include "sph/kernel/cubic_spline.hpp"

namespace sph {

// Second derivatives of a particle field T (section 9.4.6). V_j = m_j / rho_j.

// Brookshaw Laplacian (69), one pair: 2 V_j (T_i - T_j) r_ij . grad_i W_ij / |r_ij|^2.
template <int D>
double brookshaw_pair(double Vj, double Ti, double Tj, const Vec<D>& rij, double r, const Vec<D>& gradW) {
  return 2.0 * Vj * (Ti - Tj) * rij.dot(gradW) / (r * r);
}

// Its 1D form (67), one pair: 2 V_j (T_i - T_j) / (x_i - x_j) dW_ij/dx_i.
inline double brookshaw_pair_1d(double Vj, double Ti, double Tj, double xij, double dWdx) {
  return 2.0 * Vj * (Ti - Tj) / xij * dWdx;
}

// The two SPH first derivatives of the two-pass form: a gradient of a scalar (flux, 56/57) and a
// divergence of a vector (58/59), each  D_i = outer(rho_i) sum_j weight(m_j, a_i, a_j) (.) grad_i W_ij.
// (56)/(58): rho_i sum_j m_j (a_i / rho_i^2 + a_j / rho_j^2)
struct SymmetricForm {
  static constexpr const char* name = "56/58";
  static double outer(double rho_i) { return rho_i; }
  template <class A>
  static A weight(double mj, const A& ai, const A& aj, double rhoi, double rhoj) {
    return mj * (ai / (rhoi * rhoi) + aj / (rhoj * rhoj));
  }
};
// (57)/(59): (1 / rho_i) sum_j m_j (a_j - a_i)
struct DifferenceForm {
  static constexpr const char* name = "57/59";
  static double outer(double rho_i) { return 1.0 / rho_i; }
  template <class A>
  static A weight(double mj, const A& ai, const A& aj, double, double) {
    return mj * (aj - ai);
  }
};

// K, here and below: the kernel (sph/kernel/kernels.hpp).
template <int D, class Form, class K = CubicSpline<D>>
std::vector<Vec<D>> sph_gradient(const Particles<D>& p, const std::vector<double>& T, const Neighbourhood<D>& nb) {
  std::vector<Vec<D>> g(p.size(), Vec<D>::Zero());
  for_each_pair<D, K>(p.x, p.h, nb.list, nb.box, [&](std::size_t i, int j, const Vec<D>& rij, double r, double h) {
    g[i] += Form::weight(p.m[j], T[i], T[j], p.rho[i], p.rho[j]) * K::gradW(rij, r, h);
  });
  const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) g[i] *= Form::outer(p.rho[i]);
  return g;
}

// One pair of the divergence pass, without the factor outer(rho_i).
template <int D, class Form>
double divergence_pair(const Particles<D>& p, const std::vector<Vec<D>>& G, std::size_t i, int j, const Vec<D>& gradW) {
  return Form::weight(p.m[j], G[i], G[j], p.rho[i], p.rho[j]).dot(gradW);
}

// Two-pass Laplacian: the divergence (58/59) of the gradient (56/57).
template <int D, class Form, class K = CubicSpline<D>>
std::vector<double> two_pass_laplacian(const Particles<D>& p, const std::vector<double>& T, const Neighbourhood<D>& nb) {
  const auto G = sph_gradient<D, Form, K>(p, T, nb);
  std::vector<double> lap(p.size(), 0.0);
  for_each_pair<D, K>(p.x, p.h, nb.list, nb.box, [&](std::size_t i, int j, const Vec<D>& rij, double r, double h) {
    lap[i] += divergence_pair<D, Form>(p, G, i, j, K::gradW(rij, r, h));
  });
  const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) lap[i] *= Form::outer(p.rho[i]);
  return lap;
}

template <int D, class K = CubicSpline<D>>
std::vector<double> brookshaw_laplacian(const Particles<D>& p, const std::vector<double>& T, const Neighbourhood<D>& nb) {
  std::vector<double> lap(p.size(), 0.0);
  for_each_pair<D, K>(p.x, p.h, nb.list, nb.box, [&](std::size_t i, int j, const Vec<D>& rij, double r, double h) {
    lap[i] += brookshaw_pair<D>(p.m[j] / p.rho[j], T[i], T[j], rij, r, K::gradW(rij, r, h));
  });
  return lap;
}

// (67), 1D only: identical to (69) with D = 1 up to round-off.
template <class K = CubicSpline<1>>
std::vector<double> brookshaw_laplacian_1d(const Particles<1>& p, const std::vector<double>& T,
                                           const Neighbourhood<1>& nb) {
  std::vector<double> lap(p.size(), 0.0);
  for_each_pair<1, K>(p.x, p.h, nb.list, nb.box, [&](std::size_t i, int j, const Vec<1>& rij, double r, double h) {
    lap[i] += brookshaw_pair_1d(p.m[j] / p.rho[j], T[i], T[j], rij[0], K::gradW(rij, r, h)[0]);
  });
  return lap;
}

// Second-derivative tensor (73) with the errata's factor:
// d2T/dx^a dx^b = sum_j V_j (T_i - T_j) [(d + 2) r^a r^b / r^2 - delta^ab] r_ij . grad_i W_ij / r^2.
// Its trace is (69).
template <int D, class K = CubicSpline<D>>
std::vector<Eigen::Matrix<double, D, D>> hessian(const Particles<D>& p, const std::vector<double>& T,
                                                 const Neighbourhood<D>& nb) {
  using M = Eigen::Matrix<double, D, D>;
  std::vector<M> H(p.size(), M::Zero());
  for_each_pair<D, K>(p.x, p.h, nb.list, nb.box, [&](std::size_t i, int j, const Vec<D>& rij, double r, double h) {
    const double r2 = r * r;
    const double s = p.m[j] / p.rho[j] * (T[i] - T[j]) * rij.dot(K::gradW(rij, r, h)) / r2;
    H[i] += s * ((D + 2.0) * rij * rij.transpose() / r2 - M::Identity());
  });
  return H;
}

}  // namespace sph
