#pragma once
// Shared by the gas cases (sedov, noh, evrard, sound_wave, extreme_degenerate; the tube helpers
// below serve extreme_tubes and stability_map_hydro): the method's parameters, the run by the
// scheme they name (sph/schemes/; the chapter's by default: summation density (27), ideal gas,
// Euler (23), energy (38) or another form, artificial viscosity (44)-(48), h by (50) after every
// step), and radial profiles.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "sph/core/lattice.hpp"
#include "sph/hydro/evolve.hpp"
#include "sph/kernel/kernels.hpp"
#include "sph/schemes/schemes.hpp"
#include "verification/cases/common/hydro_step_params.hpp"
#include "verification/cases/shock_tubes/tube.hpp"
#include "verification/harness/params.hpp"
#include "verification/harness/result.hpp"

namespace sphv::extreme {

// The scheme by name (sph/schemes/schemes.hpp) with its options (sph::SchemeOptions: hmode
// "iterate50" sets h by (50) solved with the density at every evaluation, "rate53" integrates
// (53), "fixed" keeps the initial h), and the run's controls.
struct Method : sph::SchemeOptions {
  std::string scheme = sph::default_scheme();
  sph::HydroControls controls;
};

inline std::vector<ParamSpec> method_params(double gamma, double hfact) {
  std::vector<ParamSpec> ps = {
      choice_param("scheme", sph::default_scheme(), "SPH scheme (sph/schemes/)", sph::scheme_names()),
      real_param("gamma", gamma, "adiabatic index", 1.0),
      real_param("hfact", hfact, "support radius / particle spacing, fixes the neighbour number (50)", 0.0),
      choice_param("energy", "38", "energy form paired with Euler (23)", {"37", "38", "40", "41", "42"}),
      choice_param("hmode", "iterate50", "smoothing length: (50) iterated with the density, (53), or fixed",
                   {"iterate50", "rate53", "fixed"}),
      real_param("alpha", 1.0, "artificial viscosity alpha (45)", -1e-300),
      real_param("beta", 2.0, "artificial viscosity beta (45)", -1e-300),
      real_param("alpha_u", 1.0, "artificial conduction's coefficient (scheme gradh_switches; Price 2008: 1; 0: none)",
                 -1e-300),
      choice_param("vsig_u", "pressure", "artificial conduction's signal velocity (scheme gradh_switches): "
                   "sqrt(|P_i - P_j| / rho_ij) (Price 2008) or |v_ij . r_ij| / |r_ij|", {"pressure", "velocity"})};
  for (auto& q : time_step_params()) ps.push_back(q);
  ps.push_back(integer_param("max_steps", 20000, "step budget (ends with a verdict)"));
  return ps;
}

inline Method method(const Params& p) {
  Method m;
  m.scheme = p.text("scheme");
  m.gamma = p.real("gamma");
  m.hfact = p.real("hfact");
  m.hmode = p.text("hmode");
  m.energy = p.text("energy");
  m.alpha = p.real("alpha");
  m.beta = p.real("beta");
  m.alpha_u = p.real("alpha_u");
  m.vsig_u = p.text("vsig_u");
  read_time_step(p, m.controls.step);
  m.controls.max_steps = p.integer("max_steps");
  return m;
}

// Evolves p to m.controls.t_end by the scheme m names with the cubic spline (6). Never throws on a
// blow-up: the outcome has the verdict. `extra` terms (e.g. sph::SelfGravity) are appended to the
// scheme's force loop by reference, so the caller can read what they keep (e.g. the potential) from
// its hooks.
template <int D, class... Extra>
sph::HydroOutcome evolve_gas(sph::Particles<D>& p, const sph::Box<D>& box, const Method& m,
                             sph::HydroHooks<D> hooks = {}, Extra&... extra) {
  sph::HydroOutcome out;
  sph::with_scheme<D, sph::CubicSpline<D>>(
      m.scheme, m, [&](auto& scheme) { out = sph::evolve(scheme, p, box, m.controls, hooks); }, extra...);
  return out;
}
// Without extra terms, compiled once for each dimension (common/gas_scenes_1d.cpp, ...) rather than in
// every case that evolves gas (noh, sedov, extreme_degenerate): 12 schemes' types a dimension.
extern template sph::HydroOutcome evolve_gas<1>(sph::Particles<1>&, const sph::Box<1>&, const Method&,
                                                sph::HydroHooks<1>);
extern template sph::HydroOutcome evolve_gas<2>(sph::Particles<2>&, const sph::Box<2>&, const Method&,
                                                sph::HydroHooks<2>);
extern template sph::HydroOutcome evolve_gas<3>(sph::Particles<3>&, const sph::Box<3>&, const Method&,
                                                sph::HydroHooks<3>);

// Evolves p as evolve_gas does with the default scheme's forms (energy (38); hmode iterate50 or
// fixed) and the hooks given, with the kernel K in the density (27), the (50) iteration and the pair loop.
// Throws std::invalid_argument for another method: one scheme type a kernel (each costs compile
// time; the two h modes are the same type).
template <int D, class K>
sph::HydroOutcome evolve_gas_with_kernel(sph::Particles<D>& p, const sph::Box<D>& box, const Method& m,
                                         sph::HydroHooks<D> hooks = {}) {
  if (m.scheme != sph::ChapterScheme::name || (m.hmode != "iterate50" && m.hmode != "fixed") || m.energy != "38")
    throw std::invalid_argument(std::string("kernel ") + K::name + " runs with scheme=" + sph::ChapterScheme::name +
                                ", hmode=iterate50 or fixed, energy=38 only");
  sph::Chapter<D, K> scheme(m, {});
  return sph::evolve(scheme, p, box, m.controls, hooks);
}

// Evolves p with the kernel named: the cubic spline by evolve_gas (any scheme m names), another by
// evolve_gas_with_kernel. The other kernels' scenes compile in units of their own
// (common/gas_scenes_kernels_1d.cpp, _2d.cpp, _3d.cpp) beside the cubic's 12 scheme types a dimension.
template <int D>
sph::HydroOutcome evolve_gas_kernel(const std::string& kernel, sph::Particles<D>& p, const sph::Box<D>& box,
                                    const Method& m, sph::HydroHooks<D> hooks = {}) {
  sph::HydroOutcome out;
  sph::with_kernel<D>(kernel, [&](auto k) {
    using K = decltype(k);
    if constexpr (std::is_same_v<K, sph::CubicSpline<D>>) out = evolve_gas(p, box, m, hooks);
    else out = evolve_gas_with_kernel<D, K>(p, box, m, hooks);
  });
  return out;
}
extern template sph::HydroOutcome evolve_gas_kernel<1>(const std::string&, sph::Particles<1>&,
                                                      const sph::Box<1>&, const Method&,
                                                      sph::HydroHooks<1>);
extern template sph::HydroOutcome evolve_gas_kernel<2>(const std::string&, sph::Particles<2>&,
                                                      const sph::Box<2>&, const Method&,
                                                      sph::HydroHooks<2>);
extern template sph::HydroOutcome evolve_gas_kernel<3>(const std::string&, sph::Particles<3>&,
                                                      const sph::Box<3>&, const Method&,
                                                      sph::HydroHooks<3>);

// Mean of value over particles in radial bins [k dr, (k+1) dr), k < bins, around the origin: an
// entry (centre, mean, particle count) for each bin that holds a particle, in order of radius. An
// empty bin has no entry, so that the three vectors stay aligned and no entry is a mean of nothing.
struct Profile {
  std::vector<double> r, mean;
  std::vector<long> count;
};
inline Profile radial_profile(const std::vector<double>& radius, const std::vector<double>& value, double r_max,
                              int bins) {
  Profile pr;
  const double dr = r_max / bins;
  if (!(dr > 0.0)) return pr;  // a scored snapshot can give r_max = 0 or NaN (no shock found)
  std::vector<double> sum(bins, 0.0);
  std::vector<long> count(bins, 0);
  for (std::size_t i = 0; i < radius.size(); ++i) {
    const double q = radius[i] / dr;  // bin index, compared before the cast (NaN and huge q stay out)
    if (q >= 0.0 && q < bins) {
      const int k = static_cast<int>(q);
      sum[k] += value[i], ++count[k];
    }
  }
  for (int k = 0; k < bins; ++k)
    if (count[k] > 0)
      pr.r.push_back((k + 0.5) * dr), pr.mean.push_back(sum[k] / count[k]), pr.count.push_back(count[k]);
  return pr;
}

template <int D>
std::vector<double> radii(const sph::Particles<D>& p) {
  std::vector<double> r(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) r[i] = p.x[i].norm();
  return r;
}

// The mean smoothing length, reported as extra h_mean: the resolution a run reached.
template <int D>
double mean_h(const sph::Particles<D>& p) {
  double h = 0.0;
  for (double hi : p.h) h += hi / p.size();
  return h;
}

// particles.csv columns. p is the written state's, (gamma - 1) rho u: the particles' own p is
// from the last force evaluation, before the last kick of u (up to 1 % apart at Noh's shock),
// and a snapshot whose p, rho and u disagree is refused by sphv score.
template <int D>
Table particle_table(const sph::Particles<D>& p, double gamma) {
  Table t;
  const char* axes[] = {"x", "y", "z"};
  const char* vel[] = {"vx", "vy", "vz"};
  for (int d = 0; d < D; ++d) {
    std::vector<double> c(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) c[i] = p.x[i][d];
    t.add(axes[d], c);
  }
  for (int d = 0; d < D; ++d) {
    std::vector<double> c(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) c[i] = p.v[i][d];
    t.add(vel[d], c);
  }
  t.add("m", p.m);
  t.add("rho", p.rho);
  std::vector<double> pressure(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) pressure[i] = (gamma - 1.0) * p.rho[i] * p.u[i];
  t.add("p", pressure);
  t.add("u", p.u);
  t.add("h", p.h);
  return t;
}

}  // namespace sphv::extreme

// ---- Shock tubes through the hydro helper's tube (shock_tubes/tube.hpp): variable h by (53). ----
namespace sphv::extreme {

// L1 norm of rho - rho_exact over [lo, hi], weighted by particle volume m / rho.
inline double tube_l1_rho(const TubeRun& run, const reference::RiemannSolution& exact, double t, double lo, double hi) {
  double vol = 0.0, e = 0.0;
  for (std::size_t i = 0; i < run.active; ++i) {
    if (run.x[i] < lo || run.x[i] > hi) continue;
    const double w = run.m[i] / run.rho[i];
    vol += w;
    e += w * std::abs(run.rho[i] - exact.sample(run.x[i], t).rho);
  }
  return vol > 0.0 ? e / vol : 0.0;
}

// A gas at rest with a pressure jump p_ratio : 1 at x0 = 0.5 (density 1, gamma 1.4), run until
// the fastest wave has travelled 0.35.
inline TubeProblem pressure_jump(double p_ratio) {
  TubeProblem pr{{1.0, 0.0, p_ratio}, {1.0, 0.0, 1.0}, 1.4, 0.5, 1.0};
  const reference::RiemannSolution exact(pr.left, pr.right, pr.gamma, pr.x0);
  pr.t_end = 0.35 / std::max(std::abs(exact.slowest()), std::abs(exact.fastest()));
  return pr;
}

}  // namespace sphv::extreme
