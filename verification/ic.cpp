#include "verification/ic.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
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
#include "verification/cases/sound_wave_setup.hpp"
#include "verification/cases/square_setup.hpp"
#include "verification/snapshot/swift_ic.hpp"

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

// The state in sphv's layout, or (IcLayout::swift) moved by `shift` along every axis into the
// periodic box [0, box).
InitialState placed(Snapshot s, std::optional<double> gamma, IcLayout layout, double shift, double box) {
  InitialState st{std::move(s), {{box, box, box}, gamma}};
  if (layout == IcLayout::swift)
    for (int d = 0; d < st.s.dim; ++d)
      for (double& x : st.s.columns.at(std::string(1, "xyz"[d]))) x += shift;
  return st;
}

// The shock tube as SWIFT's SodShock examples lay it out: periodic on [0, 2] along x, the left
// state on [0, 1), the right state on [1, 2), so the interfaces lie at x = 1 and at the wrap
// x = 0 = 2 and no boundary layer is needed. The left spacing is 1/n; in 2D/3D the tube is
// periodic across with tube::layout's width and lattices. Each side's spacing along x divides its
// unit length and its particle mass makes its density exact (the masses of the two sides agree
// when the counts divide, as in makeIC.py).
template <int D>
InitialState periodic_tube(const Params& prm) {
  const TubeProblem pr = tube_problem(prm);
  if (pr.x0 != 0.5)
    throw InputError("x0 = " + prm.text("x0") + ": the periodic tube of SWIFT's layout has its interfaces at x = 1 "
                     "and at the wrap of [0, 2], the tube [0, 1]'s x0 = 0.5 moved to its middle");
  const long n = prm.integer("n");
  const double hfact = prm.real("hfact"), dxl = 1.0 / n;
  const double s = std::pow(pr.left.rho / pr.right.rho, 1.0 / D);  // isotropic spacing ratio R/L
  const int ntl = D == 1 ? 1 : static_cast<int>(std::ceil(2.5 * hfact * std::max(1.0, s)));
  const int ntr = D == 1 ? 1 : std::max(1, static_cast<int>(std::lround(ntl / s)));
  const double width = ntl * dxl, mass = pr.left.rho * std::pow(dxl, D);
  const long nr = std::max(1L, std::lround(pr.right.rho * std::pow(width / ntr, D - 1) / mass));
  auto per_slab = [](int nt) {
    long per = 1;
    for (int d = 1; d < D; ++d) per *= nt;
    return per;
  };
  sph::Particles<D> p;
  p.resize(n * per_slab(ntl) + nr * per_slab(ntr));
  std::size_t k = 0;
  auto place = [&](double from, long count, int nt, const reference::GasState& st) {
    const double dx = 1.0 / count, dy = width / nt;
    for (long i = 0; i < count; ++i)
      for (long t = 0; t < per_slab(nt); ++t, ++k) {
        p.x[k][0] = from + (i + 0.5) * dx;
        for (long d = 1, rest = t; d < D; ++d, rest /= nt) p.x[k][d] = (static_cast<double>(rest % nt) + 0.5) * dy;
        p.v[k][0] = st.u;
        p.m[k] = st.rho * dx * std::pow(dy, D - 1);
        p.rho[k] = st.rho;
        p.u[k] = st.p / ((pr.gamma - 1.0) * st.rho);
      }
  };
  place(0.0, n, ntl, pr.left);
  place(1.0, nr, ntr, pr.right);
  sph::smoothing_length_from_density(p, hfact);  // (50)
  return {at_start(p, pr.gamma), {{2.0, D == 1 ? 2.0 : width, D == 1 ? 2.0 : width}, pr.gamma}};
}

// The shock tube exactly as sod/sod2d/sod3d lay it out (tube::layout): the active particles and,
// beyond them, the boundary layers sphv holds at the initial state (a code without such layers
// may drop them; only 0 <= x <= 1 is scored). SWIFT's layout: periodic_tube.
template <int D>
InitialState tube_ic(const Params& p, IcLayout layout) {
  if (layout == IcLayout::swift) return periodic_tube<D>(p);
  const TubeProblem pr = tube_problem(p);
  TubeRun run;
  return {at_start(tube::layout<D>(pr, p.real("hfact"), p.integer("n"), run).p, pr.gamma), {{}, pr.gamma}};
}

// The blast in the periodic box [-0.5, 0.5]^d, centre at the origin (sedov_setup.hpp); SWIFT's
// layout: the box [0, 1]^d, centre (0.5, ...) as in its SedovBlast examples.
InitialState sedov_ic(const Params& p, IcLayout layout) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return placed(at_start(sedov::initial_particles<D>(p, p.real("hfact")), p.real("gamma")), p.real("gamma"), layout,
                  0.5, 1.0);
  });
}

// The inflowing ball around the origin (noh_setup.hpp); SWIFT's layout: centred in the periodic box
// of side 2 (as its Noh examples) or, for a ball that needs more, the next even side that leaves
// one initial support radius of empty space between the ball and its periodic images.
InitialState noh_ic(const Params& p, IcLayout layout) {
  noh::check_size(p);
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const noh::Setup<D> s = noh::initial<D>(p, p.real("hfact"));
    const double h0 = p.real("hfact") / p.integer("n"), side = 2.0 * std::ceil(s.R0 + 0.5 * h0);
    return placed(at_start(s.p, p.real("gamma")), p.real("gamma"), layout, side / 2.0, side);
  });
}

// The unit sphere around the origin, h before the run's iteration (evrard_setup.hpp); SWIFT's
// layout: the box of side 100 with the sphere at its centre (50, 50, 50), as its EvrardCollapse_3D.
InitialState evrard_ic(const Params& p, IcLayout layout) {
  return placed(at_start(evrard::sphere(p.integer("n"), p.real("u0"), p.real("hfact")), p.real("gamma")),
                p.real("gamma"), layout, 50.0, 100.0);
}

// The lattice in the periodic unit box with the summation density, u = c_v T(x, 0) of the chosen
// set-up (setup=gauss or sine; heat_errors.hpp); no pressure (conduction only). The unit box is
// SWIFT's layout too.
InitialState heat_ic(const Params& p, IcLayout layout) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const heat::ParticleSet<D> set(static_cast<int>(p.integer("n")), p.real("hfact"), p.real("jitter"));
    sph::Particles<D> q = set.p;
    std::vector<std::vector<double>> coords(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) coords[i] = set.coords(i);
    const double cv = p.real("c_v");
    q.u = heat::setups.at(p.text("setup")).second(coords, 0.0, heat::diffusivity(q.rho, p.real("K"), cv), cv);
    return placed(at_start(q, std::nullopt), std::nullopt, layout, 0.0, 1.0);
  });
}

// The displaced lattice in the periodic unit box [0, 1)^d (sound_wave_setup.hpp), v_x and u of
// the wave, rho the wave's exact density (a run replaces it by the summation (27)); the unit box
// is SWIFT's layout too.
InitialState sound_wave_ic(const Params& p, IcLayout layout) {
  return by_dimension(p, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return placed(at_start(sound_wave::initial_particles<D>(p), p.real("gamma")), p.real("gamma"), layout, 0.0, 1.0);
  });
}

// The square's particles in the periodic unit box [0, 1)^d (square_setup.hpp: equal masses on
// two lattices, or one lattice), rho and u exact; the unit box is SWIFT's layout too.
InitialState square_ic(const Params& p, IcLayout layout) {
  auto one = [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    return placed(at_start(square::initial_particles<D>(p), p.real("gamma")), p.real("gamma"), layout, 0.0, 1.0);
  };
  if (p.integer("dim") == 2) return one(std::integral_constant<int, 2>{});
  return one(std::integral_constant<int, 3>{});
}

const std::map<std::string, InitialConditions>& ics() {
  static const std::map<std::string, InitialConditions> m = {
      {"sod", tube_ic<1>}, {"sod2d", tube_ic<2>}, {"sod3d", tube_ic<3>}, {"sedov", sedov_ic},
      {"noh", noh_ic},     {"evrard", evrard_ic}, {"heat", heat_ic}, {"sound_wave", sound_wave_ic},
      {"square", square_ic}};
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
