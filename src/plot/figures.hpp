// The figure kinds of plot.hpp as data, from results already read: each plot_* function there is
// one of these followed by draw(). Nothing here runs gnuplot or touches a file, so results can be
// read and figures built from bytes in memory (tests/fuzz). Bad input throws InputError.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/csv_table.hpp"
#include "plot/figure.hpp"
#include "plot/plot.hpp"

namespace dlpverify::plot {

Figure convergence_figure(const std::vector<nlohmann::json>& studies, const PlotOptions& options);
Figure work_precision_figure(const std::vector<nlohmann::json>& results, const PlotOptions& options);
// Tables as read by the functions below; without options.labels each is named by its path's stem.
Figure error_vs_xi_figure(const std::vector<CsvTable>& tables, const PlotOptions& options);
Figure error_history_figure(const std::vector<CsvTable>& tables, const PlotOptions& options);

// A --per-particle or --history CSV with the columns plot.hpp names; `path` names it in errors.
CsvTable read_per_particle_csv(std::istream& in, const std::string& path);
CsvTable read_history_csv(std::istream& in, const std::string& path);

}  // namespace dlpverify::plot
