#pragma once
#include <cmath>
#include <optional>
#include <string>

#include "sph/core/particles.hpp"
#include "sph/core/threads.hpp"

namespace sph {

// The first particle whose state is unphysical: position or velocity not finite, density not
// positive, pressure or specific internal energy negative, support radius not positive, or any
// of them not finite.
struct BadParticle {
  std::size_t particle;
  std::string what;  // e.g. "rho <= 0", "u not finite"
};

// What is wrong with particle i (nullptr: nothing).
template <int D>
const char* what_is_bad(const Particles<D>& p, std::size_t i) {
  if (!p.x[i].allFinite()) return "position not finite";
  if (!p.v[i].allFinite()) return "velocity not finite";
  if (!std::isfinite(p.rho[i])) return "rho not finite";
  if (!(p.rho[i] > 0.0)) return "rho <= 0";
  if (!std::isfinite(p.u[i])) return "u not finite";
  if (p.u[i] < 0.0) return "u < 0";
  if (!std::isfinite(p.p[i])) return "p not finite";
  if (p.p[i] < 0.0) return "p < 0";
  if (!std::isfinite(p.h[i])) return "h not finite";
  if (!(p.h[i] > 0.0)) return "h <= 0";
  return nullptr;
}

// The bad particle of lowest index, whatever the thread count.
template <int D>
std::optional<BadParticle> first_bad(const Particles<D>& p) {
  const std::size_t n = p.size();
  std::size_t first = n;
#pragma omp parallel for reduction(min : first) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
    if (i < first && what_is_bad(p, i)) first = i;
  if (first == n) return std::nullopt;
  return BadParticle{first, what_is_bad(p, first)};
}

// "unstable: step 132 (t = 0.0123), particle 17: rho <= 0"
std::string unstable_verdict(long step, double t, const BadParticle& b);

}  // namespace sph
