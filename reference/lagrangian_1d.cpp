#include "reference/lagrangian_1d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace reference {
namespace {

constexpr double pi = 3.14159265358979323846;

// The least of the zones' time steps, in four running minima side by side (the least does not
// depend on the order; one chain would wait on each minimum before the next).
double time_step(const std::vector<double>& step_of_zone) {
  std::array<double, 4> least;
  least.fill(std::numeric_limits<double>::infinity());
  const std::size_t m = step_of_zone.size();
  for (std::size_t k = 0; k < m; ++k) least[k % 4] = std::min(least[k % 4], step_of_zone[k]);
  return std::min(std::min(least[0], least[1]), std::min(least[2], least[3]));
}

// Returns the first zone with a non-positive volume or energy (or a non-finite value), or -1.
int first_bad(const LagrangianState& s, int n) {
  for (int k = 0; k < n; ++k)
    if (!(s.r[k + 1] > s.r[k]) || !(s.e[k] > 0.0) || !std::isfinite(s.v[k + 1]) || !std::isfinite(s.e[k])) return k;
  return -1;
}

// y = s + a d, into y's arrays (sized as s's).
void axpy(const LagrangianState& s, double a, const LagrangianState& d, LagrangianState& y) {
  for (std::size_t i = 0; i < s.r.size(); ++i) y.r[i] = s.r[i] + a * d.r[i], y.v[i] = s.v[i] + a * d.v[i];
  for (std::size_t k = 0; k < s.e.size(); ++k) y.e[k] = s.e[k] + a * d.e[k];
}

// RK4's update of s in place, s + a1 k1 + a2 k2 + a3 k3 + a4 k4, summed left to right.
void rk4_update(LagrangianState& s, const std::array<double, 4>& a, const std::array<const LagrangianState*, 4>& k) {
  auto update = [&](std::vector<double>& y, auto field) {
    for (std::size_t i = 0; i < y.size(); ++i)
      y[i] = (((y[i] + a[0] * (k[0]->*field)[i]) + a[1] * (k[1]->*field)[i]) + a[2] * (k[2]->*field)[i]) +
             a[3] * (k[3]->*field)[i];
  };
  update(s.r, &LagrangianState::r);
  update(s.v, &LagrangianState::v);
  update(s.e, &LagrangianState::e);
}

// V(r_b) - V(r_a), its rate for node velocities v_a, v_b, and the area dV/dr at r, in dimension
// D = 2 or 3 (the header's c_d).
template <int D>
double shell_volume(double ra, double rb) {
  if constexpr (D == 3) return 4.0 * pi / 3.0 * (rb * rb * rb - ra * ra * ra);
  return pi * (rb * rb - ra * ra);
}
template <int D>
double shell_volume_rate(double ra, double va, double rb, double vb) {
  if constexpr (D == 3) return 4.0 * pi * (rb * rb * vb - ra * ra * va);
  return 2.0 * pi * (rb * vb - ra * va);
}
template <int D>
double area(double r) {
  if constexpr (D == 3) return 4.0 * pi * (r * r);
  return 2.0 * pi * r;
}

// What the rates read besides the state.
struct Mesh {
  int n;
  double gamma, c1, c2, courant;
  const double *dm, *mnode, *menc;
};

// d = d/dt of (r, v, e): the semi-discrete system of the header, with P_k (pressure + viscosity)
// into P; with_step: also each zone's time step C dr_k / (c_k + 2 (c1 c_k + c2 |dv_k|)) (the
// step's is their least) from the same evaluation of the zone. Compiled for each dimension,
// gravity and outer boundary, so that the zone and node loops test none of them.
template <int D, bool gravity, bool wall, bool with_step>
void rates(const Mesh& m, const LagrangianState& s, LagrangianState& d, double* P, double* step_of_zone) {
  const int n = m.n;
  const double *r = s.r.data(), *v = s.v.data(), *e = s.e.data();
  double *dr = d.r.data(), *dv_dt = d.v.data(), *de = d.e.data();
  dr[0] = dv_dt[0] = 0.0;  // the centre's node stays put
  P[n] = 0.0;              // vacuum outside (a wall holds the last node instead, below)
  for (int k = 0; k < n; ++k) {
    const double rho = m.dm[k] / shell_volume<D>(r[k], r[k + 1]);
    const double c = std::sqrt(m.gamma * (m.gamma - 1.0) * std::max(e[k], 0.0));
    const double dv = v[k + 1] - v[k];
    const double q = dv < 0.0 ? rho * (m.c2 * dv * dv - m.c1 * c * dv) : 0.0;
    P[k] = (m.gamma - 1.0) * rho * e[k] + q;
    de[k] = -P[k] * shell_volume_rate<D>(r[k], v[k], r[k + 1], v[k + 1]) / m.dm[k];
    if constexpr (with_step) {
      const double signal = c + 2.0 * (m.c1 * c + m.c2 * std::abs(std::min(dv, 0.0))) + 1e-300;
      step_of_zone[k] = m.courant * (r[k + 1] - r[k]) / signal;
    }
  }
  for (int i = 1; i <= n; ++i) {
    dr[i] = v[i];
    double a = area<D>(r[i]) * (P[i - 1] - P[i]) / m.mnode[i];
    if constexpr (gravity) a -= m.menc[i] / (r[i] * r[i]);
    dv_dt[i] = a;
  }
  if constexpr (wall) dr[n] = dv_dt[n] = 0.0;
}

template <int D, bool gravity, bool wall>
void rates(const Mesh& m, const LagrangianState& s, LagrangianState& d, double* P, double* step_of_zone) {
  if (step_of_zone) rates<D, gravity, wall, true>(m, s, d, P, step_of_zone);
  else rates<D, gravity, wall, false>(m, s, d, P, nullptr);
}

}  // namespace

Lagrangian1D::Lagrangian1D(const LagrangianOptions& o, std::vector<double> dm)
    : o_(o), n_(static_cast<int>(dm.size())), dm_(std::move(dm)) {
  if (o.dim != 2 && o.dim != 3) throw std::invalid_argument(o.name + ": dim must be 2 or 3");
  if (!(o.gamma > 1.0)) throw std::invalid_argument(o.name + ": gamma must be > 1");
  if (o.self_gravity && o.dim != 3) throw std::invalid_argument(o.name + ": self-gravity in spherical symmetry only");
  if (n_ < 2) throw std::invalid_argument(o.name + ": need at least 2 zones");
  mnode_.assign(n_ + 1, 0.0);
  menc_.assign(n_ + 1, 0.0);
  for (int i = 0; i <= n_; ++i) mnode_[i] = 0.5 * ((i > 0 ? dm_[i - 1] : 0.0) + (i < n_ ? dm_[i] : 0.0));
  double inside = 0.0;
  for (int i = 0; i <= n_; ++i) menc_[i] = inside + 0.5 * mnode_[i], inside += mnode_[i];
  k1_ = sized(), k2_ = sized(), k3_ = sized(), k4_ = sized(), y_ = sized();
  P_.assign(n_ + 1, 0.0);
  step_of_zone_.assign(n_, 0.0);
}

LagrangianState Lagrangian1D::sized() const {
  return {std::vector<double>(n_ + 1), std::vector<double>(n_ + 1), std::vector<double>(n_)};
}

double Lagrangian1D::shell_volume(int dim, double ra, double rb) {
  return dim == 3 ? reference::shell_volume<3>(ra, rb) : reference::shell_volume<2>(ra, rb);
}

void Lagrangian1D::rate(const LagrangianState& s, LagrangianState& d, double* step_of_zone) {
  const Mesh m{n_, o_.gamma, o_.c1, o_.c2, o_.courant, dm_.data(), mnode_.data(), menc_.data()};
  if (o_.self_gravity && o_.outer_wall) rates<3, true, true>(m, s, d, P_.data(), step_of_zone);
  else if (o_.self_gravity) rates<3, true, false>(m, s, d, P_.data(), step_of_zone);
  else if (o_.dim == 3 && o_.outer_wall) rates<3, false, true>(m, s, d, P_.data(), step_of_zone);
  else if (o_.dim == 3) rates<3, false, false>(m, s, d, P_.data(), step_of_zone);
  else if (o_.outer_wall) rates<2, false, true>(m, s, d, P_.data(), step_of_zone);
  else rates<2, false, false>(m, s, d, P_.data(), step_of_zone);
}

void Lagrangian1D::advance(LagrangianState& s, double& t, double t_next) {
  while (t < t_next) {
    if (steps_ >= o_.max_steps) throw std::invalid_argument(o_.name + ": step budget exhausted");
    rate(s, k1_, step_of_zone_.data());  // k1 does not depend on dt
    double dt = time_step(step_of_zone_);
    const bool last = t + dt >= t_next;
    if (last) dt = t_next - t;
    axpy(s, 0.5 * dt, k1_, y_);
    rate(y_, k2_);
    axpy(s, 0.5 * dt, k2_, y_);
    rate(y_, k3_);
    axpy(s, dt, k3_, y_);
    rate(y_, k4_);
    rk4_update(s, {dt / 6.0, dt / 3.0, dt / 3.0, dt / 6.0}, {&k1_, &k2_, &k3_, &k4_});
    t = last ? t_next : t + dt;
    ++steps_;
    if (const int k = first_bad(s, n_); k >= 0)
      throw std::invalid_argument(o_.name + ": zone " + std::to_string(k) + " went bad at t = " + std::to_string(t));
  }
}

RadialProfile Lagrangian1D::profile(const LagrangianState& s) const {
  RadialProfile p{s.r, s.v, std::vector<double>(n_), std::vector<double>(n_), s.e};
  for (int k = 0; k < n_; ++k) p.r_zone[k] = 0.5 * (s.r[k] + s.r[k + 1]), p.rho[k] = dm_[k] / volume(s, k);
  return p;
}

}  // namespace reference
