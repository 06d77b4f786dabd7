#pragma once
// The heat case's set-up constants and error norm, shared by `sphv run` and `sphv score`.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "reference/heat_analytic.hpp"

namespace sphv::heat {

// Background temperature, perturbation amplitude, pulse width and pulse centre (each axis).
constexpr double T0 = 1.0, A = 0.5, sigma0 = 0.1, centre = 0.5;

// ||a - b||_2 / (A sqrt(N)): RMS error relative to the perturbation amplitude; NaN-free.
inline double rms_error(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / a.size()) / A;
}

// Diffusivity chi = K / (rho c_v) with rho the mean particle density.
inline double diffusivity(const std::vector<double>& rho, double K, double cv) {
  double rho_mean = 0.0;
  for (double r : rho) rho_mean += r / rho.size();
  return K / (rho_mean * cv);
}

// The Gaussian pulse's exact u = c_v T(x, t) at the given particle coordinates.
inline std::vector<double> pulse_exact(const std::vector<std::vector<double>>& coords, double t, double chi, double cv) {
  std::vector<double> u(coords.size());
  for (std::size_t i = 0; i < coords.size(); ++i) u[i] = cv * reference::gaussian_pulse(coords[i], t, chi, T0, A, sigma0, centre);
  return u;
}

// The sine mode's exact u = c_v T(x, t), wave number 2 pi along every axis.
inline std::vector<double> sine_exact(const std::vector<std::vector<double>>& coords, double t, double chi, double cv) {
  std::vector<double> u(coords.size());
  for (std::size_t i = 0; i < coords.size(); ++i) u[i] = cv * reference::sine_mode(coords[i], t, chi, T0, A, 1);
  return u;
}

// The set-ups (error name -> exact u at the coordinates) a snapshot can be scored against.
using ExactField = std::vector<double> (*)(const std::vector<std::vector<double>>&, double, double, double);
inline const std::map<std::string, std::pair<std::string, ExactField>> setups = {
    {"gauss", {"spatial_gauss", pulse_exact}}, {"sine", {"spatial_sine", sine_exact}}};

inline const std::map<std::string, std::string> error_defs = {
    {"spatial_gauss", "sqrt(sum_i (u_i - c_v T_exact(x_i, t))^2 / N) / A over all N particles (unweighted RMS relative "
                      "to the amplitude A = 0.5): the Gaussian pulse (sigma0 = 0.1 at 0.5 per axis, T0 = 1) in the periodic "
                      "unit box, chi = K / (mean(rho) c_v); sphv run integrates the SPH semi-discretisation by CVODE "
                      "(sphv score: setup=gauss)"},
    {"spatial_sine", "as spatial_gauss for the sine mode T = T0 + A exp(-chi d (2 pi)^2 t) prod_a sin(2 pi x_a) "
                     "(sphv score: setup=sine)"},
    {"spatial_gauss_above_floor", "|spatial_gauss - spatial_gauss_floor|: the distance to the lattice floor, the RMS "
                                  "(as spatial_gauss) of the exact pulse at t_end (1 + eps) against the exact one at "
                                  "t_end, eps = symbol(k) / k^2 - 1 as k dx -> 0 by direct lattice sums "
                                  "(heat/lattice.hpp); sphv run only, where eps is not 0"},
    {"spatial_sine_above_floor", "as spatial_gauss_above_floor for spatial_sine"},
    {"time_euler", "RMS (as spatial_gauss) of forward Euler at dt = C h^2 / chi against CVODE (sphv run only)"},
    {"time_heun", "as time_euler for Heun (sphv run only)"},
    {"mismatch", "sphv score's check that a snapshot holds the problem its settings describe (not an error): the "
                 "particles' mean u is the exact field's mean at their positions within 5 % of c_v A (conduction "
                 "keeps the total); otherwise the verdict is mismatch"}};

}  // namespace sphv::heat
