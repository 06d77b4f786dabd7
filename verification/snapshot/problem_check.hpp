#pragma once
// "Is this the problem it claims to be?": before its errors mean anything, a scorer compares the
// snapshot's undisturbed parts (where no wave of the problem can have arrived by the file's time,
// or a quantity the problem fixes: a mean state, a total) with what the problem puts there. A file
// of another problem (another gamma, interface, preset, time unit) fails this by far more than a
// code's error there, and its L1 errors would measure that difference, not the code: the verdict
// is then "mismatch" (exit 1) and the console names the state measured, the one expected and the
// likely cause. The tolerances are each case's, stated in its error_defs under "mismatch".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "verification/harness/result.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

// One quantity of one undisturbed part: measured against expected, off when
// |measured - expected| > tolerance * scale (scale: |expected|, or a speed for a velocity). Over
// a part's particles (part_check) the measurement is their median, and at most a share
// max_off_share of them may be off one by one.
struct StateCheck {
  std::string region;    // where: "the left state (312 particles with 0.31 <= x <= 0.69)"
  std::string quantity;  // "rho", "p", "v_x", "total mass"
  double measured = 0.0, expected = 0.0, scale = 1.0, tolerance = 0.0;
  std::string note = "";  // more about the measurement ("12 of 312 particles off")
  std::size_t off_count = 0, count = 0;
  double max_off_share = 1.0;
  bool pass() const {
    return std::abs(measured - expected) <= tolerance * scale && off_count <= max_off_share * count;
  }
  double off() const { return std::abs(measured - expected) / scale; }
};

namespace problem_check {

inline std::string number(double v, int digits = 4) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// The checks that failed, one clause per region: "the left state (...): p 1.667 (expected 1), ...".
inline std::string failed_text(const std::vector<StateCheck>& checks) {
  std::string s, region;
  for (const auto& c : checks) {
    if (c.pass()) continue;
    if (c.region != region) {
      s += (s.empty() ? "" : "; ") + c.region + ":";
      region = c.region;
    } else {
      s += ",";
    }
    s += " " + c.quantity + (c.count > 0 ? " median " : " ") + number(c.measured) + " (expected " + number(c.expected) +
         ", off by " + number(c.off()) + (c.scale == std::abs(c.expected) ? " relative" : "") + ", tolerance " +
         number(c.tolerance) + (c.note.empty() ? "" : "; " + c.note) + ")";
  }
  return s;
}

// One quantity over the particles `at` of an undisturbed part: f_i against e_i, each off by
// |f_i - e_i| / scale_i. The measurement is the median of f_i (against the median e_i); the
// particles off beyond the tolerance may be at most max_off_share of the part (a part's edge
// still feels a wave's numerical spreading); the note names the particle farthest off.
template <class F, class E, class S>
StateCheck part_check(const std::string& region, const std::string& quantity, const std::vector<std::size_t>& at, F f,
                      E e, S scale, double tolerance, double max_off_share) {
  std::size_t worst = at.front(), off = 0;
  std::vector<double> fs, es, ss;
  for (std::size_t i : at) {
    const double d = std::abs(f(i) - e(i)) / scale(i);
    if (d > std::abs(f(worst) - e(worst)) / scale(worst)) worst = i;
    if (d > tolerance) ++off;
    fs.push_back(f(i)), es.push_back(e(i)), ss.push_back(scale(i));
  }
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const std::string note = std::to_string(off) + " of " + std::to_string(at.size()) + " particles off by more than " +
                           number(tolerance) + " (at most " + number(100.0 * max_off_share) + " % may be), the farthest " +
                           number(f(worst)) + " against " + number(e(worst));
  StateCheck c{region, quantity, median(fs), median(es), median(ss), tolerance, note};
  c.off_count = off, c.count = at.size(), c.max_off_share = max_off_share;
  return c;
}

// Each particle's kernel support radius as the checks of radial problems read it: the file's h
// (sphv's h is the support radius; SWIFT's is read as one) or, without h, 3 local spacings
// (m / rho)^(1 / dim) (a support of hfact 1.2-1.5 times a kernel reaching 2 h, as SPH codes use).
inline std::vector<double> supports(const Snapshot& s, const std::string& who) {
  std::vector<double> h(s.size());
  const auto &m = s.at("m", who), &rho = s.at("rho", who);
  for (std::size_t i = 0; i < h.size(); ++i)
    h[i] = s.has("h") && s.columns.at("h")[i] > 0.0 ? s.columns.at("h")[i] : 3.0 * std::pow(m[i] / rho[i], 1.0 / s.dim);
  return h;
}

inline bool all_pass(const std::vector<StateCheck>& checks) {
  return std::all_of(checks.begin(), checks.end(), [](const StateCheck& c) { return c.pass(); });
}

}  // namespace problem_check

// Records the checks in r.extra["problem_check"]. When one fails, the verdict becomes "mismatch"
// (whatever the scorer concluded before: its errors are of another problem) and
// r.extra["mismatch"] holds one line: the states measured and expected, and the likely cause.
// No checks (no undisturbed part at this time) are recorded as such: the errors stand unchecked.
inline void apply_problem_check(Result& r, const std::vector<StateCheck>& checks, const std::string& likely_cause,
                                const std::string& none_because = "") {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : checks)
    list.push_back({{"region", c.region}, {"quantity", c.quantity}, {"measured", c.measured}, {"expected", c.expected},
                    {"scale", c.scale}, {"tolerance", c.tolerance}, {"particles", c.count}, {"particles_off", c.off_count},
                    {"pass", c.pass()}, {"note", c.note}});
  r.extra["problem_check"] = list;
  r.extra["problem_check_passed"] = problem_check::all_pass(checks);
  if (checks.empty()) {
    r.extra["problem_check_note"] = "not checked: " + (none_because.empty() ? std::string("no undisturbed part") : none_because);
    return;
  }
  if (problem_check::all_pass(checks)) return;
  const std::string before = r.verdict == "ok" ? "" : " (the scorer also found: " + r.verdict + ")";
  r.verdict = "mismatch";
  r.extra["mismatch"] = "not the problem the settings describe: " + problem_check::failed_text(checks) +
                        ". Likely cause: " + likely_cause + before;
}

}  // namespace sphv
