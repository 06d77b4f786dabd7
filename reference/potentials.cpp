#include "reference/potentials.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace reference {

double uniform_sphere_phi(double r, double M, double R, double G) {
  return r < R ? -G * M * (3.0 * R * R - r * r) / (2.0 * R * R * R) : -G * M / r;
}

double uniform_sphere_g(double r, double M, double R, double G) {
  return r < R ? -G * M * r / (R * R * R) : -G * M / (r * r);
}

double plummer_phi(double r, double M, double a, double G) { return -G * M / std::sqrt(r * r + a * a); }

double plummer_g(double r, double M, double a, double G) { return -G * M * r / std::pow(r * r + a * a, 1.5); }

double softened_circular_speed(double r, double GM, double eps) {
  return std::sqrt(GM * r * r / std::pow(r * r + eps * eps, 1.5));
}

OrbitState kepler_orbit(double t, double GM, double a, double e) {
  if (!(e >= 0.0 && e < 1.0) || !(a > 0.0)) throw std::invalid_argument("kepler_orbit: need 0 <= e < 1, a > 0");
  const double nmean = std::sqrt(GM / (a * a * a));
  const double Mmean = std::remainder(nmean * t, 2.0 * std::numbers::pi);
  double E = e < 0.8 ? Mmean : std::numbers::pi * (Mmean < 0 ? -1 : 1);
  for (int k = 0; k < 100; ++k) {
    const double dE = (E - e * std::sin(E) - Mmean) / (1.0 - e * std::cos(E));
    E -= dE;
    if (std::abs(dE) < 1e-15) break;
  }
  const double b = a * std::sqrt(1.0 - e * e), Edot = nmean / (1.0 - e * std::cos(E));
  return {{a * (std::cos(E) - e), b * std::sin(E)}, {-a * std::sin(E) * Edot, b * std::cos(E) * Edot}};
}

}  // namespace reference
