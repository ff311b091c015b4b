// Reading members of result JSON written by another run, perhaps another version, perhaps not
// ours: a member that must be there is an InputError when missing (a file of another kind); an
// optional one takes its fallback when missing, null (the reports write null for NaN) or of
// another type. The counterpart of number_or_null in io/format.hpp.
#pragma once

#include <cmath>
#include <string>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"

namespace dlpverify {

// `where` names the place in the input: "study 2".
inline const nlohmann::json& required_member(const nlohmann::json& j, const std::string& key,
                                             const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw InputError(where + ": no \"" + key + "\"");
  return j.at(key);
}

// T: nlohmann::json (any type), std::string, bool, an integer or a floating-point type.
template <class T>
T member_or(const nlohmann::json& j, const std::string& key, T fallback) {
  if (!j.is_object() || !j.contains(key) || j.at(key).is_null()) return fallback;
  const nlohmann::json& v = j.at(key);
  const bool fits = std::is_same_v<T, nlohmann::json> ? true
                    : std::is_same_v<T, std::string>  ? v.is_string()
                    : std::is_same_v<T, bool>         ? v.is_boolean()
                    : std::is_integral_v<T>           ? v.is_number_integer()
                                                      : v.is_number();
  return fits ? v.get<T>() : fallback;
}

inline double number_or_nan(const nlohmann::json& j, const std::string& key) { return member_or(j, key, std::nan("")); }

}  // namespace dlpverify
