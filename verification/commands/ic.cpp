#include "verification/commands/ic.hpp"

#include <algorithm>
#include <cctype>
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
  const Params p = c.parse(o.settings);
  write_ic(c, p, o.out, format);
  std::printf("%s n=%ld: initial conditions written to %s (%s)\n", c.name.c_str(), p.integer("n"), o.out.c_str(),
              format.c_str());
}

}  // namespace sphv
