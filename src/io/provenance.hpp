// Where a result came from: build, libraries, host, threads, date and the command line.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace dlpverify {

nlohmann::json provenance(const std::string& command_line);
std::string version_line();  // "dlpverify 0.1.0 (commit …, SUNDIALS …, Eigen …, GSL …)"

// The `# …` header of a CSV result: what was run (`what`), the provenance and every option, so a
// CSV alone says where it came from.
std::string csv_header(const std::string& what, const nlohmann::json& provenance, const nlohmann::json& options);

}  // namespace dlpverify
