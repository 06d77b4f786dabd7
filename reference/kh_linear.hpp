#pragma once
#include <complex>
#include <vector>

namespace reference {

// The smooth two-interface shear layer of McNally, Lyra & Passy (2012, ApJS 201, 18, section 2):
// periodic unit box, light gas (rho1, U1) for y < 1/4 and y > 3/4, heavy gas (rho2, U2) between,
// joined by piecewise exponentials of width L at y = 1/4 and 3/4 (C1 profiles), pressure p0
// uniform, ideal gas gamma. Their values: rho1 = 1, rho2 = 2, U1 = 0.5, U2 = -0.5, L = 0.025,
// p0 = 2.5, gamma = 5/3.
struct KhProfile {
  double rho1 = 1.0, rho2 = 2.0, U1 = 0.5, U2 = -0.5, L = 0.025, p0 = 2.5, gamma = 5.0 / 3.0;
  double density(double y) const;   // y in [0, 1) (wrapped)
  double velocity(double y) const;  // v_x
  double shear(double y) const;     // dv_x/dy
};

// Linear growth of a perturbation ~ exp(i k x + sigma t) of that profile (compressible, inviscid).
// The linearised Euler equations with p0 uniform close on (u, v, p); eliminating u and v gives
// the compressible Rayleigh (Pridmore-Brown) equation for the pressure perturbation,
//   d/dy [p' / (rho Omega^2)] = (k^2 / (rho Omega^2) + 1 / (gamma p0)) p,  Omega = sigma + i k U(y),
// solved here as the first-order system p' = rho Omega^2 q, q' = (k^2 / (rho Omega^2) + 1/(gamma p0)) p
// (q is the Lagrangian displacement's y-part times -1, continuous across any profile). The profile
// is symmetric about y = 1/2, so the periodic box's modes split into two classes on [0, 1/2]:
// "odd" (p = 0 at y = 0 and 1/2: v even about 1/2, the class a seed v_y(x) uniform in y excites)
// and "even" (q = 0 there). Shooting from y = 0 with RK4 on steps aligned with the profile's
// joins at 1/4 (smooth on each quarter, so fourth order in the step), the secant method in complex
// sigma zeroes the far boundary condition.
enum class KhParity { odd, even };

struct KhMode {
  std::complex<double> sigma;  // Re: growth rate, Im: -k times the mode's phase velocity
  int iterations = 0;
  double residual = 0.0;
};

// Throws std::runtime_error if the secant iteration does not converge from the sharp-sheet guess.
KhMode kh_linear_mode(const KhProfile& prof, double k, int steps_per_quarter, KhParity parity = KhParity::odd);

// The vortex-sheet limit (L -> 0) in the same periodic box: two sheets at y = 1/4 and 3/4, uniform
// layers between; with m_j = sqrt(k^2 + Omega_j^2 / c_j^2) (Re m_j > 0), c_j^2 = gamma p0 / rho_j, the
// continuity of p and q at a sheet gives
//   m1 f(m1/4) / (rho1 Omega1^2) + m2 f(m2/4) / (rho2 Omega2^2) = 0,  f = coth (odd class), tanh (even),
// the compressible sheet dispersion relation; f -> 1 is the isolated sheet (Landau & Lifshitz, Fluid
// Mechanics, 84, problem; Chandrasekhar 1961, chapter XI, incompressible). Solved by Newton from
// the incompressible root.
std::complex<double> kh_sheet_sigma(const KhProfile& prof, double k, KhParity parity = KhParity::odd);
// Incompressible isolated (and, with m = k on both sides, also the periodic box's) sheet:
// sigma = k |U1 - U2| sqrt(rho1 rho2) / (rho1 + rho2), real part.
double kh_sheet_growth_incompressible(const KhProfile& prof, double k);

// The linear initial-value problem of the same layer: the Fourier mode exp(i k x) of the
// perturbation (u, v, p) evolved from v = v0 (uniform in y, McNally et al.'s seed v_y = A sin(k x)
// is v0 = -i A), u = p = 0, by
//   du/dt = -i k U u - U' v - i k p / rho,  dv/dt = -i k U v - (dp/dy) / rho,
//   dp/dt = -i k U p - gamma p0 (i k u + dv/dy),
// on the periodic y grid of N points (fourth-order central differences) with RK4 in time. It holds
// every part of the seed (the unstable eigenmode, its decaying partner, the sheared continuum and
// sound), so M(t) from it is what a converged code shows in the linear phase, transients
// included, where the eigenvalue is only its late-time slope.
// McNally et al.'s mode amplitude of this field: M = |int v(y) w(y) dy| / int w(y) dy, w =
// exp(-k |y - y_int|), y_int = 1/4 below y = 1/2 and 3/4 above (the x sums of their s and c
// reduce to the mode's complex amplitude).
struct KhAmplitudeSeries {
  std::vector<double> t, M;
  double dt = 0.0;
  // M at time t, interpolated linearly in ln M between the stored samples.
  double at(double time) const;
};
// Samples every `every` steps up to t_end; throws std::invalid_argument for N < 64 or dt_factor
// outside (0, 1] (the fraction of the RK4 stability limit used).
KhAmplitudeSeries kh_linear_amplitude(const KhProfile& prof, double k, double A, double t_end, int N,
                                      double dt_factor = 0.5, int every = 1);

}  // namespace reference
