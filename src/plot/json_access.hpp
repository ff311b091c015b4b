// Reading result JSON for figures: a missing member that the figure needs is the user's input
// error (a file of the wrong kind), named with where it was looked for; anything optional that
// is missing or of another type takes its fallback.
#pragma once

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "io/errors.hpp"

namespace dlpverify::plot {

inline const nlohmann::json& member(const nlohmann::json& j, const std::string& key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw InputError(where + ": no \"" + key + "\"");
  return j.at(key);
}

// NaN stands for null too: the reports write null for NaN.
inline double number_or_nan(const nlohmann::json& j, const std::string& key) {
  return j.is_object() && j.contains(key) && j.at(key).is_number() ? j.at(key).get<double>() : std::nan("");
}

inline long long integer_or(const nlohmann::json& j, const std::string& key, long long fallback) {
  return j.is_object() && j.contains(key) && j.at(key).is_number_integer() ? j.at(key).get<long long>() : fallback;
}

inline std::string string_or(const nlohmann::json& j, const std::string& key, const std::string& fallback) {
  return j.is_object() && j.contains(key) && j.at(key).is_string() ? j.at(key).get<std::string>() : fallback;
}

inline bool flag(const nlohmann::json& j, const std::string& key) {
  return j.is_object() && j.contains(key) && j.at(key).is_boolean() && j.at(key).get<bool>();
}

}  // namespace dlpverify::plot
