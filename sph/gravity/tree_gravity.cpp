// The tree walks of sph/gravity/tree_gravity.hpp, compiled once.
#include "sph/gravity/tree_gravity.hpp"

namespace sph {

GravityField tree_gravity_at(const Tree<3>& t, const std::vector<Vec<3>>& x, const std::vector<double>& m,
                             const GravityOptions& o, const std::vector<Vec<3>>& targets, bool at_particles) {
  if (!(o.theta > 0.0)) throw std::invalid_argument("tree gravity: opening angle theta must be > 0");
  if (!(o.eps >= 0.0)) throw std::invalid_argument("tree gravity: softening eps must be >= 0");
  using enum Multipole;
  using enum Opening;
  if (o.multipole == monopole)
    return o.opening == plain ? detail::field<monopole, plain>(t, x, m, o, targets, at_particles)
                              : detail::field<monopole, robust>(t, x, m, o, targets, at_particles);
  return o.opening == plain ? detail::field<quadrupole, plain>(t, x, m, o, targets, at_particles)
                            : detail::field<quadrupole, robust>(t, x, m, o, targets, at_particles);
}

}  // namespace sph
