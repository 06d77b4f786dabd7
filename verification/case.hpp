#pragma once
#include <functional>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "verification/params.hpp"
#include "verification/result.hpp"

namespace sphv {

struct Sweep;

// One gate: a measured value that must lie in [lo, hi], with the reason for the bounds
// (theory, or a measurement with a stated margin).
struct Check {
  std::string name;
  double value;
  double lo, hi;
  std::string why;
  bool pass() const { return value >= lo && value <= hi; }
};

// A verification case: one physical set-up, its independent reference and its gates.
struct Case {
  std::string name;
  std::string summary;   // one line for `sphv list`
  std::string n_counts;  // what the resolution parameter n counts
  std::vector<std::string> tags;   // "gate", "sweep", "extreme"
  std::vector<ParamSpec> params;   // must include "n"
  std::vector<long> levels;        // default sweep (sphv sweep, sphv verify)
  std::vector<long> gate_levels;   // CI-sized sweep checked by the Catch2 gate
  // Expected order per error name for a given set of parameters (a jittered set, say, may
  // expect none), and why those orders are expected.
  std::function<std::map<std::string, double>(const Params&)> expected_order;
  std::string expected_why;
  // Method variants the default catalogue sweeps, as settings (the first is the default).
  std::vector<std::vector<std::string>> variants = {{}};
  // Adjusts a sweep's levels to a variant (e.g. fewer in 3D); may be empty.
  std::function<std::vector<long>(const Params&, std::vector<long>)> levels_for;
  std::function<void(const Params&)> validate;   // cross-parameter checks; may be empty
  std::function<Result(const Params&)> run;
  std::function<std::vector<Check>(const Sweep&)> gates;  // may be empty

  Params parse(const std::vector<std::string>& settings) const;
  std::vector<long> sweep_levels(const std::vector<std::string>& settings, bool gate) const;
  bool has_tag(const std::string& t) const;
};

// Cases register themselves from their own source file: `static Registration r{make_case()};`
struct Registration {
  explicit Registration(Case c);
};
const std::vector<Case>& catalogue();
const Case& find_case(const std::string& name);  // throws InputError for an unknown name

// Calls f(std::integral_constant<int, D>{}) for D = the parameter "dim" (1, 2 or 3): the one
// place where a case's runtime dimension becomes a template argument.
template <class F>
Result by_dimension(const Params& p, F&& f) {
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
