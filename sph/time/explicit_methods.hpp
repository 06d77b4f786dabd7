#pragma once
#include <vector>

namespace sph {

// Explicit one-step methods for y' = f(y) on a flat state (the specific energies u of a static
// conduction problem). f(y, dydt) writes the rate. Both are stable for real negative
// eigenvalues -lambda while dt lambda <= 2.

// Forward Euler, first order: y += dt f(y).
template <class F>
void forward_euler_step(std::vector<double>& y, double dt, F&& f, std::vector<double>& k1) {
  f(y, k1);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += dt * k1[i];
}

// Heun's method (explicit trapezoid, RK2), second order:
// y* = y + dt f(y),  y += dt/2 (f(y) + f(y*)).
template <class F>
void heun_step(std::vector<double>& y, double dt, F&& f, std::vector<double>& k1, std::vector<double>& k2,
               std::vector<double>& ystar) {
  f(y, k1);
  ystar.resize(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) ystar[i] = y[i] + dt * k1[i];
  f(ystar, k2);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += 0.5 * dt * (k1[i] + k2[i]);
}

}  // namespace sph
