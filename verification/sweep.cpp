#include "verification/sweep.hpp"

#include "verification/baseline.hpp"

#include <gsl/gsl_fit.h>

#include <chrono>
#include <cmath>
#include <limits>

namespace sphv {

bool Sweep::passed() const {
  for (const auto& c : checks)
    if (!c.pass()) return false;
  return true;
}

std::string Sweep::variant() const {
  if (settings.empty()) return "default";
  std::string s;
  for (const auto& kv : settings) s += (s.empty() ? "" : ",") + kv;
  return s;
}

double observed_order(const std::vector<double>& n, const std::vector<double>& err) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < n.size() && k < err.size(); ++k)
    if (err[k] > 0.0 && std::isfinite(err[k])) {
      x.push_back(std::log(n[k]));
      y.push_back(std::log(err[k]));
    }
  if (x.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return -c1;
}

std::optional<Gci> grid_convergence_index(const std::vector<double>& n, const std::vector<double>& f,
                                          double expected_order) {
  const std::size_t k = n.size();
  if (k < 2 || f.size() != k) return std::nullopt;
  const double f1 = f[k - 1], f2 = f[k - 2];  // finest, next
  const double r = n[k - 1] / n[k - 2];
  if (!(r > 1.0) || !std::isfinite(f1) || f1 == 0.0) return std::nullopt;
  Gci g{f1, expected_order, r, 3.0, 0.0};
  if (k >= 3) {
    const double f3 = f[k - 3], r23 = n[k - 2] / n[k - 3];
    const double e21 = f1 - f2, e32 = f2 - f3;
    g.safety = 1.25;
    // Three levels at a constant ratio give the order directly (Roache 1994).
    if (std::abs(r23 - r) < 1e-9 * r && e21 != 0.0 && e32 != 0.0 && e32 / e21 > 0.0)
      g.order = std::log(e32 / e21) / std::log(r);
  }
  if (!(g.order > 0.0) || !std::isfinite(g.order)) return std::nullopt;
  g.gci = g.safety * std::abs((f1 - f2) / f1) / (std::pow(r, g.order) - 1.0);
  return g;
}

std::vector<Check> order_checks(const Sweep& s, double band, const std::string& why) {
  std::vector<Check> c;
  for (const auto& [name, p] : s.expected_order)
    if (s.observed_order.count(name))
      c.push_back({"order_" + name, s.observed_order.at(name), p - band, p + band, why});
  return c;
}

Sweep summarise(const Case& c, const std::vector<std::string>& settings, const std::vector<long>& levels,
                std::vector<Result> runs) {
  Sweep s;
  s.case_name = c.name;
  s.summary = c.summary;
  s.n_counts = c.n_counts;
  s.expected_why = c.expected_why;
  s.levels = levels;
  const Params base = c.parse(settings);
  s.settings = base.non_defaults();
  if (c.expected_order) s.expected_order = c.expected_order(base);
  s.runs = std::move(runs);
  for (const auto& r : s.runs) s.wall_time_s += r.wall_time_s;

  std::vector<double> n(levels.begin(), levels.end());
  std::map<std::string, std::vector<double>> errs, funcs;
  for (const auto& r : s.runs) {
    for (const auto& [k, v] : r.errors) errs[k].push_back(v);
    for (const auto& [k, v] : r.functionals) funcs[k].push_back(v);
  }
  for (const auto& [k, v] : errs)
    if (v.size() == n.size()) s.observed_order[k] = observed_order(n, v);
  for (const auto& [k, v] : funcs) {
    double p = s.expected_order.empty() ? 1.0 : s.expected_order.begin()->second;
    if (v.size() == n.size())
      if (auto g = grid_convergence_index(n, v, p)) s.gci[k] = *g;
  }
  if (c.gates) s.checks = c.gates(s);
  for (auto& d : drift_checks(s)) s.checks.push_back(std::move(d));
  return s;
}

Sweep run_sweep(const Case& c, const std::vector<long>& levels, const std::vector<std::string>& settings,
                const std::optional<std::filesystem::path>& out, const RunOptions& opt) {
  std::vector<Point> points;
  for (long n : levels) points.push_back({settings, n, out ? *out / ("n" + std::to_string(n)) : ""});
  Sweep s = summarise(c, settings, levels, run_points(c, points, opt));
  if (out) write_atomically(*out / "sweep.json", to_json(s).dump(1) + "\n");
  return s;
}

std::vector<std::vector<std::string>> expand_variants(const std::vector<std::string>& base,
                                                      const std::vector<std::string>& vary) {
  std::vector<std::vector<std::string>> out = {base};
  for (const auto& kv : vary) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == kv.size())
      throw InputError("malformed --vary '" + kv + "': expected key=a,b,c");
    std::vector<std::vector<std::string>> next;
    for (const auto& v : out) {
      std::size_t from = eq + 1;
      while (from <= kv.size()) {
        const auto comma = std::min(kv.find(',', from), kv.size());
        auto w = v;
        w.push_back(kv.substr(0, eq + 1) + kv.substr(from, comma - from));
        next.push_back(std::move(w));
        from = comma + 1;
      }
    }
    out = std::move(next);
  }
  return out;
}

std::vector<Sweep> run_sweeps(const Case& c, const std::vector<long>& levels,
                              const std::vector<std::vector<std::string>>& variants,
                              const std::filesystem::path& out, const RunOptions& opt) {
  std::vector<Point> points;
  std::vector<std::vector<long>> lv;
  std::vector<std::filesystem::path> dirs;
  for (const auto& v : variants) {
    lv.push_back(c.levels_for ? c.levels_for(c.parse(v), levels) : levels);
    const Sweep label{.settings = c.parse(v).non_defaults()};
    dirs.push_back(variants.size() == 1 ? out : out / label.variant());
    for (long n : lv.back()) points.push_back({v, n, dirs.back() / ("n" + std::to_string(n))});
  }
  std::vector<Result> results = run_points(c, points, opt);
  std::vector<Sweep> sweeps;
  if (results.empty()) return sweeps;  // an MPI rank other than 0
  auto it = results.begin();
  for (std::size_t k = 0; k < variants.size(); ++k) {
    std::vector<Result> runs(it, it + lv[k].size());
    it += lv[k].size();
    sweeps.push_back(summarise(c, variants[k], lv[k], std::move(runs)));
    write_atomically(dirs[k] / "sweep.json", to_json(sweeps.back()).dump(1) + "\n");
  }
  return sweeps;
}

nlohmann::json to_json(const Sweep& s) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json runs = nlohmann::json::array(), order = nlohmann::json::object(),
                 expected = nlohmann::json::object(), gci = nlohmann::json::object(),
                 checks = nlohmann::json::array();
  for (const auto& r : s.runs) runs.push_back(to_json(r));
  for (const auto& [k, v] : s.observed_order) order[k] = num(v);
  for (const auto& [k, v] : s.expected_order) expected[k] = v;
  for (const auto& [k, g] : s.gci)
    gci[k] = {{"fine_value", num(g.fine_value)}, {"order", num(g.order)}, {"ratio", g.ratio},
              {"Fs", g.safety}, {"gci", num(g.gci)}};
  for (const auto& c : s.checks)
    checks.push_back({{"name", c.name}, {"value", num(c.value)}, {"lo", num(c.lo)}, {"hi", num(c.hi)},
                      {"why", c.why}, {"pass", c.pass()}});
  return {{"case", s.case_name}, {"summary", s.summary}, {"n_counts", s.n_counts},
          {"expected_why", s.expected_why}, {"variant", s.variant()}, {"settings", s.settings},
          {"levels", s.levels},  {"runs", runs},           {"observed_order", order},
          {"expected_order", expected}, {"gci", gci},      {"checks", checks},
          {"passed", s.passed()}, {"wall_time_s", s.wall_time_s}};
}

}  // namespace sphv
