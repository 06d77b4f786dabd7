#pragma once
// A drift bound (the code's own earlier output, counted as a drift check, not as verification) on
// an error that converges at its claimed order, from one measurement: the error
// measured at level n0 times a stated margin, carried to the sweep's finest level n by the
// claimed order, bound(n) = margin * e(n0) * (n0 / n)^p. The same bound then holds at any level
// a tier (or --levels) chooses, and an error that falls more slowly than claimed still fails.
#include <cmath>
#include <cstdio>
#include <string>

#include "verification/harness/sweep.hpp"

namespace sphv {

// Without a finite claimed order (none, or 0) the bound is the same at every level.
inline Check measured_bound(const Sweep& s, const std::string& error, double measured, long n0, double margin,
                            const std::string& why = "") {
  const auto& r = s.runs.back();
  const double n = static_cast<double>(r.params.value("n", 0L));
  const auto claim = s.claims.find(error);
  const double p = claim != s.claims.end() && claim->second.claimed() ? claim->second.expected : 0.0;
  const double hi = margin * measured * std::pow(double(n0) / n, p);
  char text[160];
  std::snprintf(text, sizeof text, "measured %.4g at n = %ld, margin %g%s", measured, n0, margin,
                p != 0.0 ? ", carried to this n by the claimed order" : "");
  return {"bound_" + error, r.errors.at(error), 0.0, hi, why.empty() ? text : std::string(text) + "; " + why,
          Check::Kind::drift, error};
}

}  // namespace sphv
