#pragma once
// The shock tubes (sod, sod2d, sod3d) and other codes' files: the scorer of `sphv score` and the
// initial conditions of `sphv ic`.
#include "verification/snapshot/initial_state.hpp"
#include "verification/snapshot/scorer.hpp"

namespace sphv::tube {

Scorer scorer();
InitialConditions initial_conditions(int dim);  // dim 1, 2 or 3

}  // namespace sphv::tube
