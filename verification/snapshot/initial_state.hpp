#pragma once
// What a case declares for `sphv ic` (ic.hpp): its initial conditions as a snapshot.
#include <functional>

#include "verification/harness/params.hpp"
#include "verification/snapshot/snapshot.hpp"
#include "verification/snapshot/swift_ic.hpp"

namespace sphv {

// Where the particles lie: as sphv's own run lays them out (csv, h5part), or as SWIFT's examples
// do (swift): every particle inside a periodic box [0, box), the radial cases' centre at its
// middle, the shock tube periodic on [0, 2] with its interfaces at x = 1 and at the wrap
// (examples/HydroTests/SodShock_1D/makeIC.py) and no boundary layers.
enum class IcLayout { sphv, swift };

struct InitialState {
  Snapshot s;
  SwiftIcHeader swift;  // the box (IcLayout::swift) and the gas's gamma
};

using InitialConditions = std::function<InitialState(const Params&, IcLayout)>;

}  // namespace sphv
