#pragma once
#include <functional>
#include <string>
#include <vector>

namespace reference {

// A generic SUNDIALS CVODE (BDF, Newton) driver for y' = f(t, y) on std::vector<double>.
// Independent of the code under test: it only sees the right-hand side as a callback.
using Rhs = std::function<void(double t, const std::vector<double>& y, std::vector<double>& ydot)>;

// Linear solver of the Newton iteration:
//   spgmr: matrix-free GMRES (Jacobian-vector products by difference quotients of f);
//   band:  banded LU with a difference-quotient Jacobian of half-bandwidth `bandwidth`
//          (entries outside the band, e.g. periodic wrap, are dropped: an inexact Newton);
//   dense: dense LU with a difference-quotient Jacobian (n RHS evaluations per Jacobian).
enum class LinearSolver { Spgmr, Band, Dense };
LinearSolver linear_solver_from_name(const std::string& name);  // throws std::invalid_argument
std::string name_of(LinearSolver s);

struct CvodeOptions {
  double rtol = 1e-8;
  double atol = 1e-12;
  LinearSolver solver = LinearSolver::Spgmr;
  long bandwidth = 0;       // half-bandwidth for LinearSolver::Band
  long max_steps = 1000000; // per call of integrate
};

struct CvodeStats {
  long steps = 0;
  long rhs_evals = 0;      // all evaluations of f: the integrator's plus the linear solver's
  long linear_iters = 0;   // Krylov iterations (spgmr)
  long jacobian_evals = 0; // Jacobian evaluations (band, dense)
  long error_test_fails = 0;
};

struct CvodeResult {
  bool ok = false;
  std::string message;   // CVODE's failure, when !ok
  std::vector<std::vector<double>> y;  // the solution at each requested output time
  CvodeStats stats;
};

// Integrates from (t0, y0) and returns y at each time in `outputs` (increasing, > t0).
CvodeResult cvode_integrate(const Rhs& f, const std::vector<double>& y0, double t0,
                            const std::vector<double>& outputs, const CvodeOptions& options);

}  // namespace reference
