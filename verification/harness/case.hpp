#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "verification/snapshot/initial_state.hpp"
#include "verification/harness/params.hpp"
#include "verification/harness/result.hpp"
#include "verification/snapshot/scorer.hpp"

namespace sphv {

struct Sweep;

// One gate: a measured value that must lie in [lo, hi], with the reason for the bounds
// (theory, or a measurement with a stated margin). A verification check compares against an
// independent reference; a drift check against this code's own earlier output. A known-failure
// check holds an order claim the method is known to miss: it passes while the value stays
// outside [lo, hi], and fails once the claim holds (the mark is then stale and must go).
struct Check {
  enum class Kind { verification, drift, known_failure };
  std::string name;
  double value;
  double lo, hi;
  std::string why;
  Kind kind = Kind::verification;
  std::string error;  // the error this check is about ("" = the sweep as a whole)
  bool inside() const { return value >= lo && value <= hi; }
  bool pass() const { return kind == Kind::known_failure ? !inside() : inside(); }
};
const char* to_string(Check::Kind k);

// How much a catalogue run costs: quick = CI-sized (what the Catch2 gates run), standard = the
// README's main job, full = publication resolutions.
enum class Tier { quick, standard, full };
Tier parse_tier(const std::string& s);  // throws InputError
const char* to_string(Tier t);
// Seconds a point of the tier may run before the harness kills it (0: no limit). Margins of
// 8x and 5.6x on the longest points measured at 10f2482 on 2 cores: quick noh 2D n = 50, 14 s;
// standard noh 2D n = 100, 107 s. The full tier's points are not bounded.
double tier_timeout(Tier t);

// The levels (values of n) of a sweep in each tier.
struct Levels {
  std::vector<long> quick, standard, full;
  const std::vector<long>& at(Tier t) const;
};

// What a case claims about the convergence of one error. expected = NaN: no order is claimed,
// and `why` says why (no convergent limit: fixed theta or dt, round-off, a map of verdicts).
// Otherwise the claim is a window the observed order must lie in, one acceptance rule for every
// case (verification/harness/sweep.cpp):
// - two-sided, expected +- band, with band <= max_band unless `band_theory` derives a wider band
//   from theory (shown beside the row); the window must exclude half the claimed order
//   (expected - band > expected / 2), so a code that halves the order falls outside it;
// - one-sided (at_least), "converges at least at order expected", where theory gives only a bound
//   (a shock tube's L1 lies between its contact's and its shock's orders).
// The fit's standard error must be at most half the band (max_se for one-sided claims): a fit too
// noisy to decide needs more levels; it never widens the window. The local order of the two
// finest levels must lie within the window widened by finest_slack (the asymptotic range, Roache).
// A known failure (experiment set) is a claim the method misses for a reason the case states and
// proves: `experiment` names the catalogue variant of the same case that verifies the same error.
// `why` may quote the sweep's own numbers only through placeholders that the harness fills in
// from the runs (verification/harness/reason.hpp), never typed-in values.
struct OrderClaim {
  static constexpr double max_band = 0.3;
  static constexpr double max_se_at_least = 0.15;  // max_band / 2, as for a two-sided claim
  static constexpr double finest_slack = 0.25;     // a two-level order's scatter on these sweeps
  double expected = std::numeric_limits<double>::quiet_NaN();
  double band = 0.0;
  std::string why;
  std::string experiment;
  bool at_least = false;
  std::string band_theory;  // the derivation of a band wider than max_band
  // A claim of the physics at settings no catalogue variant measured (another gamma or state, an
  // external code's run): no measured bound backs it here, the order alone verifies it
  // (Case::claim_domain).
  bool unbounded = false;
  bool claimed() const { return std::isfinite(expected); }
  bool known_failure() const { return !experiment.empty(); }
  // The experiment's settings, "k=v,k=v" split at its commas (Case::parse reads them).
  std::vector<std::string> experiment_settings() const {
    std::vector<std::string> settings;
    for (std::size_t from = 0; from <= experiment.size();) {
      const std::size_t comma = std::min(experiment.find(',', from), experiment.size());
      settings.push_back(experiment.substr(from, comma - from));
      from = comma + 1;
    }
    return settings;
  }
  double lo() const { return at_least ? expected : expected - band; }
  double hi() const { return at_least ? std::numeric_limits<double>::infinity() : expected + band; }
  double max_se() const { return at_least ? max_se_at_least : band / 2.0; }
};
using OrderClaims = std::map<std::string, OrderClaim>;
inline OrderClaim no_order(std::string why) { return {std::numeric_limits<double>::quiet_NaN(), 0.0, std::move(why), {}}; }
inline OrderClaim known_failure(double expected, double band, std::string why, std::string experiment) {
  return {expected, band, std::move(why), std::move(experiment)};
}
// "Converges at least at order p_min": where theory bounds the order from below only.
inline OrderClaim at_least(double p_min, std::string why) { return {p_min, 0.0, std::move(why), {}, true}; }
// A claim whose band is wider than OrderClaim::max_band, with the theory that gives that band.
inline OrderClaim derived_band(double expected, double band, std::string why, std::string theory) {
  return {expected, band, std::move(why), {}, false, std::move(theory)};
}
// The same claim marked as a known failure whose experiment verifies it.
inline OrderClaim known_failure(OrderClaim claim, std::string why, std::string experiment) {
  claim.why = std::move(why);
  claim.experiment = std::move(experiment);
  return claim;
}

// A verification case: one physical set-up, its independent reference and its gates.
struct Case {
  std::string name;
  std::string summary;   // one line for `sphv list`
  std::string n_counts;  // what the resolution parameter n counts
  std::vector<std::string> tags;   // "gate", "sweep", "extreme"
  std::vector<ParamSpec> params;   // must include "n"
  Levels levels;                   // of the default variant, per tier
  // An order claim per error name the case reports, for a given set of parameters.
  std::function<OrderClaims(const Params&)> orders;
  // Each error's exact definition (norm, region, weights): `sphv info`, report axis labels.
  std::map<std::string, std::string> error_defs;
  // Method variants the catalogue sweeps, as settings (the first is the default).
  std::vector<std::vector<std::string>> variants = {{}};
  // The domain in which the order claims hold: the parameters of the problem (not of the method)
  // for every value of which they hold, e.g. the tubes' gamma, states and presets. Settings that
  // differ from a catalogue variant only in these keep that variant's claims (unbounded: its
  // measured bounds stay with it), and so does an external code's sweep (sweep --runner). Empty:
  // the case declares no such domain.
  std::vector<std::string> claim_domain;
  // A variant's levels when they differ from `levels` (e.g. fewer in 3D); may be empty.
  std::function<Levels(const Params&)> levels_for;
  std::function<void(const Params&)> validate;   // cross-parameter checks; may be empty
  // True where an "unstable" verdict is the expected outcome (a method shown to fail); may be empty.
  std::function<bool(const Params&)> expects_unstable;
  std::function<Result(const Params&)> run;
  std::function<std::vector<Check>(const Sweep&)> gates;  // may be empty
  // How `sphv score` reads another code's snapshot of the case (empty score: it cannot).
  Scorer scorer;
  // `sphv ic`: the case's initial conditions for another code (empty: none).
  InitialConditions ic;

  Params parse(const std::vector<std::string>& settings) const;
  std::vector<long> tier_levels(const std::vector<std::string>& settings, Tier t) const;
  bool has_tag(const std::string& t) const;
  // Whether p's method is a catalogue variant's: p's settings other than n and the claim
  // domain's are those of one of `variants` (so the variant's claims hold at p).
  bool method_in_catalogue(const Params& p) const;
  // Whether a run's verdict is what this case expects for these parameters.
  bool verdict_expected(const Params& p, const std::string& verdict) const;
};

// Cases register themselves from their own source file: `static Registration r{make_case()};`.
// The registration is all a case declares: its runs, sweeps, tiers, gates (every case tagged
// "gate" is a Catch2 test, verification/tests/gates.cpp), scorer and initial conditions. The
// file's names go in a namespace of its own, sphv::<file>_case (the unity build compiles
// several case files as one translation unit, CMakeLists.txt).
struct Registration {
  explicit Registration(Case c);
};
const std::vector<Case>& catalogue();
const Case& find_case(const std::string& name);  // throws InputError for an unknown name

// Calls f(std::integral_constant<int, D>{}) for D = the parameter "dim" (1, 2 or 3): the one
// place where a case's runtime dimension becomes a template argument. Returns what f returns.
template <class F>
auto by_dimension(const Params& p, F&& f) -> decltype(f(std::integral_constant<int, 1>{})) {
  switch (p.integer("dim")) {
    case 1: return f(std::integral_constant<int, 1>{});
    case 2: return f(std::integral_constant<int, 2>{});
    case 3: return f(std::integral_constant<int, 3>{});
  }
  throw InputError("parameter dim must be 1, 2 or 3, got " + std::to_string(p.integer("dim")));
}

// Runs one case with validated parameters, timing it; writes DIR/result.json when dir is set.
Result run_case(const Case& c, const Params& p);

}  // namespace sphv
