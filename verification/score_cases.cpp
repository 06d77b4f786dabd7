// The scorers of `sphv score`: each reads the columns its case needs from a snapshot and calls
// the same error function as the case's own run (sod_errors.hpp, sedov_errors.hpp,
// noh_errors.hpp, evrard_errors.hpp, heat_errors.hpp, sound_wave_errors.hpp, square_errors.hpp,
// gravity_compare.hpp).
#include <cmath>
#include <stdexcept>

#include "reference/riemann.hpp"
#include "reference/sedov.hpp"
#include "verification/cases/centre_param.hpp"
#include "verification/cases/evrard_errors.hpp"
#include "verification/cases/gravity_compare.hpp"
#include "verification/cases/heat_errors.hpp"
#include "verification/cases/noh_errors.hpp"
#include "verification/cases/sedov_errors.hpp"
#include "verification/cases/sod_errors.hpp"
#include "verification/cases/sound_wave_errors.hpp"
#include "verification/cases/square_errors.hpp"
#include "verification/cases/square_setup.hpp"
#include "verification/gravity_input.hpp"
#include "verification/score.hpp"

namespace sphv {
namespace {

// Positions (minus centre) or velocities of the first D axes as vectors.
template <int D>
std::vector<sph::Vec<D>> vectors(const Snapshot& s, const std::string& prefix, const std::string& who,
                                 const sph::Vec<D>& centre = sph::Vec<D>::Zero()) {
  std::vector<sph::Vec<D>> v(s.size());
  for (int d = 0; d < D; ++d) {
    const auto& c = s.at(prefix + std::string(1, "xyz"[d]), who);
    for (std::size_t i = 0; i < v.size(); ++i) v[i][d] = c[i] - centre[d];
  }
  return v;
}

// u, or (gamma - 1)^-1 p / rho from the pressure when the snapshot has no u (SPH-EXA).
std::vector<double> internal_energy(const Snapshot& s, double gamma, const std::string& who) {
  if (s.has("u") || !s.has("p")) return s.at("u", who + " (or p)");
  const auto &p = s.at("p", who), &rho = s.at("rho", who);
  std::vector<double> u(s.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = p[i] / ((gamma - 1.0) * rho[i]);
  return u;
}
std::vector<double> pressure(const Snapshot& s, double gamma, const std::string& who) {
  if (s.has("p") || !s.has("u")) return s.at("p", who + " (or u)");
  const auto &u = s.at("u", who), &rho = s.at("rho", who);
  std::vector<double> p(s.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = (gamma - 1.0) * rho[i] * u[i];
  return p;
}

void positive(const Snapshot& s, const std::string& name, const std::string& who) {
  const auto& c = s.at(name, who);
  for (std::size_t i = 0; i < c.size(); ++i)
    if (!(c[i] > 0.0))
      throw InputError(s.path.string() + ": " + s.taken_from.at(name) + " of particle " + std::to_string(i) + " is " +
                       std::to_string(c[i]) + " (must be > 0)");
}

// The tube's domain as text: "[0, 2], periodic".
std::string domain_text(const TubeProblem& pr) {
  return "[" + shortest(pr.x_lo) + ", " + shortest(pr.x_hi) + "], " + pr.ends;
}

// A periodic or closed tube scores every particle (one outside it fails the verdict) up to the
// time its exact solution holds; an open one is a window of an unbounded tube.
Result score_tube(const Params& prm, const Snapshot& s) {
  const TubeProblem pr = tube_problem(prm);
  const std::string who = "the shock tube";
  positive(s, "rho", who);
  positive(s, "m", who);
  const TubeExact exact(pr);
  const std::string f = s.path.string(), domain = domain_text(pr);
  if (pr.t_end > exact.valid_until())
    throw InputError(f + ": at t = " + shortest(pr.t_end) + " the exact solution no longer holds on the tube " + domain +
                     ": " + (pr.ends == "periodic" ? "the waves from x0 and from the periodic wrap meet" : "the first wave from x0 reaches an end") +
                     " at t = " + shortest(exact.valid_until()));
  Result r;
  std::size_t outside = 0;
  r.errors = tube_l1_errors(s.at("x", who), s.at("vx", who), s.at("rho", who), pressure(s, pr.gamma, who),
                            internal_energy(s, pr.gamma, who), s.at("m", who), s.size(), exact, pr.t_end, &outside);
  if (outside == s.size())
    throw InputError(f + ": no particle lies in the tube's domain " + domain + " (--set domain=x_lo,x_hi)");
  r.extra["particles_scored"] = s.size() - outside;
  r.extra["window"] = "the domain " + domain + (outside > 0 && pr.ends == "open" ? ": the rest lie outside it, not scored" : "");
  r.extra["x0"] = pr.x0;
  r.extra["gamma"] = pr.gamma;
  if (std::isfinite(exact.valid_until())) r.extra["exact_until"] = exact.valid_until();
  if (outside > 0 && pr.ends != "open")
    r.verdict = std::to_string(outside) + " of " + std::to_string(s.size()) + " particles outside the domain " + domain;
  return r;
}

Result score_sedov(const Params& prm, const Snapshot& s) {
  const std::string who = "sedov";
  positive(s, "rho", who);
  positive(s, "m", who);
  const reference::Sedov exact(static_cast<int>(prm.integer("dim")), prm.real("gamma"));
  if (!(prm.real("t") > 0.0)) throw InputError(s.path.string() + ": sedov needs a time t > 0");
  Result r;
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    if constexpr (D == 1) throw InputError("sedov: dim must be 2 or 3");
    else {
      const auto c = radial::centre<D>(prm);
      const auto v = s.has("vx") ? vectors<D>(s, "v", who) : std::vector<sph::Vec<D>>{};
      sedov::measure<D>(r, vectors<D>(s, "", who, c), v, s.at("m", who), s.at("rho", who),
                        s.has("h") ? s.at("h", who) : std::vector<double>{}, prm.real("h_support"),
                        static_cast<int>(prm.integer("n")), prm.real("E"), prm.real("rho0"), prm.real("t"), exact);
    }
    return r;
  });
  if (r.extra["ball_particles"].get<double>() == 0.0)
    r.verdict = "no particle within 1.2 R of the centre: L1_rho is not a measurement (is the centre right?)";
  else if (!r.extra["front_found"].get<bool>())
    r.verdict = "no shock front: the binned density never falls through (rho0 + peak) / 2 beyond its peak";
  return r;
}

Result score_noh(const Params& prm, const Snapshot& s) {
  const std::string who = "noh";
  positive(s, "rho", who);
  positive(s, "m", who);
  Result r;
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    const auto c = radial::centre<D>(prm);
    noh::measure<D>(r, vectors<D>(s, "", who, c), vectors<D>(s, "v", who), s.at("m", who), s.at("rho", who),
                    internal_energy(s, prm.real("gamma"), who), prm.real("t_end"), prm.real("gamma"), prm.integer("n"));
    return r;
  });
  if (!r.extra["shock_front_found"].get<bool>())
    r.verdict = "no shock front: the binned density never rises through the post-/pre-shock midpoint (rho_post and "
                "shock_speed not computed; is the centre right?)";
  return r;
}

// The wave along x with one wavelength across the box: the file's box along x where it states
// one ([lo, hi): wavelength hi - lo, phase from lo), else the unit box [0, 1) of sphv's layout.
Result score_sound_wave(const Params& prm, const Snapshot& s) {
  const std::string who = "sound_wave";
  positive(s, "rho", who);
  positive(s, "m", who);
  double lo = 0.0, L = 1.0;
  std::string from = "the unit box [0, 1): the file states no box";
  if (const auto box = s.stated.find("box"); box != s.stated.end() && box->second.value.size() >= 2) {
    lo = box->second.value[0], L = box->second.value[1] - box->second.value[0];
    from = "the file's box along x (" + box->second.from + ")";
  }
  if (!(L > 0.0)) throw InputError(s.path.string() + ": sound_wave needs a box of positive length along x");
  const reference::AcousticWave w(prm.real("rho0"), prm.real("c_s"), prm.real("gamma"), prm.real("A"), L);
  Result r;
  by_dimension(prm, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    auto x = vectors<D>(s, "", who);
    for (auto& xi : x) xi[0] -= lo;
    sound_wave::measure<D>(r, x, vectors<D>(s, "v", who), s.at("m", who), s.at("rho", who), prm.real("t_end"), w,
                           prm.real("A"), prm.integer("n"));
    return r;
  });
  r.extra["wavelength"] = L;
  r.extra["wavelength_from"] = from;
  return r;
}

// The square in the periodic unit box [0, 1)^d of sphv's and SWIFT's layout: a file that states
// another box is refused (the reference's square of side 1/2 and its speeds are in units of the
// box's side). The phases are read from u (square_errors.hpp), or from p / rho where u is absent.
Result score_square(const Params& prm, const Snapshot& s) {
  const std::string who = "square";
  positive(s, "rho", who);
  positive(s, "m", who);
  if (const auto box = s.stated.find("box"); box != s.stated.end())
    for (double side : box->second.value)
      if (side != 0.0 && std::abs(side - 1.0) > 1e-12)
        throw InputError(s.path.string() + ": square scores the periodic unit box [0, 1)^d, the file's box (" +
                         box->second.from + ") has a side " + std::to_string(side) + " (rescale the snapshot)");
  if (s.dim != prm.integer("dim"))
    throw InputError(s.path.string() + ": the file has " + std::to_string(s.dim) + " coordinate(s), dim = " +
                     prm.text("dim") + " (set dim=" + std::to_string(s.dim) + ")");
  const reference::IsobaricSquare sq = square::problem(prm);
  Result r;
  const auto u = internal_energy(s, prm.real("gamma"), who);
  auto one = [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    auto x = vectors<D>(s, "", who);
    for (auto& xi : x)
      for (int d = 0; d < D; ++d) xi[d] -= std::floor(xi[d]);  // into [0, 1)
    square::measure<D>(r, x, vectors<D>(s, "v", who), s.at("m", who), s.at("rho", who), u, prm.real("t_end"), sq,
                       prm.real("gamma"), prm.integer("n"));
  };
  if (s.dim == 2) one(std::integral_constant<int, 2>{});
  else one(std::integral_constant<int, 3>{});
  return r;
}

Result score_evrard(const Params& prm, const Snapshot& s) {
  const std::string who = "evrard";
  positive(s, "rho", who);
  positive(s, "m", who);
  if (s.dim != 3) throw InputError(s.path.string() + ": evrard needs 3D particles (x, y, z), the file has " +
                                   std::to_string(s.dim) + " coordinate(s)");
  double mass = 0.0;
  for (double m : s.at("m", who)) mass += m;
  // The reference is in units G = M = R = 1: a units check, not an accuracy bound.
  if (!(std::abs(mass - 1.0) <= 1e-3))
    throw InputError(s.path.string() + ": the particles' total mass is " + std::to_string(mass) +
                     "; evrard scores the sphere in units G = M = R = 1 (rescale the snapshot)");
  const double gamma = prm.real("gamma");
  const int zones = static_cast<int>(prm.integer("zones"));
  const double t = prm.real("t_end"), u0 = prm.real("u0");
  auto reference = [&](int z) -> const reference::EvrardSolution& {
    try {
      return evrard::reference_solution(z, gamma, u0, t);
    } catch (const std::invalid_argument& e) {  // the 1D solver's step budget or a zone gone bad
      throw InputError(s.path.string() + ": no 1D reference at its time " + std::to_string(t) + ": " + e.what());
    }
  };
  const auto& ref = reference(zones);
  const auto& half = reference(zones / 2);
  Result r;
  evrard::measure_profiles(r, vectors<3>(s, "", who, radial::centre<3>(prm)), vectors<3>(s, "v", who), s.at("m", who),
                           s.at("rho", who), internal_energy(s, gamma, who), ref.at_end, half.at_end, t);
  return r;
}

Result score_heat(const Params& prm, const Snapshot& s) {
  const std::string who = "heat";
  positive(s, "rho", who);
  const int D = static_cast<int>(prm.integer("dim"));
  std::vector<std::vector<double>> coords(s.size(), std::vector<double>(D));
  for (int a = 0; a < D; ++a) {
    const auto& c = s.at(std::string(1, "xyz"[a]), who);
    for (std::size_t i = 0; i < c.size(); ++i) coords[i][a] = c[i];
  }
  const double cv = prm.real("c_v");
  const double chi = heat::diffusivity(s.at("rho", who), prm.real("K"), cv);
  const auto& [error, exact] = heat::setups.at(prm.text("setup"));
  Result r;
  r.errors[error] = heat::rms_error(s.at("u", who), exact(coords, prm.real("t_end"), chi, cv));
  r.extra["chi"] = chi;
  r.extra["setup"] = prm.text("setup");
  return r;
}

Result score_gravity(const Params& prm, const Snapshot& s) {
  const std::string who = "gravity (the code's accelerations ax, ay, az)";
  const gravity::ParticleSet set = gravity_particles(s, prm.real("eps"));
  sph::GravityField code;
  code.a = vectors<3>(s, "a", who);
  if (s.has("phi")) code.phi = s.at("phi", who);
  const auto d = gravity::direct(set.x, set.m, prm.real("eps"));
  const auto p = gravity::percentiles(finite_values(gravity::relative_force_error(code, d)));
  Result r;
  r.errors = {{"force_p50", p.p50}, {"force_p90", p.p90}, {"force_p99", p.p99}, {"force_max", p.max}};
  if (s.has("phi")) {
    const double wd = gravity::potential_energy(set.m, d.phi), wc = gravity::potential_energy(set.m, code.phi);
    r.errors["energy"] = std::abs(wc - wd) / std::abs(wd);
  }
  return r;
}

double tube_t_end(const Params& p) { return tube_problem(p).t_end; }
double real_t_end(const Params& p) { return p.real("t_end"); }
double tube_gamma(const Params& p) { return tube_problem(p).gamma; }
double real_gamma(const Params& p) { return p.real("gamma"); }

}  // namespace

const std::map<std::string, Scorer>& scorers() {
  static const std::map<std::string, Scorer> s = {
      {"sod", {"t_end", score_tube, tube_t_end, Resolution::none, tube_gamma}},
      {"sod2d", {"t_end", score_tube, tube_t_end, Resolution::none, tube_gamma}},
      {"sod3d", {"t_end", score_tube, tube_t_end, Resolution::none, tube_gamma}},
      {"sedov", {"t", score_sedov, sedov::end_time, Resolution::per_length, real_gamma}},
      {"noh", {"t_end", score_noh, real_t_end, Resolution::per_length, real_gamma}},
      {"evrard", {"t_end", score_evrard, real_t_end, Resolution::count, real_gamma}},
      {"sound_wave", {"t_end", score_sound_wave, real_t_end, Resolution::per_length, real_gamma}},
      {"square", {"t_end", score_square, real_t_end, Resolution::none, real_gamma}},
      {"heat", {"t_end", score_heat, real_t_end}},
      {"gravity", {"", score_gravity, {}}}};
  return s;
}

}  // namespace sphv
