#include "reference/kh_linear.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace reference {
namespace {

using cplx = std::complex<double>;

// The McNally et al. profile of a field with values f1 (outer layers) and f2 (middle layer).
double blend(double f1, double f2, double L, double y) {
  const double fm = 0.5 * (f1 - f2);
  y -= std::floor(y);
  if (y < 0.25) return f1 - fm * std::exp((y - 0.25) / L);
  if (y < 0.5) return f2 + fm * std::exp(-(y - 0.25) / L);
  if (y < 0.75) return f2 + fm * std::exp(-(0.75 - y) / L);
  return f1 - fm * std::exp(-(y - 0.75) / L);
}

double blend_slope(double f1, double f2, double L, double y) {
  const double fm = 0.5 * (f1 - f2);
  y -= std::floor(y);
  if (y < 0.25) return -fm / L * std::exp((y - 0.25) / L);
  if (y < 0.5) return -fm / L * std::exp(-(y - 0.25) / L);
  if (y < 0.75) return fm / L * std::exp(-(0.75 - y) / L);
  return fm / L * std::exp(-(y - 0.75) / L);
}

// Secant iteration on a complex function from two starting points.
cplx secant(const std::function<cplx(cplx)>& F, cplx s0, cplx s1, int& iterations, double& residual) {
  cplx f0 = F(s0), f1 = F(s1);
  for (iterations = 1; iterations <= 100; ++iterations) {
    if (f1 == 0.0) {
      residual = 0.0;
      return s1;
    }
    if (f1 == f0) break;
    const cplx s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
    s0 = s1, f0 = f1;
    s1 = s2, f1 = F(s1);
    if (!std::isfinite(s1.real()) || !std::isfinite(s1.imag())) break;
    if (std::abs(s1 - s0) <= 1e-12 * std::abs(s1)) {
      residual = std::abs(s1 - s0) / std::abs(s1);
      return s1;
    }
  }
  throw std::runtime_error("kh_linear: the secant iteration did not converge (last sigma " + std::to_string(s1.real()) +
                           " + " + std::to_string(s1.imag()) + " i)");
}

}  // namespace

double KhProfile::density(double y) const { return blend(rho1, rho2, L, y); }
double KhProfile::velocity(double y) const { return blend(U1, U2, L, y); }
double KhProfile::shear(double y) const { return blend_slope(U1, U2, L, y); }

double kh_sheet_growth_incompressible(const KhProfile& prof, double k) {
  return k * std::abs(prof.U1 - prof.U2) * std::sqrt(prof.rho1 * prof.rho2) / (prof.rho1 + prof.rho2);
}

std::complex<double> kh_sheet_sigma(const KhProfile& prof, double k, KhParity parity) {
  const cplx i(0.0, 1.0);
  auto side = [&](cplx sigma, double rho, double U) {
    const cplx Om = sigma + i * k * U;
    const cplx m = std::sqrt(k * k + Om * Om * rho / (prof.gamma * prof.p0));  // principal root: Re m >= 0
    const cplx f = parity == KhParity::odd ? 1.0 / std::tanh(0.25 * m) : std::tanh(0.25 * m);
    return m * f / (rho * Om * Om);
  };
  auto G = [&](cplx s) { return side(s, prof.rho1, prof.U1) + side(s, prof.rho2, prof.U2); };
  const cplx guess(kh_sheet_growth_incompressible(prof, k),
                   -k * (prof.rho1 * prof.U1 + prof.rho2 * prof.U2) / (prof.rho1 + prof.rho2));
  int it = 0;
  double res = 0.0;
  return secant(G, guess, 0.95 * guess, it, res);
}

KhMode kh_linear_mode(const KhProfile& prof, double k, int steps_per_quarter, KhParity parity) {
  if (steps_per_quarter < 1) throw std::invalid_argument("kh_linear_mode: steps_per_quarter must be >= 1");
  if (!(prof.L > 0.0)) throw std::invalid_argument("kh_linear_mode: the interface width L must be > 0");
  const cplx i(0.0, 1.0);
  const double inv_gp = 1.0 / (prof.gamma * prof.p0);
  using State = std::array<cplx, 2>;  // (p, q)
  // p (odd) or q (even) at y = 1/2 for the profile of width L in n steps a quarter: zero where the
  // boundary condition holds. (Not p / q: the other class's root, a pole of p / q, lies within
  // 0.02 of this one, kept apart only by the layers' coupling across half a box, ~exp(-k / 2).)
  auto shoot = [&](cplx sigma, double L, int n) {
    KhProfile pr = prof;
    pr.L = L;
    const double dy = 0.25 / n;
    auto rhs = [&](double y, const State& s) -> State {
      const cplx Om = sigma + i * k * pr.velocity(y), rO2 = pr.density(y) * Om * Om;
      return {rO2 * s[1], (k * k / rO2 + inv_gp) * s[0]};
    };
    State s = parity == KhParity::odd ? State{0.0, 1.0} : State{1.0, 0.0};
    for (int q = 0; q < 2; ++q) {
      const double y0 = 0.25 * q;
      // The profile's join at 1/4 is a step end: evaluated just inside the quarter, on its own
      // smooth branch (the second derivative jumps there), so RK4 keeps its fourth order.
      auto at = [&](double y) { return std::min(std::max(y, y0 + 1e-15), y0 + 0.25 - 1e-15); };
      for (int j = 0; j < n; ++j) {
        const double ya = y0 + j * dy, yb = ya + 0.5 * dy, yc = ya + dy;
        const State k1 = rhs(at(ya), s);
        const State k2 = rhs(at(yb), {s[0] + 0.5 * dy * k1[0], s[1] + 0.5 * dy * k1[1]});
        const State k3 = rhs(at(yb), {s[0] + 0.5 * dy * k2[0], s[1] + 0.5 * dy * k2[1]});
        const State k4 = rhs(at(yc), {s[0] + dy * k3[0], s[1] + dy * k3[1]});
        for (int c = 0; c < 2; ++c) s[c] += dy / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
      }
    }
    return parity == KhParity::odd ? s[0] : s[1];
  };
  // Continuation in L: the sheet's root starts the secant at k L = 1/200 (or at L itself if
  // narrower), where the smooth root lies within a few per cent of the sheet's, and each root
  // starts the next at twice the width, four RK4 steps per width (dy = L / 4), up to L itself.
  KhMode mode;
  cplx sigma = kh_sheet_sigma(prof, k, parity);
  for (double L = std::min(prof.L, 1.0 / (200.0 * k)); L < prof.L; L *= 2.0) {
    const int n = static_cast<int>(std::ceil(1.0 / L));
    sigma = secant([&](cplx s) { return shoot(s, L, n); }, sigma, cplx(0.99 * sigma.real(), sigma.imag()),
                   mode.iterations, mode.residual);
  }
  mode.sigma = secant([&](cplx s) { return shoot(s, prof.L, steps_per_quarter); }, sigma,
                      cplx(0.99 * sigma.real(), sigma.imag()), mode.iterations, mode.residual);
  return mode;
}

double KhAmplitudeSeries::at(double time) const {
  if (t.empty()) return 0.0;
  if (time <= t.front()) return M.front();
  if (time >= t.back()) return M.back();
  const std::size_t j = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
  const double w = (time - t[j - 1]) / (t[j] - t[j - 1]);
  return std::exp((1.0 - w) * std::log(M[j - 1]) + w * std::log(M[j]));
}

KhAmplitudeSeries kh_linear_amplitude(const KhProfile& prof, double k, double A, double t_end, int N, double dt_factor,
                                      int every) {
  if (N < 64) throw std::invalid_argument("kh_linear_amplitude: N must be >= 64");
  if (!(dt_factor > 0.0 && dt_factor <= 1.0)) throw std::invalid_argument("kh_linear_amplitude: dt_factor in (0, 1]");
  if (every < 1) throw std::invalid_argument("kh_linear_amplitude: every must be >= 1");
  const cplx i(0.0, 1.0);
  const double dy = 1.0 / N;
  std::vector<double> rho(N), U(N), dU(N), w(N);
  double wsum = 0.0, c_max = 0.0, U_max = 0.0;
  for (int j = 0; j < N; ++j) {
    const double y = j * dy;
    rho[j] = prof.density(y), U[j] = prof.velocity(y), dU[j] = prof.shear(y);
    w[j] = std::exp(-k * std::abs(y - (y < 0.5 ? 0.25 : 0.75)));
    wsum += w[j];
    c_max = std::max(c_max, std::sqrt(prof.gamma * prof.p0 / rho[j]));
    U_max = std::max(U_max, std::abs(U[j]));
  }
  using Field = std::vector<cplx>;
  struct State {
    Field u, v, p;
  };
  auto ddy = [&](const Field& f, int j) {  // fourth-order central difference, periodic
    auto at = [&](int m) { return f[static_cast<std::size_t>(((j + m) % N + N) % N)]; };
    return (8.0 * (at(1) - at(-1)) - (at(2) - at(-2))) / (12.0 * dy);
  };
  auto rates = [&](const State& s, State& r) {
    for (int j = 0; j < N; ++j) {
      const cplx adv = -i * k * U[j], dv = ddy(s.v, j), dp = ddy(s.p, j);
      r.u[j] = adv * s.u[j] - dU[j] * s.v[j] - i * k * s.p[j] / rho[j];
      r.v[j] = adv * s.v[j] - dp / rho[j];
      r.p[j] = adv * s.p[j] - prof.gamma * prof.p0 * (i * k * s.u[j] + dv);
    }
  };
  // RK4's stability limit on the imaginary axis, 2.83, over the largest rate: sound at c_max on
  // the stencil's largest wavenumber (1.372 / dy) plus advection k U_max.
  const double rate_max = c_max * 1.372 / dy + k * U_max + k * c_max;
  const int steps = static_cast<int>(std::ceil(t_end / (dt_factor * 2.83 / rate_max)));
  const double dt = t_end / steps;
  State s{Field(N, 0.0), Field(N, cplx(0.0, -A)), Field(N, 0.0)}, k1 = s, k2 = s, k3 = s, k4 = s, tmp = s;
  auto amplitude = [&](const State& st) {
    cplx sum = 0.0;
    for (int j = 0; j < N; ++j) sum += st.v[j] * w[j];
    return std::abs(sum) / wsum;
  };
  auto axpy = [&](const State& a, double h, const State& b, State& out) {
    for (int j = 0; j < N; ++j) out.u[j] = a.u[j] + h * b.u[j], out.v[j] = a.v[j] + h * b.v[j], out.p[j] = a.p[j] + h * b.p[j];
  };
  KhAmplitudeSeries out;
  out.dt = dt;
  out.t.push_back(0.0), out.M.push_back(amplitude(s));
  for (int n = 1; n <= steps; ++n) {
    rates(s, k1);
    axpy(s, 0.5 * dt, k1, tmp);
    rates(tmp, k2);
    axpy(s, 0.5 * dt, k2, tmp);
    rates(tmp, k3);
    axpy(s, dt, k3, tmp);
    rates(tmp, k4);
    for (int j = 0; j < N; ++j) {
      s.u[j] += dt / 6.0 * (k1.u[j] + 2.0 * k2.u[j] + 2.0 * k3.u[j] + k4.u[j]);
      s.v[j] += dt / 6.0 * (k1.v[j] + 2.0 * k2.v[j] + 2.0 * k3.v[j] + k4.v[j]);
      s.p[j] += dt / 6.0 * (k1.p[j] + 2.0 * k2.p[j] + 2.0 * k3.p[j] + k4.p[j]);
    }
    if (n % every == 0 || n == steps) out.t.push_back(n * dt), out.M.push_back(amplitude(s));
  }
  return out;
}

}  // namespace reference
