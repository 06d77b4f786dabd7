#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "verification/harness/case.hpp"

namespace sphv {

// How the points of a sweep (or of the whole catalogue) are run.
struct RunOptions {
  int jobs = 1;                    // cores to fill; > 1 (or isolate) runs each point as a `sphv run` subprocess
  bool isolate = false;            // a subprocess per point even with jobs = 1 (crashes become verdicts)
  std::filesystem::path exe;       // the sphv binary for subprocesses (empty: in-process only)
  int threads_per_job = 0;         // OpenMP threads of a subprocess point (0: from its cost, see run_points)
  double timeout_s = 0.0;          // a subprocess point still running after this is killed (0: no limit)
  std::filesystem::path cost_table;  // measured costs for scheduling (empty: default_cost_table())
  bool force = false;              // rerun points that already have a matching result
  bool progress = false;           // progress lines on stderr (a terminal only)
  bool announce = false;           // print the estimated time before starting, terminal or not
  std::function<void(const Result&)> on_run;
};

// One run of a sweep: the settings of its variant, its level n, and where its result goes
// (dir/result.json; empty dir: kept in memory only).
struct Point {
  std::vector<std::string> settings;
  long n;
  std::filesystem::path dir;
};

// A point of some case, in a pool that may mix cases; `group` names what progress reports
// as finished (a case in the catalogue, a point in a sweep).
struct Task {
  const Case* c;
  Point pt;
  std::string group;
};

// Runs the points and returns their results in order. A point whose dir already holds a
// result with the same parameters and code version is reused unless force is set (a point the
// harness itself ended, crashed or timed out, is run again). Each finished point's result is
// written at once (atomically), so a killed sweep loses at most the points in flight.
// Subprocess points start longest first (CostModel); a point whose cost exceeds half a core's
// fair share of the total gets every core, the others one thread each, side by side. A crash, an
// out-of-memory kill or a run past timeout_s becomes that point's verdict and the rest go on.
// Under mpirun the points are spread over the ranks (run in-process there) and rank 0 returns
// all results; the other ranks return an empty list.
std::vector<Result> run_points(const std::vector<Task>& tasks, const RunOptions& opt);
std::vector<Result> run_points(const Case& c, const std::vector<Point>& points, const RunOptions& opt);

// The verdict prefixes the harness gives a point it ended itself (never reused).
bool harness_verdict(const std::string& verdict);

}  // namespace sphv
