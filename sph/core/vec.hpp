#pragma once
#include <Eigen/Core>

namespace sph {
// A position, velocity or acceleration in D dimensions (D = 1, 2, 3).
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
}  // namespace sph
