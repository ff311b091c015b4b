// What a program outside dlpverify needs to set itself up for a problem (the exchange file of
// docs/exchange.md): a capability (dlpverify/problem.hpp) the exchange uses.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

// A physical parameter: its name, SI value and unit ("1" when it has none).
struct Parameter {
  std::string name;    // as the exchange file names it
  double value = 0.0;  // in SI units
  std::string unit;    // SI, "1" when dimensionless
};

// Which problem it is, every physical parameter, the settings that are words rather than numbers
// — the active terms ("drag" = "constant" | "reynolds" | "off", "gravity" = "on" | "off", …) —
// and what each member carries besides its fields (a gas parcel's J_min), one value per member.
struct ProblemDescription {
  std::string problem;  // "dlp", "gas", …
  std::vector<Parameter> parameters;
  std::vector<std::pair<std::string, std::string>> settings;  // (name, value)
  std::vector<std::pair<Field, Eigen::ArrayXd>> member_data;
};

class ExchangeDescription : public Capability {
 public:
  // The description of the whole population (member_data has one row per member).
  virtual ProblemDescription description() const = 0;
};

// ExchangeDescription of `problem`, or by default: "problem", the numbers of CaseReport's
// parameters without units, and its strings as settings.
ProblemDescription problem_description(const Problem& problem);

}  // namespace dlpverify
