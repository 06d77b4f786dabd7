#include "sph/core/verdict.hpp"

#include <string>

namespace sph {

std::string unstable_verdict(long step, double t, const BadParticle& b) {
  return "unstable: step " + std::to_string(step) + " (t = " + std::to_string(t) + "), particle " +
         std::to_string(b.particle) + ": " + b.what;
}

}  // namespace sph
