#pragma once
// `sphv ic CASE [--set key=value]... --out FILE [--format csv|swift|h5part]`: a case's initial
// conditions at a level, so that another code starts from exactly what sphv starts from.
#include "verification/cli_app.hpp"
#include <filesystem>
#include <functional>
#include <string>

#include "verification/case.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

using InitialConditions = std::function<Snapshot(const Params&)>;
// The initial conditions of a case, or an InputError listing the cases that have them.
const InitialConditions& find_ic(const std::string& case_name);
void write_ic(const Case& c, const Params& p, const std::filesystem::path& path, const std::string& format);
void add_ic_command(CLI::App& app);

}  // namespace sphv
