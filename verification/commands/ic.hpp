#pragma once
// `sphv ic CASE [--set key=value]... --out FILE [--format csv|swift|h5part]`: a case's initial
// conditions at a level, so that another code starts from exactly what sphv starts from. The
// format follows the file's extension (.csv: csv; .hdf5, .h5: swift; .h5part: h5part) unless
// --format names it; an extension that contradicts --format is refused.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "verification/harness/case.hpp"

namespace sphv {

// The initial conditions a case declares (Case::ic), or an InputError listing the cases that have them.
const InitialConditions& find_ic(const std::string& case_name);
void write_ic(const Case& c, const Params& p, const std::filesystem::path& path, const std::string& format);

// SWIFT's adiabatic index is fixed when SWIFT is built (./configure --with-adiabatic-index, one of
// 5/3, 7/5, 4/3, 2; default 5/3) and no initial-conditions file changes it: an initial state for
// SWIFT is the state at 5/3 unless gamma is set (or the case allows no other gamma, as the n = 1
// polytrope's 2). The settings completed so, and one console line naming SWIFT's gamma and the
// configure option that gives it.
struct SwiftGamma {
  std::vector<std::string> settings;
  std::string note;  // "" where the case has no gamma
};
SwiftGamma swift_gamma(const Case& c, std::vector<std::string> settings);

// The format of an initial-conditions file: the one asked for (csv, swift, h5part, or "auto")
// checked against the file's extension. An InputError when they contradict.
std::string ic_format(const std::filesystem::path& path, const std::string& asked);

struct IcOptions {
  std::string case_name, format = "auto";
  std::filesystem::path out;
  std::vector<std::string> settings;
};
void ic_command(const IcOptions& o);

}  // namespace sphv
