/// @file
/// What a program outside dlpverify needs to set itself up for a problem: the description the
/// exchange file of an `exec:` integrator carries (docs/exchange.md). A capability (problem.hpp):
/// without it the description is the problem's name and the numbers of its CaseReport.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// A physical parameter: its name, SI value and unit ("1" when it has none).
struct Parameter {
  std::string name;    ///< as the exchange file names it
  double value = 0.0;  ///< in SI units
  std::string unit;    ///< SI, "1" when dimensionless
};

/// Which problem it is, every physical parameter, the settings that are words rather than numbers
/// — the active terms ("drag" = "constant" | "reynolds" | "off", "gravity" = "on" | "off", …) —
/// and what each member carries besides its fields (a gas parcel's J_min), one value per member.
struct ProblemDescription {
  std::string problem;                ///< "dlp", "gas", …
  std::vector<Parameter> parameters;  ///< every physical parameter
  std::vector<std::pair<std::string, std::string>> settings;  ///< (name, value)
  std::vector<std::pair<Field, Eigen::ArrayXd>> member_data;  ///< per member, beside the fields
};

/// The description of a problem for a program outside dlpverify.
class ExchangeDescription : public Capability {
 public:
  /// The description of the whole population (member_data has one row per member).
  virtual ProblemDescription description() const = 0;
};

}  // namespace dlpverify
