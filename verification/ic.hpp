#pragma once
// `sphv ic CASE [--set key=value]... --out FILE [--format csv|swift|h5part]`: a case's initial
// conditions at a level, so that another code starts from exactly what sphv starts from.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "verification/case.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

using InitialConditions = std::function<Snapshot(const Params&)>;
// The initial conditions of a case, or an InputError listing the cases that have them.
const InitialConditions& find_ic(const std::string& case_name);
void write_ic(const Case& c, const Params& p, const std::filesystem::path& path, const std::string& format);

struct IcOptions {
  std::string case_name, format = "csv";
  std::filesystem::path out;
  std::vector<std::string> settings;
};
void ic_command(const IcOptions& o);

}  // namespace sphv
