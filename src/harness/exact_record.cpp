#include "harness/exact_record.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace dlpverify {

std::string exact_text(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

double exact_number(const std::string& text) {
  if (text.empty()) throw std::invalid_argument("an empty number");
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  // ERANGE on a subnormal is not an error: "%a" of a subnormal reads back exactly.
  if (end != text.c_str() + text.size()) throw std::invalid_argument("'" + text + "' is not a number");
  return value;
}

namespace {

const nlohmann::json& member(const nlohmann::json& object, const std::string& key) {
  if (!object.is_object() || !object.contains(key)) throw std::invalid_argument("no '" + key + "'");
  return object.at(key);
}

double exact_member(const nlohmann::json& object, const std::string& key) {
  const nlohmann::json& value = member(object, key);
  if (!value.is_string()) throw std::invalid_argument("'" + key + "' is not a hexadecimal number string");
  try {
    return exact_number(value.get<std::string>());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("'" + key + "': " + e.what());
  }
}

nlohmann::json optional_exact(const std::optional<double>& value) {
  return value ? nlohmann::json(exact_text(*value)) : nlohmann::json();
}

std::optional<double> optional_member(const nlohmann::json& object, const std::string& key) {
  return member(object, key).is_null() ? std::nullopt : std::optional<double>(exact_member(object, key));
}

nlohmann::json norms_record(const ErrorNorms& n) {
  return {{"l2", exact_text(n.l2)},
          {"rms", exact_text(n.rms)},
          {"relative", exact_text(n.relative)},
          {"max", exact_text(n.max)},
          {"solution_l2", exact_text(n.reference_l2)}};
}

ErrorNorms norms_from_record(const nlohmann::json& r) {
  ErrorNorms n;
  n.l2 = exact_member(r, "l2");
  n.rms = exact_member(r, "rms");
  n.relative = exact_member(r, "relative");
  n.max = exact_member(r, "max");
  n.reference_l2 = exact_member(r, "solution_l2");
  return n;
}

long integer_member(const nlohmann::json& object, const std::string& key) {
  const nlohmann::json& value = member(object, key);
  if (!value.is_number_integer()) throw std::invalid_argument("'" + key + "' is not an integer");
  return value.get<long>();
}

SolverStatistics statistics_member(const nlohmann::json& record) {
  const nlohmann::json& statistics = member(record, "solver_statistics");
  if (!statistics.is_object()) throw std::invalid_argument("'solver_statistics' is not an object");
  return statistics.get<SolverStatistics>();
}

}  // namespace

nlohmann::json level_record(const LevelResult& level, const std::vector<Variable>& variables) {
  nlohmann::json by_variable = nlohmann::json::object();
  for (std::size_t v = 0; v < variables.size(); ++v) {
    nlohmann::json r = norms_record(level.norms.at(v));
    r["self_difference"] = optional_exact(level.self_difference.at(v));
    by_variable[variables[v].name] = r;
  }
  return {{"level", level.level},
          {"steps", level.steps},
          {"dt", exact_text(level.dt)},
          {"wall_s", exact_text(level.wall_seconds)},
          {"variables", by_variable},
          {"solver_statistics", level.solver_statistics}};
}

LevelResult level_from_record(const nlohmann::json& record, const std::vector<Variable>& variables) {
  LevelResult level;
  level.level = static_cast<int>(integer_member(record, "level"));
  level.steps = integer_member(record, "steps");
  level.dt = exact_member(record, "dt");
  level.wall_seconds = exact_member(record, "wall_s");
  const nlohmann::json& by_variable = member(record, "variables");
  for (const Variable& variable : variables) {
    const nlohmann::json& r = member(by_variable, variable.name);
    level.norms.push_back(norms_from_record(r));
    level.self_difference.push_back(optional_member(r, "self_difference"));
  }
  level.solver_statistics = statistics_member(record);
  return level;
}

nlohmann::json run_record(const PrecisionRunResult& run, const std::vector<Variable>& variables) {
  nlohmann::json by_variable = nlohmann::json::object();
  for (std::size_t v = 0; v < variables.size(); ++v) by_variable[variables[v].name] = norms_record(run.norms.at(v));
  return {{"method", run.method},
          {"rtol", optional_exact(run.rtol)},
          {"dt", optional_exact(run.dt)},
          {"steps", run.steps},
          {"rhs_evals", run.rhs_evals},
          {"wall_s", exact_text(run.wall_seconds)},
          {"variables", by_variable},
          {"solver_statistics", run.solver_statistics}};
}

PrecisionRunResult run_from_record(const nlohmann::json& record, const std::vector<Variable>& variables) {
  PrecisionRunResult run;
  const nlohmann::json& method = member(record, "method");
  if (!method.is_string()) throw std::invalid_argument("'method' is not a string");
  run.method = method.get<std::string>();
  run.rtol = optional_member(record, "rtol");
  run.dt = optional_member(record, "dt");
  run.steps = integer_member(record, "steps");
  run.rhs_evals = integer_member(record, "rhs_evals");
  run.wall_seconds = exact_member(record, "wall_s");
  const nlohmann::json& by_variable = member(record, "variables");
  for (const Variable& variable : variables) run.norms.push_back(norms_from_record(member(by_variable, variable.name)));
  run.solver_statistics = statistics_member(record);
  return run;
}

}  // namespace dlpverify
