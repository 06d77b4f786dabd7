#pragma once
// kh and other codes' files: the scorer of `sphv score` (a time series of snapshots) and the
// initial conditions of `sphv ic`.
#include "verification/snapshot/initial_state.hpp"
#include "verification/snapshot/scorer.hpp"

namespace sphv::kh {

Scorer scorer();
InitialState initial_conditions(const Params& p, IcLayout layout);

}  // namespace sphv::kh
