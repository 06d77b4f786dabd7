#include "verification/harness/params.hpp"

#include <sstream>

namespace sphv {

ParamSpec integer_param(std::string name, long def, std::string help, std::optional<double> gt) {
  return {std::move(name), ParamSpec::Kind::Integer, std::to_string(def), std::move(help), gt};
}

std::string shortest(double v) {
  char buf[32];  // the shortest round-trip form of a double needs at most 24 characters
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : "?";
}

ParamSpec real_param(std::string name, double def, std::string help, std::optional<double> gt) {
  return {std::move(name), ParamSpec::Kind::Real, shortest(def), std::move(help), gt};
}

ParamSpec choice_param(std::string name, std::string def, std::string help,
                       std::vector<std::string> choices) {
  return {std::move(name), ParamSpec::Kind::Text, std::move(def), std::move(help),
          std::nullopt, std::nullopt, std::move(choices)};
}

namespace {

std::string known_names(const std::vector<ParamSpec>& specs) {
  std::string out;
  for (const auto& s : specs) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

}  // namespace

Params::Params(std::string case_name, std::vector<ParamSpec> specs,
               const std::vector<std::string>& settings)
    : case_name_(std::move(case_name)), specs_(std::move(specs)) {
  for (const auto& s : specs_) set(s.name, s.default_value);
  for (const auto& kv : settings) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("malformed setting '" + kv + "': expected key=value");
    set(kv.substr(0, eq), kv.substr(eq + 1));
  }
}

const ParamSpec& Params::spec(const std::string& key) const {
  for (const auto& s : specs_)
    if (s.name == key) return s;
  throw InputError("unknown parameter '" + key + "' for case '" + case_name_ +
                   "' (known: " + known_names(specs_) + ")");
}

void Params::set(const std::string& key, const std::string& value) {
  const ParamSpec& s = spec(key);
  double number = 0.0;
  if (s.kind == ParamSpec::Kind::Integer) {
    long v = 0;
    if (!parse_number(value, v))
      throw InputError("parameter " + key + ": '" + value + "' is not an integer");
    number = static_cast<double>(v);
  } else if (s.kind == ParamSpec::Kind::Real) {
    if (!parse_finite(value, number))
      throw InputError("parameter " + key + ": '" + value + "' is not a finite number");
  } else if (!s.choices.empty()) {
    bool ok = false;
    for (const auto& c : s.choices) ok = ok || c == value;
    if (!ok) {
      std::string list;
      for (const auto& c : s.choices) list += (list.empty() ? "" : ", ") + c;
      throw InputError("parameter " + key + ": '" + value + "' is not one of " + list);
    }
  }
  if (s.kind != ParamSpec::Kind::Text) {
    if (key == "n" && number > max_resolution)
      throw InputError("parameter n must be <= " + std::to_string(max_resolution) + ", got " + value);
    if (s.greater_than && !(number > *s.greater_than))
      throw InputError("parameter " + key + " must be > " + shortest(*s.greater_than) + ", got " + value);
    if (s.at_least && !(number >= *s.at_least))
      throw InputError("parameter " + key + " must be >= " + shortest(*s.at_least) + ", got " + value);
  }
  values_[key] = value;
}

long Params::integer(const std::string& key) const {
  long v = 0;
  parse_number(values_.at(spec(key).name), v);
  return v;
}

double Params::real(const std::string& key) const {
  double v = 0;
  parse_number(values_.at(spec(key).name), v);
  return v;
}

const std::string& Params::text(const std::string& key) const { return values_.at(spec(key).name); }

Params Params::with(const std::string& key, const std::string& value) const {
  Params copy = *this;
  copy.set(key, value);
  return copy;
}

std::vector<std::string> Params::non_defaults() const {
  std::vector<std::string> out;
  for (const auto& s : specs_) {
    const std::string& v = values_.at(s.name);
    bool same = v == s.default_value;
    if (s.kind == ParamSpec::Kind::Real) {
      double a = 0, b = 0;
      same = parse_number(v, a) && parse_number(s.default_value, b) && a == b;
    }
    if (!same && s.name != "n") out.push_back(s.name + "=" + v);
  }
  return out;
}

nlohmann::json Params::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& s : specs_) {
    if (s.kind == ParamSpec::Kind::Integer) j[s.name] = integer(s.name);
    else if (s.kind == ParamSpec::Kind::Real) j[s.name] = real(s.name);
    else j[s.name] = text(s.name);
  }
  return j;
}

namespace {

// One element of a value: a/b of two finite numbers with b != 0 as its quotient, anything without
// '/' as it is.
std::string without_fraction(const std::string& key, const std::string& element) {
  const std::size_t slash = element.find('/');
  if (slash == std::string::npos) return element;
  double a = 0.0, b = 0.0;
  if (!parse_finite(std::string_view(element).substr(0, slash), a) ||
      !parse_finite(std::string_view(element).substr(slash + 1), b) || b == 0.0 || !std::isfinite(a / b))
    throw InputError("parameter " + key + ": '" + element + "' is not a fraction a/b of finite numbers with b != 0");
  return shortest(a / b);
}

}  // namespace

std::vector<std::string> split_settings(const std::vector<std::string>& args) {
  std::vector<std::string> items;
  for (const auto& arg : args) {
    auto take = [&](const std::string& piece) {
      if (piece.find('=') != std::string::npos || items.empty()) items.push_back(piece);
      else items.back() += "," + piece;  // a list value continued
    };
    std::size_t from = 0;
    for (std::size_t comma = arg.find(','); ; comma = arg.find(',', from)) {
      std::istringstream words(arg.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
      std::string word;
      bool any = false;
      while (words >> word) take(word), any = true;
      if (!any) throw InputError("malformed setting '" + arg + "': an empty item between commas");
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
  }
  for (auto& kv : items) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("malformed setting '" + kv + "': expected key=value");
    const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
    std::string out;
    std::size_t from = 0;
    for (std::size_t comma = value.find(','); ; comma = value.find(',', from)) {
      out += (from == 0 ? "" : ",") + without_fraction(key, value.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
    kv = key + "=" + out;
  }
  return items;
}

std::vector<long> parse_levels(const std::string& text) {
  if (text.empty()) throw InputError("--levels needs at least one value of n, e.g. 16,32,64");
  std::vector<long> levels;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    long n = 0;
    if (!parse_number(item, n))
      throw InputError("--levels '" + text + "': '" + item + "' is not an integer (expected e.g. 16,32,64)");
    if (n <= 0) throw InputError("--levels '" + text + "': n must be > 0, got " + item);
    if (n > max_resolution)
      throw InputError("--levels '" + text + "': n must be <= " + std::to_string(max_resolution) + ", got " + item);
    levels.push_back(n);
    if (comma == std::string::npos) return levels;
    start = comma + 1;
  }
}

}  // namespace sphv
