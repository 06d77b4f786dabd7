#include "verification/commands/bench.hpp"

#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <numeric>
#include <string>
#include <utility>

#include "reference/direct_sum.hpp"
#include "sph/core/lattice.hpp"
#include "sph/density/summation.hpp"
#include "sph/gravity/tree_gravity.hpp"
#include "sph/search/grid_search.hpp"
#include "sph/search/tree.hpp"
#include "verification/commands/bench_hydro.hpp"
#include "verification/harness/params.hpp"
#include "verification/commands/peak.hpp"
#include "verification/harness/result.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv {
namespace {

struct Row {
  std::string stage;
  long n;
  int threads;
  double seconds;
  double pairs;  // pair interactions (particle-particle and particle-node for the tree)
};

// f's time on each of the thread counts, which take turns run by run, so that all of them see the
// same moments of the machine: its speed drifts by up to 1.5x over minutes, and one of its two cores
// at times runs a third slower than the other for seconds. Run in turn per N instead (every stage on
// one thread, then every stage on two), a speed-up compared runs a minute apart. Each of f's parts
// (Parts) at its least over a few rounds (three when a round takes over a second, up to five), the
// parts summed: the noise only adds time. Never one round: the first run pays the first touch of
// buffers a run keeps (at N = 1e6 the search's single run took 2.07 s on one thread, a warm one
// 0.51 s on two; measured). Nor two: on two threads the second wide-h search still faulted in 22,000
// pages (0.40 s, the third 0.29 s; a thread writes past where it stopped in the first run, whose page
// faults slowed it).
Times best_times(const std::vector<int>& threads, const std::function<Parts()>& f) {
  std::vector<Parts> best(threads.size());
  double total = 0.0;
  for (int k = 0; k < 5 && (k < 3 || total < 1.0); ++k)
    for (std::size_t i = 0; i < threads.size(); ++i) {
      omp_set_num_threads(threads[i]);
      // The team started before f runs: a thread left idle through another count's run took 9-13 ms
      // to start in f's first parallel region (N = 1e6, the wide search on two threads after one
      // thread's 0.5 s; 0.1 ms once started, measured), which f's clock would count.
#pragma omp parallel
      {
      }
      const Parts t = f();
      if (k == 0) best[i] = t;
      for (std::size_t j = 0; j < t.size(); ++j) best[i][j] = std::min(best[i][j], t[j]), total += t[j];
    }
  Times sum(threads.size());
  for (std::size_t i = 0; i < threads.size(); ++i) sum[i] = std::accumulate(best[i].begin(), best[i].end(), 0.0);
  return sum;
}

// 3D uniform gas: a lattice jittered by 0.1 dx, support radius 2.4 dx (about 60 neighbours).
sph::Particles<3> uniform_gas(long n, sph::Box<3>& box) {
  const int side = static_cast<int>(std::lround(std::cbrt(static_cast<double>(n))));
  box = sph::unit_box<3>(true);
  return sph::lattice<3>(side, box, 1.0, 2.4, 0.1, 7);
}

// Every stage at N ~ n_wanted on each of o.threads (best_times).
std::vector<Row> measure(long n_wanted, const BenchOptions& o, double& bytes_per_particle, double& searches_per_step) {
  const Timer timer = [&](const std::function<Parts()>& f) { return best_times(o.threads, f); };
  std::vector<Row> rows;
  sph::Box<3> box;
  sph::Particles<3> p = uniform_gas(n_wanted, box);
  const long n = static_cast<long>(p.size());
  auto add = [&](const std::string& stage, const Times& t, double pairs) {
    for (std::size_t i = 0; i < t.size(); ++i) rows.push_back({stage, n, o.threads[i], t[i], pairs});
  };
  // Searches into kept buffers, as a run's Verlet list does. With fresh buffers every time, the
  // page faults of two threads contend: the wide search below took 0.131 s on one thread and
  // 0.167 s on two (N = 125,000, measured), against 0.123 s and 0.067 s with kept buffers.
  sph::NeighbourList nl;
  sph::GridSearchBuffers<3> buf;
  const Times search = timer(whole([&] { sph::grid_search<3>(p.x, p.h, box, nl, buf); }));  // before nl.pairs() is read
  add("neighbour search", search, static_cast<double>(nl.pairs()));
  // The same gas with the support radius of the central 0.4 % (r < 0.1) four times larger, like a
  // blast wave's hot, rarefied centre: the search's cost should follow the bulk's h, not the largest.
  std::vector<double> wide = p.h;
  for (long i = 0; i < n; ++i)
    if ((p.x[i] - sph::Vec<3>::Constant(0.5)).norm() < 0.1) wide[i] *= 4.0;
  if (*std::max_element(wide.begin(), wide.end()) < 0.5) {  // the periodic box's limit
    sph::NeighbourList nw;
    sph::GridSearchBuffers<3> bw;
    const Times t = timer(whole([&] { sph::grid_search<3>(p.x, wide, box, nw, bw); }));
    add("neighbour search, central h x4", t, static_cast<double>(nw.pairs()));
  }
  sph::Components<3> xs;  // kept, as a scene keeps its own (sph/hydro/scene.hpp)
  add("density (27)", timer(whole([&] { sph::density_summation<3>(p, nl, box, xs); })), static_cast<double>(nl.pairs()));
  const HydroTimes hydro = time_hydro_step(o.scheme, p, box, timer);
  add("hydro forces", hydro.forces, hydro.pairs);
  add("full hydro step", hydro.step, hydro.pairs);
  // Its phases (sph::StepPhases), on each thread count, then their sum, which the step's time checks.
  const std::vector<std::pair<std::string, double sph::StepPhases::*>> phases = {
      {"search or list reuse", &sph::StepPhases::search},
      {"density loop with its h", &sph::StepPhases::density},
      {"force loop", &sph::StepPhases::forces},
      {"time step", &sph::StepPhases::time_step},
      {"reorder", &sph::StepPhases::reorder},
      {"kick/drift", &sph::StepPhases::kick_drift},
      {"state check and hooks", &sph::StepPhases::check}};
  for (const auto& [name, member] : phases) {
    Times t;
    for (int threads : o.threads) t.push_back(hydro.phases.at(threads).*member);
    add("  step phase: " + name, t, 0.0);
  }
  Times sum;
  for (int threads : o.threads) sum.push_back(hydro.phases.at(threads).total());
  add("  step phases summed", sum, 0.0);
  add("full hydro step, search every step", hydro.step_fresh_search, hydro.pairs);
  if (n <= o.shuffled_max) {  // particles stored in no spatial order, as another code's snapshot may hold them
    const sph::Particles<3> q = shuffled(p);
    add("full hydro step, stored shuffled", time_evolve_step(o.scheme, q, box, timer).step, hydro.pairs);
    add("full hydro step, stored shuffled, no reordering", time_evolve_step(o.scheme, q, box, timer, 0).step, hydro.pairs);
  }
  searches_per_step = hydro.searches_per_step;
  bytes_per_particle = hydro.bytes_per_particle;
  if (n <= o.tree_max) {
    sph::Tree<3> tree;
    add("tree build", timer(whole([&] { tree = sph::build_tree<3>(p.x, p.m); })), 0.0);
    sph::GravityField g;
    const sph::GravityOptions go{.theta = 0.5, .eps = 0.01};
    const Times t = timer(whole([&] { g = sph::tree_gravity(tree, p.x, p.m, go); }));
    double inter = 0.0;
    for (long k : g.interactions) inter += static_cast<double>(k);
    add("tree gravity (quadrupole, theta 0.5)", t, inter);
  }
  if (n <= o.direct_max) {
    std::vector<double> x(n), y(n), z(n);
    for (long i = 0; i < n; ++i) x[i] = p.x[i][0], y[i] = p.x[i][1], z[i] = p.x[i][2];
    add("direct-sum gravity", timer(whole([&] { reference::direct_sum(x, y, z, p.m, 1.0, 0.01); })),
        double(n) * double(n - 1));
  }
  return rows;
}

// Peak resident memory of the process so far, in bytes.
double peak_resident_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return 1024.0 * static_cast<double>(u.ru_maxrss);
}

void bench(const BenchOptions& o) {
  std::vector<Row> rows;
  std::map<long, double> bytes, resident, searches_per_step;
  std::filesystem::create_directories(o.out);  // an unwritable output is refused before the work
  // The CPU's double-precision peak on each thread count, measured just before and just after each
  // N's runs: the force loop's share of it (the larger), and what the machine gave while the
  // speed-ups were measured. On a virtual machine two cores can give well short of twice one (at
  // times here 1.78x: the host slows both), and no loop then scales better than that.
  std::map<long, std::map<int, std::array<double, 2>>> peak;  // N -> threads -> flop/s before, after
  std::string isa;
  auto peaks = [&](std::map<int, std::array<double, 2>>& at, int when) {
    for (int threads : o.threads) {
      const Peak pk = measure_peak(threads);
      at[threads][when] = pk.flops_per_s, isa = pk.isa;
    }
  };
  auto of_peak = [&](const Row& r) {
    const std::array<double, 2>& pk = peak[r.n][r.threads];
    return r.stage == "hydro forces" && o.scheme == force_pair_flops_scheme ? force_pair_flops * r.pairs / r.seconds / std::max(pk[0], pk[1]) : NAN;
  };
  // A stage's time on one thread over its time on t threads, from the same N, timed in turn with it
  // (NaN for one thread, or without a one-thread run).
  std::map<std::pair<std::string, long>, double> one_thread;
  auto speedup = [&](const Row& r) {
    const auto one = one_thread.find({r.stage, r.n});
    return r.threads == 1 || one == one_thread.end() ? NAN : one->second / r.seconds;
  };
  std::printf("hydro stages: scheme %s (sph/schemes/), cubic spline, its default forms\n", o.scheme.c_str());
  std::printf("%-48s %9s %7s %10s %14s %14s %9s %8s %8s\n", "stage", "N", "threads", "seconds", "updates/s", "pairs/s",
              "ns/pair", "speed-up", "of peak");
  for (long n : o.sizes) {
    double b = 0.0, searches = 0.0;
    std::map<int, std::array<double, 2>> at;
    peaks(at, 0);
    const std::vector<Row> measured = measure(n, o, b, searches);
    peaks(at, 1);
    peak[measured.back().n] = at;
    for (const Row& r : measured) {
      rows.push_back(r);
      if (r.threads == 1) one_thread[{r.stage, r.n}] = r.seconds;
      std::printf("%-48s %9ld %7d %10.4f %14.3e %14.3e %9.2f", r.stage.c_str(), r.n, r.threads, r.seconds,
                  r.n / r.seconds, r.pairs / r.seconds, r.pairs > 0.0 ? 1e9 * r.seconds / r.pairs : 0.0);
      if (std::isfinite(speedup(r))) std::printf(" %7.2fx", speedup(r));
      else std::printf(" %8s", "");
      if (std::isfinite(of_peak(r))) std::printf(" %7.1f%%", 100.0 * of_peak(r));
      std::printf("\n");
      std::fflush(stdout);
    }
    for (const Row& r : measured)  // the phases' sum against the step they divide
      if (r.stage == "  step phases summed")
        for (const Row& step : measured)
          if (step.stage == "full hydro step" && step.threads == r.threads)
            std::printf("step phases on %d thread(s) sum to %.1f %% of the full hydro step\n", r.threads,
                        100.0 * r.seconds / step.seconds);
    bytes[rows.back().n] = b;
    searches_per_step[rows.back().n] = searches;
    // Measured: the process's peak over ascending N is set by the largest N so far (recorded after
    // each N's runs on every thread count).
    resident[rows.back().n] = peak_resident_bytes() / rows.back().n;
    std::printf("measured peak before / after these runs:");
    const auto one = at.find(1);
    for (const auto& [t, pk] : at) {
      std::printf(" %d thread(s) %.3e / %.3e flop/s", t, pk[0], pk[1]);
      if (t != 1 && one != at.end())
        std::printf(" (%.2fx / %.2fx one thread's)", pk[0] / one->second[0], pk[1] / one->second[1]);
      std::printf(";");
    }
    std::printf("\n");
  }

  // Cost against N with fitted slopes (GSL least squares on log-log), at the most threads.
  const int tmax = *std::max_element(o.threads.begin(), o.threads.end());
  std::map<std::string, Series> cost;
  for (const Row& r : rows)
    if (r.threads == tmax && !r.stage.starts_with("  step phase")) {
      cost[r.stage].x.push_back(r.n);
      cost[r.stage].y.push_back(r.seconds);
    }
  Figure fig{"bench_cost", "Cost against N, 3D uniform gas (" + std::to_string(tmax) + (tmax == 1 ? " thread)" : " threads)"), "particles N",
             "wall time [s]", "log", "log", {}};
  nlohmann::json slopes = nlohmann::json::object();
  for (auto& [stage, s] : cost) {
    const double slope = s.x.size() >= 2 ? -observed_order(s.x, s.y).p : NAN;
    slopes[stage] = std::isfinite(slope) ? nlohmann::json(slope) : nlohmann::json();
    char label[160];
    if (std::isfinite(slope)) std::snprintf(label, sizeof label, "%s: slope %.2f", stage.c_str(), slope);
    else std::snprintf(label, sizeof label, "%s: one N, no slope", stage.c_str());
    s.label = label;
    s.style = "line";
    fig.series.push_back(s);
  }
  Figure upd{"bench_updates", "Full hydro step throughput", "particles N", "particle updates per second", "log", "log", {}};
  for (int t : o.threads) {
    Series s{std::to_string(t) + " thread(s)", {}, {}, "line"};
    for (const Row& r : rows)
      if (r.threads == t && r.stage == "full hydro step") s.x.push_back(r.n), s.y.push_back(r.n / r.seconds);
    upd.series.push_back(s);
  }
  nlohmann::json jr = nlohmann::json::array(), jb = nlohmann::json::object();
  for (const Row& r : rows)
    jr.push_back({{"stage", r.stage}, {"n", r.n}, {"threads", r.threads}, {"seconds", r.seconds},
                  {"pairs", r.pairs}, {"particle_updates_per_s", r.n / r.seconds}, {"pairs_per_s", r.pairs / r.seconds},
                  {"ns_per_pair", r.pairs > 0.0 ? nlohmann::json(1e9 * r.seconds / r.pairs) : nlohmann::json()},
                  {"speedup", std::isfinite(speedup(r)) ? nlohmann::json(speedup(r)) : nlohmann::json()},
                  {"fraction_of_peak", std::isfinite(of_peak(r)) ? nlohmann::json(of_peak(r)) : nlohmann::json()}});
  nlohmann::json jm = nlohmann::json::object(), js = nlohmann::json::object();
  for (const auto& [n, v] : searches_per_step) js[std::to_string(n)] = v;
  for (const auto& [n, b] : bytes) jb[std::to_string(n)] = b;
  for (const auto& [n, b] : resident) jm[std::to_string(n)] = b;
  nlohmann::json jp = {{"isa", isa}, {"force_pair_flops", force_pair_flops},
                       {"method", "fused multiply-adds in 16 independent chains on the widest vectors, every thread "
                                  "at once, best of five runs of about 0.1 s (verification/commands/peak.cpp), just before and "
                                  "just after each N's runs"}};
  for (const auto& [n, at] : peak)
    for (const auto& [t, pk] : at) jp["flops_per_s"][std::to_string(n)][std::to_string(t)] = {pk[0], pk[1]};
  const nlohmann::json j = {{"benchmark", "3D uniform gas, lattice jittered 0.1 dx, h = 2.4 dx"},
                            {"scheme", o.scheme}, {"rows", jr}, {"fitted_slopes", slopes}, {"bytes_per_particle", jb},
                            {"peak_resident_bytes_per_particle", jm}, {"searches_per_step", js},
                            {"full_step_window", full_step_window}, {"peak", jp},
                            {"figures", {to_json(fig), to_json(upd)}}, {"provenance", provenance()}};
  write_atomically(o.out / "bench.json", j.dump(1) + "\n");
  std::printf("fitted cost slopes (time ~ N^slope):");
  for (const auto& [k, v] : slopes.items())
    if (v.is_number()) std::printf(" %s %.2f;", k.c_str(), v.get<double>());
  std::printf("\nbytes per particle (hydro state + neighbour list):");
  for (const auto& [n, b] : bytes) std::printf(" N=%ld: %.0f", n, b);
  std::printf("\nneighbour searches per full hydro step (lists reused while they cover):");
  for (const auto& [n, v] : searches_per_step) std::printf(" N=%ld: %.2f", n, v);
  std::printf("\npeak resident memory per particle (measured, whole process):");
  for (const auto& [n, b] : resident) std::printf(" N=%ld: %.0f", n, b);
  if (o.scheme == force_pair_flops_scheme)
    std::printf("\ndouble-precision peak measured with %s FMA chains; hydro forces counted at %.0f flops a pair\n",
                isa.c_str(), force_pair_flops);
  else
    std::printf("\n");
  std::printf("written %s\n", (o.out / "bench.json").string().c_str());
}

}  // namespace

void bench_command(BenchOptions o) {
  const std::vector<std::string> schemes = sph::scheme_names();
  if (std::find(schemes.begin(), schemes.end(), o.scheme) == schemes.end())
    throw InputError("bench: unknown scheme '" + o.scheme + "' (sph/schemes/schemes.hpp)");
  if (o.threads.empty()) {
    o.threads = {1};
    if (omp_get_num_procs() > 1) o.threads.push_back(omp_get_num_procs());
  }
  // Ascending, each once: a run on more threads finds the one-thread time it is compared with.
  std::sort(o.threads.begin(), o.threads.end());
  o.threads.erase(std::unique(o.threads.begin(), o.threads.end()), o.threads.end());
  bench(o);
}

}  // namespace sphv
