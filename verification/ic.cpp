#include "verification/ic.hpp"

#include <cstdio>
#include <map>
#include <optional>

#include "verification/cases/evrard_setup.hpp"
#include "verification/cases/heat_errors.hpp"
#include "verification/cases/heat_lattice.hpp"
#include "verification/cases/noh_setup.hpp"
#include "verification/cases/sedov_setup.hpp"
#include "verification/cases/sod_errors.hpp"
#include "verification/cases/sod_simulate.hpp"

namespace sphv {
namespace {

// A particle set as a snapshot at t = 0: positions, velocities, m, rho, u, h and, for a gas,
// p = (gamma - 1) rho u.
template <int D>
Snapshot at_start(const sph::Particles<D>& p, std::optional<double> gamma) {
  Snapshot s;
  s.dim = D;
  s.time = 0.0;
  for (int d = 0; d < D; ++d) {
    auto& x = s.columns[std::string(1, "xyz"[d])];
    auto& v = s.columns["v" + std::string(1, "xyz"[d])];
    for (std::size_t i = 0; i < p.size(); ++i) x.push_back(p.x[i][d]), v.push_back(p.v[i][d]);
  }
  s.columns["m"] = p.m;
  s.columns["rho"] = p.rho;
  s.columns["u"] = p.u;
  s.columns["h"] = p.h;
  if (!gamma) return s;
  auto& pres = s.columns["p"];
  for (std::size_t i = 0; i < p.size(); ++i) pres.push_back((*gamma - 1.0) * p.rho[i] * p.u[i]);
  return s;
}

// The shock tube exactly as sod/sod2d/sod3d lay it out (tube::layout): the active particles and,
// beyond them, the boundary layers sphv holds at the initial state (a code without such layers
// may drop them; only 0 <= x <= 1 is scored).
template <int D>
Snapshot tube_ic(const Params& p) {
  const TubeProblem pr = tube_problem(p);
  TubeRun run;
  return at_start(tube::layout<D>(pr, p.real("hfact"), p.integer("n"), run).p, pr.gamma);
}

// The blast in the periodic box [-0.5, 0.5]^d, centre at the origin (sedov_setup.hpp).
Snapshot sedov_ic(const Params& p) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return at_start(sedov::initial_particles<D>(p, p.real("hfact")), p.real("gamma"));
  });
}

// The inflowing ball around the origin (noh_setup.hpp).
Snapshot noh_ic(const Params& p) {
  noh::check_size(p);
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return at_start(noh::initial<D>(p, p.real("hfact")).p, p.real("gamma"));
  });
}

// The unit sphere around the origin, h before the run's iteration (evrard_setup.hpp).
Snapshot evrard_ic(const Params& p) {
  return at_start(evrard::sphere(p.integer("n"), p.real("u0"), p.real("hfact")), p.real("gamma"));
}

// The lattice in the periodic unit box with the summation density, u = c_v T(x, 0) of the chosen
// set-up (setup=gauss or sine; heat_errors.hpp); no pressure (conduction only).
Snapshot heat_ic(const Params& p) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const heat::ParticleSet<D> set(static_cast<int>(p.integer("n")), p.real("hfact"), p.real("jitter"));
    sph::Particles<D> q = set.p;
    std::vector<std::vector<double>> coords(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) coords[i] = set.coords(i);
    const double cv = p.real("c_v");
    q.u = heat::setups.at(p.text("setup")).second(coords, 0.0, heat::diffusivity(q.rho, p.real("K"), cv), cv);
    return at_start(q, std::nullopt);
  });
}

const std::map<std::string, InitialConditions>& ics() {
  static const std::map<std::string, InitialConditions> m = {
      {"sod", tube_ic<1>}, {"sod2d", tube_ic<2>}, {"sod3d", tube_ic<3>}, {"sedov", sedov_ic},
      {"noh", noh_ic},     {"evrard", evrard_ic}, {"heat", heat_ic}};
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

void ic_command(const IcOptions& o) {
  const Case& c = find_case(o.case_name);
  find_ic(c.name);
  const Params p = c.parse(o.settings);
  write_ic(c, p, o.out, o.format);
  std::printf("%s n=%ld: initial conditions written to %s (%s)\n", c.name.c_str(), p.integer("n"), o.out.c_str(),
              o.format.c_str());
}

}  // namespace sphv
