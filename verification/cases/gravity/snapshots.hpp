#pragma once
// gravity and other codes' files: the scorer of `sphv score` (the code's accelerations against the direct sum).
#include "verification/snapshot/initial_state.hpp"
#include "verification/snapshot/scorer.hpp"

namespace sphv::gravity {

Scorer scorer();

}  // namespace sphv::gravity
