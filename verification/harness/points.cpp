#include "verification/harness/points.hpp"

#include <spawn.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string_view>
#include <thread>

#include "build_info.hpp"
#include "sph/core/isa.hpp"
#include "verification/support/build_id.hpp"
#include "verification/harness/cost.hpp"
#include "verification/support/mpi.hpp"
#include "verification/support/reference_cache.hpp"

extern char** environ;

namespace sphv {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The point's result when one exists that this exact build produced with these parameters:
// same executable bytes (SHA-256 of `exe`, the binary that runs the points), build flags and
// instruction-set path (sph/core/isa.hpp: SPHV_ISA or another CPU changes the round-off).
// A commit alone does not say what ran: an uncommitted edit or another flag rebuilds the binary.
std::optional<Result> finished(const Point& pt, const Params& p, const std::string& exe_sha256) {
  const auto file = pt.dir / "result.json";
  if (pt.dir.empty() || !std::filesystem::exists(file)) return std::nullopt;
  try {
    std::ifstream f(file);
    const auto j = nlohmann::json::parse(f);
    const auto& prov = j.at("provenance");
    if (j.at("params") != p.to_json() || prov.at("executable_sha256") != exe_sha256 ||
        prov.at("cxx_flags") != build::cxx_flags || prov.value("isa_path", "") != sph::isa_name(sph::isa_path()))
      return std::nullopt;
    return result_from_json(j);
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable or partial: run it again
  }
}

// A point as a child process `sphv run`, so a crash ends as that point's verdict. Its environment
// names the folder where the points of its sweep share their references (support/reference_cache.hpp):
// beside the levels' folders, one per build (exe_sha256), as another build may compute them otherwise.
pid_t spawn(const RunOptions& opt, const Task& t, int threads, const std::string& exe_sha256) {
  std::vector<std::string> args = {opt.exe.string(), "--threads", std::to_string(threads), "run", t.c->name,
                                   "--out", t.pt.dir.string(), "--set", "n=" + std::to_string(t.pt.n)};
  for (const auto& s : t.pt.settings) args.push_back(s);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::filesystem::create_directories(t.pt.dir);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  const std::string log = (t.pt.dir / "log.txt").string();
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e)
    if (std::string_view(*e).rfind(std::string(reference_cache_variable) + "=", 0) != 0) env.emplace_back(*e);
  env.push_back(std::string(reference_cache_variable) + "=" +
                (t.pt.dir.parent_path() / ".references" / exe_sha256.substr(0, 16)).string());
  std::vector<char*> envp;
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = -1;
  const int err = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  if (err != 0) throw std::runtime_error("cannot start " + opt.exe.string());
  return pid;
}

Result crashed(const Case& c, const Params& p, const std::string& why, double wall) {
  Result r;
  r.case_name = c.name;
  r.params = p.to_json();
  r.verdict = why;
  r.wall_time_s = wall;
  return r;
}

std::string duration_text(double s) {
  char buf[48];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.0f min %02.0f s", std::floor(s / 60), std::fmod(s, 60));
  else std::snprintf(buf, sizeof buf, "%.0f h %02.0f min", std::floor(s / 3600), std::fmod(s, 3600) / 60);
  return buf;
}

// On a terminal: the estimate before the start, then one line per finished group (a case of the
// catalogue, a point of a sweep) with its points' wall time and the time left: the cost model's
// remaining core-seconds over the cores, rescaled by how the finished points compared with it.
class Progress {
 public:
  Progress(bool on, bool announce, const std::vector<Task>& tasks, const std::vector<std::size_t>& todo,
           const std::vector<double>& cost, int cores)
      : on_(on && isatty(2)), tasks_(tasks), cost_(cost), cores_(cores), t0_(Clock::now()) {
    for (std::size_t k : todo) ++left_[tasks[k].group], remaining_ += cost[k];
    groups_ = left_.size();
    if ((on_ || (on && announce)) && !todo.empty())
      std::fprintf(stderr, "sphv: %zu point(s) to run, estimated %s on %d core(s)\n", todo.size(),
                   duration_text(remaining_ / cores_).c_str(), cores_);
  }
  void done(std::size_t k, double wall) {
    remaining_ -= cost_[k], spent_ += cost_[k];
    const std::string& g = tasks_[k].group;
    wall_[g] += wall;
    if (--left_[g] > 0 || !on_) return;
    ++finished_;
    const double elapsed = since(t0_);
    const double scale = spent_ > 0.0 && elapsed > 5.0 ? std::clamp(elapsed * cores_ / spent_, 0.25, 4.0) : 1.0;
    std::fprintf(stderr, "[%zu/%zu] %s: %s; %s left\n", finished_, groups_, g.c_str(), duration_text(wall_[g]).c_str(),
                 duration_text(std::max(0.0, remaining_) * scale / cores_).c_str());
  }

 private:
  bool on_;
  const std::vector<Task>& tasks_;
  const std::vector<double>& cost_;
  int cores_;
  Clock::time_point t0_;
  std::map<std::string, std::size_t> left_;
  std::map<std::string, double> wall_;
  std::size_t groups_ = 0, finished_ = 0;
  double remaining_ = 0.0, spent_ = 0.0;
};

}  // namespace

bool harness_verdict(const std::string& v) {
  return v.rfind("crashed:", 0) == 0 || v.rfind("timeout", 0) == 0 || v.rfind("failed: exit status", 0) == 0;
}

std::vector<Result> run_points(const std::vector<Task>& tasks, const RunOptions& opt) {
  std::vector<Params> params;  // every point is validated before the first one runs
  for (const auto& t : tasks) {
    auto s = t.pt.settings;
    s.push_back("n=" + std::to_string(t.pt.n));
    params.push_back(t.c->parse(s));
  }
  std::vector<std::optional<Result>> out(tasks.size());
  std::vector<std::size_t> todo;
  const bool subprocesses = (opt.jobs > 1 || opt.isolate) && !opt.exe.empty() && mpi::size() == 1;
  const std::string exe_sha256 = subprocesses ? sha256_of_file(opt.exe) : executable_sha256();
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    if (!opt.force) out[k] = finished(tasks[k].pt, params[k], exe_sha256);
    if (out[k] && harness_verdict(out[k]->verdict)) out[k].reset();  // a crash or timeout is run again
    if (!out[k]) todo.push_back(k);
  }
  // Longest first. Every rank computes the same order from the same files (none writes before the barrier).
  const CostModel model(opt.cost_table.empty() ? default_cost_table() : opt.cost_table);
  std::vector<double> cost(tasks.size(), 0.0);
  double total = 0.0;
  for (std::size_t k : todo)
    total += cost[k] = model.estimate(*tasks[k].c, tasks[k].pt.settings, tasks[k].pt.n, params[k], tasks[k].pt.dir);
  std::stable_sort(todo.begin(), todo.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  // Under mpirun each rank takes every size-th remaining point. Every rank must see the same
  // finished points: none may start writing results before all have looked (a rank that started
  // late once saw another's fresh results, split the points differently and left some unrun).
  mpi::barrier();
  const int rank = mpi::rank(), ranks = mpi::size();
  if (rank == 0 && todo.size() < tasks.size())
    std::fprintf(stderr, "sphv: reusing %zu finished point(s) of %zu (--force reruns them)\n",
                 tasks.size() - todo.size(), tasks.size());
  std::vector<std::size_t> mine;
  for (std::size_t q = 0; q < todo.size(); ++q)
    if (static_cast<int>(q % ranks) == rank) mine.push_back(todo[q]);

  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  Progress progress(opt.progress && rank == 0, opt.announce && rank == 0, tasks, mine, cost,
                    cores);
  auto finish = [&](std::size_t k, Result r) {
    if (!tasks[k].pt.dir.empty()) write_result(r, tasks[k].pt.dir);
    if (opt.on_run) opt.on_run(r);
    progress.done(k, r.wall_time_s);
    out[k] = std::move(r);
  };

  if (subprocesses) {
    // Threads: a point costing more than half a core's fair share of the whole gets every core
    // (it would otherwise finish last, alone); the others share the cores one thread each.
    auto threads_of = [&](std::size_t k) {
      if (opt.threads_per_job > 0) return opt.threads_per_job;
      return cost[k] > 0.5 * total / cores ? cores : std::max(1, cores / opt.jobs);
    };
    struct Running {
      std::size_t k;
      int slots;
      Clock::time_point start;
      bool killed;
    };
    std::map<pid_t, Running> running;
    int free = opt.jobs;
    std::size_t next = 0;
    while (next < mine.size() || !running.empty()) {
      while (next < mine.size()) {  // in order: a threaded point waits for its cores
        const std::size_t k = mine[next];
        const int threads = threads_of(k), slots = std::min(threads, opt.jobs);
        if (slots > free) break;
        running[spawn(opt, tasks[k], threads, exe_sha256)] = {k, slots, Clock::now(), false};
        free -= slots, ++next;
      }
      int status = 0;
      const pid_t pid = waitpid(-1, &status, WNOHANG);
      if (pid == 0) {
        for (auto& [p, r] : running)
          if (opt.timeout_s > 0.0 && !r.killed && since(r.start) > opt.timeout_s) kill(p, SIGKILL), r.killed = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        continue;
      }
      if (pid < 0 && errno == EINTR) continue;
      if (pid < 0) throw std::runtime_error(std::string("waiting for points: ") + std::strerror(errno));
      if (!running.count(pid)) continue;
      const Running r = running.at(pid);
      running.erase(pid);
      free += r.slots;
      const std::size_t k = r.k;
      const double wall = since(r.start);
      // `sphv run` exits 1 after writing a result whose verdict the case does not expect.
      std::optional<Result> res;
      if (!r.killed && WIFEXITED(status) && WEXITSTATUS(status) <= 1) res = finished(tasks[k].pt, params[k], exe_sha256);
      if (res) {
        if (opt.on_run) opt.on_run(*res);
        progress.done(k, res->wall_time_s);
        out[k] = std::move(res);
        continue;
      }
      char why[160];
      if (r.killed) std::snprintf(why, sizeof why, "timeout after %g s", opt.timeout_s);
      else if (WIFSIGNALED(status))
        std::snprintf(why, sizeof why, "crashed: signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
      else
        std::snprintf(why, sizeof why, "failed: exit status %d (see %s)", WEXITSTATUS(status),
                      (tasks[k].pt.dir / "log.txt").c_str());
      finish(k, crashed(*tasks[k].c, params[k], why, wall));
    }
  } else {
    for (std::size_t k : mine) finish(k, run_case(*tasks[k].c, params[k]));
  }

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

std::vector<Result> run_points(const Case& c, const std::vector<Point>& points, const RunOptions& opt) {
  std::vector<Task> tasks;
  for (const auto& pt : points) {
    std::string group = c.name + " n=" + std::to_string(pt.n);
    for (const auto& s : pt.settings) group += " " + s;
    tasks.push_back({&c, pt, group});
  }
  return run_points(tasks, opt);
}

}  // namespace sphv
