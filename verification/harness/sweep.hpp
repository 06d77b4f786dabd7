#pragma once
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "verification/harness/case.hpp"
#include "verification/harness/points.hpp"

namespace sphv {

// Roache's grid convergence index of a functional on the two finest levels.
struct Gci {
  double fine_value;
  double order;      // observed from three levels, or the expected order with two
  double ratio;      // refinement ratio of the finest pair
  double safety;     // Fs: 1.25 with three or more levels, 3 with two
  double gci;        // relative uncertainty band of the finest value
};

// Observed order p of err ~ C n^-p with its standard error (NaN below three points).
struct Order {
  double p, se;
};

// What one error of a sweep establishes: verified (order inside its band and every bound held),
// known failure (the order misses its band for the reason the case proves, its bounds held),
// no order claimed (the case says why; its bounds held), or fail.
struct Row {
  std::string error;
  double fine_value, observed, se, expected, band;
  std::string outcome;  // "verified", "known failure", "provisional", "no order claimed" or "fail"
  std::string why;
  double lo = std::numeric_limits<double>::quiet_NaN(), hi = lo;  // the claim's window (hi infinite: at least lo)
  std::vector<double> local_orders;                              // between neighbouring levels, coarse to fine
};

// A case run at several resolutions, with the fitted orders of convergence.
struct Sweep {
  std::string case_name;
  std::string summary, n_counts;        // from the case, for reports
  std::vector<std::string> settings;    // the variant: settings other than n
  std::string tier;                     // "quick", "standard", "full", or "" for levels given by hand
  std::vector<long> levels;
  std::vector<Result> runs;
  std::map<std::string, Order> observed_order;  // least-squares fit, per error name
  OrderClaims claims;
  std::map<std::string, std::string> error_defs;
  std::map<std::string, Gci> gci;               // per functional
  std::vector<Check> checks;
  std::vector<Row> rows;
  // Errors whose claim holds only in the former window (expected +- (band + 2 se)) and the parts of
  // the acceptance rule it fails: their rows read "provisional", never "verified".
  std::map<std::string, std::string> provisional;
  double wall_time_s = 0.0;
  bool passed() const;
  std::string variant() const;  // "default" or the settings joined
};

// Observed order of err ~ C n^-p: minus the least-squares slope of log err on log n and its
// standard error from the fit's covariance (GSL gsl_fit_linear). Non-positive or non-finite
// errors are skipped; p is NaN below two points, se below three.
Order observed_order(const std::vector<double>& n, const std::vector<double>& err);
// Roache's GCI on the two finest levels: the order observed from three levels at a constant
// ratio (Fs = 1.25), else the claimed order with Fs = 3; none without either.
std::optional<Gci> grid_convergence_index(const std::vector<double>& n, const std::vector<double>& f,
                                          double claimed_order);

// Runs the case at each level (parameter n) with the given settings; with out set, writes
// out/n<level>/result.json as each run finishes and out/sweep.json at the end.
Sweep run_sweep(const Case& c, const std::vector<long>& levels, const std::vector<std::string>& settings,
                const std::optional<std::filesystem::path>& out = std::nullopt, const RunOptions& opt = {});
// The same at a tier's levels for the variant (what the Catch2 gates and `verify` run).
Sweep run_tier(const Case& c, Tier t, const std::vector<std::string>& settings,
               const std::optional<std::filesystem::path>& out = std::nullopt, const RunOptions& opt = {});

// The variants of `--vary key=a,b,c` (repeatable): the product of all values, each added to
// the base settings.
std::vector<std::vector<std::string>> expand_variants(const std::vector<std::string>& base,
                                                      const std::vector<std::string>& vary);

// A sweep before it runs: its case, variant, levels, folder and tier label.
struct SweepPlan {
  const Case* c;
  std::vector<std::string> settings;
  std::vector<long> levels;
  std::filesystem::path dir;
  std::string tier;  // "" for levels given by hand
};

// The sweeps of levels x variants, out/<variant>/ each (out itself with one variant). Levels:
// the tier's for each variant, or exactly the given ones when `levels` is not empty.
std::vector<SweepPlan> plan_sweeps(const Case& c, Tier t, const std::vector<long>& levels,
                                   const std::vector<std::vector<std::string>>& variants,
                                   const std::filesystem::path& out);
// Runs every point of the plans as one pool (run_points: longest first, a process per point)
// and writes dir/sweep.json per plan. Under mpirun only rank 0 returns sweeps.
std::vector<Sweep> run_plans(const std::vector<SweepPlan>& plans, const RunOptions& opt);
// plan_sweeps then run_plans: one case's levels x variants.
std::vector<Sweep> run_sweeps(const Case& c, Tier t, const std::vector<long>& levels,
                              const std::vector<std::vector<std::string>>& variants,
                              const std::filesystem::path& out, const RunOptions& opt);

// Orders, GCI, gate checks and row outcomes of a finished set of runs.
Sweep summarise(const Case& c, const std::vector<std::string>& settings, const std::vector<long>& levels,
                std::vector<Result> runs, const std::string& tier = "");

// A known failure stands only beside its experiment: for every known-failure row whose experiment
// (a variant of the same case) is among the sweeps, a verification check that the experiment
// verifies the same error; the row fails where it does not.
void check_experiments(std::vector<Sweep>& sweeps);

// The outcome of every error the runs report (and every claimed one) from the sweep's claims and checks.
std::vector<Row> rows_of(const Sweep& s);

nlohmann::json to_json(const Sweep& s);

}  // namespace sphv
