#include "verification/harness/result.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "build_info.hpp"
#include "sph/core/isa.hpp"
#include "verification/support/build_id.hpp"

namespace sphv {

namespace {
std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  for (std::string line; std::getline(f, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

// Whether the sources the binary was built from held uncommitted changes, and which.
nlohmann::json source_tree() {
  nlohmann::json changes = nlohmann::json::array();
  std::istringstream lines(build::tree_changes);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) changes.push_back(line);
  return {{"dirty", build::tree_dirty}, {"changes", changes}};
}
}  // namespace

nlohmann::json provenance() {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {{"git_commit", build::git_commit}, {"source_tree", source_tree()},
          {"executable_sha256", executable_sha256()}, {"compiler", build::compiler},
          {"cxx_flags", build::cxx_flags},   {"build_type", build::build_type},
          {"threads", omp_get_max_threads()}, {"isa_path", sph::isa_name(sph::isa_path())}, {"date", date},
          {"host", host}, {"cpu", cpu_model()}, {"cores", std::thread::hardware_concurrency()}};
}

namespace {
// Figures may hold gaps: a non-finite point is drawn as a gap (null). Nothing else is written
// non-finite: see name_non_finite.
nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }
nlohmann::json numbers(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : v) a.push_back(finite_or_null(x));
  return a;
}
}  // namespace

nlohmann::json to_json(const Figure& f) {
  nlohmann::json s = nlohmann::json::array();
  for (const auto& x : f.series)
    s.push_back({{"label", x.label}, {"x", numbers(x.x)}, {"y", numbers(x.y)}, {"style", x.style}});
  return {{"name", f.name},     {"title", f.title},   {"xlabel", f.xlabel}, {"ylabel", f.ylabel},
          {"xscale", f.xscale}, {"yscale", f.yscale}, {"series", s}};
}

namespace {
std::string text(double v) { return std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"; }

// Every non-finite number inside j, as "where=value"; with fix, each is replaced by null.
void non_finite_in(nlohmann::json& j, const std::string& where, std::vector<std::string>& found, bool fix) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    found.push_back(where + "=" + text(j.get<double>()));
    if (fix) j = nullptr;
  } else if (j.is_object()) {
    for (auto& [k, v] : j.items()) non_finite_in(v, where + "." + k, found, fix);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) non_finite_in(j[i], where + "[" + std::to_string(i) + "]", found, fix);
  }
}

// The non-finite numbers among a result's errors, functionals, extra and particles; with fix,
// they are removed (errors, functionals), nulled (extra) or the particle table dropped.
std::vector<std::string> non_finite(Result& r, bool fix) {
  std::vector<std::string> found;
  for (auto* m : {&r.errors, &r.functionals}) {
    const std::string part = m == &r.errors ? "errors." : "functionals.";
    for (auto it = m->begin(); it != m->end();) {
      if (std::isfinite(it->second)) {
        ++it;
        continue;
      }
      found.push_back(part + it->first + "=" + text(it->second));
      it = fix ? m->erase(it) : std::next(it);
    }
  }
  non_finite_in(r.extra, "extra", found, fix);
  const auto bad_particles = non_finite_entries(r.particles);
  for (const auto& e : bad_particles) found.push_back("particles." + e);
  if (fix && !bad_particles.empty()) r.particles = {};
  return found;
}
}  // namespace

void name_non_finite(Result& r) {
  const auto found = non_finite(r, true);
  if (found.empty()) return;
  std::string list;
  for (std::size_t i = 0; i < found.size() && i < 5; ++i) list += (i ? ", " : "") + found[i];
  if (found.size() > 5) list += " and " + std::to_string(found.size() - 5) + " more";
  r.verdict = (r.verdict == "ok" ? "" : r.verdict + "; ") + "non-finite " + list + " (not written)";
}

nlohmann::json to_json(const Result& r) {
  Result copy = r;  // only when the check fails is the copy's list used
  if (const auto found = non_finite(copy, false); !found.empty())
    throw std::logic_error("refusing to write a non-finite number: " + found.front() + " (" + r.case_name + ")");
  nlohmann::json errors = nlohmann::json::object(), functionals = nlohmann::json::object();
  for (const auto& [k, v] : r.errors) errors[k] = v;
  for (const auto& [k, v] : r.functionals) functionals[k] = v;
  nlohmann::json figures = nlohmann::json::array();
  for (const auto& f : r.figures) figures.push_back(to_json(f));
  return {{"case", r.case_name},       {"params", r.params},   {"n_particles", r.n_particles},
          {"wall_time_s", r.wall_time_s}, {"errors", errors},  {"functionals", functionals},
          {"verdict", r.verdict},      {"figures", figures},   {"extra", r.extra},
          {"provenance", r.provenance.is_null() ? provenance() : r.provenance}};
}

namespace {
std::vector<double> doubles(const nlohmann::json& a) {
  std::vector<double> v;
  for (const auto& x : a) v.push_back(x.is_number() ? x.get<double>() : std::nan(""));
  return v;
}
std::map<std::string, double> named(const nlohmann::json& o) {
  std::map<std::string, double> m;
  for (const auto& [k, v] : o.items())
    if (v.is_number()) m[k] = v.get<double>();  // an older file's null (non-finite) is left out
  return m;
}
}  // namespace

Result result_from_json(const nlohmann::json& j) {
  Result r;
  r.case_name = j.at("case");
  r.params = j.at("params");
  r.n_particles = j.at("n_particles");
  r.wall_time_s = j.at("wall_time_s");
  r.errors = named(j.at("errors"));
  r.functionals = named(j.at("functionals"));
  r.verdict = j.at("verdict");
  r.extra = j.at("extra");
  if (j.contains("provenance")) r.provenance = j.at("provenance");
  for (const auto& f : j.at("figures")) {
    Figure fig{f.at("name"), f.at("title"), f.at("xlabel"), f.at("ylabel"), f.at("xscale"), f.at("yscale"), {}};
    for (const auto& s : f.at("series"))
      fig.series.push_back({s.at("label"), doubles(s.at("x")), doubles(s.at("y")), s.at("style")});
    r.figures.push_back(std::move(fig));
  }
  return r;
}

void write_atomically(const std::filesystem::path& path, const std::string& text) {
  if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
  const auto tmp = path.string() + ".tmp" + std::to_string(getpid());
  {
    std::ofstream f(tmp);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + tmp);
  }
  std::filesystem::rename(tmp, path);
}

std::string csv(const Table& t) {
  std::ostringstream s;
  s.precision(17);
  for (std::size_t c = 0; c < t.names.size(); ++c) s << (c ? "," : "") << t.names[c];
  s << '\n';
  const std::size_t rows = t.columns.empty() ? 0 : t.columns[0].size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < t.columns.size(); ++c) s << (c ? "," : "") << t.columns[c][r];
    s << '\n';
  }
  return s.str();
}

std::vector<std::string> non_finite_entries(const Table& t) {
  std::vector<std::string> found;
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    const auto& col = t.columns[c];
    const auto bad = std::find_if(col.begin(), col.end(), [](double v) { return !std::isfinite(v); });
    if (bad != col.end()) found.push_back(t.names[c] + "[" + std::to_string(bad - col.begin()) + "]=" + text(*bad));
  }
  return found;
}

void write_result(const Result& r, const std::filesystem::path& dir) {
  write_atomically(dir / "result.json", to_json(r).dump(1) + "\n");
  if (!r.particles.empty()) write_atomically(dir / "particles.csv", csv(r.particles));
}

}  // namespace sphv
