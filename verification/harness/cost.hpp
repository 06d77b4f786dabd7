#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "verification/harness/case.hpp"

namespace sphv {

struct SweepPlan;

// What a point costs, in core-seconds (wall time x OpenMP threads), for scheduling (longest
// first, threads per point) and the ETA. Not a measurement of anything verified.
// Sources, first that applies:
//  1. the point's earlier result.json in its output folder (same parameters, any code version);
//  2. the cost table (verification/harness/costs.json: measured wall x threads per case, variant, n);
//  3. the nearest measured level of the same case and variant in the table, scaled by a power
//     law in n fitted to its two finest measured levels (exponent dim + 1 with one level);
//  4. a guess of 1e-6 core-seconds per particle-step, n^(dim + 1) (dim from the parameter, else 1).
class CostModel {
 public:
  explicit CostModel(const std::filesystem::path& table);  // a missing table is no error
  double estimate(const Case& c, const std::vector<std::string>& settings, long n, const Params& p,
                  const std::filesystem::path& dir) const;
  // The table key of a variant: its settings as given, joined ("default" when none).
  static std::string variant_key(const std::vector<std::string>& settings);

 private:
  nlohmann::json table_;
};

// <sphv's folder>/../verification/harness/costs.json (the table the repository carries).
std::filesystem::path default_cost_table();

// The cost table of finished plans, from their points' result.json files: what `verify` writes
// as DIR/costs.json (copy it over verification/harness/costs.json to refresh the repository's table).
nlohmann::json measured_costs(const std::vector<SweepPlan>& plans);

// Core-seconds a finished result cost (its wall time x the threads it ran with).
double cost_of(const nlohmann::json& result);

}  // namespace sphv
