// sphv: the command line of the verification harness (list, info, run, sweep, verify).
#include <omp.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <new>
#include <stdexcept>
#include <iostream>
#include <set>
#include <thread>
#include <unistd.h>

#include "sph/core/isa.hpp"
#include "verification/support/allocator.hpp"
#include "verification/harness/baseline.hpp"
#include "verification/commands/bench.hpp"
#include "verification/harness/case.hpp"
#include "verification/harness/cost.hpp"
#include "verification/commands/gravity_command.hpp"
#include "verification/commands/ic.hpp"
#include "verification/io/junit.hpp"
#include "verification/support/mpi.hpp"
#include "verification/harness/reason.hpp"
#include "verification/commands/runner.hpp"
#include "verification/commands/score.hpp"
#include "verification/snapshot/convert_command.hpp"
#include "verification/harness/sweep.hpp"

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

std::string levels_text(const std::vector<long>& levels) {
  std::string s;
  for (long n : levels) s += (s.empty() ? "" : ",") + std::to_string(n);
  return s;
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
  std::printf("\nlevels (default variant): quick %s; standard %s; full %s\n", levels_text(c.levels.quick).c_str(),
              levels_text(c.levels.standard).c_str(), levels_text(c.levels.full).c_str());
  std::printf("variants:");
  for (const auto& v : c.variants) std::printf(" [%s]", v.empty() ? "default" : join(v, " ").c_str());
  std::printf("\n\nerrors (defaults), their definitions and order claims:\n");
  const OrderClaims claims = c.orders ? c.orders(c.parse({})) : OrderClaims{};
  std::set<std::string> names;
  for (const auto& [k, v] : c.error_defs) names.insert(k);
  for (const auto& [k, v] : claims) names.insert(k);
  for (const auto& e : names) {
    const auto d = c.error_defs.find(e);
    std::printf("  %s: %s\n", e.c_str(), d == c.error_defs.end() ? "(no definition given)" : d->second.c_str());
    const auto o = claims.find(e);
    if (o == claims.end()) std::printf("      no order claim stated\n");
    else if (!o->second.claimed()) std::printf("      no order claimed: %s\n", describe_reason(o->second.why).c_str());
    else if (o->second.known_failure())
      std::printf("      known failure of order %.17g +- %g: %s; the variant [%s] converges\n", o->second.expected,
                  o->second.band, describe_reason(o->second.why).c_str(), o->second.experiment.c_str());
    else std::printf("      expected order %.17g +- %g: %s\n", o->second.expected, o->second.band, o->second.why.c_str());
  }
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

// Test-only hook (verification/tests/tiers_tests.cmake, scripts/test-faults.sh): with
// SPHV_TEST_FAULT=crash:CASE@N,hang:CASE@N (any of them; "@N" only at level n = N) `sphv run CASE`
// kills itself with SIGKILL or hangs, so a test can show the catalogue survives both. Nothing
// else sets this variable.
void test_fault(const Case& c, const Params& p) {
  const char* f = std::getenv("SPHV_TEST_FAULT");
  if (!f) return;
  const std::string faults = std::string(",") + f + ",";
  auto asked = [&](const std::string& what) {
    return faults.find("," + what + ":" + c.name + ",") != std::string::npos ||
           faults.find("," + what + ":" + c.name + "@" + std::to_string(p.integer("n")) + ",") != std::string::npos;
  };
  if (asked("crash")) std::raise(SIGKILL);
  if (asked("hang"))
    for (;;) pause();
}

// Exit status of a judged command: 0 when every gate passes and every verdict is expected, 1 otherwise.
int status_of(const std::vector<Sweep>& sweeps) {
  for (const Sweep& s : sweeps)
    if (!s.passed()) return 1;
  return 0;
}

std::string order_text(double p, double se) {
  if (!std::isfinite(p)) return "-";
  char buf[48];
  if (std::isfinite(se)) std::snprintf(buf, sizeof buf, "%.2f +- %.2f", p, se);
  else std::snprintf(buf, sizeof buf, "%.2f", p);
  return buf;
}

void print_rows_header() {
  std::printf("%-18s %-26s %-22s %-10s %-14s %-8s %s\n", "case", "variant", "error", "finest", "observed", "expected",
              "outcome");
}

// One line per error: its finest value, observed order +- standard error, expected order and
// outcome; then any failing check that no row names, and run verdicts.
void print_rows(const Sweep& s) {
  for (const auto& r : s.rows) {
    std::string outcome = r.outcome;
    if (r.outcome != "verified") outcome += ": " + r.why;
    std::printf("%-18s %-26s %-22s %-10.3e %-14s %-8s %s\n", s.case_name.c_str(), s.variant().c_str(), r.error.c_str(),
                r.fine_value, order_text(r.observed, r.se).c_str(), std::isfinite(r.expected) ? order_text(r.expected, NAN).c_str() : "-",
                outcome.c_str());
  }
  for (const auto& ch : s.checks)
    if (!ch.pass() && ch.error.empty())
      std::printf("%-18s %-26s %-22s FAIL %s = %.6g not in [%g, %g]: %s\n", s.case_name.c_str(), s.variant().c_str(),
                  "(sweep)", ch.name.c_str(), ch.value, ch.lo, ch.hi, ch.why.c_str());
  if (s.rows.empty() && s.passed())
    std::printf("%-18s %-26s %-22s verdicts and checks pass (%zu checks)\n", s.case_name.c_str(), s.variant().c_str(),
                "(no errors)", s.checks.size());
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

// Every point of every gated case and variant at the tier, as one pool (run_plans); then one
// row per error of each sweep, DIR/summary.json, DIR/costs.json and the JUnit XML.
int verify(const fs::path& out, const std::vector<std::string>& only, Tier tier, const RunOptions& opt,
           fs::path junit) {
  std::vector<SweepPlan> plans;
  for (const Case* c : gated(only))
    for (auto& p : plan_sweeps(*c, tier, {}, c->variants, out / c->name)) plans.push_back(std::move(p));
  std::vector<Sweep> all = run_plans(plans, opt);
  check_experiments(all);
  for (std::size_t k = 0; k < all.size(); ++k)  // the experiments' checks in each sweep's own file too
    write_atomically(plans[k].dir / "sweep.json", to_json(all[k]).dump(1) + "\n");
  if (mpi::rank() == 0) print_rows_header();
  nlohmann::json summary = nlohmann::json::array();
  for (const Sweep& s : all) {
    print_rows(s);
    const auto j = to_json(s);
    summary.push_back({{"case", s.case_name}, {"variant", s.variant()}, {"tier", s.tier}, {"passed", s.passed()},
                       {"wall_time_s", s.wall_time_s}, {"rows", j["rows"]}});
  }
  if (mpi::rank() != 0) return 0;
  write_atomically(out / "summary.json", summary.dump(1) + "\n");
  write_atomically(out / "costs.json", measured_costs(plans).dump(1) + "\n");
  write_atomically(junit.empty() ? out / "junit.xml" : junit, junit_xml(all));
  int verified = 0, known = 0, provisional = 0, no_claim = 0, fail = 0, failed_sweeps = 0;
  for (const Sweep& s : all) {
    failed_sweeps += !s.passed();
    for (const auto& r : s.rows)
      (r.outcome == "verified"        ? verified
       : r.outcome == "known failure" ? known
       : r.outcome == "provisional"   ? provisional
       : r.outcome == "fail"          ? fail
                                      : no_claim)++;
  }
  std::printf("%s: %d verified, %d known failures, %d provisional, %d no order claimed, %d fail; %d of %zu sweeps "
              "failing (tier %s)\n",
              failed_sweeps ? "FAIL" : "PASS", verified, known, provisional, no_claim, fail, failed_sweeps, all.size(),
              to_string(tier));
  return status_of(all);
}

// Rewrites the drift baselines from the quick-tier sweeps of every gated case (on purpose only).
int baseline_update(const std::vector<std::string>& only, const RunOptions& opt) {
  for (const Case* c : gated(only)) {
    std::vector<Sweep> sweeps;
    for (const auto& v : c->variants) sweeps.push_back(run_tier(*c, Tier::quick, v, std::nullopt, opt));
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

// A CLI11 check with a message that says what is wanted: CLI11's own range checks print their
// limits in full ("Value 0 not in range 0.000000 to 179769313486231570814527...").
CLI::Validator wanted(const CLI::Validator& check, const std::string& what, const std::string& name) {
  return CLI::Validator([check, what](std::string& v) { return check(v).empty() ? std::string() : "'" + v + "' is not " + what; },
                        name);
}
const CLI::Validator positive = wanted(CLI::PositiveNumber, "a whole number >= 1", "N>=1");
const CLI::Validator non_negative = wanted(CLI::NonNegativeNumber, "a whole number >= 0", "N>=0");

// The subcommands whose work lives in their own files (CLI11 is compiled here only: it costs
// about 6 s of compile time in every file that includes it).
void add_gravity_command(CLI::App& app) {
  auto o = std::make_shared<GravityCommandOptions>();
  auto* g = app.add_subcommand("gravity", "tree and direct-sum gravity of your particles (x,y,z,m; G = 1)");
  g->add_option("--input", o->input,
                "particles: CSV (header row; comma or blank separated; x,y,z,m or mass, pos_x, ...), or a SWIFT/GADGET "
                "or H5Part HDF5 snapshot")->required();
  g->add_option("--out", o->out, "output CSV (x,y,z,m, tree and direct accelerations and potentials)")->required();
  g->add_option("--theta", o->theta, "opening angle theta > 0 (default 0.5)");
  g->add_option("--multipole", o->multipole, "mono|quad (default quad)")->check(CLI::IsMember({"mono", "quad"}));
  g->add_option("--opening", o->opening, "robust|plain (default robust)")->check(CLI::IsMember({"robust", "plain"}));
  g->add_option("--softening", o->eps, "Plummer softening length eps >= 0 (default 0: coincident particles are refused)");
  g->add_flag("--no-direct", o->no_direct, "skip the O(N^2) direct sum (large N): tree field only, no error percentiles");
  // Runs inside app.parse(); its errors reach main's handlers as they are: bad input exits 2, an
  // output it cannot write 3.
  g->callback([o] { gravity_command(*o); });
}

// status: set to score_command's exit status (1: a verdict other than "ok").
void add_score_command(CLI::App& app, int& status) {
  auto o = std::make_shared<ScoreOptions>();
  auto* cmd = app.add_subcommand("score", "score a snapshot of any SPH code against a case's exact reference");
  cmd->add_option("case", o->case_name, "case name (sod, sod2d, sod3d, sedov, noh, evrard, heat, sound_wave, kh, gravity)")->required();
  cmd->add_option("--snapshot", o->snapshots,
                  "particle snapshot: CSV, SWIFT/GADGET HDF5 or H5Part (kh: several, a time series; repeatable)")
      ->required();
  cmd->add_option("--format", o->format, "auto|csv|swift|h5part (default auto)")
      ->check(CLI::IsMember({"auto", "csv", "swift", "h5part"}));
  cmd->add_option("--step", o->step, "H5Part step k of /Step#k (default: the last)")->check(non_negative);
  cmd->add_option("--set", o->settings, "case parameters as key=value, separated by commas or blanks (repeatable; see 'sphv info CASE')")->take_all();
  cmd->add_option("--out", o->out, "output directory (default runs/CASE-score)");
  cmd->add_flag("--force", o->force, "score with --set values that contradict what the file states");
  cmd->callback([o, &status] {
    o->settings = split_settings(o->settings);
    status = score_command(*o);
  });
}

void add_ic_command(CLI::App& app) {
  auto o = std::make_shared<IcOptions>();
  auto* cmd = app.add_subcommand("ic", "write a case's initial conditions (for another code to start from)");
  cmd->add_option("case", o->case_name, "case name (sod, sod2d, sod3d, sedov, noh, evrard, heat, sound_wave, kh)")->required();
  cmd->add_option("--set", o->settings, "case parameters as key=value, separated by commas or blanks (repeatable; n is the level)")->take_all();
  cmd->add_option("--out", o->out, "output file")->required();
  cmd->add_option("--format", o->format, "csv|swift|h5part (default: from the extension, .csv .hdf5/.h5 .h5part)")
      ->check(CLI::IsMember({"auto", "csv", "swift", "h5part"}));
  cmd->callback([o] {
    o->settings = split_settings(o->settings);
    ic_command(*o);
  });
}

void add_convert_command(CLI::App& app) {
  auto o = std::make_shared<ConvertOptions>();
  auto* cmd = app.add_subcommand("convert", "rewrite a particle snapshot in another format (csv, swift, h5part)");
  cmd->add_option("--input", o->input, "snapshot (any format sphv reads)")->required();
  cmd->add_option("--out", o->out, "output file")->required();
  cmd->add_option("--format", o->format, "csv|swift|h5part")->required()->check(CLI::IsMember({"csv", "swift", "h5part"}));
  cmd->add_option("--time", o->time, "the snapshot's time (overrides the input's)");
  cmd->callback([o] { convert_command(*o); });
}

void add_bench_command(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  auto* cmd = app.add_subcommand("bench", "throughput of search, density, hydro step, tree and direct sum");
  cmd->add_option("--sizes", o->sizes, "particle numbers (rounded to cubes)")->delimiter(',')->check(positive);
  cmd->add_option("--threads", o->threads, "thread counts (default: 1 and all cores)")->delimiter(',')->check(positive);
  cmd->add_option("--tree-max", o->tree_max, "largest N for the tree");
  cmd->add_option("--direct-max", o->direct_max, "largest N for the O(N^2) direct sum");
  cmd->add_option("--shuffled-max", o->shuffled_max, "largest N for the step from particles stored shuffled");
  cmd->add_option("--scheme", o->scheme, "the SPH scheme timed (default: the chapter's, which the blast cases verify)");
  cmd->add_option("--out", o->out, "output directory (bench.json)");
  cmd->callback([o] { bench_command(*o); });
}

}  // namespace

int run_main(int argc, char** argv) {
  CLI::App app{"sphv: verification and convergence harness for a reference SPH implementation", "sphv"};
  app.require_subcommand(1);
  // Set as soon as it is parsed: before the commands that run inside the parse (gravity, bench,
  // score, ic, convert) and the ones after it.
  app.add_option_function<int>("--threads", [](int t) { omp_set_num_threads(t); }, "OpenMP threads (default: all cores)")
      ->check(positive);
  fs::path baselines;
  app.add_option("--baselines", baselines, "drift baselines folder (default: <sphv's folder>/../reference/baselines)");
  app.footer("Exit status: 0 every gate passed and every run ended as its case expects; 1 a gate failed or a run "
             "went unstable where it should not; 2 bad input; 3 I/O error.\nEnvironment: SPHV_ISA=portable|avx2|avx512 "
             "chooses the instruction-set path of the pair loops and the tree walk (default: the fastest this CPU "
             "supports).");

  auto* list = app.add_subcommand("list", "every case, what its n counts, and its tags");
  auto* info_cmd = app.add_subcommand("info", "a case's parameters with defaults, levels and expected orders");
  std::string case_name;
  info_cmd->add_option("case", case_name, "case name")->required();

  std::vector<std::string> settings, vary, only;
  fs::path out;
  RunOptions opt;
  auto* run = app.add_subcommand("run", "run one case: writes DIR/result.json (and particles.csv)");
  run->add_option("case", case_name, "case name (see 'sphv list'; parameters: 'sphv info CASE')")->required();
  run->add_option("--set", settings, "parameters as key=value, separated by commas or blanks (repeatable)")->take_all();
  run->add_option("--out", out, "output directory (default runs/CASE)");

  std::vector<long> levels;
  std::string levels_arg;  // parsed strictly by parse_levels ("" and "16,,32" are refused)
  std::string tier_name = "standard";
  auto* sweep = app.add_subcommand("sweep", "run a case at several resolutions (and variants): DIR/sweep.json");
  sweep->add_option("case", case_name, "case name")->required();
  auto* levels_opt = sweep->add_option("--levels", levels_arg, "values of n, e.g. 16,32,64, run exactly as given (default: the tier's)");
  sweep->add_option("--tier", tier_name, "quick | standard | full: the case's levels for that tier (default standard)");
  sweep->add_option("--set", settings, "parameters as key=value, separated by commas or blanks (repeatable)")->take_all();
  sweep->add_option("--vary", vary, "variants as key=a,b,c (repeatable: the product); DIR/<variant>/sweep.json")->take_all();
  sweep->add_option("--out", out, "output directory (default runs/CASE-sweep)");
  opt.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  sweep->add_option("--jobs", opt.jobs, "points run at once as subprocesses (default: cores)")->check(positive);
  sweep->add_flag("--force", opt.force, "rerun points that already have a result of this code version");
  const CLI::Validator seconds = wanted(CLI::NonNegativeNumber, "a number of seconds >= 0", "SECONDS");
  std::optional<double> timeout;
  sweep->add_option("--timeout", timeout, "seconds a point may run before it is killed (0: no limit; default: the "
                    "tier's, quick 120, standard 600, full none; none with --levels)")->check(seconds);
  std::string runner;
  sweep->add_option("--runner", runner, "external code: COMMAND run per level with {n} {ic} {out} {t_end} {threads}; {out} scored");
  std::string ic_format = "csv";
  sweep->add_option("--ic-format", ic_format, "format of the runner's {ic} file: csv|swift|h5part (default csv)")
      ->check(CLI::IsMember({"csv", "swift", "h5part"}));

  auto* verify_cmd = app.add_subcommand("verify", "the default catalogue: sweeps, gates, summary table");
  verify_cmd->add_option("--out", out, "output directory (default runs/verify)");
  verify_cmd->add_option("--cases", only, "only these cases")->delimiter(',');
  verify_cmd->add_option("--tier", tier_name, "quick (CI-sized, the Catch2 gates) | standard | full (default standard)");
  verify_cmd->add_flag("--force", opt.force, "rerun points that already have a result of this code version");
  verify_cmd->add_option("--timeout", timeout, "seconds a point may run before it is killed (0: no limit; default: "
                         "quick 120, standard 600, full none)")->check(seconds);
  fs::path junit;
  verify_cmd->add_option("--junit", junit, "JUnit XML file, a test case per gate check (default DIR/junit.xml)");

  auto* baseline = app.add_subcommand("baseline", "drift baselines (own earlier output, not verification)");
  auto* baseline_up = baseline->add_subcommand("update", "rewrite the drift baselines from quick-tier sweeps");
  baseline->require_subcommand(1);
  baseline_up->add_option("--cases", only, "only these cases")->delimiter(',');
  add_gravity_command(app);
  int score_status = 0;
  add_score_command(app, score_status);
  add_ic_command(app);
  add_convert_command(app);
  add_bench_command(app);

  const bool root = mpi::rank() == 0;
  if (argc <= 1) {  // a bare `sphv` asks what it can do: the help, exit 0
    if (root) std::cout << app.help();
    return 0;
  }
  // One set of handlers for the parse (bench and gravity run inside it, as callbacks) and for
  // the commands after it: every error ends as one line and a non-zero exit.
  try {
    try {
      sph::isa_path();  // the pair loops' instruction-set path: SPHV_ISA is checked before any run
    } catch (const std::invalid_argument& e) {
      throw InputError(e.what());
    }
    app.parse(argc, argv);
    if (score_status != 0) return score_status;
    settings = split_settings(settings);
    if (!baselines.empty()) set_baseline_dir(baselines);
    const Tier tier = parse_tier(tier_name);
    opt.exe = fs::canonical("/proc/self/exe");
    opt.progress = true;
    if (*list) list_cases();
    if (*info_cmd) info(find_case(case_name));
    if (*run) {
      const Case& c = find_case(case_name);
      const Params p = c.parse(settings);
      test_fault(c, p);
      const Result r = run_case(c, p);
      write_result(r, out.empty() ? fs::path("runs") / c.name : out);
      std::printf("%s\n", summary_line(r).c_str());
      if (!c.verdict_expected(p, r.verdict)) return 1;
    }
    if (*sweep) {
      const Case& c = find_case(case_name);
      if (levels_opt->count() > 0) levels = parse_levels(levels_arg);
      if (!runner.empty()) {
        const Sweep s = runner_sweep(c, levels.empty() ? c.tier_levels(settings, tier) : levels, settings,
                                     out.empty() ? fs::path("runs") / (c.name + "-runner") : out, runner, ic_format);
        print_rows_header();
        print_rows(s);
        return status_of({s});
      }
      if (mpi::size() > 1) opt.jobs = 1;
      // A point past its time limit is killed and becomes its verdict: that needs a subprocess per point.
      opt.timeout_s = timeout ? *timeout : levels.empty() ? tier_timeout(tier) : 0.0;
      opt.isolate = opt.timeout_s > 0.0;
      const auto sweeps = run_sweeps(c, tier, levels, expand_variants(settings, vary),
                                     out.empty() ? fs::path("runs") / (c.name + "-sweep") : out, opt);
      if (!root) return 0;
      for (const Sweep& s : sweeps) {
        for (const auto& r : s.runs) std::printf("%s\n", summary_line(r).c_str());
        for (const auto& ch : s.checks)
          std::printf("gate %-28s %-10.4g in [%g, %g] (%s): %s\n", ch.name.c_str(), ch.value, ch.lo, ch.hi,
                      to_string(ch.kind), ch.pass() ? "pass" : "FAIL");
      }
      print_rows_header();
      for (const Sweep& s : sweeps) print_rows(s);
      return status_of(sweeps);
    }
    if (*verify_cmd) {
      // A process per point, the cores filled (run_points); under mpirun each rank runs its points in-process.
      opt.isolate = true;
      opt.announce = tier == Tier::full;
      opt.timeout_s = timeout ? *timeout : tier_timeout(tier);
      return verify(out.empty() ? fs::path("runs/verify") : out, only, tier, opt, junit);
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
  } catch (const std::exception& e) {
    // Allocation failure (e.g. n = 10^7 in 3D asks for more than memory holds) is bad input;
    // anything else here is I/O (e.g. an output path that cannot be written).
    const bool memory = dynamic_cast<const std::bad_alloc*>(&e) || dynamic_cast<const std::length_error*>(&e);
    if (root) error_line(memory ? "not enough memory for these parameters (choose a smaller n)" : e.what());
    return memory ? 2 : 3;
  }
  return 0;
}

int main(int argc, char** argv) {
  sphv::keep_freed_memory();
  sphv::mpi::init(&argc, &argv);
  const int status = run_main(argc, argv);
  sphv::mpi::finalize();
  return status;
}
