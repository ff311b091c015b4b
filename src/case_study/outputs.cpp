#include "case_study/outputs.hpp"

#include "io/format.hpp"
#include "plot/plot.hpp"

namespace dlpverify::case_study {

void add_study_outputs(OutputSet& outputs, const OutputOptions& files, bool plot_relative,
                       const StudyDescription& description, const StudyResult& study, const nlohmann::json& result,
                       const std::string& table) {
  if (wanted(files.plot_file))
    outputs.add(files.plot_file,
                plot_convergence({result}, PlotOptions{files.plot_file, files.title, "--plot", plot_relative, {}}));
  if (wanted(files.json_file)) outputs.add(files.json_file, json_text(result, 2) + "\n");
  if (wanted(files.csv_file)) outputs.add(files.csv_file, format_csv(description, study));
  if (wanted(files.table_file)) outputs.add(files.table_file, table);
}

}  // namespace dlpverify::case_study
