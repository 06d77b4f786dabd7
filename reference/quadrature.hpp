#pragma once
#include <functional>
#include <vector>

namespace reference {

// Adaptive quadrature of f over [a, b] with known breakpoints (GSL QAGP), to a relative
// tolerance of about 1e-13. Returns the integral and GSL's error estimate.
struct Integral {
  double value;
  double abserr;
};
Integral integrate(const std::function<double(double)>& f, std::vector<double> points);

}  // namespace reference
