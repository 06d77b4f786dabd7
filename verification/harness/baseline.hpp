#pragma once
#include <filesystem>
#include <vector>

#include "verification/harness/case.hpp"

namespace sphv {

struct Sweep;

// Drift baselines: the errors this code produced at the quick-tier levels when someone last ran
// `sphv baseline update`. They are the code's own earlier output, NOT verification: they catch
// an error that grows beyond drift_grow * baseline + drift_slack, and a baseline gone stale (an
// error below drift_stale * baseline - drift_slack: the code got better, update on purpose).
inline constexpr double drift_grow = 1.10;   // 10%: errors are deterministic for one build and thread-count
                                             // independent; compilers and flags move them by round-off
inline constexpr double drift_stale = 0.90;  // the same margin the other way
inline constexpr double drift_slack = 1e-12; // errors at round-off level (conservation) wander by more than 10%

// Where baselines live: the directory given with --baselines, else <dir of the running
// executable>/../reference/baselines (the build folder inside the source tree).
void set_baseline_dir(const std::filesystem::path& dir);
std::filesystem::path baseline_dir();
// Drift checks of a sweep against the stored baseline of its case and variant. A catalogue
// variant of a gated case without a readable baseline gets one failing check saying so.
std::vector<Check> drift_checks(const Sweep& s);
// Writes <baseline_dir>/<case>.json from sweeps of every variant.
void write_baseline(const Case& c, const std::vector<Sweep>& sweeps);

}  // namespace sphv
