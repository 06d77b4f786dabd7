#include "verification/commands/score.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace sphv {

const Scorer& find_scorer(const std::string& case_name) {
  const Case& c = find_case(case_name);
  if (c.scorer.score) return c.scorer;
  std::string names;
  for (const auto& k : catalogue())
    if (k.scorer.score) names += (names.empty() ? "" : ", ") + k.name;
  throw InputError("case '" + case_name + "' cannot score snapshots (cases that can: " + names + ")");
}

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

const ParamSpec* find_param(const Case& c, const std::string& key) {
  for (const auto& p : c.params)
    if (p.name == key) return &p;
  return nullptr;
}
bool has_param(const Case& c, const std::string& key) { return find_param(c, key) != nullptr; }

// A setting's value as a number, parsed as the case parses it (text parameters such as the
// tubes' gamma: a plain number).
double set_number(const Case& c, const std::string& key, const std::string& text) {
  const ParamSpec* spec = find_param(c, key);
  if (spec && spec->kind == ParamSpec::Kind::Real) return Params(c.name, {*spec}, {key + "=" + text}).real(key);
  double v = 0.0;
  if (!parse_finite(text, v)) throw InputError("--set " + key + "=" + text + ": not a finite number");
  return v;
}

// Comma-separated finite numbers (a centre, a domain).
std::vector<double> numbers(const std::string& key, const std::string& text) {
  std::vector<double> v;
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t to = std::min(text.find(',', from), text.size());
    double x = 0.0;
    if (!parse_finite(std::string_view(text).substr(from, to - from), x))
      throw InputError("--set " + key + "=" + text + ": not comma-separated finite numbers");
    v.push_back(x);
    from = to + 1;
  }
  return v;
}

std::string brief(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", v);
  return buf;
}

std::string joined(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ",") + shortest(x);
  return s;
}

// Equal within the round-off the file stores its value with (and a double's).
bool agrees(double set, double stated, double round_off) {
  return std::abs(set - stated) <= 2.0 * (round_off + std::ldexp(1.0, -52)) * std::max(std::abs(set), std::abs(stated));
}

// The settings completed from the file, and where each value came from.
struct Completion {
  const Case& c;
  const Snapshot& s;
  bool force;
  std::vector<std::string> settings;
  nlohmann::json values = nlohmann::json::object();  // key -> {value, from}

  std::string file() const { return s.path.string(); }
  void record(const std::string& key, const std::string& value, const std::string& from) {
    values[key] = {{"value", value}, {"from", from}};
  }
  // key from the file unless set; a set value that the file contradicts (agree false) is refused
  // unless forced.
  void take(const std::string& key, const std::string& stated, const std::string& from,
            const std::function<bool(const std::string&)>& agree) {
    if (const auto given = setting(settings, key)) {
      if (agree(*given)) return record(key, *given, "--set (agrees with the file's " + from + ")");
      if (!force)
        throw InputError(file() + ": its " + from + " says " + key + "=" + stated + " but --set " + key + "=" + *given +
                         " (--force to score with the setting)");
      return record(key, *given, "--set, forced against the file's " + from + " (" + stated + ")");
    }
    settings.push_back(key + "=" + stated);
    record(key, stated, "file: " + from);
  }
  void set_or_default(const std::string& key, const std::string& default_value, const std::string& why) {
    if (const auto given = setting(settings, key)) return record(key, *given, "--set");
    record(key, default_value, "default (" + why + ")");
  }
};

void complete_time(Completion& k, const Scorer& sc) {
  if (sc.time_key.empty()) return;
  const Snapshot& s = k.s;
  if (s.time) {
    const double t = *s.time;
    k.take(sc.time_key, shortest(t), s.time_from.empty() ? "header time" : s.time_from, [&](const std::string& v) {
      return std::abs(set_number(k.c, sc.time_key, v) - t) <= 1e-12 * std::max(1.0, std::abs(t));
    });
  } else if (setting(k.settings, sc.time_key)) {
    k.record(sc.time_key, *setting(k.settings, sc.time_key), "--set");
  } else {
    throw InputError(k.file() + ": no time in the snapshot (give it with --set " + sc.time_key + "=T)");
  }
}

void complete_dim(Completion& k) {
  const Snapshot& s = k.s;
  if (!has_param(k.c, "dim")) return;
  if (const auto d = setting(k.settings, "dim")) {
    const long dim = std::strtol(d->c_str(), nullptr, 10);
    if (dim > s.dim) throw InputError(k.file() + ": has " + std::to_string(s.dim) + " coordinate(s) but dim=" + *d);
    for (int a = static_cast<int>(dim); a < s.dim; ++a) {
      const auto& col = s.columns.at(std::string(1, "xyz"[a]));
      for (double v : col)
        if (v != col.front())
          throw InputError(k.file() + ": " + std::to_string(s.dim) + "D particles (" + std::string(1, "xyz"[a]) +
                           " varies) but dim=" + *d);
    }
    k.record("dim", *d, "--set");
  } else {
    k.settings.push_back("dim=" + std::to_string(s.dim));
    k.record("dim", std::to_string(s.dim), "file: its coordinates");
  }
}

void complete_gamma(Completion& k) {
  if (!has_param(k.c, "gamma")) return;
  const auto it = k.s.stated.find("gamma");
  if (it == k.s.stated.end()) return k.set_or_default("gamma", "", "the case's: the file states none");  // value filled in once parsed
  const Stated& g = it->second;
  k.take("gamma", shortest(g.value.at(0)), g.from,
         [&](const std::string& v) { return agrees(set_number(k.c, "gamma", v), g.value.at(0), g.round_off); });
}

// The radial cases' centre: the box's middle by default (without a box, the case's default); a
// set centre has a component per dimension and lies inside a stated box.
void complete_centre(Completion& k, int dim) {
  if (!has_param(k.c, "centre")) return;
  const auto box = k.s.stated.find("box");
  if (const auto given = setting(k.settings, "centre")) {
    const auto c = numbers("centre", *given);
    if (c.size() < static_cast<std::size_t>(dim) || c.size() > 3)
      throw InputError(k.file() + ": --set centre=" + *given + " has " + std::to_string(c.size()) + " component(s) for " +
                       std::to_string(dim) + "D particles (give " + std::to_string(dim) + ")");
    bool inside = true;
    if (box != k.s.stated.end())
      for (int d = 0; d < dim; ++d) inside = inside && c[d] >= box->second.value[2 * d] && c[d] <= box->second.value[2 * d + 1];
    if (inside) return k.record("centre", *given, "--set");
    if (!k.force)
      throw InputError(k.file() + ": --set centre=" + *given + " lies outside its box (" + box->second.from + ": " +
                       joined(box->second.value) + "; --force to score with it)");
    return k.record("centre", *given, "--set, forced outside the file's box");
  }
  if (box == k.s.stated.end())
    return k.set_or_default("centre", find_param(k.c, "centre")->default_value, "the case's: the file states no box");
  std::vector<double> mid;
  for (int d = 0; d < dim; ++d) mid.push_back(0.5 * (box->second.value[2 * d] + box->second.value[2 * d + 1]));
  k.settings.push_back("centre=" + joined(mid));
  k.record("centre", joined(mid), "file: the middle of its box (" + box->second.from + ")");
}

// The tubes' domain (the box along x) and ends (periodic or closed, as the file states).
void complete_tube(Completion& k) {
  if (!has_param(k.c, "ends")) return;
  const auto box = k.s.stated.find("box");
  const auto periodic = k.s.stated.find("periodic");
  if (box != k.s.stated.end()) {
    const double lo = box->second.value[0], hi = box->second.value[1];
    k.take("domain", shortest(lo) + "," + shortest(hi), box->second.from + " along x", [&](const std::string& v) {
      const auto d = numbers("domain", v);
      return d.size() == 2 && agrees(d[0], lo, 0.0) && agrees(d[1], hi, 0.0);
    });
  } else {
    k.set_or_default("domain", "0,1", "Toro's tube: the file states no box");
  }
  if (periodic != k.s.stated.end()) {
    const bool yes = periodic->second.value.at(0) != 0.0;
    k.take("ends", yes ? "periodic" : "closed", periodic->second.from,
           [&](const std::string& v) { return (v == "periodic") == yes; });
  } else if (box != k.s.stated.end() && !setting(k.settings, "ends")) {
    k.settings.push_back("ends=closed");
    k.record("ends", "closed", "default (the file states a box but not whether it is periodic)");
  } else {
    k.set_or_default("ends", "open", "the file states no box: a window of an unbounded tube");
  }
  if (const auto x0 = setting(k.settings, "x0"); x0 && *x0 != "preset") k.record("x0", *x0, "--set");
  else k.record("x0", "", "default: the domain's middle");  // value filled in once scored
}

// Whether the case accepts these settings.
bool accepted(const Case& c, const std::vector<std::string>& settings) {
  try {
    c.parse(settings);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// n from the particle count, as the case counts it. A count below what the case's runs accept
// (sedov n >= 8, noh's shock resolution, evrard n >= 100) leaves n at its default, saying why:
// the scorers read n only for bin widths and titles.
void complete_n(Completion& k, const Scorer& sc) {
  if (sc.n == Resolution::none) return;
  if (const auto given = setting(k.settings, "n")) return k.record("n", *given, "--set");
  std::string n, how;
  if (sc.n == Resolution::count) {
    n = std::to_string(k.s.size());
    how = "snapshot: its particle count N";
  } else {
    const long dim = has_param(k.c, "dim") ? Params(k.c.name, k.c.params, k.settings).integer("dim") : k.s.dim;
    const auto box = k.s.stated.find("box");
    const double side = box == k.s.stated.end() ? 1.0 : box->second.value[1] - box->second.value[0];
    n = std::to_string(std::max(1L, std::lround(std::pow(double(k.s.size()), 1.0 / dim) / side)));
    how = "snapshot: N^(1/" + std::to_string(dim) + ") / L = " + std::to_string(k.s.size()) + "^(1/" + std::to_string(dim) +
          ") / " + shortest(side) + " particles per unit length (L: " +
          (box == k.s.stated.end() ? std::string("1, the file states no box") : "the box's side along x, " + box->second.from) + ")";
  }
  auto with_n = k.settings;
  with_n.push_back("n=" + n);
  if (!accepted(k.c, with_n) && accepted(k.c, k.settings))
    return k.record("n", Params(k.c.name, k.c.params, k.settings).text("n"),
                    "default: the snapshot's n = " + n + " (" + how + ") is below what the case's runs accept");
  k.settings = std::move(with_n);
  k.record("n", n, how);
}

// p = (gamma - 1) rho u for every particle where the three are present, within their round-off:
// each value's relative round-off as stored, at least float32's (codes compute in single
// precision and write doubles, or convert float32 files to text: the stored type does not tell),
// and the writer's own product (two roundings), times 8 for the pow or division a code may take
// instead (SWIFT derives u and p from its entropy). Measured on SWIFT's two float32 snapshots
// (tests/data) with their own gamma: the largest relative residual is 1.8e-7, the bound 2.4e-6
// (margin 13); gamma 1.4 against 5/3 is off by 0.4 relative.
void check_equation_of_state(const Completion& k, const Params& p, const Scorer& sc) {
  const Snapshot& s = k.s;
  if (!sc.gamma || !s.has("p") || !s.has("rho") || !s.has("u")) return;
  const double gamma = sc.gamma(p);
  const auto &P = s.columns.at("p"), &rho = s.columns.at("rho"), &u = s.columns.at("u");
  const double single = std::ldexp(1.0, -24);
  auto ro = [&](const std::string& c) { return std::max(single, s.round_off.count(c) ? s.round_off.at(c) : 0.0); };
  const double tol = 8.0 * (ro("p") + ro("rho") + ro("u") + 2.0 * std::max({ro("p"), ro("rho"), ro("u")}));
  std::size_t worst = 0;
  double worst_rel = 0.0;
  std::vector<double> implied;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double eos = (gamma - 1.0) * rho[i] * u[i], scale = std::max(std::abs(P[i]), std::abs(eos));
    if (scale == 0.0) continue;
    const double rel = std::abs(P[i] - eos) / scale;
    if (rel > worst_rel) worst_rel = rel, worst = i;
    if (rho[i] * u[i] != 0.0) implied.push_back(1.0 + P[i] / (rho[i] * u[i]));
  }
  if (worst_rel <= tol) return;
  std::nth_element(implied.begin(), implied.begin() + implied.size() / 2, implied.end());
  const std::string from = k.values.contains("gamma") ? k.values["gamma"]["from"].get<std::string>() : "the case's";
  throw InputError(k.file() + ": p = (gamma - 1) rho u does not hold with the gamma in use, " + shortest(gamma) + " (" + from +
                   "): the data's p / (rho u) gives gamma " + (implied.empty() ? std::string("-") : shortest(implied[implied.size() / 2])) +
                   " (particle " + std::to_string(worst) + " off by " + brief(worst_rel) + " relative, bound " + brief(tol) +
                   "; --set gamma=G to score another gas)");
}

}  // namespace

namespace {

// The settings completed from the file and parsed, with the record of where each value came from.
Params complete(Completion& k, const Scorer& sc) {
  complete_time(k, sc);
  complete_dim(k);
  const int dim = has_param(k.c, "dim") ? static_cast<int>(std::strtol(setting(k.settings, "dim")->c_str(), nullptr, 10))
                                        : k.s.dim;
  complete_gamma(k);
  complete_centre(k, dim);
  complete_tube(k);
  complete_n(k, sc);
  for (const std::string& key : sc.constants)
    for (const ParamSpec& ps : k.c.params)
      if (ps.name == key) k.set_or_default(key, ps.default_value, "the case's: no file states it");
  const Params p = k.c.parse(k.settings);
  check_equation_of_state(k, p, sc);
  return p;
}

nlohmann::json snapshot_json(const Snapshot& s, const nlohmann::json& values) {
  nlohmann::json cols = nlohmann::json::object();
  for (const auto& [key, v] : s.taken_from)
    if (s.has(key)) cols[key] = v;
  return {{"format", s.format}, {"dim", s.dim}, {"columns", cols},
          {"time", s.time ? nlohmann::json(*s.time) : nlohmann::json()}, {"values", values}};
}

void finish(Result& r, const Case& c, const Params& p, std::size_t particles) {
  r.case_name = c.name;
  r.params = p.to_json();
  r.n_particles = particles;
  nlohmann::json defs = nlohmann::json::object();  // the case's definitions (sphv info CASE)
  for (const auto& [key, v] : r.errors)
    if (c.error_defs.count(key)) defs[key] = c.error_defs.at(key);
  if (r.extra.contains("problem_check") && c.error_defs.count("mismatch")) defs["mismatch"] = c.error_defs.at("mismatch");
  r.extra["error_defs"] = defs;
  name_non_finite(r);  // a snapshot's extreme values (u = 1e300) can overflow an error: a verdict, not a NaN
}

}  // namespace

Result score_snapshot(const Case& c, std::vector<std::string> settings, const Snapshot& s, bool force) {
  const Scorer& sc = find_scorer(c.name);
  if (sc.series) return score_snapshots(c, settings, {s}, force);
  Completion k{c, s, force, std::move(settings), nlohmann::json::object()};
  const Params p = complete(k, sc);
  const auto t0 = std::chrono::steady_clock::now();
  Result r = sc.score(p, s);
  if (k.values.contains("gamma") && k.values["gamma"]["value"] == "") k.values["gamma"]["value"] = shortest(sc.gamma(p));
  if (k.values.contains("x0") && k.values["x0"]["value"] == "") k.values["x0"]["value"] = shortest(r.extra["x0"].get<double>());
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.extra["snapshot"] = snapshot_json(s, k.values);
  finish(r, c, p, s.size());
  return r;
}

Result score_snapshots(const Case& c, const std::vector<std::string>& settings, const std::vector<Snapshot>& snaps,
                       bool force) {
  const Scorer& sc = find_scorer(c.name);
  if (snaps.empty()) throw InputError("score " + c.name + ": no snapshot");
  if (!sc.series) {
    if (snaps.size() > 1)
      throw InputError("score " + c.name + ": scores one snapshot, got " + std::to_string(snaps.size()) +
                       " (only a time-series case, e.g. kh, takes several)");
    return score_snapshot(c, settings, snaps.front(), force);
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Result> each;
  std::vector<std::string> first_settings;
  nlohmann::json listed = nlohmann::json::array();
  std::size_t particles = 0;
  std::optional<Params> params;
  for (const Snapshot& s : snaps) {
    Completion k{c, s, force, settings, nlohmann::json::object()};
    const Params p = complete(k, sc);
    if (!params) params = p, first_settings = k.settings;
    else if (k.settings != first_settings)
      throw InputError(s.path.string() + ": its values (" + p.to_json().dump() + ") differ from " +
                       snaps.front().path.string() + "'s (" + params->to_json().dump() +
                       "): one series is one run (--set the values to score them alike)");
    each.push_back(sc.score(p, s));
    if (k.values.contains("gamma") && k.values["gamma"]["value"] == "") k.values["gamma"]["value"] = shortest(sc.gamma(p));
    listed.push_back(snapshot_json(s, k.values));
    listed.back()["path"] = s.path.string();
    particles = std::max(particles, s.size());
  }
  Result r = sc.series(*params, each);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.extra["snapshots"] = listed;
  r.extra["snapshot"] = listed.front();
  finish(r, c, *params, particles);
  return r;
}

void write_score(const Result& r, const std::vector<Snapshot>& s, const std::filesystem::path& dir) {
  nlohmann::json j = to_json(r);
  if (s.size() == 1) {
    j["provenance"]["snapshot"] = file_provenance(s.front().path);
  } else {
    j["provenance"]["snapshots"] = nlohmann::json::array();
    for (const Snapshot& one : s) j["provenance"]["snapshots"].push_back(file_provenance(one.path));
  }
  write_atomically(dir / "result.json", j.dump(1) + "\n");
}

int score_command(const ScoreOptions& o) {
  const Case& c = find_case(o.case_name);
  const Scorer& sc = find_scorer(c.name);
  if (o.snapshots.size() > 1 && !sc.series)
    throw InputError("score " + c.name + ": scores one snapshot, got " + std::to_string(o.snapshots.size()) +
                     " (only a time-series case, e.g. kh, takes several)");
  std::vector<Snapshot> snaps;
  for (const auto& path : o.snapshots)
    snaps.push_back(read_snapshot(path, o.format, o.step >= 0 ? std::optional<long>(o.step) : std::nullopt));
  const Result r = score_snapshots(c, o.settings, snaps, o.force);
  const auto dir = o.out.empty() ? std::filesystem::path("runs") / (c.name + "-score") : o.out;
  write_score(r, snaps, dir);
  for (const Snapshot& s : snaps)
    std::printf("%s: %zu particles (%s, %dD, t = %s): %s\n", s.path.c_str(), s.size(), s.format.c_str(), s.dim,
                s.time ? number(*s.time).c_str() : "-", s.describe().c_str());
  std::string values;
  for (const auto& [key, v] : r.extra["snapshot"]["values"].items())
    values += (values.empty() ? "" : "; ") + key + "=" + v["value"].get<std::string>() + " (" + v["from"].get<std::string>() + ")";
  std::printf("values%s: %s\n", snaps.size() > 1 ? " (every file alike)" : "", values.c_str());
  if (r.extra.contains("particles_scored"))
    std::printf("scored %zu of %zu particles (%s)\n", r.extra["particles_scored"].get<std::size_t>(), snaps.front().size(),
                r.extra["window"].get<std::string>().c_str());
  if (r.extra.contains("series_note")) std::printf("%s\n", r.extra["series_note"].get<std::string>().c_str());
  if (r.extra.contains("mismatch")) std::printf("mismatch: %s\n", r.extra["mismatch"].get<std::string>().c_str());
  if (r.extra.contains("problem_check_note"))  // the errors stand unchecked: said, not hidden
    std::printf("problem check: %s\n", r.extra["problem_check_note"].get<std::string>().c_str());
  std::string line = c.name;
  for (const auto& [k, v] : r.errors) {
    char buf[96];
    std::snprintf(buf, sizeof buf, ", %s=%.6e", k.c_str(), v);
    line += buf;
  }
  std::printf("%s, verdict: %s; written %s\n", line.c_str(), r.verdict.c_str(), (dir / "result.json").c_str());
  return r.verdict == "ok" ? 0 : 1;
}

}  // namespace sphv
