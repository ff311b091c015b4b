#include "io/result_units.hpp"

#include <array>
#include <utility>

namespace dlpverify {

namespace {

constexpr std::array<std::pair<const char*, const char*>, 5> kImplied = {
    {{"position", "m"}, {"velocity", "m/s"}, {"temperature", "K"}, {"mass", "kg"}, {"pressure", "Pa"}}};

}  // namespace

std::string implied_unit(const std::string& variable) {
  for (const auto& [name, unit] : kImplied)
    if (variable == name) return unit;
  return "";
}

const std::vector<std::string>& implied_variables() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& [name, unit] : kImplied) list.push_back(name);
    return list;
  }();
  return names;
}

bool dimensionless(const std::string& unit) { return unit.empty() || unit == "1"; }

std::string units_line(const std::vector<std::string>& units, const std::vector<std::string>& implied) {
  if (units == implied) return "";
  std::string line = "# units: ";
  for (std::size_t c = 0; c < units.size(); ++c) {
    if (c > 0) line += ',';
    for (char ch : units[c]) line += ch == ',' || ch == '\n' || ch == '\r' ? ' ' : ch;
  }
  return line + "\n";
}

}  // namespace dlpverify
