#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace reference {

// Piecewise-linear interpolation of samples y(x), x ascending, at s; clamped to the end values
// outside [x.front(), x.back()].
inline double interpolate_linear(const std::vector<double>& x, const std::vector<double>& y, double s) {
  if (s <= x.front()) return y.front();
  if (s >= x.back()) return y.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), s) - x.begin());
  const double w = (s - x[k - 1]) / (x[k] - x[k - 1]);
  return (1.0 - w) * y[k - 1] + w * y[k];
}

}  // namespace reference
