#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "sph/grid_search.hpp"

namespace sph {

// Neighbour lists reused across steps (a Verlet list: 9.4.3's search with a skin). A search at
// positions x0 and support radii h0 lists the pairs within the padded radii (1 + skin) h0, and
// serves until a pair that now interacts might be missing from it. With d_k = |x_k - x0_k|
// (nearest image) and g_k = max(0, h_k - h0_k), a pair with |r_ij| < max(h_i, h_j) has
// |r0_ij| <= |r_ij| + d_i + d_j < max(h0_i, h0_j) + max(g_i, g_j) + d_i + d_j, so it is listed
// while either
//   (a) d_k + g_k <= skin h0_k / 2 for every k (particles that move, each by its own h), or
//   (b) 2 max_k d_k + g_k <= skin h0_k for every k (particles at rest while h changes, as in (50)).
// Pair loops skip listed pairs beyond h_ij (pairs.hpp), so every sum is over the same pairs as
// with a fresh search. The padding is dropped where it would exceed half a periodic box.
template <int D>
class VerletList {
 public:
  explicit VerletList(double skin = 0.1) : skin_(skin) {}

  // The list for the particles at x with support radii h: the last one, or a new search.
  // Throws std::invalid_argument from the search (h not positive and finite, or beyond half a
  // periodic box).
  const NeighbourList& update(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
    if (!covers(x, h, box)) search(x, h, box);
    return list_;
  }
  long searches() const { return searches_; }

 private:
  bool covers(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) const {
    if (x.size() != x0_.size() || box.lo != box_.lo || box.hi != box_.hi || box.periodic != box_.periodic) return false;
    const Vec<D> L = box.length(), wrap = box.wrap_factor();
    const double s = used_skin_;
    bool each = true, finite = true;
    double d_max = 0.0, slack = std::numeric_limits<double>::infinity();
    const std::size_t n = x.size();
#pragma omp parallel for reduction(&& : each, finite) reduction(max : d_max) reduction(min : slack) if (n >= parallel_threshold)
    for (std::size_t k = 0; k < n; ++k) {
      const double d = min_image<D>(x[k] - x0_[k], L, wrap).norm(), g = std::max(0.0, h[k] - h0_[k]);
      finite = finite && std::isfinite(d + h[k]);
      each = each && d + g <= 0.5 * s * h0_[k];  // (a)
      d_max = std::max(d_max, d);
      slack = std::min(slack, s * h0_[k] - g);  // (b): 2 d_max <= min_k (skin h0_k - g_k)
    }
    return finite && (each || 2.0 * d_max <= slack);
  }

  void search(const std::vector<Vec<D>>& x, const std::vector<double>& h, const Box<D>& box) {
    std::vector<double> reach = h;
    const double widest = h.empty() ? 0.0 : (1.0 + skin_) * *std::max_element(h.begin(), h.end());
    const Vec<D> L = box.length();
    used_skin_ = skin_;
    for (int d = 0; d < D; ++d)
      if (box.periodic[d] && widest > 0.5 * L[d]) used_skin_ = 0.0;
    for (double& r : reach) r *= 1.0 + used_skin_;
    list_ = grid_search<D>(x, reach, box);
    x0_ = x, h0_ = h, box_ = box;
    ++searches_;
  }

  double skin_, used_skin_ = 0.0;
  NeighbourList list_;
  std::vector<Vec<D>> x0_;
  std::vector<double> h0_;
  Box<D> box_;
  long searches_ = 0;
};

}  // namespace sph
