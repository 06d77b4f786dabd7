#include "verification/ic.hpp"

#include <cstdio>
#include <map>

#include "verification/cases/sod_errors.hpp"
#include "verification/cases/sod_simulate.hpp"

namespace sphv {
namespace {

// The shock tube exactly as sod/sod2d/sod3d lay it out (tube::layout): the active particles and,
// beyond them, the boundary layers sphv holds at the initial state (a code without such layers
// may drop them; only 0 <= x <= 1 is scored).
template <int D>
Snapshot tube_ic(const Params& p) {
  const TubeProblem pr = tube_problem(p);
  TubeRun run;
  const auto L = tube::layout<D>(pr, p.real("hfact"), p.integer("n"), run);
  Snapshot s;
  s.dim = D;
  s.time = 0.0;
  for (int d = 0; d < D; ++d) {
    auto& x = s.columns[std::string(1, "xyz"[d])];
    auto& v = s.columns["v" + std::string(1, "xyz"[d])];
    for (std::size_t i = 0; i < L.p.size(); ++i) x.push_back(L.p.x[i][d]), v.push_back(L.p.v[i][d]);
  }
  s.columns["m"] = L.p.m;
  s.columns["rho"] = L.p.rho;
  s.columns["u"] = L.p.u;
  s.columns["h"] = L.p.h;
  auto& pres = s.columns["p"];
  for (std::size_t i = 0; i < L.p.size(); ++i) pres.push_back((pr.gamma - 1.0) * L.p.rho[i] * L.p.u[i]);
  return s;
}

const std::map<std::string, InitialConditions>& ics() {
  static const std::map<std::string, InitialConditions> m = {
      {"sod", tube_ic<1>}, {"sod2d", tube_ic<2>}, {"sod3d", tube_ic<3>}};
  return m;
}

}  // namespace

const InitialConditions& find_ic(const std::string& case_name) {
  const auto it = ics().find(case_name);
  if (it != ics().end()) return it->second;
  std::string names;
  for (const auto& [k, v] : ics()) names += (names.empty() ? "" : ", ") + k;
  throw InputError("case '" + case_name + "' has no initial-conditions writer (cases that have one: " + names + ")");
}

void write_ic(const Case& c, const Params& p, const std::filesystem::path& path, const std::string& format) {
  Snapshot s = find_ic(c.name)(p);
  for (const auto& [k, v] : s.columns) s.taken_from[k] = k;
  write_snapshot(s, path, format);
}

namespace {
struct Options {
  std::string case_name, format = "csv";
  std::filesystem::path out;
  std::vector<std::string> settings;
};
}  // namespace

void add_ic_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("ic", "write a case's initial conditions (for another code to start from)");
  cmd->add_option("case", o->case_name, "case name (sod, sod2d, sod3d)")->required();
  cmd->add_option("--set", o->settings, "case parameter as key=value (repeatable; n is the level)")->take_all();
  cmd->add_option("--out", o->out, "output file")->required();
  cmd->add_option("--format", o->format, "csv|swift|h5part (default csv)")->check(CLI::IsMember({"csv", "swift", "h5part"}));
  cmd->callback([o] {
    const Case& c = find_case(o->case_name);
    find_ic(c.name);
    const Params p = c.parse(o->settings);
    write_ic(c, p, o->out, o->format);
    std::printf("%s n=%ld: initial conditions written to %s (%s)\n", c.name.c_str(), p.integer("n"), o->out.c_str(),
                o->format.c_str());
  });
}

}  // namespace sphv
