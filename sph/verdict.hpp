#pragma once
#include <cmath>
#include <optional>
#include <string>

#include "sph/particles.hpp"

namespace sph {

// The first particle whose state is unphysical: position or velocity not finite, density not
// positive, pressure or specific internal energy negative, support radius not positive, or any
// of them not finite.
struct BadParticle {
  std::size_t particle;
  std::string what;  // e.g. "rho <= 0", "u not finite"
};

template <int D>
std::optional<BadParticle> first_bad(const Particles<D>& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.x[i].allFinite()) return BadParticle{i, "position not finite"};
    if (!p.v[i].allFinite()) return BadParticle{i, "velocity not finite"};
    if (!std::isfinite(p.rho[i])) return BadParticle{i, "rho not finite"};
    if (!(p.rho[i] > 0.0)) return BadParticle{i, "rho <= 0"};
    if (!std::isfinite(p.u[i])) return BadParticle{i, "u not finite"};
    if (p.u[i] < 0.0) return BadParticle{i, "u < 0"};
    if (!std::isfinite(p.p[i])) return BadParticle{i, "p not finite"};
    if (p.p[i] < 0.0) return BadParticle{i, "p < 0"};
    if (!std::isfinite(p.h[i])) return BadParticle{i, "h not finite"};
    if (!(p.h[i] > 0.0)) return BadParticle{i, "h <= 0"};
  }
  return std::nullopt;
}

// "unstable: step 132 (t = 0.0123), particle 17: rho <= 0"
inline std::string unstable_verdict(long step, double t, const BadParticle& b) {
  return "unstable: step " + std::to_string(step) + " (t = " + std::to_string(t) + "), particle " +
         std::to_string(b.particle) + ": " + b.what;
}

}  // namespace sph
