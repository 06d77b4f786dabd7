#include "verification/harness/cost.hpp"

#include "verification/harness/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace sphv {

namespace {
nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream f(file);
  if (!f) return nullptr;
  return nlohmann::json::parse(f, nullptr, false);
}
}  // namespace

std::filesystem::path default_cost_table() {
  return std::filesystem::canonical("/proc/self/exe").parent_path().parent_path() / "verification" / "harness" / "costs.json";
}

double cost_of(const nlohmann::json& r) {
  const double wall = r.value("wall_time_s", 0.0);
  int threads = 1;
  if (r.contains("provenance") && r["provenance"].is_object()) threads = r["provenance"].value("threads", 1);
  return wall * std::max(1, threads);
}

CostModel::CostModel(const std::filesystem::path& table) : table_(read_json(table)) {
  if (!table_.is_object()) table_ = nlohmann::json::object();
}

std::string CostModel::variant_key(const std::vector<std::string>& settings) {
  std::string s;
  for (const auto& kv : settings) s += (s.empty() ? "" : ",") + kv;
  return s.empty() ? "default" : s;
}

double CostModel::estimate(const Case& c, const std::vector<std::string>& settings, long n, const Params& p,
                           const std::filesystem::path& dir) const {
  if (!dir.empty()) {
    const auto j = read_json(dir / "result.json");
    if (j.is_object() && j.contains("params") && j["params"] == p.to_json() && cost_of(j) > 0.0) return cost_of(j);
  }
  const auto pj = p.to_json();
  const double dim = pj.contains("dim") && pj["dim"].is_number() ? pj["dim"].get<double>() : 1.0;
  // Measured levels of this case and variant: n -> core-seconds.
  std::map<long, double> known;
  if (table_.contains(c.name) && table_[c.name].contains(variant_key(settings)))
    for (const auto& [k, v] : table_[c.name][variant_key(settings)].items())
      if (v.is_number() && v.get<double>() > 0.0) known[std::stol(k)] = v.get<double>();
  if (known.count(n)) return known.at(n);
  if (known.empty()) return 1e-6 * std::pow(static_cast<double>(n), dim + 1.0);
  double exponent = dim + 1.0;
  if (known.size() >= 2) {
    const auto b = std::prev(known.end()), a = std::prev(b);
    const double fitted = std::log(b->second / a->second) / std::log(double(b->first) / double(a->first));
    if (std::isfinite(fitted)) exponent = std::clamp(fitted, 1.0, dim + 2.0);
  }
  auto near = known.lower_bound(n);
  if (near == known.end()) near = std::prev(near);
  return near->second * std::pow(double(n) / double(near->first), exponent);
}

nlohmann::json measured_costs(const std::vector<SweepPlan>& plans) {
  nlohmann::json t = nlohmann::json::object();
  for (const auto& p : plans)
    for (long n : p.levels) {
      const auto j = read_json(p.dir / ("n" + std::to_string(n)) / "result.json");
      if (j.is_object() && cost_of(j) > 0.0) t[p.c->name][CostModel::variant_key(p.settings)][std::to_string(n)] = cost_of(j);
    }
  return t;
}

}  // namespace sphv
