#include "verification/points.hpp"

#include <spawn.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <thread>

#include "build_info.hpp"
#include "verification/build_id.hpp"
#include "verification/mpi.hpp"

extern char** environ;

namespace sphv {
namespace {

using Clock = std::chrono::steady_clock;

// The point's result when one exists that this exact build produced with these parameters:
// same executable bytes (SHA-256 of `exe`, the binary that runs the points) and build flags.
// A commit alone does not say what ran: an uncommitted edit or another flag rebuilds the binary.
std::optional<Result> finished(const Point& pt, const Params& p, const std::string& exe_sha256) {
  const auto file = pt.dir / "result.json";
  if (pt.dir.empty() || !std::filesystem::exists(file)) return std::nullopt;
  try {
    std::ifstream f(file);
    const auto j = nlohmann::json::parse(f);
    const auto& prov = j.at("provenance");
    if (j.at("params") != p.to_json() || prov.at("executable_sha256") != exe_sha256 ||
        prov.at("cxx_flags") != build::cxx_flags)
      return std::nullopt;
    return result_from_json(j);
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable or partial: run it again
  }
}

// A point as a child process `sphv run`, so a crash ends as that point's verdict.
pid_t spawn(const RunOptions& opt, const Case& c, const Point& pt, int threads) {
  std::vector<std::string> args = {opt.exe.string(), "--threads", std::to_string(threads), "run", c.name,
                                   "--out", pt.dir.string(), "--set", "n=" + std::to_string(pt.n)};
  for (const auto& s : pt.settings) args.push_back(s);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::filesystem::create_directories(pt.dir);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  const std::string log = (pt.dir / "log.txt").string();
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid = -1;
  const int err = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (err != 0) throw std::runtime_error("cannot start " + opt.exe.string());
  return pid;
}

Result crashed(const Case& c, const Params& p, const std::string& why) {
  Result r;
  r.case_name = c.name;
  r.params = p.to_json();
  r.verdict = why;
  return r;
}

class Progress {
 public:
  Progress(bool on, std::size_t total) : on_(on && isatty(2)), total_(total), t0_(Clock::now()) {}
  void show(std::size_t done, std::size_t running, std::size_t fresh) const {
    if (!on_) return;
    const double t = std::chrono::duration<double>(Clock::now() - t0_).count();
    const double left = fresh ? t / fresh * (total_ - done) / std::max<std::size_t>(1, running) : 0.0;
    std::fprintf(stderr, "\r%zu/%zu points done, %zu running, ~%.0f s left   ", done, total_, running, left);
    if (done == total_) std::fprintf(stderr, "\n");
  }

 private:
  bool on_;
  std::size_t total_;
  Clock::time_point t0_;
};

}  // namespace

std::vector<Result> run_points(const Case& c, const std::vector<Point>& points, const RunOptions& opt) {
  std::vector<Params> params;  // every point is validated before the first one runs
  for (const auto& pt : points) {
    auto s = pt.settings;
    s.push_back("n=" + std::to_string(pt.n));
    params.push_back(c.parse(s));
  }
  std::vector<std::optional<Result>> out(points.size());
  std::vector<std::size_t> todo;
  const bool subprocesses = opt.jobs > 1 && !opt.exe.empty() && mpi::size() == 1;
  const std::string exe_sha256 = subprocesses ? sha256_of_file(opt.exe) : executable_sha256();
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (!opt.force) out[k] = finished(points[k], params[k], exe_sha256);
    if (!out[k]) todo.push_back(k);
  }
  // Under mpirun each rank takes every size-th remaining point. Every rank must see the same
  // finished points: none may start writing results before all have looked (a rank that started
  // late once saw another's fresh results, split the points differently and left some unrun).
  mpi::barrier();
  const int rank = mpi::rank(), ranks = mpi::size();
  if (rank == 0 && todo.size() < points.size())
    std::fprintf(stderr, "sphv: reusing %zu finished point(s) of %zu (--force reruns them)\n",
                 points.size() - todo.size(), points.size());
  std::vector<std::size_t> mine;
  for (std::size_t q = 0; q < todo.size(); ++q)
    if (static_cast<int>(q % ranks) == rank) mine.push_back(todo[q]);

  Progress progress(opt.progress && rank == 0, points.size());
  std::size_t done = points.size() - todo.size(), fresh = 0;
  auto finish = [&](std::size_t k, Result r) {
    if (!points[k].dir.empty()) write_result(r, points[k].dir);
    if (opt.on_run) opt.on_run(r);
    out[k] = std::move(r);
    ++done, ++fresh;
  };

  if (subprocesses) {
    const int threads = opt.threads_per_job > 0 ? opt.threads_per_job
                                                : std::max(1u, std::thread::hardware_concurrency() / opt.jobs);
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0;
    while (next < mine.size() || !running.empty()) {
      while (next < mine.size() && static_cast<int>(running.size()) < opt.jobs) {
        running[spawn(opt, c, points[mine[next]], threads)] = mine[next];
        ++next;
      }
      progress.show(done, running.size(), fresh);
      int status = 0;
      const pid_t pid = waitpid(-1, &status, 0);
      if (pid < 0 || !running.count(pid)) continue;
      const std::size_t k = running.at(pid);
      running.erase(pid);
      std::optional<Result> r;
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0) r = finished(points[k], params[k], exe_sha256);
      if (!r) {
        r = crashed(c, params[k], WIFSIGNALED(status)
                                      ? "crashed: signal " + std::to_string(WTERMSIG(status))
                                      : "failed: exit status " + std::to_string(WEXITSTATUS(status)) +
                                            " (see " + (points[k].dir / "log.txt").string() + ")");
        write_result(*r, points[k].dir);
      }
      if (opt.on_run) opt.on_run(*r);
      out[k] = std::move(r);
      ++done, ++fresh;
    }
  } else {
    for (std::size_t k : mine) {
      progress.show(done, 1, fresh);
      finish(k, run_case(c, params[k]));
    }
  }
  progress.show(points.size(), 0, fresh);

  if (ranks > 1) {
    nlohmann::json part = nlohmann::json::array();
    for (std::size_t k : mine) part.push_back({{"k", k}, {"result", to_json(*out[k])}});
    const auto parts = mpi::gather(part.dump());
    if (rank != 0) return {};
    for (const auto& text : parts)
      for (const auto& e : nlohmann::json::parse(text)) out[e.at("k").get<std::size_t>()] = result_from_json(e.at("result"));
  }
  std::vector<Result> results;
  for (auto& r : out) results.push_back(std::move(*r));
  return results;
}

}  // namespace sphv
