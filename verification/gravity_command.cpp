#include "verification/gravity_command.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "verification/cases/gravity_compare.hpp"
#include "verification/cases/gravity_models.hpp"
#include "verification/params.hpp"
#include "verification/result.hpp"

namespace sphv {
namespace {

struct Options {
  std::string input, out, multipole = "quad", opening = "robust";
  double theta = 0.5, eps = 0.0;
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream ss(line);
  for (std::string s; std::getline(ss, s, ',');) {
    const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    f.push_back(a == std::string::npos ? "" : s.substr(a, b - a + 1));
  }
  if (!line.empty() && line.back() == ',') f.push_back("");
  return f;
}

// Reads columns x, y, z, m (any order, further columns ignored) after a header row.
gravity::ParticleSet read_particles(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read " + path);
  std::string line;
  if (!std::getline(in, line)) throw InputError(path + " is empty (expected a header row x,y,z,m)");
  const auto header = split(line);
  int col[4];
  const char* names[4] = {"x", "y", "z", "m"};
  for (int k = 0; k < 4; ++k) {
    col[k] = -1;
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == names[k]) col[k] = static_cast<int>(c);
    if (col[k] < 0) throw InputError(path + ": header has no column '" + names[k] + "' (need x,y,z,m)");
  }
  gravity::ParticleSet s;
  for (long row = 2; std::getline(in, line); ++row) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto f = split(line);
    if (f.size() != header.size())
      throw InputError(path + ":" + std::to_string(row) + ": " + std::to_string(f.size()) + " fields, header has " +
                       std::to_string(header.size()));
    double v[4];
    for (int k = 0; k < 4; ++k) {
      const std::string& t = f[col[k]];
      char* end = nullptr;
      v[k] = std::strtod(t.c_str(), &end);
      if (t.empty() || *end != '\0' || !std::isfinite(v[k]))
        throw InputError(path + ":" + std::to_string(row) + ": " + names[k] + " = '" + t + "' is not a finite number");
    }
    if (v[3] < 0.0) throw InputError(path + ":" + std::to_string(row) + ": negative mass " + f[col[3]]);
    s.x.push_back({v[0], v[1], v[2]});
    s.m.push_back(v[3]);
  }
  if (s.x.empty()) throw InputError(path + " has no particles (only a header row)");
  return s;
}

void run(const Options& o) {
  if (!(o.theta > 0.0)) throw InputError("--theta must be > 0, got " + std::to_string(o.theta));
  if (!(o.eps >= 0.0)) throw InputError("--softening must be >= 0, got " + std::to_string(o.eps));
  const auto s = read_particles(o.input);
  using Clock = std::chrono::steady_clock;
  const sph::GravityOptions go{.theta = o.theta, .eps = o.eps, .G = 1.0,
                               .multipole = o.multipole == "mono" ? sph::Multipole::monopole : sph::Multipole::quadrupole,
                               .opening = o.opening == "plain" ? sph::Opening::plain : sph::Opening::robust};
  auto t0 = Clock::now();
  const auto tree = sph::build_tree<3>(s.x, s.m);
  const auto f = sph::tree_gravity(tree, s.x, s.m, go);
  const double t_tree = std::chrono::duration<double>(Clock::now() - t0).count();
  t0 = Clock::now();
  const auto d = gravity::direct(s.x, s.m, o.eps);
  const double t_direct = std::chrono::duration<double>(Clock::now() - t0).count();

  std::string csv = "x,y,z,m,ax_tree,ay_tree,az_tree,phi_tree,ax_direct,ay_direct,az_direct,phi_direct\n";
  char buf[512];
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  s.x[i][0], s.x[i][1], s.x[i][2], s.m[i], f.a[i][0], f.a[i][1], f.a[i][2], f.phi[i], d.ax[i],
                  d.ay[i], d.az[i], d.phi[i]);
    csv += buf;
  }
  write_atomically(o.out, csv);

  // Particles with zero direct force (e.g. a single particle) have no relative error.
  std::vector<double> rel;
  const auto all = gravity::relative_force_error(f, d);
  for (double e : all)
    if (std::isfinite(e)) rel.push_back(e);
  const auto p = gravity::percentiles(rel);
  const double wd = gravity::potential_energy(s.m, d.phi), wt = gravity::potential_energy(s.m, f.phi);
  double inter = 0.0;
  for (long c : f.interactions) inter += c;
  std::printf("gravity: N = %zu, theta = %g, %s, %s opening, eps = %g, G = 1\n", s.x.size(), o.theta,
              o.multipole == "mono" ? "monopole" : "quadrupole", o.opening.c_str(), o.eps);
  std::printf("relative force error |a_tree - a_direct|/|a_direct| over %zu particles: median %.3e, 90%% %.3e, "
              "99%% %.3e, max %.3e\n", rel.size(), p.p50, p.p90, p.p99, p.max);
  std::printf("potential energy: tree %.10e, direct %.10e, relative error %.3e\n", wt, wd,
              wd != 0.0 ? std::abs(wt - wd) / std::abs(wd) : 0.0);
  std::printf("cost: tree %.3f s (%.0f interactions per particle), direct %.3f s; written %s\n", t_tree,
              inter / s.x.size(), t_direct, o.out.c_str());
}

}  // namespace

void add_gravity_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* g = app.add_subcommand("gravity", "tree and direct-sum gravity of your particles (CSV x,y,z,m; G = 1)");
  g->add_option("--input", o->input, "particles: CSV with header row x,y,z,m")->required();
  g->add_option("--out", o->out, "output CSV (x,y,z,m, tree and direct accelerations and potentials)")->required();
  g->add_option("--theta", o->theta, "opening angle theta > 0 (default 0.5)");
  g->add_option("--multipole", o->multipole, "mono|quad (default quad)")->check(CLI::IsMember({"mono", "quad"}));
  g->add_option("--opening", o->opening, "robust|plain (default robust)")->check(CLI::IsMember({"robust", "plain"}));
  g->add_option("--softening", o->eps, "Plummer softening length eps >= 0 (default 0)");
  g->callback([o, &app] {
    if (const auto* t = app.get_option_no_throw("--threads"); t && t->count() > 0) omp_set_num_threads(t->as<int>());
    // Runs inside app.parse(): errors leave as a CLI error, which main prints as one line.
    try {
      run(*o);
    } catch (const std::exception& e) {
      throw CLI::RuntimeError(e.what(), 2);
    }
  });
}

}  // namespace sphv
