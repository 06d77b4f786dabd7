#include "reference/sedov.hpp"

#include "reference/interpolate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

namespace reference {
namespace {

struct Shape {
  int d;
  double gamma;
};

// y = (f, g, h, I): the similarity ODEs (derived from the Euler equations with v = U f,
// rho = rho0 g, p = rho0 U^2 h, R R''/R'^2 = -d/2), and the energy integrand for I.
//   (f - xi) f' + h'/g = (d/2) f
//   (f - xi) g' + g (f' + n f/xi) = 0
//   (f - xi) h' + gamma h (f' + n f/xi) = d h,        n = d - 1
int rhs(double xi, const double y[], double dy[], void* params) {
  const auto& s = *static_cast<const Shape*>(params);
  const double f = y[0], g = y[1], h = y[2], n = s.d - 1.0, w = f - xi;
  const double df = (0.5 * s.d * f * w * g - s.d * h + s.gamma * h * n * f / xi) / (g * w * w - s.gamma * h);
  const double div = df + n * f / xi;
  dy[0] = df;
  dy[1] = -g * div / w;
  dy[2] = (s.d * h - s.gamma * h * div) / w;
  dy[3] = std::pow(xi, s.d - 1) * (0.5 * g * f * f + h / (s.gamma - 1.0));
  return GSL_SUCCESS;
}

}  // namespace

Sedov::Sedov(int d, double gamma) : d_(d), gamma_(gamma) {
  if (d < 1 || d > 3) throw std::invalid_argument("Sedov: dimension must be 1, 2 or 3");
  if (!(gamma > 1.0)) throw std::invalid_argument("Sedov: gamma must exceed 1");
  Shape shape{d, gamma};
  gsl_odeiv2_system sys{rhs, nullptr, 4, &shape};
  gsl_odeiv2_driver* drv = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, -1e-6, 1e-13, 1e-13);
  // Strong-shock (Rankine-Hugoniot) values just behind the shock, xi = 1.
  double y[4] = {2.0 / (gamma + 1.0), (gamma + 1.0) / (gamma - 1.0), 2.0 / (gamma + 1.0), 0.0};
  // Table on a grid uniform in xi down to xi_min; the integrand is bounded, so the part of the
  // energy integral below xi_min is O(xi_min^d).
  constexpr int N = 8000;
  constexpr double xi_min = 1e-7;
  std::vector<double> xs(N + 1), fs(N + 1), gs(N + 1), hs(N + 1);
  double xi = 1.0;
  for (int k = N; k >= 0; --k) {
    const double target = k == 0 ? xi_min : static_cast<double>(k) / N;
    if (target < xi) {
      const int status = gsl_odeiv2_driver_apply(drv, &xi, target, y);
      if (status != GSL_SUCCESS) {
        gsl_odeiv2_driver_free(drv);
        throw std::runtime_error("Sedov: ODE integration failed");
      }
    }
    xs[k] = target;
    fs[k] = y[0];
    gs[k] = y[1];
    hs[k] = y[2];
  }
  gsl_odeiv2_driver_free(drv);
  const double integral = -y[3];  // integrated from 1 down to xi_min
  const double sigma = d == 1 ? 2.0 : d == 2 ? 2.0 * M_PI : 4.0 * M_PI;
  const double alpha = 2.0 / (d + 2.0);
  xi0_ = std::pow(sigma * alpha * alpha * integral, -1.0 / (d + 2.0));
  xi_ = std::move(xs);
  f_ = std::move(fs);
  g_ = std::move(gs);
  h_ = std::move(hs);
}

double Sedov::shock_radius(double E, double rho0, double t) const {
  return xi0_ * std::pow(E * t * t / rho0, 1.0 / (d_ + 2.0));
}

double Sedov::shock_speed(double E, double rho0, double t) const {
  return 2.0 / (d_ + 2.0) * shock_radius(E, rho0, t) / t;
}

double Sedov::f(double xi) const { return xi > 1.0 ? 0.0 : interpolate_linear(xi_, f_, xi); }
double Sedov::g(double xi) const { return xi > 1.0 ? 1.0 : interpolate_linear(xi_, g_, xi); }
double Sedov::h(double xi) const { return xi > 1.0 ? 0.0 : interpolate_linear(xi_, h_, xi); }

double Sedov::density(double r, double E, double rho0, double t) const {
  return rho0 * g(r / shock_radius(E, rho0, t));
}
double Sedov::velocity(double r, double E, double rho0, double t) const {
  return shock_speed(E, rho0, t) * f(r / shock_radius(E, rho0, t));
}
double Sedov::pressure(double r, double E, double rho0, double t) const {
  const double U = shock_speed(E, rho0, t);
  return rho0 * U * U * h(r / shock_radius(E, rho0, t));
}

}  // namespace reference
