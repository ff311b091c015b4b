// The level search as the console and the JSON report show it.
#include <sstream>

#include "dlpverify/level_search.hpp"
#include "io/format.hpp"

namespace dlpverify {

std::string format_level_search(const LevelSearch& search, const StudyResult& study) {
  std::ostringstream out;
  out << printf_string("levels found by search (target: order interval ±%.3g over %d asymptotic levels; budget %.3g s)\n",
                       search.rules.order_half_width, search.rules.min_fit_levels, search.rules.budget_seconds);
  for (const SearchedLevel& level : search.run)
    out << printf_string("  dt %10.3e %9ld steps  ", level.dt, level.steps)
        << (level.kept ? "kept" : "set aside: " + level.note) << "\n";
  for (const std::string& line : search.tightenings) out << "  reference tightened " << line << "\n";
  for (const std::string& line : search.settled) out << "  " << line << "\n";
  out << "  stopped (" << to_string(search.stop) << "): " << search.reason << "\n";
  for (std::size_t v = 0; v < search.extrapolations.size() && v < study.plan.variables.size(); ++v)
    if (search.extrapolations[v])
      out << "  " << study.plan.variables[v].name << ": " << describe(*search.extrapolations[v]) << "\n";
  return out.str();
}

nlohmann::json to_json(const LevelSearch& search, const StudyResult& study) {
  nlohmann::json run = nlohmann::json::array();
  for (const SearchedLevel& level : search.run)
    run.push_back({{"dt", level.dt}, {"steps", level.steps}, {"kept", level.kept}, {"note", level.note}});
  nlohmann::json used = nlohmann::json::object(), settled = nlohmann::json::object(),
                 extrapolated = nlohmann::json::object();
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    used[study.plan.variables[v].name] = study.orders[v].fit.levels;
    if (v < search.settled.size()) settled[study.plan.variables[v].name] = search.settled[v];
    if (v < search.extrapolations.size() && search.extrapolations[v])
      extrapolated[study.plan.variables[v].name] = to_json(*search.extrapolations[v]);
  }
  return {{"target_half_width", search.rules.order_half_width},
          {"min_fit_levels", search.rules.min_fit_levels},
          {"budget_seconds", search.rules.budget_seconds},
          {"run", run},
          {"levels_used", used},
          {"stop", to_string(search.stop)},
          {"reason", search.reason},
          {"settled", settled},
          {"reference_tightenings", search.tightenings},
          {"extrapolated_order", extrapolated}};
}

}  // namespace dlpverify
