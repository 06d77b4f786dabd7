#pragma once
#include <array>
#include <cmath>

#include "sph/core/vec.hpp"

namespace sph {

// The computational domain [lo, hi). A periodic dimension wraps pair separations to the
// nearest image; the wrap is branch-free so pair loops do not test the flags.
template <int D>
struct Box {
  Vec<D> lo = Vec<D>::Zero();
  Vec<D> hi = Vec<D>::Ones();
  std::array<bool, D> periodic{};

  Vec<D> length() const { return hi - lo; }

  // 1/L in periodic dimensions, 0 in open ones.
  Vec<D> wrap_factor() const {
    Vec<D> f;
    for (int d = 0; d < D; ++d) f[d] = periodic[d] ? 1.0 / (hi[d] - lo[d]) : 0.0;
    return f;
  }
};

// Nearest-image separation dx = r_i - r_j (unchanged in open dimensions, where wrap = 0).
// Rounds s = dx / L to the nearest integer by adding and subtracting 1.5 * 2^52 (exact for
// |s| < 2^51 in the default rounding mode): no branch on the sign of dx, which pair loops would
// mispredict half the time, and no library call (std::nearbyint is one without SSE4.1).
// One dimension of it (wrap = 1/L, or 0 where open); the vectorised pair filter
// (search/verlet_list.cpp) rounds with the same shift.
inline constexpr double min_image_shift = 6755399441055744.0;  // 1.5 * 2^52
inline double min_image(double dx, double L, double wrap) {
  const double s = dx * wrap + min_image_shift;  // IEEE: not folded without -ffast-math
  return dx - L * (s - min_image_shift);
}
template <int D>
inline Vec<D> min_image(Vec<D> dx, const Vec<D>& L, const Vec<D>& wrap) {
  for (int d = 0; d < D; ++d) dx[d] = min_image(dx[d], L[d], wrap[d]);
  return dx;
}

// Box where every dimension is periodic (or every one open).
template <int D>
Box<D> unit_box(bool periodic) {
  Box<D> b;
  b.periodic.fill(periodic);
  return b;
}

}  // namespace sph
