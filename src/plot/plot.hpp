// Figures of results (issue 5), drawn headless by gnuplot (gnuplot-nox) through gnuplot-iostream,
// from results alone (JSON, CSV); the output's extension picks the format: .png, .svg or .pdf.
// Each plot_* function returns the drawn figure (empty for /dev/null) for the caller's OutputSet
// (io/atomic_file.hpp), which writes it together with the run's other outputs. Bad input (an
// unknown extension, a result of another kind, a malformed CSV) throws InputError before anything
// is written, gnuplot's failure SolverError. No text from results or options ever becomes a gnuplot command (gnuplot_script.hpp):
// a title such as  x"; system("rm -rf ~"); print "  is drawn, not run.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dlpverify {

struct PlotOptions {
  std::string output;             // the figure file: .png, .svg or .pdf
  std::string title;              // empty: built from the results (case · integrator · particles)
  std::string option;  // the option that named `output`, for error messages (the command names it)
  bool relative_error = false;    // plot_convergence: relative L2 errors ‖e‖₂/‖y‖₂, one axis, no unit
  // plot_error_vs_xi / plot_error_history: the inputs' legend names (default: their file names).
  std::vector<std::string> labels;
};

// Throws InputError (naming `option`) unless `path` can be a figure: a .png, .svg or .pdf in a
// folder that exists or can be made. Nothing is created: for checking --plot before a study.
void check_plot_path(const std::string& option, const std::string& path);

// Every figure draws the variables its inputs declare (a JSON's "variables" and "units", a CSV's
// columns and "# units:" line; io/result_units.hpp), in their order, and labels Δt and t with the
// inputs' unit of time ("Δt [s]"; "Δt" when dimensionless). Inputs without units draw with the
// units their variables' names imply, time in seconds.

// Error against Δt, log–log, from converge/check JSON. One study: one panel, a colour per variable,
// each level's point shaped by its status (● ok and fitted, ○ ok but not fitted, △ pre-asymptotic,
// ◇ reference-limited, □ round-off, × unstable, ✳ a status word the legend does not know, on the top edge when off scale or NaN, ▽ an error of exactly 0 on the bottom edge),
// the least-squares line over the fit's levels with "position [m]: p = 2.04 [2.01, 2.07]" (order,
// 95% interval) in the legend, a slope triangle of check.expected_order, else integrator_order.
// Several studies: a panel per variable, a colour and a triangle per study.
std::string plot_convergence(const std::vector<nlohmann::json>& studies, const PlotOptions& options);

// From precision JSON: relative L2 error against RHS evaluations (left) and wall time (right),
// log–log, a colour per method (and result), a line and point style per variable (the first
// solid with ●, the second dashed with ○, the third dotted with ■, …), runs whose error is
// limited by the reference ringed.
std::string plot_work_precision(const std::vector<nlohmann::json>& precision_results, const PlotOptions& options);

// From the JSON of a study by --tolerances: relative L2 error against rtol, log–log, a colour per
// variable with its fitted exponent in the legend and the dashed line error = rtol (left), and
// the work each run reported (right-hand-side evaluations, steps, rejected steps) against rtol
// (right).
std::string plot_tolerance(const nlohmann::json& study, const PlotOptions& options);

// Each particle's error at the finest level against ξ, log y, from CSV files with the header
// particle,xi,err_<variable>… (the cloud: err_position,err_velocity[,…]). One file: one panel, a
// colour per variable; several: a panel per variable, a colour per file. Past 40 000 particles a
// file is thinned (every k-th particle and each ξ bin's extremes), and a note says so.
std::string plot_error_vs_xi(const std::vector<std::string>& per_particle_csv, const PlotOptions& options);

// L2 error against time at the finest level, log y, from CSV files with the header
// t,l2_<variable>…[,ref_l2_<variable>…]. Panels and colours as plot_error_vs_xi.
std::string plot_error_history(const std::vector<std::string>& history_csv, const PlotOptions& options);

}  // namespace dlpverify
