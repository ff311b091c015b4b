#include "io/gsl_errors.hpp"

#include <gsl/gsl_errno.h>

namespace dlpverify {

void use_gsl_return_codes() {
  static const bool off = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)off;
}

}  // namespace dlpverify
