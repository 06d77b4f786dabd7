#pragma once
#include "sph/hydro/euler.hpp"

namespace sph {

// Energy equation (36) for the specific internal energy u (the chapter's epsilon).
// v_ij = v_i - v_j; every form writes only du_i/dt.
enum class EnergyForm { direct37, difference38, swapped40 };

template <int D, EnergyForm F>
struct EnergyAsymmetric {
  static constexpr Writes writes{.dudt = true};
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    const double w = p.m[q.j] / (p.rho[q.i] * p.rho[q.j]);
    if constexpr (F == EnergyForm::direct37)
      s.dudt -= w * p.p[q.i] * q.vj.dot(q.gradW);  // (37)
    else if constexpr (F == EnergyForm::difference38)
      s.dudt += w * p.p[q.i] * (q.vi - q.vj).dot(q.gradW);  // (38)
    else
      s.dudt += w * p.p[q.j] * (q.vi - q.vj).dot(q.gradW);  // (40)
  }
};

// Symmetric forms: du_i/dt = 1/2 sum_j m_j P_ij v_ij . grad_i W_ij with the P_ij of the Euler
// form: (41) with Lambda1, (42) with Lambda2, and the same pairing for any lambda of (25). With
// the matching EulerSymmetric, dE_tot/dt = 0 exactly (9.5.3, (96)-(104)).
template <int D, class Lambda>
struct EnergySymmetric {
  static constexpr Writes writes{.dudt = true};
  Lambda lambda{};
  void prepare(Particles<D>& p, const Neighbourhood<D>&) { prepare_lambda(lambda, p); }
  void pair(const Particles<D>& p, PairSums<D>& s, const Pair<D>& q) const {
    s.dudt += 0.5 * p.m[q.j] * lambda.factor(p, q.i, q.j) * (q.vi - q.vj).dot(q.gradW);
  }
};

}  // namespace sph
