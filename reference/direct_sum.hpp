#pragma once
#include <span>
#include <vector>

namespace reference {

// Self-gravity by direct summation over all pairs, O(N^2), the reference for the tree.
// Plummer softening: phi_i = -G sum_j m_j / sqrt(r_ij^2 + eps^2), a_i = -grad_i phi_i.
// Plain arrays (independent of sph/); OpenMP over targets.
struct DirectField {
  std::vector<double> ax, ay, az, phi;
};

// At the particles themselves, each skipping its own mass (j != i).
DirectField direct_sum(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                       std::span<const double> m, double G, double eps);

// At points px, py, pz that are not particles (all particles contribute).
DirectField direct_sum_at(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                          std::span<const double> m, double G, double eps, std::span<const double> px,
                          std::span<const double> py, std::span<const double> pz);

}  // namespace reference
