#include "verification/commands/runner.hpp"

#include <omp.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>

#include "verification/commands/ic.hpp"
#include "verification/commands/score.hpp"

namespace sphv {
namespace {

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t k = s.find(from); k != std::string::npos; k = s.find(from, k + to.size())) s.replace(k, from.size(), to);
  return s;
}

// A word for /bin/sh: single-quoted.
std::string quoted(const std::string& s) { return "'" + replace_all(s, "'", "'\\''") + "'"; }

Result failed(const Case& c, const Params& p, std::string why) {
  Result r;
  r.case_name = c.name;
  r.params = p.to_json();
  r.verdict = std::move(why);
  return r;
}

}  // namespace

Sweep runner_sweep(const Case& c, const std::vector<long>& levels, std::vector<std::string> settings,
                   const std::filesystem::path& out, const std::string& command, const std::string& ic_format) {
  const Scorer& sc = find_scorer(c.name);
  const bool wants_ic = command.find("{ic}") != std::string::npos;
  if (wants_ic && ic_format == "swift") {  // SWIFT runs the gamma it was built with: the state for it, said once
    SwiftGamma g = swift_gamma(c, std::move(settings));
    settings = std::move(g.settings);
    if (!g.note.empty()) std::printf("%s\n", g.note.c_str());
  }
  std::vector<Params> params;  // every level is validated before the first command runs
  for (long n : levels) {
    auto s = settings;
    s.push_back("n=" + std::to_string(n));
    params.push_back(c.parse(s));
    if (wants_ic) find_ic(c.name);
  }
  std::vector<Result> runs;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const Params& p = params[k];
    const auto dir = out / ("n" + std::to_string(levels[k]));
    std::filesystem::create_directories(dir);
    const auto snapshot = dir / "snapshot", ic = dir / ("ic." + std::string(ic_format == "swift" ? "hdf5" : ic_format)), log = dir / "log.txt";
    std::filesystem::remove(snapshot);
    std::string cmd = command;
    if (wants_ic) write_ic(c, p, ic, ic_format);
    cmd = replace_all(cmd, "{n}", std::to_string(levels[k]));
    cmd = replace_all(cmd, "{ic}", quoted(ic.string()));
    cmd = replace_all(cmd, "{out}", quoted(snapshot.string()));
    cmd = replace_all(cmd, "{t_end}", sc.t_end ? shortest(sc.t_end(p)) : "");
    cmd = replace_all(cmd, "{threads}", std::to_string(omp_get_max_threads()));
    const auto t0 = std::chrono::steady_clock::now();
    const int status = std::system(("(" + cmd + ") > " + quoted(log.string()) + " 2>&1").c_str());
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Result r;
    std::optional<Snapshot> snap;
    if (status != 0) {
      r = failed(c, p, "failed: runner exit status " +
                           std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status) + " (see " + log.string() + ")");
    } else if (!std::filesystem::exists(snapshot)) {
      r = failed(c, p, "failed: the runner wrote no snapshot " + snapshot.string() + " (see " + log.string() + ")");
    } else {
      try {
        snap = read_snapshot(snapshot);
        auto s = settings;
        s.push_back("n=" + std::to_string(levels[k]));
        r = score_snapshot(c, s, *snap);
        r.extra["score_time_s"] = r.wall_time_s;
      } catch (const InputError& e) {
        r = failed(c, p, std::string("bad snapshot: ") + e.what());
        snap.reset();
      }
    }
    r.wall_time_s = wall;  // the external code's cost
    r.extra["runner_command"] = cmd;
    if (snap) write_score(r, {*snap}, dir);
    else write_result(r, dir);
    std::printf("n=%ld: %s (%.2f s)\n", levels[k], r.verdict.c_str(), wall);
    if (r.extra.contains("mismatch")) std::printf("  %s\n", r.extra["mismatch"].get<std::string>().c_str());
    std::fflush(stdout);
    runs.push_back(std::move(r));
  }
  Sweep s = summarise(c, settings, levels, std::move(runs));
  // Another code is gated by the claims of the physics: the observed orders and each level's
  // verdict (a snapshot of another problem reads "mismatch"). The bounds on an error's value and
  // the drift baselines were measured on sphv's own method and stay with it.
  std::erase_if(s.checks, [](const Check& ch) {
    const bool order = ch.name.starts_with("order_") || ch.name.starts_with("known_failure_order_") ||
                       ch.name.starts_with("window_");
    return ch.kind == Check::Kind::drift || (!ch.error.empty() && !order);
  });
  for (auto& [error, claim] : s.claims) claim.unbounded = true;
  s.rows = rows_of(s);
  nlohmann::json j = to_json(s);
  j["runner"] = command;
  write_atomically(out / "sweep.json", j.dump(1) + "\n");
  return s;
}

}  // namespace sphv
