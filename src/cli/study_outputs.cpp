#include "cli/study_outputs.hpp"

#include "io/format.hpp"
#include "plot/plot.hpp"

namespace dlpverify::cli {

StudyReport study_report(const StudyDescription& description, const StudyResult& study,
                         const std::optional<CheckVerdict>& verdict) {
  return {format_table(description, study, verdict), to_json(description, study, verdict)};
}

void add_study_outputs(OutputSet& outputs, const OutputOptions& files, bool plot_relative,
                       const StudyDescription& description, const StudyResult& study, const StudyReport& report) {
  const nlohmann::json& result = report.result;
  if (wanted(files.plot_file))
    outputs.add(files.plot_file,
                plot_convergence({result}, PlotOptions{files.plot_file, files.title, "--plot", plot_relative, {}}));
  if (wanted(files.json_file)) outputs.add(files.json_file, json_text(result, 2) + "\n");
  if (wanted(files.csv_file)) outputs.add(files.csv_file, format_csv(description, study));
  if (wanted(files.table_file)) outputs.add(files.table_file, report.table);
}

}  // namespace dlpverify::cli
