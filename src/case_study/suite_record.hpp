// A suite's study as one JSON object: a line of the suite's journal, which reads back as the study
// ended (every finite double exactly, as JSON numbers are written to round-trip; a NaN as null),
// and an element of the suite's --json result.
//
//   {"name": "drag-rk2", "file": "verification/drag-rk2.toml", "exit_code": 0, "error": "",
//    "seconds": 0.04,
//    "outcome": {"exit_code": 0, "console": …, "table": …, "study": "drag-rk2", "seconds": 0.04,
//                "verdicts": [{"variable": "position", "result": "pass", "expected": 2,
//                              "fit": {"valid": true, "value": 2.003, "stderr": …, "ci_low": …,
//                                      "ci_high": …, "levels": [0, 1, 2, 3, 4]},
//                              "tolerance": 0.1, "constant": {"valid": true, "order": 2,
//                                      "value": …, "log_stderr": …, "ci_low": …, "ci_high": …,
//                                      "levels": [0, 1, 2, 3, 4]},
//                              "finding": "pass, fitted order …", "quantity": "order"}, …],
//                "report": the study's JSON result}}        (no "outcome": it ended without a verdict)
#pragma once

#include <nlohmann/json.hpp>

#include "case_study/suite.hpp"

namespace dlpverify::case_study {

nlohmann::json suite_study_json(const SuiteStudy& study);
// Its inverse; std::invalid_argument or nlohmann::json's exceptions when `record` is not one.
SuiteStudy suite_study_from_json(const nlohmann::json& record);

}  // namespace dlpverify::case_study
