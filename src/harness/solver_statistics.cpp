#include "dlpverify/solver_statistics.hpp"

#include <array>
#include <stdexcept>
#include <utility>

namespace dlpverify {
namespace {

using Count = std::optional<long> SolverStatistics::*;

// The typed counts and the keys the reports write them under.
constexpr std::array<std::pair<const char*, Count>, 8> kCounts{{
    {"steps", &SolverStatistics::steps},
    {"rhs_evals", &SolverStatistics::rhs_evals},
    {"rhs_evals_jacobian", &SolverStatistics::rhs_evals_jacobian},
    {"error_test_failures", &SolverStatistics::error_test_failures},
    {"nonlinear_iterations", &SolverStatistics::nonlinear_iterations},
    {"nonlinear_convergence_failures", &SolverStatistics::nonlinear_convergence_failures},
    {"linear_solver_setups", &SolverStatistics::linear_solver_setups},
    {"linear_iterations", &SolverStatistics::linear_iterations},
}};

}  // namespace

bool SolverStatistics::empty() const {
  for (const auto& [key, count] : kCounts)
    if (this->*count) return false;
  return extras.empty();
}

std::optional<long> SolverStatistics::extra_count(const std::string& key) const {
  const auto found = extras.find(key);
  if (found == extras.end()) return std::nullopt;
  if (const long* value = std::get_if<long>(&found->second)) return *value;
  return std::nullopt;
}

std::optional<double> SolverStatistics::extra_real(const std::string& key) const {
  const auto found = extras.find(key);
  if (found == extras.end()) return std::nullopt;
  if (const double* value = std::get_if<double>(&found->second)) return *value;
  if (const long* value = std::get_if<long>(&found->second)) return static_cast<double>(*value);
  return std::nullopt;
}

SolverStatistics& SolverStatistics::operator+=(const SolverStatistics& other) {
  for (const auto& [key, count] : kCounts)
    if (other.*count) this->*count = (this->*count).value_or(0) + *(other.*count);
  return *this;
}

void to_json(nlohmann::json& j, const SolverStatistics& statistics) {
  j = nlohmann::json::object();
  for (const auto& [key, value] : statistics.extras) {
    if (std::holds_alternative<long>(value)) j[key] = std::get<long>(value);
    else if (std::holds_alternative<double>(value)) j[key] = std::get<double>(value);
    else if (std::holds_alternative<std::string>(value)) j[key] = std::get<std::string>(value);
    else j[key] = nullptr;
  }
  for (const auto& [key, count] : kCounts)
    if (statistics.*count) j[key] = *(statistics.*count);
}

void from_json(const nlohmann::json& j, SolverStatistics& statistics) {
  if (!j.is_object()) throw std::invalid_argument("solver statistics are not an object");
  statistics = SolverStatistics{};
  for (const auto& [key, value] : j.items()) {
    bool typed = false;
    for (const auto& [name, count] : kCounts) {
      if (key != name) continue;
      if (!value.is_number_integer())
        throw std::invalid_argument("solver statistic '" + key + "' is not an integer: " + value.dump());
      statistics.*count = value.get<long>();
      typed = true;
    }
    if (typed) continue;
    if (value.is_number_integer()) statistics.extras[key] = value.get<long>();
    else if (value.is_number_float()) statistics.extras[key] = value.get<double>();
    else if (value.is_string()) statistics.extras[key] = value.get<std::string>();
    else if (value.is_null()) statistics.extras[key] = std::monostate{};
    else throw std::invalid_argument("solver statistic '" + key + "' is neither a number, a word nor null: " + value.dump());
  }
}

}  // namespace dlpverify
