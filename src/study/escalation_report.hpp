// How the report shows an escalation (study/escalation.hpp): a paragraph before the table of the
// study it ended on, and an "escalation" object in the JSON result.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "dlpverify/study_request.hpp"

namespace dlpverify {

// "escalation: …": what the first study could not decide and what was done, or why nothing could
// be; `study` is the one the report shows.
std::string format_escalation(const Escalation& escalation, const StudyResult& study);

// {"ran", "not_possible", "double_findings", "double_levels", "means", "precision", "levels",
// "seconds", "budget_spent"}; `study` is the one the report shows.
nlohmann::json to_json(const Escalation& escalation, const StudyResult& study);

}  // namespace dlpverify
