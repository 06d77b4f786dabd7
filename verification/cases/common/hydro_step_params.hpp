#pragma once
// The time-step parameters of the hydro cases (sod*, common/extreme_hydro.hpp) and their reading into
// the time-step control: "timestep" (the signal-speed Courant step with the acceleration
// criterion, or the chapter's (43)), the Courant number C and eta of (43).
#include <vector>

#include "sph/time/timestep.hpp"
#include "verification/harness/params.hpp"

namespace sphv {

inline std::vector<ParamSpec> time_step_params() {
  return {choice_param("timestep", "courant", "signal-speed Courant + acceleration criterion, or (43)",
                       {"courant", "chapter"}),
          real_param("C", 0.3, "Courant number", 0.0), real_param("eta", 0.3, "eta of (43)", 0.0)};
}

inline void read_time_step(const Params& p, sph::TimeStepControl& step) {
  using enum sph::TimeStepCriterion;
  step.criterion = p.text("timestep") == "courant" ? courant : chapter43;
  step.C = p.real("C");
  step.eta = p.real("eta");
}

}  // namespace sphv
