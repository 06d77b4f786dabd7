#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "verification/case.hpp"

namespace sphv {

// How the points of a sweep are run.
struct RunOptions {
  int jobs = 1;                    // points at once; > 1 runs each as a `sphv run` subprocess
  std::filesystem::path exe;       // the sphv binary for subprocesses (empty: in-process only)
  int threads_per_job = 0;         // OpenMP threads of a subprocess point (0: cores / jobs)
  bool force = false;              // rerun points that already have a matching result
  bool progress = false;           // progress line on stderr
  std::function<void(const Result&)> on_run;
};

// One run of a sweep: the settings of its variant, its level n, and where its result goes
// (dir/result.json; empty dir: kept in memory only).
struct Point {
  std::vector<std::string> settings;
  long n;
  std::filesystem::path dir;
};

// Runs the points and returns their results in order. A point whose dir already holds a
// result with the same parameters and code version is reused unless force is set. Each
// finished point's result is written at once (atomically), so a killed sweep loses at most
// the points in flight. Under mpirun the points are spread over the ranks and rank 0 returns
// all results; the other ranks return an empty list.
std::vector<Result> run_points(const Case& c, const std::vector<Point>& points, const RunOptions& opt);

}  // namespace sphv
