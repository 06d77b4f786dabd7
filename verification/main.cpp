// sphv: the command line of the verification harness (list, info, run, sweep, verify).
#include <omp.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>
#include <unistd.h>

#include "verification/case.hpp"
#include "verification/baseline.hpp"
#include "verification/bench.hpp"
#include "verification/gravity_command.hpp"
#include "verification/mpi.hpp"
#include "verification/sweep.hpp"

namespace fs = std::filesystem;
using namespace sphv;

namespace {

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

void list_cases() {
  for (const auto& c : catalogue())
    std::printf("%-14s %-55s [%s]\n%14s n = %s\n", c.name.c_str(), c.summary.c_str(),
                join(c.tags, ",").c_str(), "", c.n_counts.c_str());
}

void info(const Case& c) {
  std::printf("%s: %s\ntags: %s\nn counts: %s\n\nparameters (sphv run %s --set key=value):\n",
              c.name.c_str(), c.summary.c_str(), join(c.tags, ",").c_str(), c.n_counts.c_str(),
              c.name.c_str());
  for (const auto& p : c.params) {
    std::string help = p.help;
    if (!p.choices.empty()) help += " (" + join(p.choices, "|") + ")";
    std::printf("  %-12s %-12s %s\n", p.name.c_str(), p.default_value.c_str(), help.c_str());
  }
  std::string lv, gl;
  for (long n : c.levels) lv += (lv.empty() ? "" : ",") + std::to_string(n);
  for (long n : c.gate_levels) gl += (gl.empty() ? "" : ",") + std::to_string(n);
  std::printf("\ndefault sweep levels: %s\ngate levels (ctest): %s\nexpected orders (defaults):", lv.c_str(),
              gl.c_str());
  if (c.expected_order)
    for (const auto& [k, v] : c.expected_order(c.parse({}))) std::printf(" %s=%g", k.c_str(), v);
  std::printf("\n  %s\n", c.expected_why.c_str());
}

std::string summary_line(const Result& r) {
  std::string s = r.case_name + " n=" + std::to_string(r.params.value("n", 0L)) + ": " +
                  std::to_string(r.n_particles) + " particles, " + std::to_string(r.wall_time_s) + " s";
  for (const auto& [k, v] : r.errors) {
    char buf[64];
    std::snprintf(buf, sizeof buf, ", %s=%.3e", k.c_str(), v);
    s += buf;
  }
  return s + ", verdict: " + r.verdict;
}

// The error a summary shows first: the first one with an expected order, else the first.
std::string headline_error(const Sweep& s) {
  if (!s.expected_order.empty()) return s.expected_order.begin()->first;
  return s.runs.empty() || s.runs.back().errors.empty() ? "" : s.runs.back().errors.begin()->first;
}

void print_sweep_row(const Case& c, const Sweep& s) {
  const std::string e = headline_error(s);
  const double fine = s.runs.back().errors.count(e) ? s.runs.back().errors.at(e) : NAN;
  const double obs = s.observed_order.count(e) ? s.observed_order.at(e) : NAN;
  const double exp = s.expected_order.count(e) ? s.expected_order.at(e) : NAN;
  std::string verdict = s.passed() ? "pass" : "FAIL";
  for (const auto& ch : s.checks)
    if (!ch.pass()) verdict += " [" + ch.name + "=" + std::to_string(ch.value) + "]";
  for (const auto& r : s.runs)
    if (r.verdict != "ok" && r.verdict.rfind("stable", 0) != 0) verdict += " (n=" + r.params["n"].dump() + ": " + r.verdict + ")";
  std::printf("%-14s %-24s %-12s %-11.3e %8.2f %9.2f %8.2f  %s\n", c.name.c_str(), s.variant().c_str(), e.c_str(),
              fine, obs, exp, s.wall_time_s, verdict.c_str());
  std::fflush(stdout);
}

std::vector<const Case*> gated(const std::vector<std::string>& only) {
  for (const auto& name : only) find_case(name);  // unknown names are refused
  std::vector<const Case*> out;
  for (const auto& c : catalogue())
    if (c.has_tag("gate") && (only.empty() || std::find(only.begin(), only.end(), c.name) != only.end()))
      out.push_back(&c);
  return out;
}

int verify(const fs::path& out, const std::vector<std::string>& only, const RunOptions& opt) {
  const auto cases = gated(only);
  if (mpi::rank() == 0)
    std::printf("%-14s %-24s %-12s %-11s %8s %9s  %s\n", "case", "variant", "error", "finest", "observed",
                "expected", "wall s   verdict");
  int failed = 0;
  nlohmann::json summary = nlohmann::json::array();
  for (const Case* c : cases) {
    for (const Sweep& s : run_sweeps(*c, c->levels, c->variants, out / c->name, opt)) {
      print_sweep_row(*c, s);
      failed += !s.passed();
      summary.push_back({{"case", c->name}, {"variant", s.variant()}, {"passed", s.passed()},
                         {"wall_time_s", s.wall_time_s}});
    }
  }
  if (mpi::rank() != 0) return 0;
  write_atomically(out / "summary.json", summary.dump(1) + "\n");
  std::printf("%s: %d failing gate sweep(s)\n", failed ? "FAIL" : "PASS", failed);
  return failed ? 1 : 0;
}

// Rewrites the drift baselines from the gate-level sweeps of every gated case (on purpose only).
int baseline_update(const std::vector<std::string>& only, const RunOptions& opt) {
  for (const Case* c : gated(only)) {
    std::vector<Sweep> sweeps;
    for (const auto& v : c->variants) sweeps.push_back(run_sweep(*c, c->sweep_levels(v, true), v, std::nullopt, opt));
    write_baseline(*c, sweeps);
    std::printf("baseline %s: %zu variant(s) -> %s\n", c->name.c_str(), sweeps.size(),
                (baseline_dir() / (c->name + ".json")).string().c_str());
  }
  return 0;
}

// Prints "sphv: error: <what>" as one line: control characters from the user's input (a newline
// inside a --set value, say) are shown escaped.
void error_line(const std::string& what) {
  std::string line;
  for (unsigned char ch : what) {
    if (ch >= 0x20 && ch != 0x7f) {
      line += static_cast<char>(ch);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      line += buf;
    }
  }
  std::fprintf(stderr, "sphv: error: %s\n", line.c_str());
}

}  // namespace

int run_main(int argc, char** argv) {
  CLI::App app{"sphv: verification and convergence harness for a reference SPH implementation", "sphv"};
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);

  auto* list = app.add_subcommand("list", "every case, what its n counts, and its tags");
  auto* info_cmd = app.add_subcommand("info", "a case's parameters with defaults, levels and expected orders");
  std::string case_name;
  info_cmd->add_option("case", case_name, "case name")->required();

  std::vector<std::string> settings, vary, only;
  fs::path out;
  RunOptions opt;
  auto* run = app.add_subcommand("run", "run one case: writes DIR/result.json (and particles.csv)");
  run->add_option("case", case_name, "case name (see 'sphv list'; parameters: 'sphv info CASE')")->required();
  run->add_option("--set", settings, "parameter as key=value (repeatable)")->take_all();
  run->add_option("--out", out, "output directory (default runs/CASE)");

  std::vector<long> levels;
  std::string levels_arg;  // parsed strictly by parse_levels ("" and "16,,32" are refused)
  auto* sweep = app.add_subcommand("sweep", "run a case at several resolutions (and variants): DIR/sweep.json");
  sweep->add_option("case", case_name, "case name")->required();
  auto* levels_opt = sweep->add_option("--levels", levels_arg, "values of n, e.g. 16,32,64 (default: the case's)");
  sweep->add_option("--set", settings, "parameter as key=value (repeatable)")->take_all();
  sweep->add_option("--vary", vary, "variants as key=a,b,c (repeatable: the product); DIR/<variant>/sweep.json")->take_all();
  sweep->add_option("--out", out, "output directory (default runs/CASE-sweep)");
  opt.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  sweep->add_option("--jobs", opt.jobs, "points run at once as subprocesses (default: cores)")->check(CLI::PositiveNumber);
  sweep->add_flag("--force", opt.force, "rerun points that already have a result of this code version");

  auto* verify_cmd = app.add_subcommand("verify", "the default catalogue: sweeps, gates, summary table");
  verify_cmd->add_option("--out", out, "output directory (default runs/verify)");
  verify_cmd->add_option("--cases", only, "only these cases")->delimiter(',');
  verify_cmd->add_flag("--force", opt.force, "rerun points that already have a result of this code version");

  auto* baseline = app.add_subcommand("baseline", "drift baselines (own earlier output, not verification)");
  auto* baseline_up = baseline->add_subcommand("update", "rewrite reference/baselines/ from gate-level sweeps");
  baseline->require_subcommand(1);
  baseline_up->add_option("--cases", only, "only these cases")->delimiter(',');
  add_gravity_command(app);
  add_bench_command(app);

  const bool root = mpi::rank() == 0;
  if (argc <= 1) {  // a bare `sphv` asks what it can do: the help, exit 0
    if (root) std::cout << app.help();
    return 0;
  }
  // One set of handlers for the parse (bench and gravity run inside it, as callbacks) and for
  // the commands after it: every error ends as one line and a non-zero exit.
  try {
    app.parse(argc, argv);
    if (threads > 0) omp_set_num_threads(threads);
    opt.exe = fs::canonical("/proc/self/exe");
    opt.progress = true;
    if (*list) list_cases();
    if (*info_cmd) info(find_case(case_name));
    if (*run) {
      const Case& c = find_case(case_name);
      const Params p = c.parse(settings);
      const Result r = run_case(c, p);
      write_result(r, out.empty() ? fs::path("runs") / c.name : out);
      std::printf("%s\n", summary_line(r).c_str());
    }
    if (*sweep) {
      const Case& c = find_case(case_name);
      if (levels_opt->count() > 0) levels = parse_levels(levels_arg);
      if (!levels.empty()) c.parse({"n=" + std::to_string(*std::min_element(levels.begin(), levels.end()))});
      if (mpi::size() > 1) opt.jobs = 1;
      const auto sweeps = run_sweeps(c, levels.empty() ? c.levels : levels, expand_variants(settings, vary),
                                     out.empty() ? fs::path("runs") / (c.name + "-sweep") : out, opt);
      for (const Sweep& s : sweeps) {
        for (const auto& r : s.runs) std::printf("%s\n", summary_line(r).c_str());
        for (const auto& [k, v] : s.observed_order)
          std::printf("observed order %-10s %6.2f  (expected %s)\n", k.c_str(), v,
                      s.expected_order.count(k) ? std::to_string(s.expected_order.at(k)).c_str() : "-");
        for (const auto& ch : s.checks)
          std::printf("gate %-28s %-10.4g in [%g, %g]: %s\n", ch.name.c_str(), ch.value, ch.lo, ch.hi,
                      ch.pass() ? "pass" : "FAIL");
      }
    }
    if (*verify_cmd) {
      opt.jobs = 1;  // each point uses every core through OpenMP
      opt.progress = false;
      return verify(out.empty() ? fs::path("runs/verify") : out, only, opt);
    }
    if (*baseline_up) return root ? baseline_update(only, {}) : 0;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (root) error_line(e.what());
    return 2;
  } catch (const InputError& e) {
    if (root) error_line(e.what());
    return 2;
  } catch (const std::exception& e) {  // e.g. an output path that cannot be written
    if (root) error_line(e.what());
    return 3;
  }
  return 0;
}

int main(int argc, char** argv) {
  sphv::mpi::init(&argc, &argv);
  const int status = run_main(argc, argv);
  sphv::mpi::finalize();
  return status;
}
