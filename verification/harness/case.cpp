#include "verification/harness/case.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace sphv {

namespace {
std::vector<Case>& registry() {
  static std::vector<Case> cases;
  return cases;
}
bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

Tier parse_tier(const std::string& s) {
  if (s == "quick") return Tier::quick;
  if (s == "standard") return Tier::standard;
  if (s == "full") return Tier::full;
  throw InputError("unknown tier '" + s + "' (quick, standard or full)");
}

const char* to_string(Tier t) { return t == Tier::quick ? "quick" : t == Tier::standard ? "standard" : "full"; }

const char* to_string(Check::Kind k) {
  return k == Check::Kind::drift ? "drift" : k == Check::Kind::known_failure ? "known_failure" : "verification";
}

double tier_timeout(Tier t) { return t == Tier::quick ? 120.0 : t == Tier::standard ? 600.0 : 0.0; }

const std::vector<long>& Levels::at(Tier t) const {
  return t == Tier::quick ? quick : t == Tier::standard ? standard : full;
}

Registration::Registration(Case c) {
  auto& r = registry();
  r.push_back(std::move(c));
  std::sort(r.begin(), r.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
}

const std::vector<Case>& catalogue() { return registry(); }

const Case& find_case(const std::string& name) {
  for (const auto& c : registry())
    if (c.name == name) return c;
  throw InputError("unknown case '" + name + "' (see 'sphv list')");
}

Params Case::parse(const std::vector<std::string>& settings) const {
  Params p(name, params, settings);
  if (validate) validate(p);
  return p;
}

std::vector<long> Case::tier_levels(const std::vector<std::string>& settings, Tier t) const {
  return (levels_for ? levels_for(parse(settings)) : levels).at(t);
}

bool Case::has_tag(const std::string& t) const {
  return std::find(tags.begin(), tags.end(), t) != tags.end();
}

bool Case::method_in_catalogue(const Params& p) const {
  auto method = [&](const Params& q) {
    std::vector<std::string> m;
    for (const auto& kv : q.non_defaults())
      if (std::find(claim_domain.begin(), claim_domain.end(), kv.substr(0, kv.find('='))) == claim_domain.end())
        m.push_back(kv);
    return m;
  };
  const auto mine = method(p);
  return std::any_of(variants.begin(), variants.end(), [&](const auto& v) { return method(parse(v)) == mine; });
}

bool Case::verdict_expected(const Params& p, const std::string& verdict) const {
  if (verdict == "ok" || starts_with(verdict, "ok:") || starts_with(verdict, "stable")) return true;
  return starts_with(verdict, "unstable") && expects_unstable && expects_unstable(p);
}

Result run_case(const Case& c, const Params& p) {
  const auto t0 = std::chrono::steady_clock::now();
  // The library refuses options that do not fit together (a scheme's h mode or energy form, a
  // kernel's scheme) with std::invalid_argument before it steps: the settings' fault, so bad input.
  Result r = [&] {
    try {
      return c.run(p);
    } catch (const std::invalid_argument& e) {
      throw InputError(c.name + ": " + e.what());
    }
  }();
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.case_name = c.name;
  r.params = p.to_json();
  r.provenance = provenance();
  name_non_finite(r);
  return r;
}

}  // namespace sphv
