// Reading result JSON for figures: a missing or mistyped member is the user's input error (a
// file of the wrong kind), named with where it was looked for.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"

namespace dlpverify::plot {

inline const nlohmann::json& member(const nlohmann::json& j, const std::string& key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw InputError(where + ": no \"" + key + "\"");
  return j.at(key);
}

// A number, or NaN for null, a missing member or anything else (the reports write null for NaN).
inline double number_or_nan(const nlohmann::json& j, const std::string& key) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_number()) return std::numeric_limits<double>::quiet_NaN();
  return j.at(key).get<double>();
}

inline std::string string_or(const nlohmann::json& j, const std::string& key, const std::string& fallback) {
  if (!j.is_object() || !j.contains(key) || !j.at(key).is_string()) return fallback;
  return j.at(key).get<std::string>();
}

}  // namespace dlpverify::plot
