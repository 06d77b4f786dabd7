#pragma once
// L1_rho_deposit: the density's L1 against the blast a run poses, its heat deposited with the
// cubic spline's shape on r_b (sedov/setup.hpp), solved in 1D (reference/blast_lagrangian.hpp).
// At a fixed r_b that blast is the limit of the runs, not the point blast: the hot, nearly empty
// centre is made from the deposit's gas and remembers its size, and the two solutions differ by
// extra.deposit_memory (the same L1 between them) at every n. `sphv run` only: a scored
// snapshot's deposit is its code's.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "reference/blast_lagrangian.hpp"
#include "reference/interpolate.hpp"
#include "reference/lagrangian_1d.hpp"
#include "reference/sedov.hpp"
#include "sph/core/vec.hpp"
#include "sph/kernel/cubic_spline.hpp"
#include "verification/cases/sedov/errors.hpp"
#include "verification/harness/result.hpp"
#include "verification/support/reference_cache.hpp"

namespace sphv::sedov {

inline const char* const deposit_error_def =
    "sum over particles with r < 1.2 R of (m_i/rho_i) |rho_i - rho_dep(r_i, t)|, divided by vol_d(1.2 R) and by rho0; "
    "rho_dep: the blast the run poses, its heat deposited by the cubic spline's weight on r_b, solved by a 1D "
    "Lagrangian code (reference/blast_lagrangian) on zones R / 1200 wide, linear in r between zone centres";

// The reference's zones over [0, 4/3 R] (a wall beyond the ball of the errors, 1.2 R, which the
// shock does not reach by t): R / 1200 wide. With half as many, the L1 between the two at the
// particles' radii (extra.reference_L1_rho_half_zones) is 0.0025 to 0.009, 2 to 7 % of the full
// tier's finest L1_rho_deposit (docs/cases/sedov.md).
constexpr int deposit_zones = 1600;

// Solved once per sweep (support/reference_cache.hpp): every level poses the same blast.
template <int D>
reference::RadialProfile deposit_blast(double gamma, double E, double rho0, double u_ambient, double r_b, double t,
                                       double R, int zones) {
  std::string key = "sedov deposit blast (reference/blast_lagrangian), cubic spline deposit: dim " + std::to_string(D) +
                    ", zones " + std::to_string(zones);
  for (double v : {gamma, E, rho0, u_ambient, r_b, t, R}) key += " " + key_number(v);
  const Columns c = cached_reference(key, [&] {
    reference::BlastOptions o;
    o.dim = D, o.gamma = gamma, o.E = E, o.rho0 = rho0, o.u_ambient = u_ambient, o.t_end = t;
    o.r_out = 4.0 / 3.0 * R, o.zones = zones;
    o.deposit = [r_b](double r) { return sph::CubicSpline<D>::W(r, r_b); };
    const reference::RadialProfile p = reference::blast_lagrangian(o);
    return Columns{p.r_node, p.v, p.r_zone, p.rho, p.e};
  });
  return {c.at(0), c.at(1), c.at(2), c.at(3), c.at(4)};
}

// Fills r.errors["L1_rho_deposit"], its extras and the deposit's curve in the density figure
// (sedov::measure's "profile_rho", when there) from the particles at time t.
template <int D>
void measure_deposit(Result& r, const std::vector<sph::Vec<D>>& x, const std::vector<double>& m,
                     const std::vector<double>& rho, double gamma, double E, double rho0, double u_ambient,
                     double r_b, double t, const reference::Sedov& exact) {
  using reference::interpolate_linear;
  const double R = exact.shock_radius(E, rho0, t);
  const reference::RadialProfile dep = deposit_blast<D>(gamma, E, rho0, u_ambient, r_b, t, R, deposit_zones),
                                 half = deposit_blast<D>(gamma, E, rho0, u_ambient, r_b, t, R, deposit_zones / 2);
  std::vector<double> rad(x.size()), volume(x.size()), at_dep(x.size()), at_half(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    rad[i] = x[i].norm();
    volume[i] = m[i] / rho[i];
    at_dep[i] = interpolate_linear(dep.r_zone, dep.rho, rad[i]);
    at_half[i] = interpolate_linear(half.r_zone, half.rho, rad[i]);
  }
  // The reference's own error, the same norm with the same particle volumes.
  r.errors["L1_rho_deposit"] = ball_l1<D>(rad, volume, rho, at_dep, R, rho0);
  r.extra["reference_L1_rho_half_zones"] = ball_l1<D>(rad, volume, at_half, at_dep, R, rho0);
  r.extra["deposit_reference_zones"] = deposit_zones;
  // The deposit's memory: the same L1 between the deposit's solution and the point blast's,
  // summed over the reference's zones inside the ball, their volumes the mesh's own.
  using reference::Lagrangian1D;
  double memory = 0.0;
  for (std::size_t k = 0; k + 1 < dep.r_node.size() && dep.r_node[k] < 1.2 * R; ++k)
    memory += Lagrangian1D::shell_volume(D, dep.r_node[k], std::min(dep.r_node[k + 1], 1.2 * R)) *
              std::abs(dep.rho[k] - exact.density(dep.r_zone[k], E, rho0, t));
  r.extra["deposit_memory"] = memory / error_ball<D>(R) / rho0;
  for (Figure& f : r.figures)
    if (f.name == "profile_rho") {
      Series line{"the run's finite deposit (1D Lagrangian reference)", {}, {}, "dashed"};
      for (std::size_t k = 0; k < dep.r_zone.size(); ++k)
        if (dep.r_zone[k] < 1.5 * R) line.x.push_back(dep.r_zone[k] / R), line.y.push_back(dep.rho[k] / rho0);
      f.series.push_back(std::move(line));
    }
}

}  // namespace sphv::sedov
