#pragma once
// The shock tubes' errors (cases sod, sod2d, sod3d), shared by `sphv run` and `sphv score`.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reference/riemann.hpp"
#include "verification/cases/sod_tube.hpp"
#include "verification/params.hpp"

namespace sphv {

// The Riemann problem of a sod/sod2d/sod3d parameter set (preset and overrides), validated.
TubeProblem tube_problem(const Params& p);

// L1 errors of density, x-velocity, pressure and specific internal energy over the tube [0, 1]
// at time t against the exact Riemann solution, weighted by particle volume m/rho:
//   L1_f = sum_i (m_i / rho_i) |f_i - f_exact(x_i, t)| / sum_i (m_i / rho_i),  0 <= x_i <= 1,
// over the particles [0, count) (2D/3D tubes: read along x, every particle counts).
inline std::map<std::string, double> tube_l1_errors(const std::vector<double>& x, const std::vector<double>& v,
                                                    const std::vector<double>& rho, const std::vector<double>& p,
                                                    const std::vector<double>& u, const std::vector<double>& m,
                                                    std::size_t count, const reference::RiemannSolution& exact, double t) {
  double vol = 0.0, e_rho = 0.0, e_v = 0.0, e_p = 0.0, e_u = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    if (x[i] < 0.0 || x[i] > 1.0) continue;
    const auto s = exact.sample(x[i], t);
    const double w = m[i] / rho[i];
    vol += w;
    e_rho += w * std::abs(rho[i] - s.rho);
    e_v += w * std::abs(v[i] - s.u);
    e_p += w * std::abs(p[i] - s.p);
    e_u += w * std::abs(u[i] - s.e);
  }
  return {{"L1_rho", e_rho / vol}, {"L1_v", e_v / vol}, {"L1_p", e_p / vol}, {"L1_u", e_u / vol}};
}

inline const std::map<std::string, std::string> tube_error_defs = {
    {"L1_rho", "sum_i (m_i/rho_i) |rho_i - rho_exact(x_i, t)| / sum_i (m_i/rho_i) over particles with 0 <= x_i <= 1 "
               "(the tube [0, 1], read along x); exact: Toro's Riemann solver"},
    {"L1_v", "as L1_rho for the x-velocity v_x"},
    {"L1_p", "as L1_rho for the pressure p"},
    {"L1_u", "as L1_rho for the specific internal energy u"}};

}  // namespace sphv
