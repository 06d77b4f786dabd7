#pragma once
// Shared by the heat cases: the SPH conduction semi-discretisation du/dt = f(u) of a static
// particle set as a rate function, integrated explicitly (with a verdict when it goes bad) or by
// CVODE, and the runtime choice of form dispatched once to a scene type.
#include <chrono>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "reference/cvode.hpp"
#include "sph/conduction/conduction.hpp"
#include "sph/time/explicit_methods.hpp"
#include "verification/cases/heat/lattice.hpp"
#include "verification/harness/params.hpp"

namespace sphv::heat {

using Rate = std::function<void(const std::vector<double>& u, std::vector<double>& dudt)>;

// The scene of one conduction form: exactly one term, chosen at compile time.
template <int D>
using BrookshawScene = sph::Scene<D, sph::BrookshawConduction<D>>;
template <int D>
using Symmetric2Scene = sph::Scene<D, sph::TwoPassConduction<D, sph::SymmetricForm>>;
template <int D>
using Difference2Scene = sph::Scene<D, sph::TwoPassConduction<D, sph::DifferenceForm>>;

const std::vector<std::string> forms = {"brookshaw", "flux_56_58", "flux_57_59"};

// du/dt of the set for the named form (dispatched here, once, not per pair). The rate function
// owns its scene and a working copy of the particles.
template <int D>
Rate make_rate(const ParticleSet<D>& s, const std::string& form, const sph::ConductionParams& k) {
  k.check();
  auto bind = [&](auto scene) -> Rate {
    auto p = std::make_shared<sph::Particles<D>>(s.p);
    auto d = std::make_shared<sph::Derivatives<D>>();
    auto sc = std::make_shared<decltype(scene)>(scene);
    const ParticleSet<D>* set = &s;
    return [p, d, sc, set](const std::vector<double>& u, std::vector<double>& dudt) {
      p->u = u;
      sc->derivatives(*p, set->nb(), *d);
      dudt = d->dudt;
    };
  };
  if (form == "brookshaw") return bind(BrookshawScene<D>{{sph::BrookshawConduction<D>{k}}});
  if (form == "flux_56_58") return bind(Symmetric2Scene<D>{{sph::TwoPassConduction<D, sph::SymmetricForm>{k, {}}}});
  if (form == "flux_57_59") return bind(Difference2Scene<D>{{sph::TwoPassConduction<D, sph::DifferenceForm>{k, {}}}});
  throw InputError("unknown conduction form '" + form + "' (brookshaw, flux_56_58, flux_57_59)");
}
// Compiled once (heat/rate.cpp) for the three cases that integrate it (heat, heat_stability,
// stability_map_heat): three scenes a dimension.
extern template Rate make_rate<1>(const ParticleSet<1>&, const std::string&, const sph::ConductionParams&);
extern template Rate make_rate<2>(const ParticleSet<2>&, const std::string&, const sph::ConductionParams&);
extern template Rate make_rate<3>(const ParticleSet<3>&, const std::string&, const sph::ConductionParams&);

// Largest lattice eigenvalue of the form's operator times the diffusivity chi = K / (rho0 S0 c_v)
// (the lattice's summation density is rho0 S0): the independent explicit stability bound is 2 / it.
template <int D>
double lattice_lambda_max(int n, double hfact, const std::string& form, double chi_rho) {
  const double lam = form == "brookshaw" ? lambda_max<D>(n, hfact, brookshaw_symbol<D>)
                                         : lambda_max<D>(n, hfact, two_pass_symbol<D>);
  return chi_rho / lattice_kernel_sum<D>(hfact) * lam;
}

// The initial state of the stability runs: u = 1 plus uniform noise in [-0.1, 0.1] (fixed seed),
// so that every mode of the operator, the unstable one too, is present.
inline std::vector<double> noisy_field(std::size_t size) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  std::vector<double> u(size);
  for (auto& v : u) v = 1.0 + noise(rng);
  return u;
}

struct Explicit {
  std::vector<double> u;
  long steps = 0;
  std::string verdict = "ok";
  double wall_s = 0.0;
};

// Integrates u' = f(u) to t_end with forward Euler ("euler") or Heun ("heun") at step <= dt.
// Stops with a verdict at the first step where some u is not finite or the L2 norm of u - mean
// has grown beyond `growth_limit` times its initial value (a stable step of a symmetric
// negative semi-definite operator never raises it), naming the particle of largest |u - mean|.
inline Explicit integrate_explicit(const Rate& f, std::vector<double> u, double t_end, double dt,
                                   const std::string& method, double growth_limit = 1.0 + 1e-9) {
  const auto t0 = std::chrono::steady_clock::now();
  Explicit r;
  double mean = 0.0;
  for (double v : u) mean += v / u.size();
  auto norm = [&](std::size_t& worst) {
    double s = 0.0, w = -1.0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      const double d = std::abs(u[i] - mean);
      s += d * d;
      if (!(d <= w)) w = d, worst = i;  // also picks a NaN
    }
    return std::sqrt(s);
  };
  std::size_t worst = 0;
  const double norm0 = norm(worst);
  const long steps = static_cast<long>(std::ceil(t_end / dt - 1e-9));
  const double h = t_end / steps;
  std::vector<double> k1, k2, ys;
  for (long s = 0; s < steps; ++s) {
    if (method == "euler") sph::forward_euler_step(u, h, f, k1);
    else sph::heun_step(u, h, f, k1, k2, ys);
    const double nrm = norm(worst);
    if (!(nrm <= growth_limit * norm0)) {
      r.verdict = "unstable: step " + std::to_string(s + 1) + ", particle " + std::to_string(worst) +
                  (std::isfinite(u[worst]) ? ": |T - mean| grew" : ": T not finite");
      r.steps = s + 1;
      break;
    }
  }
  if (r.verdict == "ok") r.steps = steps;
  r.u = std::move(u);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

struct Implicit {
  std::vector<double> u;
  reference::CvodeStats stats;
  std::string verdict = "ok";
  double wall_s = 0.0;
};

inline Implicit integrate_cvode(const Rate& f, const std::vector<double>& u0, double t_end,
                                const reference::CvodeOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  auto res = reference::cvode_integrate([&](double, const std::vector<double>& y, std::vector<double>& yd) { f(y, yd); },
                                        u0, 0.0, {t_end}, o);
  Implicit r;
  r.stats = res.stats;
  if (!res.ok) r.verdict = "cvode: " + res.message;
  else r.u = res.y.back();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

inline reference::LinearSolver solver_of(const Params& p) {
  try {
    return reference::linear_solver_from_name(p.text("solver"));
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

}  // namespace sphv::heat
