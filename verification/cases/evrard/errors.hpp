#pragma once
// The Evrard collapse's profile errors at time t, shared by `sphv run` (at t_end) and `sphv
// score`: density, radial velocity and specific internal energy of the particles against the 1D
// Lagrangian reference (reference/evrard_lagrangian) at the same time. Units G = M = R = 1.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reference/evrard_lagrangian.hpp"
#include "reference/interpolate.hpp"
#include "sph/core/vec.hpp"
#include "verification/harness/result.hpp"
#include "verification/support/reference_cache.hpp"

namespace sphv::evrard {

// The 1D reference, solved once per sweep or process (support/reference_cache.hpp): every level
// poses the same collapse.
inline reference::EvrardSolution reference_solution(int zones, double gamma, double u0, double t_end) {
  std::string key = "evrard collapse (reference/evrard_lagrangian): zones " + std::to_string(zones);
  for (double v : {gamma, u0, t_end}) key += " " + key_number(v);
  const Columns c = cached_reference(key, [&] {
    reference::EvrardOptions o;
    o.zones = zones, o.gamma = gamma, o.u0 = u0, o.t_end = t_end;
    const reference::EvrardSolution s = reference::evrard_lagrangian(o);
    const reference::EvrardProfile& e = s.at_end;
    return Columns{s.t,         s.kinetic,     s.thermal, s.potential, {double(s.steps), s.t_max_compression},
                   s.r_profile, s.rho_profile, e.r_node,  e.v,         e.r_zone,
                   e.rho,       e.e};
  });
  reference::EvrardSolution s;
  s.t = c.at(0), s.kinetic = c.at(1), s.thermal = c.at(2), s.potential = c.at(3);
  s.steps = static_cast<long>(c.at(4).at(0)), s.t_max_compression = c.at(4).at(1);
  s.r_profile = c.at(5), s.rho_profile = c.at(6);
  s.at_end = {c.at(7), c.at(8), c.at(9), c.at(10), c.at(11)};
  return s;
}

inline const std::map<std::string, std::string> profile_error_defs = {
    {"rho_profile_L1",
     "sum_i m_i |rho_i - rho_ref(r_i, t)| / sum_i m_i rho_ref(r_i, t) over all particles, r_i = |x_i - centre|; "
     "rho_ref: the 1D Lagrangian reference's zone densities at the same t, linear in r between zone centres, the end "
     "zones' values outside them"},
    {"vr_profile_L1",
     "sum_i m_i |v_i . x_i / r_i - v_ref(r_i, t)| / sum_i m_i, units sqrt(G M / R); v_ref: the reference's node "
     "velocities, linear in r between nodes"},
    {"u_profile_L1",
     "sum_i m_i |u_i - u_ref(r_i, t)| / sum_i m_i, units G M / R; u_ref: the reference's zone specific internal "
     "energies, as rho_ref"},
    {"mismatch", "sphv score's check that a snapshot holds the problem its settings describe (not an error): the "
                 "particles' kinetic + thermal + Plummer-softened potential energy (G = 1, softening eps) is the "
                 "problem's E(0) = u0 - 2/3 within 10 % of |E(0)| (the particle sphere's discreteness: -1.9 % at 912 "
                 "particles; a code's energy error adds); otherwise the verdict is mismatch"}};

// The three errors above of values (rho, v_r, u) at radii rad against the reference's profiles.
// The density's is relative to the reference's mass-weighted density as a whole, not particle by
// particle: beyond the bounce the outer few per cent of the mass expand to densities a thousand
// times below the centre's, where an SPH particle's density is set by neighbours a support
// radius away and |rho_i / rho_ref - 1| is unbounded; a pointwise ratio lets that unresolved tail
// carry most of the norm at every resolution.
struct ProfileL1 {
  double rho = 0.0, vr = 0.0, u = 0.0;
};
inline ProfileL1 profile_l1(const std::vector<double>& rad, const std::vector<double>& m, const std::vector<double>& rho,
                            const std::vector<double>& v_r, const std::vector<double>& u,
                            const reference::EvrardProfile& ref) {
  using reference::interpolate_linear;
  double mass = 0.0, mass_rho = 0.0;
  ProfileL1 e;
  for (std::size_t i = 0; i < rad.size(); ++i) {
    const double rho_ref = interpolate_linear(ref.r_zone, ref.rho, rad[i]);
    mass += m[i], mass_rho += m[i] * rho_ref;
    e.rho += m[i] * std::abs(rho[i] - rho_ref);
    e.vr += m[i] * std::abs(v_r[i] - interpolate_linear(ref.r_node, ref.v, rad[i]));
    e.u += m[i] * std::abs(u[i] - interpolate_linear(ref.r_zone, ref.e, rad[i]));
  }
  return {e.rho / mass_rho, e.vr / mass, e.u / mass};
}

// Fills r.errors (the three above), the profile figures and extras from the particles at time t
// (positions relative to the sphere's centre) and the reference's state at t; half: the
// reference with half the zones, whose profiles at the particles' radii, measured the same way,
// give the reference's own error (extra.reference_profile_L1_half_zones).
inline void measure_profiles(Result& r, const std::vector<sph::Vec<3>>& x, const std::vector<sph::Vec<3>>& v,
                             const std::vector<double>& m, const std::vector<double>& rho, const std::vector<double>& u,
                             const reference::EvrardProfile& ref, const reference::EvrardProfile& half, double t) {
  using reference::interpolate_linear;
  std::vector<double> rad(x.size()), v_r(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    rad[i] = x[i].norm();
    v_r[i] = rad[i] > 0.0 ? v[i].dot(x[i]) / rad[i] : 0.0;
  }
  const ProfileL1 e = profile_l1(rad, m, rho, v_r, u, ref);
  r.errors["rho_profile_L1"] = e.rho;
  r.errors["vr_profile_L1"] = e.vr;
  r.errors["u_profile_L1"] = e.u;
  std::vector<double> h_rho(x.size()), h_v(x.size()), h_u(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    h_rho[i] = interpolate_linear(half.r_zone, half.rho, rad[i]);
    h_v[i] = interpolate_linear(half.r_node, half.v, rad[i]);
    h_u[i] = interpolate_linear(half.r_zone, half.e, rad[i]);
  }
  const ProfileL1 eh = profile_l1(rad, m, h_rho, h_v, h_u, ref);
  r.extra["reference_profile_L1_half_zones"] = {{"rho", eh.rho}, {"vr", eh.vr}, {"u", eh.u}};
  r.extra["profile_time"] = t;
  r.extra["reference_outer_radius"] = ref.r_node.back();

  // Particles (at most ~3000) against the reference's profile.
  auto figure = [&](const std::string& name, const std::string& what, const std::vector<double>& value,
                    const std::vector<double>& r_ref, const std::vector<double>& v_ref, bool log) {
    Series pts{"SPH particles", {}, {}, "points"};
    const std::size_t stride = std::max<std::size_t>(1, x.size() / 3000);
    for (std::size_t i = 0; i < x.size(); i += stride)
      if (!log || rad[i] > 0.0) pts.x.push_back(rad[i]), pts.y.push_back(value[i]);
    Figure f{name, "Evrard collapse at t = " + std::to_string(t) + ": " + what, "r (R)", what, log ? "log" : "linear",
             log ? "log" : "linear", {pts, {"1D Lagrangian", r_ref, v_ref, "line"}}};
    r.figures.push_back(std::move(f));
  };
  figure("profile_rho_t", "rho (M / R^3)", rho, ref.r_zone, ref.rho, true);
  figure("profile_vr_t", "v_r (sqrt(G M / R))", v_r, ref.r_node, ref.v, false);
  figure("profile_u_t", "u (G M / R)", u, ref.r_zone, ref.e, false);
}

}  // namespace sphv::evrard
