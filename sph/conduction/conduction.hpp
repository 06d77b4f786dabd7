#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sph/hydro/scene.hpp"
#include "sph/kernel/laplacian.hpp"

namespace sph {

// Heat conduction (55) with constant conductivity K: rho c_v dT/dt = -div F = K lap T, with
// u = c_v T, so du/dt = (K / rho_i) lap T_i. The diffusivity is chi = K / (rho c_v); with
// rho c_v = 1 this is (60). Scene terms for sph/hydro/scene.hpp.

struct ConductionParams {
  double K;          // conductivity, >= 0
  double c_v = 1.0;  // specific heat, > 0
  void check() const {
    if (!(K >= 0.0) || !std::isfinite(K)) throw std::invalid_argument("conduction: K must be finite and >= 0");
    if (!(c_v > 0.0) || !std::isfinite(c_v)) throw std::invalid_argument("conduction: c_v must be > 0");
  }
};

// Brookshaw form (69): one pass, first kernel derivatives only.
template <int D>
struct BrookshawConduction {
  static constexpr Writes writes{.dudt = true};
  ConductionParams k;
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& pr) const {
    const double Ti = p.u[pr.i] / k.c_v, Tj = p.u[pr.j] / k.c_v;
    s.dudt += k.K / p.rho[pr.i] * brookshaw_pair<D>(p.m[pr.j] / p.rho[pr.j], Ti, Tj, pr.rij, pr.r, pr.gradW);
  }
};

// Two-pass flux form: prepare() computes grad T = -F / K by (56) or (57); the pair loop takes
// its divergence by (58) or (59). K: the kernel of both passes (the pair loop's is the scene's,
// Scene::Kernel, which this term names).
template <int D, class Form, class K = CubicSpline<D>>
struct TwoPassConduction {
  using kernel = K;
  static constexpr Writes writes{.dudt = true};
  ConductionParams k;
  std::vector<Vec<D>> gradT;
  void prepare(const Particles<D>& p, const Neighbourhood<D>& nb) {
    const std::size_t n = p.size();
    std::vector<double> T(n);
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) T[i] = p.u[i] / k.c_v;
    gradT = sph_gradient<D, Form, K>(p, T, nb);
  }
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& pr) const {
    s.dudt += k.K / p.rho[pr.i] * Form::outer(p.rho[pr.i]) * divergence_pair<D, Form>(p, gradT, pr.i, pr.j, pr.gradW);
  }
};

// Diffusion time-step criterion (errata, 9.4.6): dt = C min_i h_i^2 / chi_i, chi = K / (rho c_v).
template <int D>
double diffusion_timestep(const Particles<D>& p, const ConductionParams& k, double C) {
  double dt = std::numeric_limits<double>::infinity();
  const std::size_t n = p.size();
#pragma omp parallel for reduction(min : dt) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) dt = std::min(dt, C * p.h[i] * p.h[i] * p.rho[i] * k.c_v / k.K);
  return dt;
}

}  // namespace sph
