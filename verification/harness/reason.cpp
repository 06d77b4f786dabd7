#include "verification/harness/reason.hpp"

#include <cmath>
#include <cstdio>
#include <regex>

#include "verification/harness/sweep.hpp"

namespace sphv {

namespace {
std::string figure_of(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// Replaces every {...} by what `expand` returns for its contents.
template <class F>
std::string substitute(const std::string& why, F&& expand) {
  std::string out;
  std::size_t from = 0;
  while (true) {
    const std::size_t open = why.find('{', from);
    const std::size_t close = open == std::string::npos ? open : why.find('}', open);
    if (close == std::string::npos) return out + why.substr(from);
    out += why.substr(from, open - from) + expand(why.substr(open + 1, close - open - 1));
    from = close + 1;
  }
}
}  // namespace

std::string fill_reason(const std::string& why, const Sweep& s) {
  auto per_level = [&](auto value_of) {
    std::string t;
    for (const Result& r : s.runs) t += (t.empty() ? "" : ", ") + figure_of(value_of(r));
    return t;
  };
  return substitute(why, [&](const std::string& key) -> std::string {
    if (key == "levels") {
      std::string t;
      for (long n : s.levels) t += (t.empty() ? "n = " : ", ") + std::to_string(n);
      return t;
    }
    if (key.rfind("order.", 0) == 0) {
      const auto o = s.observed_order.find(key.substr(6));
      if (o == s.observed_order.end()) return "-";
      return figure_of(o->second.p) + (std::isfinite(o->second.se) ? " +- " + figure_of(o->second.se) : "");
    }
    if (key.rfind("extra.", 0) == 0) {
      // A setting's consequence (a lattice sum at fixed hfact) is one number at every level:
      // printed once, so the reader sees that it does not change with n.
      auto value = [&](const Result& r) {
        const auto it = r.extra.find(key.substr(6));
        return it != r.extra.end() && it->is_number() ? it->get<double>() : std::nan("");
      };
      bool same = s.runs.size() > 1;
      for (const Result& r : s.runs) same = same && figure_of(value(r)) == figure_of(value(s.runs.front()));
      return same ? figure_of(value(s.runs.front())) + " at every level" : per_level(value);
    }
    for (const Result& r : s.runs)
      if (r.errors.count(key))
        return per_level([&](const Result& q) { return q.errors.count(key) ? q.errors.at(key) : std::nan(""); });
    return "{" + key + "}";
  });
}

std::string describe_reason(const std::string& why) {
  return substitute(why, [](const std::string& key) -> std::string {
    if (key == "levels") return "<the levels>";
    if (key.rfind("order.", 0) == 0) return "<observed order of " + key.substr(6) + ">";
    if (key.rfind("extra.", 0) == 0) return "<" + key.substr(6) + " at each level>";
    return "<" + key + " at each level>";
  });
}

std::string reason_without_placeholders(const std::string& why) {
  std::string t = substitute(why, [](const std::string&) { return std::string(); });
  static const std::regex allowed(R"(\(\d+\)|section \d+(\.\d+)*)");
  return std::regex_replace(t, allowed, "");
}

}  // namespace sphv
