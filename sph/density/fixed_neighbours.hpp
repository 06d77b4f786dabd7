#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sph/density/summation.hpp"
#include "sph/search/verlet_list.hpp"

namespace sph {

// Variable smoothing length of 9.4.4 by a fixed number of neighbours: (50) written per particle,
//   h_i = hfact (m_i / rho_i)^(1/D),
// iterated with the summation density (27) (which itself needs h) until h changes by less than
// tol. The evolution equation (53) is the scene term SmoothingLengthRate (density/variable_h.hpp).
//
// Floor: a particle without neighbours has the self-density (49) m_i W(0, h_i) ~ m_i / h_i^D, and
// (50) then asks for h_i -> hfact h_i / sigma^(1/D), which grows without end when hfact exceeds
// sigma^(1/D) (the fixed point is unstable). h is therefore capped at h_max, which makes the
// self-density at h_max, m_i W(0, h_max), the smallest representable density.
struct SmoothingLengthControl {
  double hfact = 2.4;
  double h_max = std::numeric_limits<double>::infinity();
  double tol = 1e-3;   // relative change of h that ends the iteration
  int max_iterations = 30;
  double skin = 0.1;   // the search pads every support radius by this fraction (reused while h fits)
};

struct SmoothingLengthOutcome {
  int iterations = 0;
  double change = 0.0;        // last max_i |dh_i| / h_i
  std::size_t at_cap = 0;     // particles held at h_max (self-density floor)
  bool converged = false;
};

// Sets h from (50) and rho from (27) consistently (to tol); rho is the summation density of the
// returned h. One neighbour search serves the whole iteration while the h fit its padding
// (search/verlet_list.hpp: the particles stand still), and `lists`, kept by a caller that iterates
// again, serves the next calls while the particles stay within it. Throws std::invalid_argument
// from the search if h exceeds half a periodic box. K: the kernel of (27). It sets h once (a run's
// start, initial conditions); a scheme's density phase solves (50) per particle at every
// evaluation (fixed_neighbours_newton.hpp).
template <int D, class K = CubicSpline<D>>
SmoothingLengthOutcome smoothing_length_iterate(Particles<D>& p, const Box<D>& box, const SmoothingLengthControl& c,
                                                VerletList<D>& lists) {
  SmoothingLengthOutcome out;
  Components<D> xs;  // kept over the iterations
  auto density = [&] { density_summation<D, K>(p, lists.update(p.x, p.h, box), box, xs); };
  for (out.iterations = 1; out.iterations <= c.max_iterations; ++out.iterations) {
    density();
    double change = 0.0;
    std::size_t at_cap = 0;
    const std::size_t n = p.size();
#pragma omp parallel for reduction(max : change) reduction(+ : at_cap) if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) {
      double h = c.hfact * std::pow(p.m[i] / p.rho[i], 1.0 / D);  // (50)
      if (!(h < c.h_max)) h = c.h_max, ++at_cap;
      change = std::max(change, std::abs(h - p.h[i]) / p.h[i]);
      p.h[i] = h;
    }
    out.change = change, out.at_cap = at_cap;
    if (out.change < c.tol) {
      out.converged = true;
      break;
    }
  }
  out.iterations = std::min(out.iterations, c.max_iterations);
  density();
  return out;
}

template <int D, class K = CubicSpline<D>>
SmoothingLengthOutcome smoothing_length_iterate(Particles<D>& p, const Box<D>& box, const SmoothingLengthControl& c) {
  VerletList<D> lists(c.skin);
  return smoothing_length_iterate<D, K>(p, box, c, lists);
}

}  // namespace sph
