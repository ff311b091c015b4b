// Small formatting helpers shared by the reports and the command line.
#pragma once

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dlpverify {

// snprintf into a std::string (up to 511 characters).
template <class... Args>
std::string printf_string(const char* format, Args... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

// printf appended to `text`, whatever its length (a report built line by line).
[[gnu::format(printf, 2, 3)]] inline void appendf(std::string& text, const char* format, ...) {
  va_list args, measure;
  va_start(args, format);
  va_copy(measure, args);
  const int length = std::vsnprintf(nullptr, 0, format, measure);
  va_end(measure);
  if (length > 0) {
    const std::size_t at = text.size();
    text.resize(at + static_cast<std::size_t>(length) + 1);
    std::vsnprintf(text.data() + at, static_cast<std::size_t>(length) + 1, format, args);
    text.resize(at + static_cast<std::size_t>(length));
  }
  va_end(args);
}

// A number as a user would type it back (15 significant digits), for messages naming a value.
inline std::string value_text(double value) {
  std::ostringstream out;
  out.precision(15);
  out << value;
  return out.str();
}

// A computed value exactly, as the shortest %g text that reads back to the same double: "0.0005",
// where %.17g prints 0.00050000000000000001 (and the shortest of all, std::to_chars's, 5e-04).
inline std::string shortest_text(double value) {
  char text[32];
  for (int digits = 1; digits < 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) return text;
  }
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// Level numbers as the reports list them: "0,1,2".
inline std::string levels_text(const std::vector<int>& levels) {
  std::string text;
  for (int level : levels) {
    if (!text.empty()) text += ',';
    text += std::to_string(level);
  }
  return text;
}

// JSON text of j. User text in it (file names are bytes on Linux, titles anything) may not be
// UTF-8, which JSON requires: such bytes become U+FFFD instead of failing the output at the end.
inline std::string json_text(const nlohmann::json& j, int indent = -1) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

// JSON has no NaN or infinity: those become null.
inline nlohmann::json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}
inline nlohmann::json optional_or_null(const std::optional<double>& value) {
  return value && std::isfinite(*value) ? nlohmann::json(*value) : nlohmann::json();
}

}  // namespace dlpverify
