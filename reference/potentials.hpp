#pragma once
#include <array>

namespace reference {

// Analytic gravitational fields (G = 1 unless given), as functions of the radius r from the
// centre: potential phi(r) and radial acceleration g(r) = -dphi/dr (negative: inwards).

// Homogeneous sphere of mass M and radius R: phi = -M (3 R^2 - r^2) / (2 R^3) inside,
// -M / r outside; g = -M r / R^3 inside, -M / r^2 outside.
double uniform_sphere_phi(double r, double M, double R, double G = 1.0);
double uniform_sphere_g(double r, double M, double R, double G = 1.0);

// Plummer sphere of mass M and scale radius a: phi = -M / sqrt(r^2 + a^2),
// g = -M r / (r^2 + a^2)^(3/2); enclosed mass M r^3 / (r^2 + a^2)^(3/2).
double plummer_phi(double r, double M, double a, double G = 1.0);
double plummer_g(double r, double M, double a, double G = 1.0);

// Circular speed about a Plummer-softened point mass GM (77): v^2 = GM r^2 / (r^2 + eps^2)^(3/2).
double softened_circular_speed(double r, double GM, double eps);

// Kepler orbit about a point mass GM with semi-major axis a and eccentricity e, pericentre on
// the +x axis at t = 0, moving in the x-y plane counter-clockwise: position and velocity at t
// (Kepler's equation M = E - e sin E solved by Newton's method to round-off).
struct OrbitState {
  std::array<double, 2> x, v;
};
OrbitState kepler_orbit(double t, double GM, double a, double e);

}  // namespace reference
