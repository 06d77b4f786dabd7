// Case `kernel`: normalisation and consistency of the cubic spline (eqs 6-10) and the discrete
// normalisation condition (20) on lattices, in 1D, 2D and 3D.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/quadrature.hpp"
#include "sph/kernel/cubic_spline.hpp"
#include "verification/case.hpp"
#include "verification/sweep.hpp"

namespace sphv::kernel_case {
namespace {

// Surface of the unit sphere in D dimensions: 2, 2 pi, 4 pi.
constexpr double unit_sphere(int d) { return d == 1 ? 2.0 : d == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi; }

// |integral of W over its support - 1| by GSL adaptive quadrature in r, with the kernel's
// breakpoints at h/2 and h given to the integrator.
template <int D>
double quadrature_error(double h) {
  auto f = [h](double r) { return unit_sphere(D) * std::pow(r, D - 1) * sph::CubicSpline<D>::W(r, h); };
  return std::abs(reference::integrate(f, {0.0, 0.5 * h, h}).value - 1.0);
}

// Condition (20) at a lattice point of spacing dx with m_j / rho_j = dx^D:
// |sum_j dx^D W(|r_j|, h) - 1|, summed directly over the lattice (no neighbour search).
template <int D>
double lattice_sum_error(double h, double dx) {
  const int k = static_cast<int>(std::ceil(h / dx));
  double sum = 0.0;
  if constexpr (D == 1) {
    for (int a = -k; a <= k; ++a) sum += sph::CubicSpline<1>::W(std::abs(a) * dx, h);
  } else if constexpr (D == 2) {
    for (int a = -k; a <= k; ++a)
      for (int b = -k; b <= k; ++b) sum += sph::CubicSpline<2>::W(dx * std::hypot(a, b), h);
  } else {
    for (int a = -k; a <= k; ++a)
      for (int b = -k; b <= k; ++b)
        for (int c = -k; c <= k; ++c)
          sum += sph::CubicSpline<3>::W(dx * std::sqrt(double(a * a + b * b + c * c)), h);
  }
  return std::abs(sum * std::pow(dx, D) - 1.0);
}

// Largest |dW/dr - central difference of W| relative to max |dW/dr|, over 0 < r < 1.2 h.
// Step 1e-5 h: truncation ~ (1e-5)^2 |W'''| / 6 and round-off ~ 1e-16 / 1e-5 both stay < 1e-9.
template <int D>
double derivative_error(double h) {
  using K = sph::CubicSpline<D>;
  const double d = 1e-5 * h;
  double worst = 0.0, scale = 0.0;
  for (int s = 1; s < 1200; ++s) {
    const double r = s * 1e-3 * h;
    if (std::abs(r - 0.5 * h) < 2 * d || std::abs(r - h) < 2 * d) continue;  // kinks of W''
    worst = std::max(worst, std::abs(K::dWdr(r, h) - (K::W(r + d, h) - K::W(r - d, h)) / (2 * d)));
    scale = std::max(scale, std::abs(K::dWdr(r, h)));
  }
  return worst / scale;
}

// Largest jump of W and of dW/dr across q = 1/2 and q = 1 (relative to W(0)), plus any
// negative value inside or non-zero value outside the support.
template <int D>
double shape_violation(double h) {
  using K = sph::CubicSpline<D>;
  const double e = 1e-13 * h, w0 = K::W(0.0, h), g0 = 6.0 * K::sigma / std::pow(h, D + 1);
  double v = 0.0;
  for (double q : {0.5, 1.0}) {
    v = std::max(v, std::abs(K::W(q * h - e, h) - K::W(q * h + e, h)) / w0);
    v = std::max(v, std::abs(K::dWdr(q * h - e, h) - K::dWdr(q * h + e, h)) / g0);
  }
  for (int s = 0; s <= 2000; ++s) {
    const double r = s * 1e-3 * h;
    if (K::W(r, h) < 0.0) v = std::max(v, -K::W(r, h) / w0);
    if (r > h && K::W(r, h) != 0.0) v = std::max(v, 1.0);
  }
  return v;
}

template <int D>
Series kernel_shape(bool derivative) {
  Series s{std::to_string(D) + "D", {}, {}, "line"};
  for (int k = 0; k <= 120; ++k) {
    const double q = k / 100.0;
    s.x.push_back(q);
    s.y.push_back(derivative ? sph::CubicSpline<D>::dWdr(q, 1.0) : sph::CubicSpline<D>::W(q, 1.0));
  }
  return s;
}

template <int D>
Series sum_against_ratio() {
  Series s{std::to_string(D) + "D", {}, {}, "line"};
  for (double ratio = 1.2; ratio <= 6.0 + 1e-9; ratio += (D == 3 ? 0.05 : 0.02)) {
    s.x.push_back(ratio);
    s.y.push_back(std::max(lattice_sum_error<D>(1.0, 1.0 / ratio), 1e-17));
  }
  return s;
}

// The lattice-sum error oscillates with how the kinks at h/2 and h fall between lattice points
// (period 2 dx in h). Its envelope, the worst error over one period [h, h + 2 dx), is what
// converges cleanly; a single h would give a fit that depends on luck.
template <int D>
double worst_lattice_sum_error(double h, double dx) {
  double worst = 0.0;
  for (int k = 0; k < 32; ++k) worst = std::max(worst, lattice_sum_error<D>(h + k * dx / 16.0, dx));
  return worst;
}

Result run(const Params& p) {
  const double h = p.real("h"), dx = 1.0 / p.integer("n");
  Result r;
  r.n_particles = 0;
  r.errors = {{"sum_1d", worst_lattice_sum_error<1>(h, dx)},
              {"sum_2d", worst_lattice_sum_error<2>(h, dx)},
              {"sum_3d", worst_lattice_sum_error<3>(h, dx)}};
  r.extra = {{"ratio_h_dx", h / dx},
             {"quadrature_error", {quadrature_error<1>(h), quadrature_error<2>(h), quadrature_error<3>(h)}},
             {"derivative_error", {derivative_error<1>(h), derivative_error<2>(h), derivative_error<3>(h)}},
             {"shape_violation", {shape_violation<1>(h), shape_violation<2>(h), shape_violation<3>(h)}}};
  r.figures.push_back({"kernel_W", "Cubic spline kernel (6), h = 1", "q = r/h", "W(q; h = 1)", "linear",
                       "linear", {kernel_shape<1>(false), kernel_shape<2>(false), kernel_shape<3>(false)}});
  r.figures.push_back({"kernel_dW", "Kernel derivative (8), h = 1", "q = r/h", "dW/dr (h = 1)", "linear",
                       "linear", {kernel_shape<1>(true), kernel_shape<2>(true), kernel_shape<3>(true)}});
  r.figures.push_back({"lattice_sum_ratio", "Condition (20) on a lattice against h/dx",
                       "support radius / lattice spacing h/dx", "|sum_j m_j/rho_j W_ij - 1|", "linear", "log",
                       {sum_against_ratio<1>(), sum_against_ratio<2>(), sum_against_ratio<3>()}});
  return r;
}

std::vector<Check> gates(const Sweep& s) {
  std::vector<Check> c;
  const auto& x = s.runs.back().extra;
  for (int d = 0; d < 3; ++d) {
    const std::string dim = std::to_string(d + 1) + "d";
    // The bound; GSL's QAGP reaches ~1e-15 on this piecewise cubic.
    c.push_back({"quadrature_" + dim, x["quadrature_error"][d], 0.0, 1e-10, "issue 2: |int W - 1| <= 1e-10"});
    // Truncation + round-off estimate of the central difference, see derivative_error.
    c.push_back({"derivative_" + dim, x["derivative_error"][d], 0.0, 1e-8, "central difference, step 1e-5 h"});
    // W is C^1 (C^2 in fact): jumps across 1/2 and 1 are round-off only (~1e-12 at e = 1e-13 h).
    c.push_back({"shape_" + dim, x["shape_violation"][d], 0.0, 1e-9, "W >= 0, W = 0 beyond h, W and dW/dr continuous"});
  }
  // The lattice-sum error at the finest level, as err n^p <= C with p half an order below theory
  // (the measured slopes): err n^p measured at n = 128 and 256: 1D (p 3.5) 60.8, 57.5; 2D (p 4)
  // 257, 209; 3D (p 4.5) 1068, 802. C = 1.5 times the larger (the error oscillates with n).
  const auto& fine = s.runs.back();
  const double n = fine.params["n"].get<double>();
  const struct { const char* e; double p, C; } bound[] = {{"sum_1d", 3.5, 92.0}, {"sum_2d", 4.0, 385.0}, {"sum_3d", 4.5, 1600.0}};
  for (const auto& b : bound)
    c.push_back({std::string(b.e) + "_times_n^p", fine.errors.at(b.e) * std::pow(n, b.p), 0.0, b.C,
                 "lattice-sum error at the finest level, measured constant, margin 50%", Check::Kind::verification, b.e});
  return c;
}

const Registration reg{Case{
    .name = "kernel",
    .summary = "cubic spline: normalisation by quadrature, W' consistency, lattice sums (20)",
    .n_counts = "lattice points per unit length at fixed support radius h (h/dx = n h)",
    .tags = {"gate", "sweep"},
    .params = {integer_param("n", 32, "lattice points per unit length"),
               real_param("h", 0.137, "support radius (not a multiple of dx: 1D sums are exact then)", 0.0)},
    // CPU (user, one thread): quick 0.03 s, standard 0.10 s; the 3D sum grows as n^3, so full's
    // n = 512 adds ~0.6 s and 1024 ~5 s (estimated).
    .levels = {.quick = {16, 32, 64, 128}, .standard = {16, 32, 64, 128, 256}, .full = {16, 32, 64, 128, 256, 512, 1024}},
    // Lattice sums converge at the expected order; the fit over oscillating errors is rough.
    // Measured (h = 0.137): quick (n = 16-128) 3.57 +- 0.21, 3.95 +- 0.28, 4.53 +- 0.18; standard
    // (16-256) 3.65 +- 0.13, 4.11 +- 0.18, 4.66 +- 0.13 in 1D, 2D, 3D: at most 0.55 below theory
    // (the fits are pre-asymptotic, the errors oscillate with how the kinks fall between lattice
    // points). Band 0.6 around theory (plus the harness's 2 se); a wrong kernel constant gives a
    // floor and an order near 0.
    .orders = [](const Params&) {
      const std::string why = "trapezoidal lattice sum of a C^2 piecewise cubic: jumps of W''' on the sphere "
                              "r = h/2 and r = h decay as |k|^-(4 + (d-1)/2) in Fourier space";
      return OrderClaims{{"sum_1d", {4.0, 0.6, why}}, {"sum_2d", {4.5, 0.6, why}}, {"sum_3d", {5.0, 0.6, why}}};
    },
    .error_defs = {{"sum_1d", "max over 32 shifts of h within [h, h + 2 dx) of |dx sum_j W(x_j, h) - 1|, 1D lattice (20)"},
                   {"sum_2d", "max over 32 shifts of h within [h, h + 2 dx) of |dx^2 sum_j W(x_j, h) - 1|, 2D lattice (20)"},
                   {"sum_3d", "max over 32 shifts of h within [h, h + 2 dx) of |dx^3 sum_j W(x_j, h) - 1|, 3D lattice (20)"}},
    .run = run,
    .gates = gates,
}};

}  // namespace
}  // namespace sphv::kernel_case
