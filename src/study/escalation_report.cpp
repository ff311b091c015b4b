#include "study/escalation_report.hpp"

#include "dlpverify/precision.hpp"
#include "io/format.hpp"

namespace dlpverify {

std::string format_escalation(const Escalation& escalation, const StudyResult& study) {
  const bool finer = escalation.means == Escalation::Means::finer_levels;
  // A search of finer levels ran first when the first study's levels reached no floor.
  const bool above_floors = finer || escalation.searched_levels > 0;
  std::string text = "escalation: the check could not decide over " + std::to_string(escalation.double_levels) +
                     (above_floors ? " levels, none at the round-off floor or the reference's accuracy:\n"
                            : " levels in double, some at the round-off floor or the reference's accuracy:\n");
  for (const std::string& line : escalation.double_findings) text += "  " + line + "\n";
  if (escalation.searched_levels > 0)
    text += "  a level search went on to finer levels in double, " + std::to_string(escalation.searched_levels) +
            " levels in " + printf_string("%.1f", escalation.searched_seconds) + " s, and reached a floor undecided\n";
  if (!escalation.ran) return text + "  nothing the tool controls can go further: " + escalation.not_possible + "\n";
  text += finer ? std::string("  so a level search went on to finer levels in the same arithmetic, ")
                : std::string("  so the study ran again in extended precision (double-double, against the extended reference), ");
  text += std::to_string(escalation.levels) + " levels from dt = " + shortest_text(study.plan.coarsest_dt) + " in " +
          printf_string("%.1f", escalation.seconds) + " s";
  if (escalation.budget_spent) text += ", until its budget was spent";
  return text + "; what follows is that study\n";
}

nlohmann::json to_json(const Escalation& escalation, const StudyResult& study) {
  nlohmann::json j{{"ran", escalation.ran},
                   {"double_findings", escalation.double_findings},
                   {"double_levels", escalation.double_levels}};
  if (escalation.ran) {
    j.update({{"means", escalation.means == Escalation::Means::finer_levels ? "finer-levels" : "extended-precision"},
              {"precision", to_string(study.plan.precision)}, {"levels", escalation.levels}, {"seconds", escalation.seconds},
              {"budget_spent", escalation.budget_spent}});
  } else {
    j.update({{"not_possible", escalation.not_possible}, {"budget_spent", escalation.budget_spent}});
  }
  if (escalation.searched_levels > 0)
    j.update({{"searched_levels", escalation.searched_levels}, {"searched_seconds", escalation.searched_seconds}});
  return j;
}

}  // namespace dlpverify
