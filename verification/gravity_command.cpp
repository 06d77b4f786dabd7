#include "verification/gravity_command.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "verification/cases/gravity_compare.hpp"
#include "verification/cases/gravity_models.hpp"
#include "verification/gravity_input.hpp"
#include "verification/params.hpp"
#include "verification/result.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {
namespace {

struct Options {
  std::string input, out, multipole = "quad", opening = "robust";
  double theta = 0.5, eps = 0.0;
  bool no_direct = false;
};

void run(const Options& o) {
  if (!(o.theta > 0.0)) throw InputError("--theta must be > 0, got " + std::to_string(o.theta));
  if (!(o.eps >= 0.0)) throw InputError("--softening must be >= 0, got " + std::to_string(o.eps));
  const Snapshot snap = read_snapshot(o.input);
  const auto s = gravity_particles(snap, o.eps);
  std::printf("%s: %zu particles: %s\n", o.input.c_str(), snap.size(), snap.describe().c_str());
  using Clock = std::chrono::steady_clock;
  const sph::GravityOptions go{.theta = o.theta, .eps = o.eps, .G = 1.0,
                               .multipole = o.multipole == "mono" ? sph::Multipole::monopole : sph::Multipole::quadrupole,
                               .opening = o.opening == "plain" ? sph::Opening::plain : sph::Opening::robust};
  auto t0 = Clock::now();
  const auto tree = sph::build_tree<3>(s.x, s.m);
  const auto f = sph::tree_gravity(tree, s.x, s.m, go);
  const double t_tree = std::chrono::duration<double>(Clock::now() - t0).count();
  double inter = 0.0;
  for (long c : f.interactions) inter += c;
  std::printf("gravity: N = %zu, theta = %g, %s, %s opening, eps = %g, G = 1\n", s.x.size(), o.theta,
              o.multipole == "mono" ? "monopole" : "quadrupole", o.opening.c_str(), o.eps);
  Table out;
  const char* axes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) out.add(axes[k], [&] { std::vector<double> c; for (const auto& x : s.x) c.push_back(x[k]); return c; }());
  out.add("m", s.m);
  for (int k = 0; k < 3; ++k) out.add(std::string("a") + axes[k] + "_tree", [&] { std::vector<double> c; for (const auto& a : f.a) c.push_back(a[k]); return c; }());
  out.add("phi_tree", f.phi);
  if (o.no_direct) {
    write_atomically(o.out, csv(out));
    std::printf("cost: tree %.3f s (%.0f interactions per particle); direct sum skipped (--no-direct); written %s\n",
                t_tree, inter / s.x.size(), o.out.c_str());
    return;
  }
  t0 = Clock::now();
  const auto d = gravity::direct(s.x, s.m, o.eps);
  const double t_direct = std::chrono::duration<double>(Clock::now() - t0).count();
  out.add("ax_direct", d.ax);
  out.add("ay_direct", d.ay);
  out.add("az_direct", d.az);
  out.add("phi_direct", d.phi);
  for (std::size_t c = 0; c < out.columns.size(); ++c)
    for (double v : out.columns[c])
      if (!std::isfinite(v)) throw std::runtime_error("non-finite " + out.names[c] + " (not written)");
  write_atomically(o.out, csv(out));

  // Particles with zero direct force (e.g. a single particle) have no relative error.
  const auto rel = finite_values(gravity::relative_force_error(f, d));
  const auto p = gravity::percentiles(rel);
  const double wd = gravity::potential_energy(s.m, d.phi), wt = gravity::potential_energy(s.m, f.phi);
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
  auto* g = app.add_subcommand("gravity", "tree and direct-sum gravity of your particles (x,y,z,m; G = 1)");
  g->add_option("--input", o->input,
                "particles: CSV (header row; comma or blank separated; x,y,z,m or mass, pos_x, ...), or a SWIFT/GADGET "
                "or H5Part HDF5 snapshot")->required();
  g->add_option("--out", o->out, "output CSV (x,y,z,m, tree and direct accelerations and potentials)")->required();
  g->add_option("--theta", o->theta, "opening angle theta > 0 (default 0.5)");
  g->add_option("--multipole", o->multipole, "mono|quad (default quad)")->check(CLI::IsMember({"mono", "quad"}));
  g->add_option("--opening", o->opening, "robust|plain (default robust)")->check(CLI::IsMember({"robust", "plain"}));
  g->add_option("--softening", o->eps, "Plummer softening length eps >= 0 (default 0: coincident particles are refused)");
  g->add_flag("--no-direct", o->no_direct, "skip the O(N^2) direct sum (large N): tree field only, no error percentiles");
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
