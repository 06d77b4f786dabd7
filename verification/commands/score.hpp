#pragma once
// `sphv score CASE --snapshot FILE`: a snapshot written by any SPH code scored against the case's
// exact reference, with the same error names and definitions as the case's own runs.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "verification/harness/case.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

// The scorer a case declares (Case::scorer), or an InputError listing the cases that have one.
const Scorer& find_scorer(const std::string& case_name);

// Scores a snapshot. What the file states is used unless set: the time (the case's time
// parameter), the dimension, gamma, the box (the radial cases' centre: its middle; the tubes'
// domain, and ends from its periodicity) and the resolution n. A setting that contradicts the
// file is refused unless force; so is a time with neither, a centre with fewer components than
// the dimension, and p, rho, u that do not satisfy p = (gamma - 1) rho u with the gamma in use.
// Result as `sphv run`'s, with extra.snapshot (format, columns, and each value with where it
// came from: the file, --set or a default) and the scoring time.
Result score_snapshot(const Case& c, std::vector<std::string> settings, const Snapshot& s, bool force = false);
// A series scorer's snapshots, each completed from its own file as score_snapshot does (they must
// agree on every value taken from them); extra.snapshots lists each file's time and values. A
// case without a series scorer is refused for more than one snapshot.
Result score_snapshots(const Case& c, const std::vector<std::string>& settings, const std::vector<Snapshot>& s,
                       bool force = false);

// result.json of scored snapshots: the run's keys, provenance.snapshot = path, size, SHA-256 (of
// each file, a list, provenance.snapshots, for several).
void write_score(const Result& r, const std::vector<Snapshot>& s, const std::filesystem::path& dir);

struct ScoreOptions {
  std::string case_name, format = "auto";
  std::vector<std::filesystem::path> snapshots;  // one, or a time series (kh)
  std::filesystem::path out;
  std::vector<std::string> settings;
  long step = -1;  // H5Part step (-1: the last)
  bool force = false;  // settings may contradict the file
};
// Scores and writes the result; returns the exit status: 0 for verdict "ok", 1 otherwise.
int score_command(const ScoreOptions& o);

}  // namespace sphv
