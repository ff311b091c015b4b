// A finished level of a convergence study, or run of a work-precision sweep, as one JSON object
// that reads back bit for bit (a study's journal, docs/cli.md, "The journal and --resume"): every double is written as a C99 hexadecimal float ("0x1.4p-3",
// "inf", "-inf", "nan"), which strtod reads back exactly, so neither decimal rounding nor JSON's
// want of NaN and infinity can change a resumed study. The solver's statistics are written in their
// JSON form (SolverStatistics: counts, names and finite step sizes, which nlohmann-json writes so that they read back unchanged).
//
//   {"level": 2, "steps": 80, "dt": "0x1.0624dd2f1a9fcp-13", "wall_s": "0x1.8p-4",
//    "variables": {"position": {"l2": …, "rms": …, "relative": …, "max": …, "solution_l2": …,
//                               "self_difference": … | null}, …},
//    "solver_statistics": {…}}
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/study.hpp"
#include "dlpverify/work_precision.hpp"

namespace dlpverify {

std::string exact_text(double value);         // "%a": hexadecimal, exact
double exact_number(const std::string& text);  // its inverse; std::invalid_argument if not a number

nlohmann::json level_record(const LevelResult& level, const std::vector<Variable>& variables);

// The level back from its record, for the plan's `variables` (which the record must hold, every
// one). Throws std::invalid_argument naming what is missing or malformed.
LevelResult level_from_record(const nlohmann::json& record, const std::vector<Variable>& variables);

// A work-precision run: method, rtol and dt (null when not set), steps, rhs_evals, wall_s, the
// norms per variable and the solver's statistics; its reference margins are judged on reading.
nlohmann::json run_record(const PrecisionRunResult& run, const std::vector<Variable>& variables);
PrecisionRunResult run_from_record(const nlohmann::json& record, const std::vector<Variable>& variables);

}  // namespace dlpverify
