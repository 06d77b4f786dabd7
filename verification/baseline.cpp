#include "verification/baseline.hpp"

#include <cmath>
#include <fstream>

#include "build_info.hpp"
#include "verification/sweep.hpp"

namespace sphv {

std::filesystem::path baseline_dir() { return std::filesystem::path(SPHV_SOURCE_DIR) / "reference" / "baselines"; }

std::vector<Check> drift_checks(const Sweep& s) {
  const auto file = baseline_dir() / (s.case_name + ".json");
  if (!std::filesystem::exists(file)) return {};
  std::ifstream f(file);
  const auto j = nlohmann::json::parse(f, nullptr, false);
  if (j.is_discarded() || !j.contains("variants") || !j["variants"].contains(s.variant())) return {};
  const auto& v = j["variants"][s.variant()];
  std::vector<Check> out;
  for (const auto& r : s.runs) {
    const std::string n = std::to_string(r.params.value("n", 0L));
    if (!v.contains(n)) continue;
    for (const auto& [name, base] : v[n].items()) {
      if (!base.is_number() || !r.errors.count(name)) continue;
      const double b = base.get<double>();
      out.push_back({"drift_" + name + "_n" + n, r.errors.at(name), 0.0, drift_factor * b + drift_slack,
                     "drift baseline (own earlier output, not verification): <= 1.1 x " + std::to_string(b)});
    }
  }
  return out;
}

void write_baseline(const Case& c, const std::vector<Sweep>& sweeps) {
  nlohmann::json variants = nlohmann::json::object();
  for (const auto& s : sweeps)
    for (const auto& r : s.runs) {
      nlohmann::json e = nlohmann::json::object();
      for (const auto& [k, v] : r.errors)
        if (std::isfinite(v)) e[k] = v;
      variants[s.variant()][std::to_string(r.params.value("n", 0L))] = e;
    }
  const nlohmann::json j = {
      {"label", "DRIFT BASELINE: this code's own earlier output, not a verification reference"},
      {"case", c.name},
      {"written_by", "sphv baseline update"},
      {"git_commit", build::git_commit},
      {"factor", drift_factor},
      {"slack", drift_slack},
      {"variants", variants}};
  write_atomically(baseline_dir() / (c.name + ".json"), j.dump(1) + "\n");
}

}  // namespace sphv
