#pragma once
#include <filesystem>
#include <vector>

#include "verification/case.hpp"

namespace sphv {

struct Sweep;

// Drift baselines: the errors this code produced at the gate levels when someone last ran
// `sphv baseline update`. They are the code's own earlier output, NOT verification: they only
// catch an error that grows. A run fails its drift check when an error exceeds
// drift_factor * baseline + drift_slack.
inline constexpr double drift_factor = 1.10;  // 10%: errors are deterministic for one build and thread-count
                                              // independent; compilers and flags move them by round-off
inline constexpr double drift_slack = 1e-12;  // errors at round-off level (conservation) wander by more than 10%

std::filesystem::path baseline_dir();
// Drift checks of a sweep against the stored baseline of its case and variant (none if absent).
std::vector<Check> drift_checks(const Sweep& s);
// Writes reference/baselines/<case>.json from sweeps of every variant.
void write_baseline(const Case& c, const std::vector<Sweep>& sweeps);

}  // namespace sphv
