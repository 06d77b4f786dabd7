#include "verification/commands/gravity_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "verification/cases/gravity/compare.hpp"
#include "verification/cases/gravity/models.hpp"
#include "verification/io/gravity_input.hpp"
#include "verification/harness/params.hpp"
#include "verification/harness/result.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

void gravity_command(const GravityCommandOptions& o) {
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
  auto write = [&] {
    if (const auto bad = non_finite_entries(out); !bad.empty())  // the input's numbers overflow the field
      throw InputError("non-finite " + bad.front() + " (not written)");
    write_atomically(o.out, csv(out));
  };
  const char* axes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) out.add(axes[k], [&] { std::vector<double> c; for (const auto& x : s.x) c.push_back(x[k]); return c; }());
  out.add("m", s.m);
  for (int k = 0; k < 3; ++k) out.add(std::string("a") + axes[k] + "_tree", [&] { std::vector<double> c; for (const auto& a : f.a) c.push_back(a[k]); return c; }());
  out.add("phi_tree", f.phi);
  if (o.no_direct) {
    write();
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
  write();

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

}  // namespace sphv
