#include "verification/result.hpp"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "build_info.hpp"

namespace sphv {

namespace {
std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  for (std::string line; std::getline(f, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}
}  // namespace

nlohmann::json provenance() {
  char host[256] = "unknown";
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {{"git_commit", build::git_commit}, {"compiler", build::compiler},
          {"cxx_flags", build::cxx_flags},   {"build_type", build::build_type},
          {"threads", omp_get_max_threads()}, {"date", date},
          {"host", host}, {"cpu", cpu_model()}, {"cores", std::thread::hardware_concurrency()}};
}

namespace {
// JSON has no NaN or infinity: non-finite numbers are written as null and named in the verdict.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }
nlohmann::json numbers(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : v) a.push_back(number(x));
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

nlohmann::json to_json(const Result& r) {
  nlohmann::json errors = nlohmann::json::object(), functionals = nlohmann::json::object();
  for (const auto& [k, v] : r.errors) errors[k] = number(v);
  for (const auto& [k, v] : r.functionals) functionals[k] = number(v);
  nlohmann::json figures = nlohmann::json::array();
  for (const auto& f : r.figures) figures.push_back(to_json(f));
  return {{"case", r.case_name},       {"params", r.params},   {"n_particles", r.n_particles},
          {"wall_time_s", r.wall_time_s}, {"errors", errors},  {"functionals", functionals},
          {"verdict", r.verdict},      {"figures", figures},   {"extra", r.extra},
          {"provenance", provenance()}};
}

namespace {
std::vector<double> doubles(const nlohmann::json& a) {
  std::vector<double> v;
  for (const auto& x : a) v.push_back(x.is_number() ? x.get<double>() : std::nan(""));
  return v;
}
std::map<std::string, double> named(const nlohmann::json& o) {
  std::map<std::string, double> m;
  for (const auto& [k, v] : o.items()) m[k] = v.is_number() ? v.get<double>() : std::nan("");
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

void write_result(const Result& r, const std::filesystem::path& dir) {
  write_atomically(dir / "result.json", to_json(r).dump(1) + "\n");
  if (!r.particles.empty()) write_atomically(dir / "particles.csv", csv(r.particles));
}

}  // namespace sphv
