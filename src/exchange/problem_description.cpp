#include "exchange/problem_description.hpp"

#include "dlpverify/case_report.hpp"

namespace dlpverify {

ProblemDescription problem_description(const Problem& problem) {
  if (const ExchangeDescription* own = problem.capability<ExchangeDescription>()) return own->description();
  ProblemDescription d{"problem", {}, {}, {}};
  const nlohmann::json parameters = case_parameters(problem);
  for (const auto& [key, value] : parameters.items()) {
    if (value.is_number()) d.parameters.push_back({key, value.get<double>(), ""});
    if (value.is_string()) d.settings.emplace_back(key, value.get<std::string>());
  }
  return d;
}

}  // namespace dlpverify
