#include "verification/score.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace sphv {

const Scorer& find_scorer(const std::string& case_name) {
  const auto it = scorers().find(case_name);
  if (it != scorers().end()) return it->second;
  std::string names;
  for (const auto& [k, v] : scorers()) names += (names.empty() ? "" : ", ") + k;
  throw InputError("case '" + case_name + "' cannot score snapshots (cases that can: " + names + ")");
}

bool has_scorer(const std::string& case_name) { return scorers().count(case_name) > 0; }

namespace {

// The value of key in key=value settings, if set there.
std::optional<std::string> setting(const std::vector<std::string>& settings, const std::string& key) {
  std::optional<std::string> v;
  for (const auto& s : settings)
    if (s.rfind(key + "=", 0) == 0) v = s.substr(key.size() + 1);
  return v;
}

// A time as the console and the settings show it: the shortest form that reads back exactly.
std::string number(double v) { return shortest(v); }

bool has_param(const Case& c, const std::string& key) {
  for (const auto& p : c.params)
    if (p.name == key) return true;
  return false;
}

}  // namespace

Result score_snapshot(const Case& c, std::vector<std::string> settings, const Snapshot& s) {
  const Scorer& sc = find_scorer(c.name);
  const std::string f = s.path.string();
  if (!sc.time_key.empty()) {
    const auto given = setting(settings, sc.time_key);
    if (given && s.time) {
      char* end = nullptr;
      const double t = std::strtod(given->c_str(), &end);
      if (end == given->c_str() || *end != '\0') throw InputError("--set " + sc.time_key + "=" + *given + ": not a number");
      if (!(std::abs(t - *s.time) <= 1e-12 * std::max(1.0, std::abs(*s.time))))
        throw InputError(f + ": its header says time " + number(*s.time) + " but --set " + sc.time_key + "=" + *given);
    } else if (s.time) {
      settings.push_back(sc.time_key + "=" + number(*s.time));
    } else if (!given) {
      throw InputError(f + ": no time in the snapshot (give it with --set " + sc.time_key + "=T)");
    }
  }
  if (has_param(c, "dim")) {
    if (const auto d = setting(settings, "dim")) {
      const long dim = std::strtol(d->c_str(), nullptr, 10);
      if (dim > s.dim)
        throw InputError(f + ": has " + std::to_string(s.dim) + " coordinate(s) but dim=" + *d);
      for (int a = static_cast<int>(dim); a < s.dim; ++a) {
        const auto& col = s.columns.at(std::string(1, "xyz"[a]));
        for (double v : col)
          if (v != col.front())
            throw InputError(f + ": " + std::to_string(s.dim) + "D particles (" + std::string(1, "xyz"[a]) +
                             " varies) but dim=" + *d);
      }
    } else {
      settings.push_back("dim=" + std::to_string(s.dim));
    }
  }
  if (sc.n_per_side && !setting(settings, "n")) {
    const long dim = has_param(c, "dim") ? Params(c.name, c.params, settings).integer("dim") : s.dim;
    settings.push_back("n=" + std::to_string(std::lround(std::pow(double(s.size()), 1.0 / dim))));
  }
  const Params p = c.parse(settings);
  const auto t0 = std::chrono::steady_clock::now();
  Result r = sc.score(p, s);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.case_name = c.name;
  r.params = p.to_json();
  r.n_particles = s.size();
  nlohmann::json cols = nlohmann::json::object();
  for (const auto& [k, v] : s.taken_from)
    if (s.has(k)) cols[k] = v;
  r.extra["snapshot"] = {{"format", s.format}, {"dim", s.dim}, {"columns", cols},
                         {"time", s.time ? nlohmann::json(*s.time) : nlohmann::json()}};
  nlohmann::json defs = nlohmann::json::object();  // the case's definitions (sphv info CASE)
  for (const auto& [k, v] : r.errors)
    if (c.error_defs.count(k)) defs[k] = c.error_defs.at(k);
  r.extra["error_defs"] = defs;
  name_non_finite(r);  // a snapshot's extreme values (u = 1e300) can overflow an error: a verdict, not a NaN
  return r;
}

void write_score(const Result& r, const Snapshot& s, const std::filesystem::path& dir) {
  nlohmann::json j = to_json(r);
  j["provenance"]["snapshot"] = file_provenance(s.path);
  write_atomically(dir / "result.json", j.dump(1) + "\n");
}

void score_command(const ScoreOptions& o) {
  const Case& c = find_case(o.case_name);
  find_scorer(c.name);
  const Snapshot s = read_snapshot(o.snapshot, o.format, o.step >= 0 ? std::optional<long>(o.step) : std::nullopt);
  const Result r = score_snapshot(c, o.settings, s);
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / (c.name + "-score") : o.out;
  write_score(r, s, dir);
  std::printf("%s: %zu particles (%s, %dD, t = %s): %s\n", o.snapshot.c_str(), s.size(), s.format.c_str(), s.dim,
              s.time ? number(*s.time).c_str() : "-", s.describe().c_str());
  std::string line = c.name;
  for (const auto& [k, v] : r.errors) {
    char buf[96];
    std::snprintf(buf, sizeof buf, ", %s=%.6e", k.c_str(), v);
    line += buf;
  }
  std::printf("%s, verdict: %s; written %s\n", line.c_str(), r.verdict.c_str(), (dir / "result.json").c_str());
}

}  // namespace sphv
