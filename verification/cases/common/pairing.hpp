#pragma once
// The pairing instability's mark (Dehnen & Aly 2012): the fraction of particles that have another
// within a distance d, for d well below the mean spacing (none on a lattice or a glass).
#include <cstddef>
#include <vector>

#include "sph/core/box.hpp"
#include "sph/core/particles.hpp"
#include "sph/search/grid_search.hpp"

namespace sphv::extreme {

template <int D>
double paired_fraction(const sph::Particles<D>& p, const sph::Box<D>& box, double d) {
  if (p.size() == 0) return 0.0;
  const sph::NeighbourList nl = sph::grid_search<D>(p.x, std::vector<double>(p.size(), d), box);
  std::size_t paired = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (const int j : nl.of(i))
      if (static_cast<std::size_t>(j) != i) {
        ++paired;
        break;
      }
  return static_cast<double>(paired) / static_cast<double>(p.size());
}

}  // namespace sphv::extreme
