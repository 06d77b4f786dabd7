#include "reference/riemann.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace reference {
namespace {

struct Problem {
  GasState l, r;
  double gamma, cl, cr;
};

// Toro (4.6)/(4.7): velocity change across the K wave as a function of the star pressure,
// shock branch for p > p_K, rarefaction branch otherwise.
double f_k(double p, const GasState& k, double c, double g) {
  if (p > k.p) {
    const double A = 2.0 / ((g + 1.0) * k.rho), B = (g - 1.0) / (g + 1.0) * k.p;
    return (p - k.p) * std::sqrt(A / (p + B));
  }
  return 2.0 * c / (g - 1.0) * (std::pow(p / k.p, (g - 1.0) / (2.0 * g)) - 1.0);
}

// Toro (4.5): f(p) = f_L + f_R + u_R - u_L, monotone increasing in p; its root is p*.
double pressure_function(double p, void* params) {
  const auto& q = *static_cast<const Problem*>(params);
  return f_k(p, q.l, q.cl, q.gamma) + f_k(p, q.r, q.cr, q.gamma) + q.r.u - q.l.u;
}

// Brent's method (GSL) on [0, p_hi]: f(0) < 0 when no vacuum forms, and f grows without
// bound, so doubling p_hi brackets the root.
double solve_p_star(Problem& q) {
  gsl_function F{&pressure_function, &q};
  double hi = std::max(q.l.p, q.r.p);
  while (pressure_function(hi, &q) < 0.0) hi *= 2.0;
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(s, &F, 0.0, hi);
  int status = GSL_CONTINUE;
  double root = hi;
  for (int it = 0; it < 500 && status == GSL_CONTINUE; ++it) {
    gsl_root_fsolver_iterate(s);
    root = gsl_root_fsolver_root(s);
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-14);
  }
  gsl_root_fsolver_free(s);
  if (status != GSL_SUCCESS) throw RiemannError("exact Riemann solver: root finding did not converge");
  return root;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw RiemannError("Riemann problem: " + what);
}

}  // namespace

RiemannSolution::RiemannSolution(GasState left, GasState right, double gamma, double x0)
    : l_(left), r_(right), gamma_(gamma), x0_(x0) {
  require(gamma > 1.0, "gamma must be > 1");
  require(l_.rho > 0.0 && r_.rho > 0.0, "densities must be > 0");
  require(l_.p > 0.0 && r_.p > 0.0, "pressures must be > 0");
  require(std::isfinite(l_.u) && std::isfinite(r_.u), "velocities must be finite");
  cl_ = std::sqrt(gamma * l_.p / l_.rho);
  cr_ = std::sqrt(gamma * r_.p / r_.rho);
  require(2.0 * (cl_ + cr_) / (gamma - 1.0) > r_.u - l_.u, "the states generate vacuum (Toro 4.40)");
  Problem q{l_, r_, gamma_, cl_, cr_};
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  p_star_ = solve_p_star(q);
  gsl_set_error_handler(old);
  // Toro (4.9).
  u_star_ = 0.5 * (l_.u + r_.u) + 0.5 * (f_k(p_star_, r_, cr_, gamma_) - f_k(p_star_, l_, cl_, gamma_));
}

// Toro (4.50) behind a shock, (4.53) behind a rarefaction.
double RiemannSolution::star_density(const GasState& k) const {
  const double ratio = p_star_ / k.p, g6 = (gamma_ - 1.0) / (gamma_ + 1.0);
  if (p_star_ > k.p) return k.rho * (ratio + g6) / (g6 * ratio + 1.0);
  return k.rho * std::pow(ratio, 1.0 / gamma_);
}
double RiemannSolution::rho_star_left() const { return star_density(l_); }
double RiemannSolution::rho_star_right() const { return star_density(r_); }

// Toro (4.52) shock speed, (4.55) rarefaction head and tail; the right wave mirrors the left.
double RiemannSolution::left_head() const {
  if (p_star_ > l_.p)
    return l_.u - cl_ * std::sqrt((gamma_ + 1.0) / (2.0 * gamma_) * p_star_ / l_.p + (gamma_ - 1.0) / (2.0 * gamma_));
  return l_.u - cl_;
}
double RiemannSolution::left_tail() const {
  if (p_star_ > l_.p) return left_head();
  return u_star_ - cl_ * std::pow(p_star_ / l_.p, (gamma_ - 1.0) / (2.0 * gamma_));
}
double RiemannSolution::right_head() const {
  if (p_star_ > r_.p)
    return r_.u + cr_ * std::sqrt((gamma_ + 1.0) / (2.0 * gamma_) * p_star_ / r_.p + (gamma_ - 1.0) / (2.0 * gamma_));
  return r_.u + cr_;
}
double RiemannSolution::right_tail() const {
  if (p_star_ > r_.p) return right_head();
  return u_star_ + cr_ * std::pow(p_star_ / r_.p, (gamma_ - 1.0) / (2.0 * gamma_));
}
double RiemannSolution::slowest() const { return left_head(); }
double RiemannSolution::fastest() const { return right_head(); }

// Toro's sampling procedure (section 4.5) at S = (x - x0) / t.
Primitive RiemannSolution::sample(double x, double t) const {
  const double g = gamma_;
  auto out = [g](double rho, double u, double p) { return Primitive{rho, u, p, p / ((g - 1.0) * rho)}; };
  if (t <= 0.0) return x < x0_ ? out(l_.rho, l_.u, l_.p) : out(r_.rho, r_.u, r_.p);
  const double S = (x - x0_) / t;
  if (S <= u_star_) {
    if (S <= left_head()) return out(l_.rho, l_.u, l_.p);
    if (S >= left_tail()) return out(rho_star_left(), u_star_, p_star_);
    // Inside the left fan, Toro (4.56).
    const double c = 2.0 / (g + 1.0) * (cl_ + 0.5 * (g - 1.0) * (l_.u - S));
    return out(l_.rho * std::pow(c / cl_, 2.0 / (g - 1.0)), 2.0 / (g + 1.0) * (cl_ + 0.5 * (g - 1.0) * l_.u + S),
               l_.p * std::pow(c / cl_, 2.0 * g / (g - 1.0)));
  }
  if (S >= right_head()) return out(r_.rho, r_.u, r_.p);
  if (S <= right_tail()) return out(rho_star_right(), u_star_, p_star_);
  // Inside the right fan, Toro (4.63).
  const double c = 2.0 / (g + 1.0) * (cr_ - 0.5 * (g - 1.0) * (r_.u - S));
  return out(r_.rho * std::pow(c / cr_, 2.0 / (g - 1.0)), 2.0 / (g + 1.0) * (-cr_ + 0.5 * (g - 1.0) * r_.u + S),
             r_.p * std::pow(c / cr_, 2.0 * g / (g - 1.0)));
}

}  // namespace reference
