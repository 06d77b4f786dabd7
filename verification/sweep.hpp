#pragma once
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "verification/case.hpp"
#include "verification/points.hpp"

namespace sphv {

// Roache's grid convergence index of a functional on the two finest levels.
struct Gci {
  double fine_value;
  double order;      // observed from three levels, or the expected order with two
  double ratio;      // refinement ratio of the finest pair
  double safety;     // Fs: 1.25 with three or more levels, 3 with two
  double gci;        // relative uncertainty band of the finest value
};

// A case run at several resolutions, with the fitted orders of convergence.
struct Sweep {
  std::string case_name;
  std::string summary, n_counts, expected_why;  // from the case, for reports
  std::vector<std::string> settings;  // the variant: settings other than n
  std::vector<long> levels;
  std::vector<Result> runs;
  std::map<std::string, double> observed_order;  // least-squares slope, per error name
  std::map<std::string, double> expected_order;
  std::map<std::string, Gci> gci;                // per functional
  std::vector<Check> checks;
  double wall_time_s = 0.0;
  bool passed() const;
  std::string variant() const;  // "default" or the settings joined
};

// Observed order p of err ~ C n^-p: minus the least-squares slope of log err on log n
// (GSL gsl_fit_linear). Non-positive or non-finite errors are skipped; NaN below two points.
double observed_order(const std::vector<double>& n, const std::vector<double>& err);
std::optional<Gci> grid_convergence_index(const std::vector<double>& n, const std::vector<double>& f,
                                          double expected_order);

// Gates on the expected orders: "order_<error>" with the observed order within [p - band, p + band]
// of the expected p, for each error observed at every level (others get no check).
std::vector<Check> order_checks(const Sweep& s, double band, const std::string& why);

// Runs the case at each level (parameter n) with the given settings; with out set, writes
// out/n<level>/result.json as each run finishes and out/sweep.json at the end.
Sweep run_sweep(const Case& c, const std::vector<long>& levels, const std::vector<std::string>& settings,
                const std::optional<std::filesystem::path>& out = std::nullopt, const RunOptions& opt = {});

// The variants of `--vary key=a,b,c` (repeatable): the product of all values, each added to
// the base settings.
std::vector<std::vector<std::string>> expand_variants(const std::vector<std::string>& base,
                                                      const std::vector<std::string>& vary);

// Runs levels x variants as one pool of points (levels adjusted per variant by the case) and
// writes out/<variant>/sweep.json per variant. Under mpirun only rank 0 returns sweeps.
std::vector<Sweep> run_sweeps(const Case& c, const std::vector<long>& levels,
                              const std::vector<std::vector<std::string>>& variants,
                              const std::filesystem::path& out, const RunOptions& opt);

// Orders, GCI and gate checks of a finished set of runs.
Sweep summarise(const Case& c, const std::vector<std::string>& settings, const std::vector<long>& levels,
                std::vector<Result> runs);

nlohmann::json to_json(const Sweep& s);

}  // namespace sphv
