#include "reference/evrard_lagrangian.hpp"

#include "reference/interpolate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace reference {
namespace {

constexpr double pi = 3.14159265358979323846;

struct State {
  std::vector<double> r, v, e;  // nodes 0..N (r, v), zones 0..N-1 (e)
};

struct Mesh {
  int n;
  double gamma, c1, c2;
  std::vector<double> dm, mnode, menc;  // zone masses, node masses, M_i of the node shells

  double volume(const State& s, int k) const {
    return 4.0 * pi / 3.0 * (s.r[k + 1] * s.r[k + 1] * s.r[k + 1] - s.r[k] * s.r[k] * s.r[k]);
  }
  // Zone density, sound speed, pressure + viscosity P_k, velocity jump dv_k.
  void zone(const State& s, int k, double& rho, double& c, double& P, double& dv) const {
    rho = dm[k] / volume(s, k);
    c = std::sqrt(gamma * (gamma - 1.0) * std::max(s.e[k], 0.0));
    dv = s.v[k + 1] - s.v[k];
    const double q = dv < 0.0 ? rho * (c2 * dv * dv - c1 * c * dv) : 0.0;
    P = (gamma - 1.0) * rho * s.e[k] + q;
  }

  // d = d/dt of (r, v, e): the semi-discrete system of the header. d and P are the caller's, sized
  // by sized(): a step evaluates this four times, and fresh arrays for each would take a large
  // share of the solver's time. With step_of_zone, also each zone's time step
  // C dr_k / (c_k + 2 (c1 c_k + c2 |dv_k|)) (the step's is their least, time_step), from the same
  // evaluation of the zone.
  void rate(const State& s, State& d, std::vector<double>& P, double* step_of_zone = nullptr,
            double courant = 0.0) const {
    d.r[0] = d.v[0] = 0.0;  // the centre's node stays put
    P[n] = 0.0;             // P_N = 0: vacuum outside
    for (int k = 0; k < n; ++k) {
      double rho, c, dv;
      zone(s, k, rho, c, P[k], dv);
      const double dVdt = 4.0 * pi * (s.r[k + 1] * s.r[k + 1] * s.v[k + 1] - s.r[k] * s.r[k] * s.v[k]);
      d.e[k] = -P[k] * dVdt / dm[k];
      if (step_of_zone) {
        const double signal = c + 2.0 * (c1 * c + c2 * std::abs(std::min(dv, 0.0))) + 1e-300;
        step_of_zone[k] = courant * (s.r[k + 1] - s.r[k]) / signal;
      }
    }
    for (int i = 1; i <= n; ++i) {
      d.r[i] = s.v[i];
      const double r2 = s.r[i] * s.r[i];
      d.v[i] = 4.0 * pi * r2 * (P[i - 1] - P[i]) / mnode[i] - menc[i] / r2;
    }
  }
  State sized() const { return {std::vector<double>(n + 1), std::vector<double>(n + 1), std::vector<double>(n)}; }

  // The least of the zones' time steps, in four running minima side by side (the least does not
  // depend on the order; one chain would wait on each minimum before the next).
  static double time_step(const std::vector<double>& step_of_zone) {
    std::array<double, 4> least;
    least.fill(std::numeric_limits<double>::infinity());
    const std::size_t m = step_of_zone.size();
    for (std::size_t k = 0; k < m; ++k) least[k % 4] = std::min(least[k % 4], step_of_zone[k]);
    return std::min(std::min(least[0], least[1]), std::min(least[2], least[3]));
  }

  void record(const State& s, double t, EvrardSolution& out) const {
    double kin = 0.0, th = 0.0, w = 0.0;
    for (int i = 1; i <= n; ++i) kin += 0.5 * mnode[i] * s.v[i] * s.v[i], w -= mnode[i] * menc[i] / s.r[i];
    for (int k = 0; k < n; ++k) th += dm[k] * s.e[k];
    out.t.push_back(t);
    out.kinetic.push_back(kin);
    out.thermal.push_back(th);
    out.potential.push_back(w);
    if (w <= *std::min_element(out.potential.begin(), out.potential.end())) {
      out.t_max_compression = t;
      EvrardProfile p = profile(s);
      out.r_profile = std::move(p.r_zone);
      out.rho_profile = std::move(p.rho);
    }
  }

  EvrardProfile profile(const State& s) const {
    EvrardProfile p{s.r, s.v, std::vector<double>(n), std::vector<double>(n), s.e};
    for (int k = 0; k < n; ++k) p.r_zone[k] = 0.5 * (s.r[k] + s.r[k + 1]), p.rho[k] = dm[k] / volume(s, k);
    return p;
  }
};

// Returns the first zone with a non-positive volume or energy (or a non-finite value), or -1.
int first_bad(const State& s, int n) {
  for (int k = 0; k < n; ++k)
    if (!(s.r[k + 1] > s.r[k]) || !(s.e[k] > 0.0) || !std::isfinite(s.v[k + 1]) || !std::isfinite(s.e[k])) return k;
  return -1;
}

// y = s + a d, into y's arrays (sized as s's).
void axpy(const State& s, double a, const State& d, State& y) {
  for (std::size_t i = 0; i < s.r.size(); ++i) y.r[i] = s.r[i] + a * d.r[i], y.v[i] = s.v[i] + a * d.v[i];
  for (std::size_t k = 0; k < s.e.size(); ++k) y.e[k] = s.e[k] + a * d.e[k];
}

// RK4's update of s in place, s + a1 k1 + a2 k2 + a3 k3 + a4 k4, summed left to right.
void rk4_update(State& s, const std::array<double, 4>& a, const std::array<const State*, 4>& k) {
  auto update = [&](std::vector<double>& y, auto field) {
    for (std::size_t i = 0; i < y.size(); ++i)
      y[i] = (((y[i] + a[0] * (k[0]->*field)[i]) + a[1] * (k[1]->*field)[i]) + a[2] * (k[2]->*field)[i]) +
             a[3] * (k[3]->*field)[i];
  };
  update(s.r, &State::r);
  update(s.v, &State::v);
  update(s.e, &State::e);
}

}  // namespace

double EvrardSolution::at(const std::vector<double>& curve, double s) const {
  return t.empty() ? 0.0 : interpolate_linear(t, curve, s);
}

EvrardSolution evrard_lagrangian(const EvrardOptions& o) {
  if (o.zones < 2) throw std::invalid_argument("evrard reference: need at least 2 zones");
  if (!(o.gamma > 1.0)) throw std::invalid_argument("evrard reference: gamma must be > 1");
  if (!(o.u0 > 0.0)) throw std::invalid_argument("evrard reference: u0 must be > 0");
  if (!(o.t_end > 0.0) || !(o.dt_out > 0.0)) throw std::invalid_argument("evrard reference: t_end, dt_out must be > 0");
  const int n = o.zones;
  Mesh mesh{n, o.gamma, o.c1, o.c2, {}, {}, {}};
  State s{std::vector<double>(n + 1), std::vector<double>(n + 1, 0.0), std::vector<double>(n, o.u0)};
  for (int i = 0; i <= n; ++i) s.r[i] = static_cast<double>(i) / n;
  mesh.dm.resize(n);
  for (int k = 0; k < n; ++k) mesh.dm[k] = s.r[k + 1] * s.r[k + 1] - s.r[k] * s.r[k];  // M(r) = r^2
  mesh.mnode.assign(n + 1, 0.0);
  mesh.menc.assign(n + 1, 0.0);
  for (int i = 0; i <= n; ++i) mesh.mnode[i] = 0.5 * ((i > 0 ? mesh.dm[i - 1] : 0.0) + (i < n ? mesh.dm[i] : 0.0));
  double inside = 0.0;
  for (int i = 0; i <= n; ++i) mesh.menc[i] = inside + 0.5 * mesh.mnode[i], inside += mesh.mnode[i];

  EvrardSolution out;
  State k1 = mesh.sized(), k2 = mesh.sized(), k3 = mesh.sized(), k4 = mesh.sized(), y = mesh.sized();
  std::vector<double> P(n + 1), step_of_zone(n);
  const long n_out = std::lround(o.t_end / o.dt_out);
  double t = 0.0;
  mesh.record(s, t, out);
  for (long j = 1; j <= n_out || t < o.t_end; ++j) {
    const double t_next = std::min(o.t_end, j * o.dt_out);
    while (t < t_next) {
      if (out.steps >= o.max_steps) throw std::invalid_argument("evrard reference: step budget exhausted");
      mesh.rate(s, k1, P, step_of_zone.data(), o.courant);  // k1 does not depend on dt
      double dt = Mesh::time_step(step_of_zone);
      const bool last = t + dt >= t_next;
      if (last) dt = t_next - t;
      axpy(s, 0.5 * dt, k1, y);
      mesh.rate(y, k2, P);
      axpy(s, 0.5 * dt, k2, y);
      mesh.rate(y, k3, P);
      axpy(s, dt, k3, y);
      mesh.rate(y, k4, P);
      rk4_update(s, {dt / 6.0, dt / 3.0, dt / 3.0, dt / 6.0}, {&k1, &k2, &k3, &k4});
      t = last ? t_next : t + dt;
      ++out.steps;
      if (const int k = first_bad(s, n); k >= 0)
        throw std::invalid_argument("evrard reference: zone " + std::to_string(k) + " went bad at t = " +
                                    std::to_string(t));
    }
    mesh.record(s, t, out);
  }
  out.at_end = mesh.profile(s);
  return out;
}

}  // namespace reference
