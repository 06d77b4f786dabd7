#pragma once
// What a case declares for `sphv score` (score.hpp): how it reads another code's snapshot and
// scores it against the case's reference.
#include <functional>
#include <string>
#include <vector>

#include "verification/harness/params.hpp"
#include "verification/harness/result.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

// How a case's resolution n follows from a snapshot (unless set): not at all, as particles per
// unit length N^(1/dim) / L (L: the box's side along x, 1 where the file states no box), or as
// the particle count N.
enum class Resolution { none, per_length, count };

// How one case scores a snapshot (an empty score: the case scores none).
struct Scorer {
  std::string time_key;                          // the case's time parameter ("" = none)
  std::function<Result(const Params&, const Snapshot&)> score;
  std::function<double(const Params&)> t_end;     // the time a run of these parameters ends at (may be empty)
  Resolution n = Resolution::none;
  std::function<double(const Params&)> gamma;     // the adiabatic index in use (empty: the case has none)
  std::vector<std::string> constants = {};        // parameters no file states (e.g. K, G): from --set or default
  // A case scored on a time series (kh's growth rate): score measures one snapshot, series joins
  // the snapshots' results, in the order given, into the case's errors. Empty: one snapshot.
  std::function<Result(const Params&, const std::vector<Result>&)> series = {};
};

}  // namespace sphv
