#include "reference/quadrature.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <stdexcept>
#include <string>

namespace reference {

Integral integrate(const std::function<double(double)>& f, std::vector<double> points) {
  gsl_function F;
  F.function = [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); };
  F.params = const_cast<std::function<double(double)>*>(&f);
  const std::size_t limit = 1000;
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(limit);
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  Integral r{};
  const int status = gsl_integration_qagp(&F, points.data(), points.size(), 1e-14, 1e-13, limit, w,
                                          &r.value, &r.abserr);
  gsl_set_error_handler(old);
  gsl_integration_workspace_free(w);
  if (status != GSL_SUCCESS && status != GSL_EROUND)
    throw std::runtime_error(std::string("GSL quadrature failed: ") + gsl_strerror(status));
  return r;
}

}  // namespace reference
