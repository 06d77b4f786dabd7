#pragma once
// Particle sets for the gravity cases (G = 1, total mass 1, equal masses, seeded).
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "sph/core/vec.hpp"
#include "verification/harness/params.hpp"

namespace sphv::gravity {

struct ParticleSet {
  std::vector<sph::Vec<3>> x;
  std::vector<double> m;
};

inline sph::Vec<3> random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), phi(0.0, 2.0 * std::numbers::pi);
  const double c = u(rng), s = std::sqrt(1.0 - c * c), f = phi(rng);
  return {s * std::cos(f), s * std::sin(f), c};
}

// Homogeneous sphere of radius R about the origin: r = R q^(1/3), q uniform.
inline ParticleSet uniform_sphere(long n, std::uint64_t seed, double R = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> q(0.0, 1.0);
  ParticleSet s{std::vector<sph::Vec<3>>(n), std::vector<double>(n, 1.0 / n)};
  for (auto& x : s.x) x = R * std::cbrt(q(rng)) * random_direction(rng);
  return s;
}

// Plummer sphere of scale radius a: enclosed mass fraction q = r^3 / (r^2 + a^2)^(3/2), so
// r = a / sqrt(q^(-2/3) - 1); radii beyond rmax are drawn again (rmax = infinity: exact model).
inline ParticleSet plummer_sphere(long n, std::uint64_t seed, double a = 1.0,
                                  double rmax = std::numeric_limits<double>::infinity(),
                                  const sph::Vec<3>& centre = sph::Vec<3>::Zero(), double mass = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> q(0.0, 1.0);
  ParticleSet s{std::vector<sph::Vec<3>>(n), std::vector<double>(n, mass / n)};
  for (auto& x : s.x) {
    double r;
    do r = a / std::sqrt(std::pow(q(rng), -2.0 / 3.0) - 1.0);
    while (!(r < rmax));
    x = centre + r * random_direction(rng);
  }
  return s;
}

// Strongly clustered: 32 Plummer clumps with scale radii 0.005 to 0.05 (log-uniform), truncated at
// 5 scale radii, centred uniformly in the unit sphere, equal clump masses; density contrast ~1e6.
inline ParticleSet clustered(long n, std::uint64_t seed) {
  constexpr int clumps = 32;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> q(0.0, 1.0);
  ParticleSet s;
  for (int k = 0; k < clumps; ++k) {
    const long nk = n / clumps + (k < n % clumps ? 1 : 0);
    const double a = 0.005 * std::pow(10.0, q(rng));
    const sph::Vec<3> c = std::cbrt(q(rng)) * random_direction(rng);
    const auto part = plummer_sphere(nk, rng(), a, 5.0 * a, c, double(nk) / n);
    s.x.insert(s.x.end(), part.x.begin(), part.x.end());
    s.m.insert(s.m.end(), part.m.begin(), part.m.end());
  }
  return s;
}

// model: uniform | plummer (truncated at 10 a for the tree cases) | clustered.
inline ParticleSet make_model(const std::string& model, long n, std::uint64_t seed) {
  if (model == "uniform") return uniform_sphere(n, seed);
  if (model == "plummer") return plummer_sphere(n, seed, 1.0, 10.0);
  if (model == "clustered") return clustered(n, seed);
  throw InputError("unknown gravity model '" + model + "'");
}

}  // namespace sphv::gravity
