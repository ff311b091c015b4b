// Where a result came from: build, libraries, host, threads, date and the command line.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace dlpverify {

nlohmann::json provenance(const std::string& command_line);
std::string version_line();  // "dlpverify 0.1.0 (commit …, SUNDIALS …, Eigen …, GSL …)"

}  // namespace dlpverify
