#pragma once
// `sphv score CASE --snapshot FILE`: a snapshot written by any SPH code scored against the case's
// exact reference, with the same error names and definitions as the case's own runs.
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "verification/case.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

// How one case scores a snapshot.
struct Scorer {
  std::string time_key;                          // the case's time parameter ("" = none)
  std::function<Result(const Params&, const Snapshot&)> score;
  std::function<double(const Params&)> t_end;     // the time a run of these parameters ends at (may be empty)
  bool n_per_side = false;  // n (unless set) from the particle count: N^(1/dim) particles per side
};

// The scorer of a case, or an InputError listing the cases that have one.
const Scorer& find_scorer(const std::string& case_name);
bool has_scorer(const std::string& case_name);
const std::map<std::string, Scorer>& scorers();  // defined in score_cases.cpp

// Scores a snapshot: the time comes from the settings (the case's time parameter) or the
// snapshot's header (one clear error when both exist and differ, or when neither does); a case
// with a parameter `dim` takes it from the snapshot unless set. Result as `sphv run`'s, with
// extra.snapshot (format, time, which column was taken for what) and the scoring time.
Result score_snapshot(const Case& c, std::vector<std::string> settings, const Snapshot& s);

// result.json of a scored snapshot: the run's keys, provenance.snapshot = path, size, SHA-256.
void write_score(const Result& r, const Snapshot& s, const std::filesystem::path& dir);

struct ScoreOptions {
  std::string case_name, format = "auto";
  std::filesystem::path snapshot, out;
  std::vector<std::string> settings;
  long step = -1;  // H5Part step (-1: the last)
};
void score_command(const ScoreOptions& o);

}  // namespace sphv
