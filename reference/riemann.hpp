#pragma once
#include <stdexcept>

namespace reference {

// Exact solution of the Riemann problem for the ideal gas p = (gamma - 1) rho e
// (Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, ch. 4). Independent of sph/.
struct GasState {
  double rho, u, p;
};

struct Primitive {
  double rho, u, p, e;  // density, velocity, pressure, specific internal energy
};

// Thrown when the data are not a valid problem (gamma <= 1, rho or p not positive) or when the
// two states generate vacuum (Toro 4.40: 2 (c_L + c_R) / (gamma - 1) <= u_R - u_L).
struct RiemannError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

class RiemannSolution {
 public:
  RiemannSolution(GasState left, GasState right, double gamma, double x0 = 0.5);

  double p_star() const { return p_star_; }
  double u_star() const { return u_star_; }
  double rho_star_left() const;
  double rho_star_right() const;
  // Slowest and fastest wave speeds (shock speed or rarefaction head): the solution equals
  // the left state for x < x0 + t * slowest() and the right state for x > x0 + t * fastest().
  double slowest() const;
  double fastest() const;
  // Speeds of the left wave: shock speed (both equal) or rarefaction head and tail.
  double left_head() const;
  double left_tail() const;
  double right_head() const;
  double right_tail() const;

  // The solution at (x, t); at t <= 0 the initial discontinuity.
  Primitive sample(double x, double t) const;

 private:
  double star_density(const GasState& k) const;
  GasState l_, r_;
  double gamma_, x0_, cl_, cr_, p_star_, u_star_;
};

}  // namespace reference
