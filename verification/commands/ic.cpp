#include "verification/commands/ic.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>

#include "verification/snapshot/swift_ic.hpp"

namespace sphv {

const InitialConditions& find_ic(const std::string& case_name) {
  const Case& c = find_case(case_name);
  if (c.ic) return c.ic;
  std::string names;
  for (const auto& k : catalogue())
    if (k.ic) names += (names.empty() ? "" : ", ") + k.name;
  throw InputError("case '" + case_name + "' has no initial-conditions writer (cases that have one: " + names + ")");
}

std::string ic_format(const std::filesystem::path& path, const std::string& asked) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::map<std::string, std::vector<std::string>> by_extension = {
      {".csv", {"csv"}}, {".hdf5", {"swift", "h5part"}}, {".h5", {"swift", "h5part"}}, {".h5part", {"h5part"}}};
  const auto it = by_extension.find(ext);
  if (asked == "auto") {
    if (it == by_extension.end())
      throw InputError("--out " + path.string() + ": no format from the extension '" + ext +
                       "' (.csv, .hdf5, .h5, .h5part); name it with --format csv|swift|h5part");
    return it->second.front();
  }
  if (it != by_extension.end() && std::find(it->second.begin(), it->second.end(), asked) == it->second.end())
    throw InputError("--out " + path.string() + ": the extension '" + ext + "' contradicts --format " + asked);
  return asked;
}

namespace {

bool sets(const std::vector<std::string>& settings, const std::string& key) {
  return std::any_of(settings.begin(), settings.end(), [&](const std::string& s) {
    return s.rfind(key + "=", 0) == 0 && s != key + "=preset";
  });
}

// The configure value of SWIFT's adiabatic index equal to gamma, or "".
std::string swift_option(double gamma) {
  const std::pair<double, const char*> options[] = {{5.0 / 3.0, "5/3"}, {7.0 / 5.0, "7/5"}, {4.0 / 3.0, "4/3"}, {2.0, "2"}};
  for (const auto& [g, text] : options)
    if (std::abs(gamma - g) <= 1e-12 * g) return text;
  return "";
}

}  // namespace

SwiftGamma swift_gamma(const Case& c, std::vector<std::string> settings) {
  const Scorer& sc = c.scorer;
  if (!sc.gamma || std::none_of(c.params.begin(), c.params.end(), [](const ParamSpec& p) { return p.name == "gamma"; }))
    return {std::move(settings), ""};
  const bool given = sets(settings, "gamma");
  if (!given) {
    auto at_five_thirds = settings;
    at_five_thirds.push_back("gamma=" + shortest(5.0 / 3.0));
    try {
      c.parse(at_five_thirds);
      settings = std::move(at_five_thirds);
    } catch (const InputError&) {  // the case allows no other gamma than its own (the n = 1 polytrope's 2)
    }
  }
  const double gamma = sc.gamma(c.parse(settings));
  const std::string option = swift_option(gamma), g = shortest(gamma);
  std::string note;
  if (option == "5/3")
    note = "gamma 5/3" + std::string(given ? "" : " (SWIFT's default)") + ": the state SWIFT runs as built by default "
           "(its gamma is fixed when it is built: ./configure --with-adiabatic-index=5/3, 7/5, 4/3 or 2; --set gamma=G "
           "for another)";
  else if (!option.empty())
    note = "gamma " + g + (given ? "" : " (the case's only gamma)") + ": SWIFT runs this state only when built with "
           "./configure --with-adiabatic-index=" + option + " (its default is 5/3; the file's gamma does not change it)";
  else
    note = "gamma " + g + ": no SWIFT build runs it (./configure --with-adiabatic-index offers 5/3, 7/5, 4/3 or 2 "
           "only; SWIFT would run this state at its own gamma)";
  return {std::move(settings), note};
}

void write_ic(const Case& c, const Params& p, const std::filesystem::path& path, const std::string& format) {
  InitialState st = find_ic(c.name)(p, format == "swift" ? IcLayout::swift : IcLayout::sphv);
  for (const auto& [k, v] : st.s.columns) st.s.taken_from[k] = k;
  if (format == "swift") write_swift_ic(st.s, st.swift, path);
  else write_snapshot(st.s, path, format);
}

void ic_command(const IcOptions& o) {
  const Case& c = find_case(o.case_name);
  find_ic(c.name);
  const std::string format = ic_format(o.out, o.format);
  const SwiftGamma g = format == "swift" ? swift_gamma(c, o.settings) : SwiftGamma{o.settings, ""};
  const Params p = c.parse(g.settings);
  write_ic(c, p, o.out, format);
  std::printf("%s n=%ld: initial conditions written to %s (%s)\n", c.name.c_str(), p.integer("n"), o.out.c_str(),
              format.c_str());
  if (!g.note.empty()) std::printf("%s\n", g.note.c_str());
}

}  // namespace sphv
