// The 1D shock tube with the kernels other than the cubic spline (sph/kernel/kernels.hpp), one
// scene each, in a unit of its own (not in the sod_tube unit, which holds the 96 scenes of the
// forms): the two compile side by side.
#include <type_traits>

#include "sph/kernel/kernels.hpp"
#include "verification/cases/shock_tubes/simulate.hpp"

namespace sphv {
TubeRun simulate_tube_other_kernel(const TubeProblem& pr, const TubeMethod& m, long n) {
  TubeRun run;
  sph::with_kernel<1>(m.kernel, [&](auto k) {
    using K = decltype(k);
    if constexpr (!std::is_same_v<K, sph::CubicSpline<1>>) run = simulate_tube_with<1, K>(pr, m, n);
    else throw std::logic_error("simulate_tube runs the cubic spline itself");
  });
  return run;
}
}  // namespace sphv
