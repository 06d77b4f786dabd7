#pragma once
#include <cmath>

#include "sph/core/vec.hpp"

namespace sph {

// Plummer-softened point-mass gravity, the softening of (77) used for every gravitational
// interaction (external point mass, tree leaves, direct sum): potential
// phi = -G m / sqrt(r^2 + eps^2) and its exact gradient, a = -G m r / (r^2 + eps^2)^(3/2)
// ((76) with the softened distance). r = r_i - r_source. eps = 0 gives Newton's law.
template <int D>
inline void add_plummer(const Vec<D>& r, double Gm, double eps2, Vec<D>& a, double& phi) {
  const double inv = 1.0 / std::sqrt(r.squaredNorm() + eps2);
  phi -= Gm * inv;
  a -= (Gm * inv * inv * inv) * r;
}

}  // namespace sph
