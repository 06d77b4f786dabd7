#pragma once
#include <vector>

namespace reference {

// Exact solutions of the heat equation dT/dt = chi lap T (60) in the periodic unit box [0, 1)^d.

// Sine mode T = T0 + A exp(-chi |k|^2 t) prod_a sin(k_a x_a), k_a = 2 pi m: decay rate chi |k|^2.
double sine_mode(const std::vector<double>& x, double t, double chi, double T0, double A, int m);

// Gaussian pulse T = T0 + A prod_a g(x_a), g the periodic sum of images of a 1D Gaussian of
// variance s0^2 + 2 chi t centred at c, scaled by s0 / s(t) (the heat kernel's spreading).
double gaussian_pulse(const std::vector<double>& x, double t, double chi, double T0, double A, double s0,
                      double c);

}  // namespace reference
