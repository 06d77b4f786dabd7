#pragma once
#include <cstddef>

#include "sph/gravity/plummer.hpp"
#include "sph/hydro/scene.hpp"

namespace sph {

// External gravity of a point mass (75)-(77), e.g. a star: a scene term whose finish() hook
// adds a_i = -G M (r_i - r_star) / (|r_i - r_star|^2 + eps^2)^(3/2) to dv_i/dt.
template <int D>
struct PointMassGravity {
  double GM = 1.0;                    // G M_star
  Vec<D> position = Vec<D>::Zero();   // r_star
  double eps = 0.0;                   // softening length of (77)

  // Acceleration and potential at r.
  void field(const Vec<D>& r, Vec<D>& a, double& phi) const {
    a.setZero();
    phi = 0.0;
    add_plummer<D>(r - position, GM, eps * eps, a, phi);
  }
  double potential(const Vec<D>& r) const {
    Vec<D> a;
    double phi;
    field(r, a, phi);
    return phi;
  }
  void finish(const Particles<D>& p, const Neighbourhood<D>&, Derivatives<D>& d) const {
    const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) {
      Vec<D> a;
      double phi;
      field(p.x[i], a, phi);
      d.dvdt[i] += a;
    }
  }
};

}  // namespace sph
