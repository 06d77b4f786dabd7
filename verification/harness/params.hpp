#pragma once
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace sphv {

// Bad input from the user (unknown case or parameter, malformed or out-of-range value,
// unreadable file). main() prints it as one line and exits non-zero.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Whether the whole of text is one number (std::from_chars: no leading '+' or spaces); sets v.
template <class T>
bool parse_number(std::string_view text, T& v) {
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return !text.empty() && ec == std::errc() && ptr == text.data() + text.size();
}
// Whether the whole of text is one finite number (from_chars also reads "inf" and "nan"); sets v.
inline bool parse_finite(std::string_view text, double& v) { return parse_number(text, v) && std::isfinite(v); }

// One parameter a case accepts, with its default and the range it must lie in.
struct ParamSpec {
  enum class Kind { Integer, Real, Text };
  std::string name;
  Kind kind;
  std::string default_value;
  std::string help;
  std::optional<double> greater_than = std::nullopt;  // strict lower bound (n > 0, h > 0, gamma > 1)
  std::optional<double> at_least = std::nullopt;      // inclusive lower bound
  std::vector<std::string> choices = {};              // allowed words for Text
};

// The shortest text that reads back as exactly v (std::to_chars): 5.0/3 is "1.6666666666666667".
std::string shortest(double v);

// The largest resolution n any case accepts: beyond it particle counts overflow the integers
// the cases index with (n^3 in 3D) or no machine's memory holds them.
constexpr long max_resolution = 10'000'000;

ParamSpec integer_param(std::string name, long def, std::string help, std::optional<double> gt = 0.0);
ParamSpec real_param(std::string name, double def, std::string help, std::optional<double> gt = std::nullopt);
ParamSpec choice_param(std::string name, std::string def, std::string help, std::vector<std::string> choices);

// Validated parameter values of one run: defaults overridden by key=value settings.
class Params {
 public:
  Params(std::string case_name, std::vector<ParamSpec> specs,
         const std::vector<std::string>& settings = {});

  long integer(const std::string& key) const;
  double real(const std::string& key) const;
  const std::string& text(const std::string& key) const;
  Params with(const std::string& key, const std::string& value) const;
  // The settings that differ from the defaults, as "key=value" (names a variant).
  std::vector<std::string> non_defaults() const;
  nlohmann::json to_json() const;

 private:
  const ParamSpec& spec(const std::string& key) const;
  void set(const std::string& key, const std::string& value);
  std::string case_name_;
  std::vector<ParamSpec> specs_;
  std::map<std::string, std::string> values_;
};

// The settings as the user types them after --set, one key=value each: items separated by
// commas or blanks ("E=1,rho0=1", "E=1 rho0=1"); an item without '=' continues the previous
// value as a list (centre=0.5,0.5,0.5); a number written as a simple fraction a/b (gamma=5/3)
// becomes the shortest form of its quotient. An InputError names a malformed item or fraction.
std::vector<std::string> split_settings(const std::vector<std::string>& args);

// A list of levels n as the user writes it after --levels: "16,32,64" (positive integers,
// comma-separated). Anything else, the empty list included, is an InputError naming the fault.
std::vector<long> parse_levels(const std::string& text);

}  // namespace sphv
