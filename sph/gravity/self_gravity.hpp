#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "sph/gravity/tree_gravity.hpp"
#include "sph/hydro/scene.hpp"
#include "sph/search/tree.hpp"

namespace sph {

// Self-gravity as a scene term (9.4.7, 3D): after the pair loop, the Barnes-Hut tree (9.4.3)
// is built over the current positions and the tree acceleration (75) with multipoles
// (81)-(88), the opening criterion of GravityOptions and Plummer softening (77) is added to
// dv/dt. The potential phi_i of the last evaluation stays available, so that the
// gravitational energy W = 1/2 sum_i m_i phi_i enters the total energy. A scene that does not
// list this term builds no tree.
struct SelfGravity {
  static constexpr bool keeps_particle_arrays = true;  // phi, read in the caller's order (hydro/storage_order.hpp)
  GravityOptions options;
  std::vector<double> phi;  // phi_i of the last evaluation (particles' current positions)

  void finish(const Particles<3>& p, const Neighbourhood<3>&, Derivatives<3>& d) {
    GravityField f = tree_gravity(build_tree<3>(p.x, p.m), p.x, p.m, options);
    const std::size_t n = p.size();
#pragma omp parallel for if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) d.dvdt[i] += f.a[i];
    phi = std::move(f.phi);
  }

  // W = 1/2 sum_i m_i phi_i (each pair counted once).
  double potential_energy(const Particles<3>& p) const {
    double w = 0.0;
    for (std::size_t i = 0; i < phi.size(); ++i) w += 0.5 * p.m[i] * phi[i];
    return w;
  }
};

}  // namespace sph
