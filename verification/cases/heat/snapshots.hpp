#pragma once
// heat and other codes' files: the scorer of `sphv score` and the initial conditions of `sphv ic`.
#include "verification/snapshot/initial_state.hpp"
#include "verification/snapshot/scorer.hpp"

namespace sphv::heat {

Scorer scorer();
InitialState initial_conditions(const Params& p, IcLayout layout);

}  // namespace sphv::heat
