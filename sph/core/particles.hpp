#pragma once
#include <cstddef>
#include <vector>

#include "sph/core/vec.hpp"

namespace sph {

// Particle state, one array per quantity (structure of arrays). Names follow the chapter:
// m mass, rho density, p pressure, c sound speed, u specific internal energy (epsilon),
// h support radius.
template <int D>
struct Particles {
  std::vector<Vec<D>> x, v;
  std::vector<double> m, rho, p, c, u, h;

  std::size_t size() const { return x.size(); }

  void resize(std::size_t n) {
    x.assign(n, Vec<D>::Zero());
    v.assign(n, Vec<D>::Zero());
    m.assign(n, 0.0);
    rho.assign(n, 0.0);
    p.assign(n, 0.0);
    c.assign(n, 0.0);
    u.assign(n, 0.0);
    h.assign(n, 0.0);
  }
};

}  // namespace sph
