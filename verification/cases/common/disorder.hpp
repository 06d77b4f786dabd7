#pragma once
// Orders of SPH operators on jittered particle sets (a lattice whose particles are displaced by up
// to jitter dx per axis, independently), shared by the interpolation and laplacian cases.
//
// The error is the kernel's smoothing error plus a disorder part. Each of the (h/dx)^d neighbour
// terms of a sum has the size dx^d / h^d (times h^-s, the inverse powers of h the operator keeps
// after its cancellations). Jitter moves each term by O(jitter dx / h) of its size,
// independently, so their sum carries (h/dx)^(d/2) jitter (dx/h)^(d+1) h^-s, relative to the
// field: a term (dx/h)^a h^-s with a = d/2 + 1. The interpolant (18) and the difference gradient
// (32) keep s = 0; the direct gradient (19), the Brookshaw Laplacian (69) and the tensor (73) a
// first moment over h, s = 1. A two-pass form applies a gradient to a gradient field that already
// carries this noise: the outer sum adds it up, (dx/h)^(d/2) over h, so it keeps the inner form's
// term with a = d + 1 and one more power of h besides its own term on the smooth field:
// (56)+(58) the terms (d/2 + 1, 1) and (d + 1, 2), (57)+(59) (d/2 + 1, 0) and (d + 1, 1).
// With h/dx = hfact (n/16)^hgrow, dx/h ~ n^-hgrow and h ~ n^(hgrow-1): a term falls as n^-q and
// the smoothing error O(h^2) as n^-p with
//   q = hgrow a - s (1 - hgrow),   p = 2 (1 - hgrow).
// At fixed h/dx (hgrow = 0) q = -s: the disorder part levels off or grows and the operator has no
// limit on a disordered set. Where every q > 0 the error is a sum of positive power laws, and the
// slope of such a sum lies between the smallest and the largest of their exponents.
//
// The disorder part is measured as the relative L2 of the difference, particle by particle, between
// the residual on the jittered set and that on the unjittered lattice at the same n and h/dx (the
// lattice's residual is smooth, so the jitter moves it by O(jitter k dx) of itself).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "verification/harness/case.hpp"
#include "verification/harness/sweep.hpp"

namespace sphv::disorder {

// A disorder term (dx/h)^a h^-s with a = halves d/2 + 1.
struct Term {
  int halves;
  int s;
};
using Terms = std::vector<Term>;

inline double term_order(int dim, double hgrow, const Term& t) {
  return hgrow * (t.halves * dim / 2.0 + 1.0) - t.s * (1.0 - hgrow);
}
inline double smoothing_order(double hgrow) { return 2.0 * (1.0 - hgrow); }
// The smallest and the largest order among the terms and, with_smoothing, the smoothing error's.
inline std::pair<double, double> order_range(int dim, double hgrow, const Terms& terms, bool with_smoothing) {
  double lo = with_smoothing ? smoothing_order(hgrow) : term_order(dim, hgrow, terms.front()), hi = lo;
  for (const Term& t : terms) lo = std::min(lo, term_order(dim, hgrow, t)), hi = std::max(hi, term_order(dim, hgrow, t));
  return {lo, hi};
}
// The disorder part's asymptotic order: its slowest term.
inline double disorder_order(int dim, double hgrow, const Terms& terms) {
  return order_range(dim, hgrow, terms, false).first;
}

// sqrt(sum_i |r_i - m_i|^2 / sum_i |ref_i|^2) over particles, m = 0 without minus: an error from
// its residuals, or the disorder part from the residuals of a jittered set and of its lattice
// (the same particle order). T is double or an Eigen vector or matrix.
template <class T>
double relative_l2(const std::vector<T>& r, const std::vector<T>* minus, const std::vector<T>& ref) {
  auto sq = [](const T& v) {
    if constexpr (std::is_arithmetic_v<T>) return v * v;
    else return v.squaredNorm();
  };
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) num += sq(minus ? T(r[i] - (*minus)[i]) : r[i]), den += sq(ref[i]);
  return std::sqrt(num / den);
}

// The claim for `error` on a jittered set where every order (the smoothing error's and its
// disorder terms') is positive: the error is a sum of positive power laws, whose slope tends to
// the smallest exponent as n grows, so the claim is that exponent.
// At these levels the smoothing error dominates (on the unjittered lattice at the same n and h/dx
// the error is within 1 % of the jittered set's in 2D at hgrow 0.6: the disorder part is a tenth of
// it) and its own slope approaches 2 (1 - hgrow) from below while k h is not small (k h = 2.2 at
// n = 16 for the Laplacian's field); the finest pair shows it within the rule's slack. Otherwise
// the operator has no limit, with the measured disorder part (extras disorder_<error> and
// disorder_order_<error>, written by the case's run) as the evidence.
// The band: where the orders differ the fit lies anywhere between them before the slowest
// dominates, so the acceptance rule's band; where they coincide, min_band (the lattice claim's,
// for the fit's pre-asymptotic effects) plus the scatter of one random set's disorder part about
// its power law (0.1), within the rule's.
inline OrderClaim jittered_claim(int dim, double hgrow, const Terms& terms, double min_band, const std::string& error) {
  const auto [lo, hi] = order_range(dim, hgrow, terms, true);
  if (!(lo > 0.0))
    return no_order("jittered set with h/dx = hfact (n/16)^hgrow: the operator has no limit. Its disorder part (its "
                    "residual's difference with the unjittered lattice's) is {extra.disorder_" + error + "} at {levels}: by theory "
                    "(common/disorder.hpp) of order {extra.disorder_order_" + error + "} in n, not above zero (gated)");
  char why[260];
  std::snprintf(why, sizeof why,
                "jittered set, h/dx growing as (n/16)^hgrow: the smoothing error O(h^2) and the disorder terms fall at "
                "orders from %.3g to %.3g (common/disorder.hpp); the slowest, %.3g, is the asymptotic order",
                lo, hi, lo);
  constexpr double scatter = 0.1;
  return {lo, hi > lo ? OrderClaim::max_band : std::min(OrderClaim::max_band, min_band + scatter), why, {}};
}

// The model the claims rest on, checked: the disorder part's order fitted over the sweep's levels
// (extras disorder_<error>) between its terms' orders, within tol, for each error.
inline std::vector<Check> disorder_scaling(const Sweep& sw, const std::map<std::string, Terms>& terms, int dim,
                                           double hgrow, double tol, const std::string& measured) {
  std::vector<Check> c;
  if (sw.runs.size() < 2) return c;
  for (const auto& [e, ts] : terms) {
    std::vector<double> n, part;
    for (std::size_t k = 0; k < sw.runs.size() && k < sw.levels.size(); ++k)
      n.push_back(double(sw.levels[k])), part.push_back(sw.runs[k].extra.value("disorder_" + e, 0.0));
    const auto [lo, hi] = order_range(dim, hgrow, ts, false);
    c.push_back({"disorder_order_" + e, observed_order(n, part).p, lo - tol, hi + tol,
                 "the disorder part's fitted order between its terms' hgrow a - s (1 - hgrow) (common/disorder.hpp); " + measured,
                 Check::Kind::verification, e});
  }
  return c;
}

}  // namespace sphv::disorder
