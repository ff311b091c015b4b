// The domain checks of a value a user gives: each throws InputError naming the option (or
// quantity) and the value.
#pragma once

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"
#include "io/format.hpp"

namespace dlpverify {

inline void require_positive(const std::string& option, double value) {
  if (!std::isfinite(value) || value <= 0.0) throw InputError(option, value_text(value), "must be positive and finite");
}
inline void require_non_negative(const std::string& option, double value) {
  if (!std::isfinite(value) || value < 0.0) throw InputError(option, value_text(value), "must be zero or positive, and finite");
}
// A relative tolerance CVODE can honour in double precision.
inline void require_tolerance(const std::string& option, double value) {
  if (!std::isfinite(value) || value < 1e-14 || value >= 1.0) throw InputError(option, value_text(value), "must lie in [1e-14, 1)");
}
// A relative band, such as --constant-tolerance: strictly between 0 and 1.
inline void require_fraction(const std::string& option, double value) {
  if (!std::isfinite(value) || value <= 0.0 || value >= 1.0) throw InputError(option, value_text(value), "must lie in (0, 1)");
}
// An optional value as JSON: null when unset.
template <class Optional>
nlohmann::json optional_json(const Optional& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

}  // namespace dlpverify
