#include "verification/harness/sweep.hpp"

#include "verification/harness/baseline.hpp"
#include "verification/harness/reason.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <set>

namespace sphv {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The local orders of an error between neighbouring levels that report it, coarse to fine.
std::vector<double> local_orders(const Sweep& s, const std::string& e) {
  std::vector<std::pair<double, double>> pts;
  for (std::size_t k = 0; k < s.runs.size() && k < s.levels.size(); ++k)
    if (auto it = s.runs[k].errors.find(e); it != s.runs[k].errors.end() && it->second > 0.0 && std::isfinite(it->second))
      pts.emplace_back(static_cast<double>(s.levels[k]), it->second);
  std::vector<double> p;
  for (std::size_t k = 1; k < pts.size(); ++k)
    p.push_back(-std::log(pts[k].second / pts[k - 1].second) / std::log(pts[k].first / pts[k - 1].first));
  return p;
}

// An order or band as the window's text shows it.
std::string order_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

// The acceptance rule of the order claims (OrderClaim, verification/harness/case.hpp), the same for
// every case: the observed order inside the claim's window (no widening by the fit's standard
// error); that standard error at most half the band; the two finest levels' local order inside
// the window widened by finest_slack; and the window itself one a wrong code falls outside (band
// at most max_band unless derived from theory, lower edge above half the claimed order). A known
// failure's check passes while the order stays outside its window: a curve that levels off fits a
// power law badly, and the standard error of that poor fit must not count as the claim coming true.
//
// A claim that fails the rule but holds in the former window, expected +- (band + 2 se) with se at
// most the band, is provisional (Sweep::provisional): its row says so and which parts of the rule
// it fails, and is never counted as verified; a claim outside both windows fails.
std::vector<Check> order_checks(Sweep& s) {
  std::vector<Check> c;
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& [name, claim] : s.claims) {
    if (!claim.claimed()) continue;
    std::vector<Check> rule;
    if (!claim.at_least) {
      const double limit = claim.band_theory.empty() ? OrderClaim::max_band : inf;
      // band < expected / 2, i.e. the lower edge expected - band strictly above half the order.
      const double below_half = claim.expected > 0.0 ? std::nextafter(claim.expected / 2.0, -inf) : inf;
      rule.push_back({"window_" + name, claim.band, 0.0, std::min(below_half, limit),
                      claim.band_theory.empty()
                          ? "the claim's band at most " + order_text(OrderClaim::max_band) +
                                (claim.expected > 0.0 ? " and its window's lower edge above half the claimed order" : "")
                          : "band derived from theory: " + claim.band_theory +
                                (claim.expected > 0.0 ? "; the window's lower edge above half the claimed order" : ""),
                      Check::Kind::verification, name});
    }
    const auto o = s.observed_order.find(name);
    const bool observed = o != s.observed_order.end() && std::isfinite(o->second.p);
    const std::string window = claim.at_least ? "at least " + order_text(claim.expected)
                                              : order_text(claim.expected) + " +- " + order_text(claim.band);
    if (claim.known_failure()) {
      if (observed)
        c.push_back({"known_failure_order_" + name, o->second.p, claim.lo(), claim.hi(),
                     "known failure (the order stays outside " + window + "): " + fill_reason(claim.why, s) +
                         "; the variant [" + claim.experiment + "] verifies it",
                     Check::Kind::known_failure, name});
      if (!rule.empty() && !rule.front().pass()) s.provisional[name] = "the claim's window: band " + order_text(claim.band);
      else for (auto& r : rule) c.push_back(std::move(r));
      continue;
    }
    if (observed) {
      rule.push_back({"order_" + name, o->second.p, claim.lo(), claim.hi(), claim.why, Check::Kind::verification, name});
      if (std::isfinite(o->second.se))
        rule.push_back({"order_resolved_" + name, o->second.se, 0.0, claim.max_se(),
                        "the order fit's standard error at most " + std::string(claim.at_least ? "" : "half the band, ") +
                            order_text(claim.max_se()) + " (the levels decide the order; a noisy fit needs more levels)",
                        Check::Kind::verification, name});
      if (const auto local = local_orders(s, name); local.size() >= 2)
        rule.push_back({"order_finest_" + name, local.back(), claim.lo() - OrderClaim::finest_slack,
                        claim.hi() + OrderClaim::finest_slack,
                        "the two finest levels' local order within the window widened by " +
                            order_text(OrderClaim::finest_slack) + " (the sweep reaches the asymptotic range)",
                        Check::Kind::verification, name});
    }
    std::string failed;
    for (const auto& r : rule)
      if (!r.pass()) failed += (failed.empty() ? "" : "; ") + r.name + " = " + order_text(r.value) + " outside [" +
                               order_text(r.lo) + ", " + order_text(r.hi) + "]";
    const double se = observed && std::isfinite(o->second.se) ? o->second.se : 0.0;
    const bool former = observed && !claim.at_least && se <= claim.band &&
                        std::abs(o->second.p - claim.expected) <= claim.band + 2.0 * se;
    if (!observed && !failed.empty()) {  // one level: only the window is judged, and it is marked
      s.provisional[name] = failed;
      continue;
    }
    if (failed.empty() || !former) {
      for (auto& r : rule) c.push_back(std::move(r));
      continue;
    }
    s.provisional[name] = failed;
    c.push_back({"order_" + name, o->second.p, claim.expected - claim.band - 2.0 * se,
                 claim.expected + claim.band + 2.0 * se,
                 "provisional: the former window, expected +- (band + 2 se); the acceptance rule fails: " + failed,
                 Check::Kind::verification, name});
  }
  return c;
}

std::string failed_names(const std::vector<const Check*>& checks) {
  std::string s;
  for (const Check* c : checks)
    if (!c->pass()) s += (s.empty() ? "" : ", ") + c->name;
  return s;
}

}  // namespace

std::vector<Row> rows_of(const Sweep& s) {
  std::set<std::string> names;
  for (const auto& r : s.runs)
    for (const auto& [k, v] : r.errors) names.insert(k);
  std::vector<Row> rows;
  for (const auto& e : names) {
    Row row{e, nan, nan, nan, nan, 0.0, "fail", ""};
    row.local_orders = local_orders(s, e);
    if (!s.runs.empty() && s.runs.back().errors.count(e)) row.fine_value = s.runs.back().errors.at(e);
    if (auto o = s.observed_order.find(e); o != s.observed_order.end()) row.observed = o->second.p, row.se = o->second.se;
    std::vector<const Check*> on;
    for (const auto& c : s.checks)
      if (c.error == e) on.push_back(&c);
    const auto order_check = std::find_if(on.begin(), on.end(), [&](const Check* c) {
      return c->name == "order_" + e || c->name == "known_failure_order_" + e;
    });
    const bool ordered = order_check != on.end();
    const bool bounded = std::any_of(on.begin(), on.end(), [&](const Check* c) {
      return c->kind != Check::Kind::known_failure && c->name != "order_" + e && c->name != "order_resolved_" + e &&
             c->name != "order_finest_" + e && c->name != "window_" + e;
    });
    const auto reporting = std::count_if(s.runs.begin(), s.runs.end(), [&](const Result& r) { return r.errors.count(e) > 0; });
    const auto claim = s.claims.find(e);
    if (claim == s.claims.end()) {
      row.why = "the case states no order claim for this error";
      rows.push_back(std::move(row));
      continue;
    }
    if (claim->second.claimed()) {
      row.expected = claim->second.expected, row.band = claim->second.band;
      row.lo = claim->second.lo(), row.hi = claim->second.hi();
    }
    if (ordered && (*order_check)->kind == Check::Kind::known_failure && !(*order_check)->pass()) {
      row.why = "known failure now passes: remove the mark (observed order inside its band)";
    } else if (const std::string f = failed_names(on); !f.empty()) {
      row.why = "failed: " + f;
    } else if (!claim->second.claimed()) {
      row.outcome = "no order claimed";
      row.why = fill_reason(claim->second.why, s);
    } else if (ordered && (bounded || claim->second.unbounded) && s.provisional.count(e)) {
      const bool known = (*order_check)->kind == Check::Kind::known_failure;
      row.outcome = "provisional";
      row.why = std::string(known ? "known failure whose claim fails the acceptance rule (" : "inside the former window only; the acceptance rule fails (") +
                s.provisional.at(e) + ")" + (known ? ": " + fill_reason(claim->second.why, s) : "");
    } else if (ordered && (bounded || claim->second.unbounded)) {
      const bool known = (*order_check)->kind == Check::Kind::known_failure;
      row.outcome = known ? "known failure" : "verified";
      row.why = known ? fill_reason(claim->second.why, s) + "; the variant [" + claim->second.experiment + "] verifies it"
                      : claim->second.why;
      if (!bounded) row.why += "; a claim of the physics where no measured bound applies: the order alone is gated";
    } else if (!ordered && reporting < 2 && (bounded || claim->second.unbounded)) {
      row.outcome = "no order claimed";
      row.why = std::string(s.levels.size() < 2 ? "one level in this sweep: the order is not observable"
                                                : "reported at one level of this sweep only: the order is not observable") +
                (bounded ? "; its bound held" : "; only the verdict is gated");
    } else {
      row.why = !ordered ? "order claimed but not observed at every level" : "order claimed but the error has no bound";
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

bool Sweep::passed() const {
  for (const auto& c : checks)
    if (!c.pass()) return false;
  for (const auto& r : rows)
    if (r.outcome == "fail") return false;
  return true;
}

std::string Sweep::variant() const {
  if (settings.empty()) return "default";
  std::string s;
  for (const auto& kv : settings) s += (s.empty() ? "" : ",") + kv;
  return s;
}

Order observed_order(const std::vector<double>& n, const std::vector<double>& err) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < n.size() && k < err.size(); ++k)
    if (err[k] > 0.0 && std::isfinite(err[k])) {
      x.push_back(std::log(n[k]));
      y.push_back(std::log(err[k]));
    }
  if (x.size() < 2) return {nan, nan};
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return {-c1, x.size() > 2 ? std::sqrt(cov11) : nan};
}

std::optional<Gci> grid_convergence_index(const std::vector<double>& n, const std::vector<double>& f,
                                          double claimed_order) {
  const std::size_t k = n.size();
  if (k < 2 || f.size() != k) return std::nullopt;
  const double f1 = f[k - 1], f2 = f[k - 2];  // finest, next
  const double r = n[k - 1] / n[k - 2];
  if (!(r > 1.0) || !std::isfinite(f1) || f1 == 0.0) return std::nullopt;
  Gci g{f1, claimed_order, r, 3.0, 0.0};
  if (k >= 3) {
    const double f3 = f[k - 3], r23 = n[k - 2] / n[k - 3];
    const double e21 = f1 - f2, e32 = f2 - f3;
    // Three levels at a constant ratio give the order directly (Roache 1994).
    if (std::abs(r23 - r) < 1e-9 * r && e21 != 0.0 && e32 != 0.0 && e32 / e21 > 0.0) {
      g.order = std::log(e32 / e21) / std::log(r);
      g.safety = 1.25;
    }
  }
  if (!(g.order > 0.0) || !std::isfinite(g.order)) return std::nullopt;
  g.gci = g.safety * std::abs((f1 - f2) / f1) / (std::pow(r, g.order) - 1.0);
  return g;
}

Sweep summarise(const Case& c, const std::vector<std::string>& settings, const std::vector<long>& levels,
                std::vector<Result> runs, const std::string& tier) {
  Sweep s;
  s.case_name = c.name;
  s.summary = c.summary;
  s.n_counts = c.n_counts;
  s.error_defs = c.error_defs;
  s.tier = tier;
  s.levels = levels;
  const Params base = c.parse(settings);
  s.settings = base.non_defaults();
  if (c.orders) s.claims = c.orders(base);
  s.runs = std::move(runs);
  for (const auto& r : s.runs) s.wall_time_s += r.wall_time_s;

  std::vector<double> n(levels.begin(), levels.end());
  // An error is fitted over the levels that report it (a shock front found only from some n on),
  // from two levels up; functionals need every level (the GCI's constant ratio).
  std::map<std::string, std::vector<double>> err_n, errs, funcs;
  for (std::size_t k = 0; k < s.runs.size() && k < n.size(); ++k) {
    for (const auto& [key, v] : s.runs[k].errors) err_n[key].push_back(n[k]), errs[key].push_back(v);
    for (const auto& [key, v] : s.runs[k].functionals) funcs[key].push_back(v);
  }
  for (const auto& [k, v] : errs)
    if (v.size() >= 2) s.observed_order[k] = observed_order(err_n[k], v);
  for (const auto& [k, v] : funcs) {
    const auto claim = s.claims.find(k);
    if (v.size() == n.size())
      if (auto g = grid_convergence_index(n, v, claim == s.claims.end() ? nan : claim->second.expected)) s.gci[k] = *g;
  }
  // A run that crashed or timed out lacks its errors: gates that cannot be evaluated fail the sweep
  // (the verdict check below names the run) instead of ending a whole catalogue.
  try {
    if (c.gates) s.checks = c.gates(s);
  } catch (const std::exception& e) {
    s.checks = {{"gates_evaluated", 0.0, 1.0, 1.0, std::string("the gates could not be evaluated: ") + e.what()}};
  }
  for (auto& o : order_checks(s)) s.checks.push_back(std::move(o));
  for (std::size_t k = 0; k < s.runs.size(); ++k)
    if (!c.verdict_expected(base, s.runs[k].verdict))
      s.checks.push_back({"expected_verdict_n" + std::to_string(levels[k]), 0.0, 1.0, 1.0,
                          "the run ended '" + s.runs[k].verdict + "' where the case expects it to complete"});
  for (auto& d : drift_checks(s)) s.checks.push_back(std::move(d));
  s.rows = rows_of(s);
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

Sweep run_tier(const Case& c, Tier t, const std::vector<std::string>& settings,
               const std::optional<std::filesystem::path>& out, const RunOptions& opt) {
  const auto levels = c.tier_levels(settings, t);
  std::vector<Point> points;
  for (long n : levels) points.push_back({settings, n, out ? *out / ("n" + std::to_string(n)) : ""});
  Sweep s = summarise(c, settings, levels, run_points(c, points, opt), to_string(t));
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

std::vector<SweepPlan> plan_sweeps(const Case& c, Tier t, const std::vector<long>& levels,
                                   const std::vector<std::vector<std::string>>& variants,
                                   const std::filesystem::path& out) {
  std::vector<SweepPlan> plans;
  for (const auto& v : variants) {
    const Sweep label{.settings = c.parse(v).non_defaults()};
    plans.push_back({&c, v, levels.empty() ? c.tier_levels(v, t) : levels,
                     variants.size() == 1 ? out : out / label.variant(), levels.empty() ? to_string(t) : ""});
  }
  return plans;
}

std::vector<Sweep> run_plans(const std::vector<SweepPlan>& plans, const RunOptions& opt) {
  // Progress reports each case of a catalogue, or each point of a single case's sweeps.
  const bool one_case = std::all_of(plans.begin(), plans.end(), [&](const SweepPlan& p) { return p.c == plans[0].c; });
  std::vector<Task> tasks;
  for (const auto& p : plans)
    for (long n : p.levels) {
      std::string group = p.c->name;
      if (one_case) {
        group += " n=" + std::to_string(n);
        for (const auto& s : p.settings) group += " " + s;
      }
      tasks.push_back({p.c, {p.settings, n, p.dir / ("n" + std::to_string(n))}, group});
    }
  std::vector<Result> results = run_points(tasks, opt);
  std::vector<Sweep> sweeps;
  if (results.empty()) return sweeps;  // an MPI rank other than 0
  auto it = results.begin();
  for (const auto& p : plans) {
    std::vector<Result> runs(it, it + p.levels.size());
    it += p.levels.size();
    sweeps.push_back(summarise(*p.c, p.settings, p.levels, std::move(runs), p.tier));
    write_atomically(p.dir / "sweep.json", to_json(sweeps.back()).dump(1) + "\n");
  }
  return sweeps;
}

std::vector<Sweep> run_sweeps(const Case& c, Tier t, const std::vector<long>& levels,
                              const std::vector<std::vector<std::string>>& variants,
                              const std::filesystem::path& out, const RunOptions& opt) {
  return run_plans(plan_sweeps(c, t, levels, variants, out), opt);
}

void check_experiments(std::vector<Sweep>& sweeps) {
  for (Sweep& s : sweeps) {
    const Case* c = nullptr;
    for (const auto& k : catalogue())
      if (k.name == s.case_name) c = &k;
    for (Row& row : s.rows) {
      const auto claim = s.claims.find(row.error);
      if (row.outcome != "known failure" || claim == s.claims.end()) continue;
      // The experiment as its variant is named (defaults dropped), for a case of the catalogue.
      const std::string variant = c ? Sweep{.settings = c->parse(claim->second.experiment_settings()).non_defaults()}.variant()
                                    : claim->second.experiment;
      const auto exp = std::find_if(sweeps.begin(), sweeps.end(), [&](const Sweep& x) {
        return x.case_name == s.case_name && x.variant() == variant;
      });
      // Not in this run (a case's variants run together), or one level only: nothing to decide here.
      if (exp == sweeps.end() || exp->levels.size() < 2) continue;
      const auto same = std::find_if(exp->rows.begin(), exp->rows.end(), [&](const Row& r) { return r.error == row.error; });
      const std::string outcome = same == exp->rows.end() ? "not reported" : same->outcome;
      const bool verifies = outcome == "verified";
      if (outcome == "provisional") {  // neither verified nor failed: the known failure waits with it
        row.outcome = "provisional";
        row.why = "known failure whose experiment [" + variant + "] is provisional for " + row.error + ": " + row.why;
        continue;
      }
      s.checks.push_back({"experiment_verifies_" + row.error, verifies ? 1.0 : 0.0, 1.0, 1.0,
                          "the known failure's experiment [" + variant + "] verifies " + row.error + " (its outcome: " +
                              outcome + ")",
                          Check::Kind::verification, row.error});
      if (!verifies) {
        row.outcome = "fail";
        row.why = "failed: experiment_verifies_" + row.error + " (the experiment [" + variant + "] reads '" + outcome +
                  "' for this error)";
      }
    }
  }
}

nlohmann::json to_json(const Sweep& s) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json runs = nlohmann::json::array(), order = nlohmann::json::object(), se = nlohmann::json::object(),
                 claims = nlohmann::json::object(), gci = nlohmann::json::object(),
                 checks = nlohmann::json::array(), rows = nlohmann::json::array();
  for (const auto& r : s.runs) runs.push_back(to_json(r));
  for (const auto& [k, v] : s.observed_order) order[k] = num(v.p), se[k] = num(v.se);
  for (const auto& [k, v] : s.claims) {
    claims[k] = {{"expected", num(v.expected)}, {"band", v.band}, {"why", fill_reason(v.why, s)}};
    if (v.claimed()) claims[k]["window"] = {num(v.lo()), num(v.hi())};
    if (v.at_least) claims[k]["at_least"] = true;
    if (!v.band_theory.empty()) claims[k]["band_theory"] = v.band_theory;
    if (v.known_failure()) claims[k]["experiment"] = v.experiment;
  }
  for (const auto& [k, g] : s.gci)
    gci[k] = {{"fine_value", num(g.fine_value)}, {"order", num(g.order)}, {"ratio", g.ratio},
              {"Fs", g.safety}, {"gci", num(g.gci)}};
  for (const auto& c : s.checks)
    checks.push_back({{"name", c.name}, {"value", num(c.value)}, {"lo", num(c.lo)}, {"hi", num(c.hi)},
                      {"why", c.why}, {"pass", c.pass()}, {"kind", to_string(c.kind)}, {"error", c.error}});
  for (const auto& r : s.rows)
    rows.push_back({{"error", r.error}, {"fine_value", num(r.fine_value)}, {"observed", num(r.observed)},
                    {"se", num(r.se)}, {"expected", num(r.expected)}, {"band", r.band},
                    {"outcome", r.outcome}, {"why", r.why}, {"window", {num(r.lo), num(r.hi)}},
                    {"local_orders", r.local_orders}});
  return {{"case", s.case_name}, {"summary", s.summary}, {"n_counts", s.n_counts}, {"variant", s.variant()},
          {"settings", s.settings}, {"tier", s.tier}, {"levels", s.levels}, {"runs", runs},
          {"observed_order", order}, {"order_se", se}, {"claims", claims}, {"error_defs", s.error_defs},
          {"gci", gci}, {"checks", checks}, {"rows", rows}, {"passed", s.passed()},
          {"wall_time_s", s.wall_time_s}};
}

}  // namespace sphv
