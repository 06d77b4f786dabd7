#pragma once
// Gas with tree self-gravity (sph::SelfGravity) in the force loop, as evrard and polytrope evolve
// it: the one scene both cases share, compiled once (common/gas_self_gravity_3d.cpp) rather than in each.
#include "sph/gravity/self_gravity.hpp"
#include "verification/cases/common/extreme_hydro.hpp"

namespace sphv::extreme {
extern template sph::HydroOutcome evolve_gas<3, sph::SelfGravity>(sph::Particles<3>&, const sph::Box<3>&,
                                                                  const Method&, sph::HydroHooks<3>,
                                                                  sph::SelfGravity&);
}  // namespace sphv::extreme
