#pragma once
// The isobaric square's errors at time t, shared by `sphv run` and `sphv score`: the velocity
// noise of the light gas, the density field against the exact (carried) step and the dense
// phase's misfit against the exact square (reference/square.hpp). Each particle's phase is given:
// `sphv run` knows it from the set-up (the run hands the particles back in the order it was
// given them), `sphv score` reads it from the specific internal energy (phase_by_u): the phases'
// u differ by the density contrast at the one pressure, and an adiabatic flow keeps u within the
// pdV work of its pressure changes (a few per cent here), while the SPH density is smeared across
// the interface. A scheme with artificial conduction mixes u across the contact, so only the
// set-up's tag scores it.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reference/square.hpp"
#include "sph/core/vec.hpp"
#include "verification/harness/result.hpp"

namespace sphv::square {

inline const std::map<std::string, std::string> error_defs = {
    {"v_rms", "sqrt(sum_light m_i |v_i - v_adv|^2 / sum_light m_i) / c_out: the mass-weighted RMS velocity noise of the "
              "light phase (its particles by the set-up in a run; in a scored snapshot those with u_i above "
              "sqrt(u_in u_out)) relative to its sound speed c_out = sqrt(gamma p0 / rho_out); exact 0"},
    {"L1_rho", "sum_i V_i |rho_i - rho(x_i, t)| / ((rho_in - rho_out) sum_i V_i), V_i = m_i / rho_i, rho the exact "
               "density carried by v_adv (reference/square): the L1 error of the density field relative to the jump"},
    {"misfit", "sum_i c_i^d w_i / (1/2)^d: the area (volume) of the particles' cells on the wrong side of the carried "
               "square's edge, relative to the square's; c_i = (m_i / rho_phase)^(1/d) the side of particle i's cell at "
               "its phase's exact density (the phase as for v_rms), w_i the fraction of that cell outside the "
               "square for a dense particle, inside it for a light one: 0 at t = 0, where the cells tile each phase "
               "exactly; only for the sharp step (width = 0)"},
    {"mismatch", "sphv score's check that a snapshot holds the problem its settings describe (not an error): the "
                 "particles' median pressure is p0 within 5 % (the square is isobaric at every time); otherwise the "
                 "verdict is mismatch"}};

// The phase of each particle from its u (1: dense), against sqrt(u_in u_out), the geometric mean of
// the phases' u at the one pressure.
inline std::vector<char> phase_by_u(const std::vector<double>& u, const reference::IsobaricSquare& sq, double gamma) {
  const double u_cut = std::sqrt(sq.pressure() * sq.pressure() / (sq.rho_in() * sq.rho_out())) / (gamma - 1.0);
  std::vector<char> dense(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) dense[i] = u[i] < u_cut;
  return dense;
}

// Fills r.errors, extras and figures from the particles at time t, dense[i] the phase of particle i.
template <int D>
void measure(Result& r, const std::vector<sph::Vec<D>>& x, const std::vector<sph::Vec<D>>& v, const std::vector<double>& m,
             const std::vector<double>& rho, const std::vector<double>& u, const std::vector<char>& dense_phase,
             double t, const reference::IsobaricSquare& sq, double gamma, long n) {
  const double jump = sq.rho_in() - sq.rho_out();
  double m_light = 0.0, v2 = 0.0, v_max = 0.0, vol = 0.0, l1 = 0.0, wrong = 0.0, u_dev = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double V = m[i] / rho[i], exact = sq.density(x[i].data(), t);
    const bool dense = dense_phase[i];
    vol += V;
    l1 += V * std::abs(rho[i] - exact);
    const double cell = m[i] / (dense ? sq.rho_in() : sq.rho_out());
    const double in = sq.inside_fraction(x[i].data(), std::pow(cell, 1.0 / D), t);
    wrong += cell * (dense ? 1.0 - in : in);
    const double speed = (v[i] - sph::Vec<D>::Constant(sq.advection_speed())).norm();
    v_max = std::max(v_max, speed);
    if (!dense) m_light += m[i], v2 += m[i] * speed * speed;
    // The largest relative change of u from the exact state's (the phase tag's margin).
    const double u0 = sq.pressure() / ((gamma - 1.0) * (dense ? sq.rho_in() : sq.rho_out()));
    u_dev = std::max(u_dev, std::abs(u[i] / u0 - 1.0));
  }
  const double c_out = sq.sound_speed_out();
  r.errors = {{"v_rms", m_light > 0.0 ? std::sqrt(v2 / m_light) / c_out : 0.0},
              {"L1_rho", l1 / (jump * vol)},
              {"misfit", wrong / std::pow(0.5, D)}};
  if (sq.width() > 0.0) r.errors.erase("misfit");
  r.extra["v_max_over_c_out"] = v_max / c_out;
  r.extra["u_deviation_max"] = u_dev;
  r.extra["light_mass"] = m_light;
  // Density along the cut through the square's centre (the particles within half a light
  // spacing of the line y = 1/2 + v_adv t, z likewise), against the exact step.
  const double shift = sq.advection_speed() * t, half = 0.5 / n;
  Series pts{"SPH particles", {}, {}, "points"}, line{"exact (reference/square)", {}, {}, "line"};
  for (std::size_t i = 0; i < x.size(); ++i) {
    bool on = true;
    for (int d = 1; d < D; ++d) {
      const double y = x[i][d] - shift - 0.5;
      on = on && std::abs(y - std::round(y)) < half;
    }
    if (!on) continue;
    const double s = x[i][0] - shift;
    pts.x.push_back(s - std::floor(s)), pts.y.push_back(rho[i]);
  }
  for (int k = 0; k <= 600; ++k) {
    sph::Vec<D> q = sph::Vec<D>::Constant(0.5 + shift);
    q[0] = k / 600.0 + shift;
    line.x.push_back(k / 600.0), line.y.push_back(sq.density(q.data(), t));
  }
  const std::string at = ", n = " + std::to_string(n) + ", t = " + std::to_string(t);
  r.figures.push_back({"density_cut", "Isobaric square " + std::to_string(D) + "D" + at + ": density along the centre line",
                       "x - v_adv t", "rho", "linear", "linear", {pts, line}});
  // The dense phase's particles in the (x, y) plane (the square's frame), against the square.
  Series dense{"dense phase", {}, {}, "points"}, edge{"exact square", {}, {}, "line"};
  const std::size_t stride = std::max<std::size_t>(1, x.size() / 6000);
  for (std::size_t i = 0; i < x.size(); i += stride) {
    if (!dense_phase[i]) continue;
    if (D == 3 && std::abs(x[i][D - 1] - shift - 0.5 - std::round(x[i][D - 1] - shift - 0.5)) > 0.125) continue;
    const double a = x[i][0] - shift, b = x[i][1] - shift;
    dense.x.push_back(a - std::floor(a)), dense.y.push_back(b - std::floor(b));
  }
  edge.x = {0.25, 0.75, 0.75, 0.25, 0.25};
  edge.y = {0.25, 0.25, 0.75, 0.75, 0.25};
  r.figures.push_back({"dense_phase", "Isobaric square " + std::to_string(D) + "D" + at +
                                          (D == 3 ? ": dense phase, |z - 1/2| < 1/8" : ": dense phase"),
                       "x - v_adv t", "y - v_adv t", "linear", "linear", {dense, edge}});
}

}  // namespace sphv::square
