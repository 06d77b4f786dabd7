#pragma once
// An independent reference solved once per sweep instead of once per level. The levels of a sweep
// pose the same reference at every n (the 1D solutions of sedov's deposit and of the Evrard
// collapse). Run as child processes (harness/points.cpp), the first point to solve it leaves it in
// a folder for the others; run in one process (the gates, an in-process sweep), the process keeps
// it. A reference is kept under the full text of its inputs, as the doubles it computed, so a
// point reads exactly the numbers it would have computed.
#include <functional>
#include <string>
#include <vector>

namespace sphv {

// The environment variable through which `sphv verify` and `sphv sweep` hand their child points
// that folder, one per sweep and build (harness/points.cpp).
inline constexpr const char* reference_cache_variable = "SPHV_REFERENCE_CACHE";

using Columns = std::vector<std::vector<double>>;

// The columns stored under key in the folder SPHV_REFERENCE_CACHE names, or else make()'s, which
// are then stored there: written to a file of their own and renamed into place, so that a point
// reading meanwhile finds the whole file or none. A file that cannot be read or written costs
// only the solve; one stored under another key (a hash collision) is not read. Without the
// variable, the columns this process solved for key before, or make()'s, kept for the next call.
Columns cached_reference(const std::string& key, const std::function<Columns()>& make);

// A double as a key holds it: exact (hexadecimal), so inputs that differ in the last bit differ.
std::string key_number(double v);

}  // namespace sphv
