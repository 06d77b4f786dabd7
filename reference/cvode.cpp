#include "reference/cvode.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace reference {

LinearSolver linear_solver_from_name(const std::string& name) {
  if (name == "spgmr") return LinearSolver::Spgmr;
  if (name == "band") return LinearSolver::Band;
  if (name == "dense") return LinearSolver::Dense;
  throw std::invalid_argument("unknown CVODE linear solver '" + name + "' (spgmr, band, dense)");
}

std::string name_of(LinearSolver s) {
  return s == LinearSolver::Spgmr ? "spgmr" : s == LinearSolver::Band ? "band" : "dense";
}

namespace {

// Owns the SUNDIALS objects of one integration and frees them in reverse order.
struct Session {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver ls = nullptr;
  void* mem = nullptr;
  ~Session() {
    if (mem) CVodeFree(&mem);
    if (ls) SUNLinSolFree(ls);
    if (A) SUNMatDestroy(A);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

struct UserData {
  const Rhs* f;
  std::vector<double> y, ydot;
};

int rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
  auto& u = *static_cast<UserData*>(user);
  const double* py = N_VGetArrayPointer(y);
  std::copy(py, py + u.y.size(), u.y.begin());
  (*u.f)(t, u.y, u.ydot);
  std::copy(u.ydot.begin(), u.ydot.end(), N_VGetArrayPointer(ydot));
  return 0;
}

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE: ") + what + " failed (flag " + std::to_string(flag) + ")");
}

}  // namespace

CvodeResult cvode_integrate(const Rhs& f, const std::vector<double>& y0, double t0,
                            const std::vector<double>& outputs, const CvodeOptions& o) {
  const auto n = static_cast<sunindextype>(y0.size());
  Session s;
  check(SUNContext_Create(nullptr, &s.ctx), "SUNContext_Create");
  s.y = N_VNew_Serial(n, s.ctx);
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(s.y));
  s.mem = CVodeCreate(CV_BDF, s.ctx);
  if (!s.mem) throw std::runtime_error("CVODE: CVodeCreate failed");
  UserData data{&f, std::vector<double>(y0.size()), std::vector<double>(y0.size())};
  check(CVodeInit(s.mem, rhs, t0, s.y), "CVodeInit");
  check(CVodeSStolerances(s.mem, o.rtol, o.atol), "CVodeSStolerances");
  check(CVodeSetUserData(s.mem, &data), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(s.mem, o.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetErrFile(s.mem, nullptr), "CVodeSetErrFile");  // failures are returned, not printed
  switch (o.solver) {
    case LinearSolver::Spgmr:
      s.ls = SUNLinSol_SPGMR(s.y, SUN_PREC_NONE, 0, s.ctx);  // 0: default Krylov dimension (5)
      break;
    case LinearSolver::Band: {
      const auto bw = static_cast<sunindextype>(std::clamp<long>(o.bandwidth, 0, n - 1));
      s.A = SUNBandMatrix(n, bw, bw, s.ctx);
      s.ls = SUNLinSol_Band(s.y, s.A, s.ctx);
      break;
    }
    case LinearSolver::Dense:
      s.A = SUNDenseMatrix(n, n, s.ctx);
      s.ls = SUNLinSol_Dense(s.y, s.A, s.ctx);
      break;
  }
  check(CVodeSetLinearSolver(s.mem, s.ls, s.A), "CVodeSetLinearSolver");

  CvodeResult r;
  r.ok = true;
  double t = t0;
  for (double tout : outputs) {
    const int flag = CVode(s.mem, tout, s.y, &t, CV_NORMAL);
    if (flag < 0) {
      r.ok = false;
      r.message = std::string("CVODE failed at t = ") + std::to_string(t) + ": " + CVodeGetReturnFlagName(flag);
      break;
    }
    const double* py = N_VGetArrayPointer(s.y);
    r.y.emplace_back(py, py + n);
  }
  long nfe = 0, nfe_ls = 0;
  CVodeGetNumSteps(s.mem, &r.stats.steps);
  CVodeGetNumRhsEvals(s.mem, &nfe);
  CVodeGetNumLinRhsEvals(s.mem, &nfe_ls);
  CVodeGetNumLinIters(s.mem, &r.stats.linear_iters);
  CVodeGetNumJacEvals(s.mem, &r.stats.jacobian_evals);
  CVodeGetNumErrTestFails(s.mem, &r.stats.error_test_fails);
  r.stats.rhs_evals = nfe + nfe_ls;
  return r;
}

}  // namespace reference
