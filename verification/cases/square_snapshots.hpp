#pragma once
// square and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/initial_state.hpp"
#include "verification/scorer.hpp"

namespace sphv::square {

Scorer scorer();
InitialState initial_conditions(const Params& p, IcLayout layout);

}  // namespace sphv::square
