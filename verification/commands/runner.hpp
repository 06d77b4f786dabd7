#pragma once
// `sphv sweep CASE --runner 'COMMAND'`: an external code driven through a convergence sweep.
#include <filesystem>
#include <string>
#include <vector>

#include "verification/harness/sweep.hpp"

namespace sphv {

// Runs COMMAND (through /bin/sh) once per level with the placeholders {n}, {ic} (initial
// conditions sphv writes as `sphv ic` does, in ic_format: csv, swift or h5part), {out} (the snapshot path sphv then scores, any format
// read_snapshot reads), {t_end} and {threads} replaced; measures the command's wall time, scores
// {out} and writes out/n<level>/result.json (wall_time_s: the command's) and out/sweep.json.
// A failing command, a missing or bad snapshot, a snapshot of another problem ("mismatch")
// becomes that level's verdict. The sweep is gated by the case's order claims (claims of the
// physics: no bound measured on sphv's method applies, nor a drift baseline) and the verdicts.
// With {ic} in SWIFT's format the settings take SWIFT's gamma (swift_gamma, ic.hpp).
Sweep runner_sweep(const Case& c, const std::vector<long>& levels, std::vector<std::string> settings,
                   const std::filesystem::path& out, const std::string& command, const std::string& ic_format = "csv");

}  // namespace sphv
