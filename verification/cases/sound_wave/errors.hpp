#pragma once
// The sound wave's errors at time t, shared by `sphv run` and `sphv score`: the velocity along x
// against the reference (reference/sound_wave.hpp), and (extras) the wave's amplitude and phase
// speed from its projection on sin(k x) and cos(k x). With artificial viscosity, the damping rate against the
// viscosity's own prediction on the lattice (viscous_damping_rate).
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "reference/sound_wave.hpp"
#include "sph/core/vec.hpp"
#include "sph/kernel/cubic_spline.hpp"
#include "verification/cases/common/radial_result.hpp"
#include "verification/harness/result.hpp"

namespace sphv::sound_wave {

inline const std::map<std::string, std::string> error_defs = {
    {"L1_v", "sum_i V_i |v_x,i - v_x(x_i, t)| / (sum_i V_i A c_s), V_i = m_i / rho_i, v_x = A c_s sin(k (x - c_s t)) "
             "(linear acoustic wave, reference/sound_wave): the L1 error of v_x relative to the wave's amplitude. extra: "
             "amplitude_ratio a / (A c_s), a = sqrt(a_s^2 + a_c^2), (a_s, a_c) = 2 sum_i V_i v_x,i (sin, cos)(k x_i) / "
             "sum_i V_i; phase_speed_ratio 1 + delta / (k c_s t), delta = atan2(-a_c, a_s) - k c_s t wrapped to (-pi, pi]"},
    {"damping", "|Gamma / Gamma_visc - 1|, Gamma = -ln(amplitude_ratio) / t the measured decay rate of v_x's fundamental, Gamma_visc = "
                "nu k^2 / 4 the artificial viscosity's (45) rate in the continuum limit on the run's lattice "
                "(sound_wave/errors.hpp: nu = -(alpha c_s h_mu / 2) sum_j dx^d s_x^4 W'(r_j) / (r_j (r_j^2 + eps "
                "h_mu^2)), acting only in the compression half of the wave); only with alpha > 0"},
    {"mismatch", "sphv score's check that a snapshot holds the problem its settings describe (not an error): the "
                 "particles' mass over the box's volume is rho0 within 1e-3, their mass-weighted mean pressure rho0 "
                 "c_s^2 / gamma within 5 % and their mean v_x 0 within 5 % of c_s (a linear wave leaves the mean state "
                 "as it is); otherwise the verdict is mismatch"}};

// The amplitude decay rate of the wave's fundamental that the viscosity (44)-(46) gives in the
// continuum limit (k h -> 0, small A). Expanding v_j about x_i, the pair terms' v'' part sums to
// dv_x/dt = nu v'' with nu = -(alpha c h_mu / 2) sum_j dx^d s_x^4 W'(r) / (r (r^2 + eps h_mu^2))
// over the lattice offsets s = x_j - x_i (h_mu = h_scale h, (46)); the integral is alpha c h_mu
// d <n_x^4> / 2 (1/2, 3/8, 3/10 alpha c h_mu in 1D, 2D, 3D), the lattice sum differs from it at
// fixed h/dx. Only approaching pairs (45): the force acts where v' < 0, half the wave, and its
// projection on the fundamental is half of nu's (<sin^2 phi H(-cos phi)> = 1/4 against 1/2),
// with no phase shift. A momentum diffusivity nu damps a sound wave's amplitude at nu k^2 / 2:
// Gamma = nu k^2 / 4. First order in h at fixed h/dx.
template <int D, class K = sph::CubicSpline<D>>
double viscous_damping_rate(double alpha, double c, double h, double dx, double eps, double h_scale, double k) {
  const double h_mu = h_scale * h;
  const int reach = static_cast<int>(std::ceil(h / dx));
  const int side = 2 * reach + 1;
  int count = 1;
  for (int d = 0; d < D; ++d) count *= side;
  double sum = 0.0, cell = std::pow(dx, D);
  for (int idx = 0; idx < count; ++idx) {
    int rest = idx;
    sph::Vec<D> s;
    for (int d = 0; d < D; ++d) s[d] = dx * (rest % side - reach), rest /= side;
    const double r = s.norm();
    if (r == 0.0 || r >= h) continue;
    const double sx2 = s[0] * s[0];
    sum += cell * sx2 * sx2 * K::dWdr(r, h) / (r * (r * r + eps * h_mu * h_mu));
  }
  const double nu = -0.5 * alpha * c * h_mu * sum;
  return nu * k * k / 4.0;
}

// The phase speed the linearised scheme (summation density (27), Euler (23) with lambda = 1, h
// fixed) gives a long wave (k h -> 0) on a cubic lattice of spacing dx at support h, over c_s.
// Displacing particle j by xi e^(i k x_j) along x: delta rho = -i k xi rho S1, and
//   omega^2 / k^2 = (c_s^2 - 2 p/rho) S1^2 + (p/rho) S2,  p/rho = c_s^2 / gamma,
// S1 = -sum_j V s_x^2 W'(r) / r (the first moment), S2 = sum_j V s_x^2 d^2W/dx^2 (the second),
// V = dx^d / S0 the particle volume at the summed density S0 = dx^d sum_j W. In the continuum
// S1 = 1 and S2 = 2: omega = c_s k. On the lattice at fixed h/dx they carry an error no resolution
// removes (common/lattice_sums.hpp; exact in 1D at h/dx = 2 and 4), the phase-speed floor of the
// scheme, a property of the method (not of the reference): what a case reports beside its error.
// d^2W/dr^2 by a central difference of K::dWdr (step 1e-5 h: relative error ~1e-10, far below the
// floors of interest, ~1e-3; every kernel of kernels.hpp is C2, so the difference is smooth).
template <int D, class K = sph::CubicSpline<D>>
double lattice_phase_speed_ratio(double h_over_dx, double gamma) {
  const double h = h_over_dx;
  const int reach = static_cast<int>(std::ceil(h));
  const int side = 2 * reach + 1;
  int count = 1;
  for (int d = 0; d < D; ++d) count *= side;
  double S0 = 0.0, S1 = 0.0, S2 = 0.0;
  for (int idx = 0; idx < count; ++idx) {
    int rest = idx;
    sph::Vec<D> s;
    for (int d = 0; d < D; ++d) s[d] = rest % side - reach, rest /= side;
    const double r = s.norm();
    S0 += K::W(r, h);
    if (r == 0.0 || r >= h) continue;
    const double d1 = K::dWdr(r, h), step = 1e-5 * h;
    const double d2 = (K::dWdr(r + step, h) - K::dWdr(r - step, h)) / (2.0 * step);
    const double nx2 = s[0] * s[0] / (r * r);
    S1 -= s[0] * s[0] * d1 / r;
    S2 += s[0] * s[0] * (d2 * nx2 + d1 / r * (1.0 - nx2));
  }
  S1 /= S0, S2 /= S0;
  return std::sqrt(S1 * S1 + (2.0 / gamma) * (S2 / 2.0 - S1 * S1));
}

struct Fundamental {
  double amplitude = 0.0;  // of v_x, relative to A c_s
  double phase_error = 0.0;  // measured phase minus k c_s t, in (-pi, pi]
};

// Fills r.errors (L1_v), the fundamental's amplitude and phase speed (extra), figures and extras from the particles at time t
// (x from the box's lower edge, along the wavelength of w).
template <int D>
Fundamental measure(Result& r, const std::vector<sph::Vec<D>>& x, const std::vector<sph::Vec<D>>& v,
                    const std::vector<double>& m, const std::vector<double>& rho, double t,
                    const reference::AcousticWave& w, double A, long n) {
  const double k = w.wave_number(), c = w.sound_speed(), scale = A * c;
  double vol = 0.0, l1 = 0.0, as = 0.0, ac = 0.0, vy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double V = m[i] / rho[i];
    vol += V;
    l1 += V * std::abs(v[i][0] - w.at(x[i][0], t).v);
    as += V * v[i][0] * std::sin(k * x[i][0]);
    ac += V * v[i][0] * std::cos(k * x[i][0]);
    for (int d = 1; d < D; ++d) vy = std::max(vy, std::abs(v[i][d]));
  }
  as *= 2.0 / vol, ac *= 2.0 / vol;
  Fundamental f;
  f.amplitude = std::hypot(as, ac) / scale;
  const double expected = -w.phase(0.0, t);  // k c_s t, the reference's phase at x = 0
  f.phase_error = std::remainder(std::atan2(-ac, as) - expected, 2.0 * std::numbers::pi);
  r.errors = {{"L1_v", l1 / (vol * scale)}};
  r.functionals = {{"amplitude", f.amplitude}};
  r.extra["amplitude_ratio"] = f.amplitude;
  r.extra["phase_error"] = f.phase_error;
  r.extra["phase_speed_ratio"] = expected > 0.0 ? 1.0 + f.phase_error / expected : 1.0;
  r.extra["transverse_v_max"] = vy / scale;  // zero by symmetry on the lattice
  r.extra["nonlinear_error_estimate"] = w.nonlinear_error(t);
  r.extra["amplitude_decay_rate"] = t > 0.0 && f.amplitude > 0.0 ? -std::log(f.amplitude) / t : 0.0;
  std::vector<double> xs(x.size()), vs(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) xs[i] = x[i][0], vs[i] = v[i][0] / scale;
  r.figures.push_back(radial::profile_figure(
      "profile_vx", "Sound wave " + std::to_string(D) + "D, n = " + std::to_string(n) + ": v_x / (A c_s) at t = " +
                        std::to_string(t),
      "x", "v_x / (A c_s)", xs, vs, w.wavelength(), 1.0, "linear acoustic wave", [&](double s) { return w.at(s, t).v / scale; }));
  return f;
}

}  // namespace sphv::sound_wave
