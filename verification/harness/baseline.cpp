#include "verification/harness/baseline.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include "build_info.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv {

namespace {
std::optional<std::filesystem::path>& chosen_dir() {
  static std::optional<std::filesystem::path> dir;
  return dir;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
}  // namespace

void set_baseline_dir(const std::filesystem::path& dir) { chosen_dir() = dir; }

std::filesystem::path baseline_dir() {
  if (chosen_dir()) return *chosen_dir();
  return std::filesystem::canonical("/proc/self/exe").parent_path().parent_path() / "reference" / "baselines";
}

std::vector<Check> drift_checks(const Sweep& s) {
  // A sweep of a case outside the catalogue (a test's own) has no baseline.
  const auto& all = catalogue();
  const auto it = std::find_if(all.begin(), all.end(), [&](const Case& k) { return k.name == s.case_name; });
  if (it == all.end()) return {};
  const Case& c = *it;
  const bool catalogued = c.has_tag("gate") && std::any_of(c.variants.begin(), c.variants.end(), [&](const auto& v) {
                            return c.parse(v).non_defaults() == s.settings;
                          });
  const auto file = baseline_dir() / (s.case_name + ".json");
  nlohmann::json j;
  if (std::ifstream f(file); f) j = nlohmann::json::parse(f, nullptr, false);
  const bool readable = j.is_object() && j.contains("variants") && j["variants"].is_object();
  if (!readable || !j["variants"].contains(s.variant())) {
    if (!catalogued) return {};
    return {{"drift_baseline_present", 0.0, 1.0, 1.0,
             (readable ? "no variant '" + s.variant() + "' in " : "missing or unreadable: ") + file.string() +
                 " (sphv baseline update writes it; or pass --baselines DIR)",
             Check::Kind::drift, ""}};
  }
  const auto& v = j["variants"][s.variant()];
  std::vector<Check> out;
  for (const auto& r : s.runs) {
    const std::string n = std::to_string(r.params.value("n", 0L));
    if (!v.contains(n)) continue;
    for (const auto& [name, base] : v[n].items()) {
      if (!base.is_number() || !r.errors.count(name)) continue;
      const double b = base.get<double>();
      out.push_back({"drift_" + name + "_n" + n, r.errors.at(name), std::max(0.0, drift_stale * b - drift_slack),
                     drift_grow * b + drift_slack,
                     "drift baseline (own earlier output, not verification) " + fmt(b) +
                         ": above 1.1x it grew; below 0.9x the baseline is stale, update on purpose",
                     Check::Kind::drift, name});
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
      {"grow", drift_grow},
      {"stale", drift_stale},
      {"slack", drift_slack},
      {"variants", variants}};
  write_atomically(baseline_dir() / (c.name + ".json"), j.dump(1) + "\n");
}

}  // namespace sphv
