#pragma once
#include "sph/core/vec.hpp"

namespace sph {

// (9) for a radial kernel K: grad_i W_ij = r_ij / |r_ij| dW/dr, with r_ij = r_i - r_j; zero at
// r = 0. Every kernel of sph/kernel/kernels.hpp inherits it (K names itself: K::dWdr).
template <class K, int D>
struct RadialGradient {
  static Vec<D> gradW(const Vec<D>& rij, double r, double h) {
    return r > 0.0 ? Vec<D>(rij * (K::dWdr(r, h) / r)) : Vec<D>::Zero();
  }
};

}  // namespace sph
