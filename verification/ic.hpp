#pragma once
// `sphv ic CASE [--set key=value]... --out FILE [--format csv|swift|h5part]`: a case's initial
// conditions at a level, so that another code starts from exactly what sphv starts from. The
// format follows the file's extension (.csv: csv; .hdf5, .h5: swift; .h5part: h5part) unless
// --format names it; an extension that contradicts --format is refused.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "verification/case.hpp"
#include "verification/snapshot/snapshot.hpp"
#include "verification/snapshot/swift_ic.hpp"

namespace sphv {

// Where the particles lie: as sphv's own run lays them out (csv, h5part), or as SWIFT's examples
// do (swift): every particle inside a periodic box [0, box), the radial cases' centre at its
// middle, the shock tube periodic on [0, 2] with its interfaces at x = 1 and at the wrap
// (examples/HydroTests/SodShock_1D/makeIC.py) and no boundary layers.
enum class IcLayout { sphv, swift };

struct InitialState {
  Snapshot s;
  SwiftIcHeader swift;  // the box (IcLayout::swift) and the gas's gamma
};

using InitialConditions = std::function<InitialState(const Params&, IcLayout)>;
// The initial conditions of a case, or an InputError listing the cases that have them.
const InitialConditions& find_ic(const std::string& case_name);
void write_ic(const Case& c, const Params& p, const std::filesystem::path& path, const std::string& format);

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
