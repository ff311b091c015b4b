// Figures of results (issue 5), drawn by gnuplot (Debian's gnuplot-nox) through gnuplot-iostream,
// headless: the format follows the output's extension — .png (pngcairo), .svg, .pdf (pdfcairo).
//
//   plot_convergence     error against Δt, log–log, from `converge`/`check` JSON
//   plot_work_precision  error against RHS evaluations and wall time, from `precision` JSON
//   plot_error_vs_xi     each particle's finest-level error against ξ, from the per-particle CSV
//   plot_error_history   L2 error against time at the finest level, from the history CSV
//
// Every figure is written whole or not at all (a temporary file beside the target, renamed when
// gnuplot succeeded). Bad input — an unknown extension, a result that is not of the kind asked,
// a malformed CSV — throws InputError before anything is written; gnuplot's own failure throws
// SolverError with its message in one line.
//
// No text from the results or the options — titles, case, integrator and method names, file
// names — ever becomes a gnuplot command: it reaches gnuplot as data (plot/gnuplot_script.hpp
// says how), so a title such as  x"; system("rm -rf ~"); print "  is drawn, not run.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dlpverify {

struct PlotOptions {
  std::string output;            // the figure file: .png, .svg or .pdf
  std::string title;             // empty: built from the results (case · integrator · particles)
  std::string option;  // the option that named `output`, for error messages (the command names it)
  // plot_convergence: relative L2 errors ‖e‖₂/‖y‖₂ (one dimensionless axis) instead of absolute
  // L2 errors with each norm's unit in the legend.
  bool relative_error = false;
  // plot_error_vs_xi / plot_error_history: legend names of the inputs, in order (default: each
  // file's name without its folder and extension).
  std::vector<std::string> labels;
};

// Throws InputError (naming `option`) unless `path` can be a figure: a .png, .svg or .pdf in a
// folder that exists or can be made. Nothing is created. For checking --plot before a long study.
void check_plot_path(const std::string& option, const std::string& path);

// Error against Δt, log–log, from converge/check JSON (report.hpp to_json).
// One study: one panel, one colour per measured variable (position, velocity, temperature, mass):
// the levels' l2_<variable> as points whose shape gives the level's status (● ok and fitted,
// ○ ok but not fitted, □ round-off, × unstable — on the top edge when off scale or NaN, ▽ an
// error of exactly 0 on the bottom edge), the least-squares line over fitted_order.levels_used
// with "position [m]: p = 2.04 [2.01, 2.07]" (order and 95% interval) in the legend, and a slope
// triangle of the expected order (check.expected_order, else integrator_order) labelled
// "slope 2" under the finest fitted level. Units: the y axis says "L2 error [m, m/s]" and each
// legend entry names its unit (PlotOptions::relative_error: one dimensionless axis).
// Several studies (an overlay: Euler, RK2, RK4, CVODE …): one panel per variable, one colour per
// study, its integrator (disambiguated by case when repeated) in the legend, a triangle each.
void plot_convergence(const std::vector<nlohmann::json>& studies, const PlotOptions& options);

// From precision JSON (work_precision.hpp to_json): two panels side by side — relative L2 error
// against RHS evaluations (left) and against wall time (right), log–log — one colour per method
// (adams, bdf, rk2 …; per method and result when several results are given), position as solid
// lines with ●, velocity dashed with ○; runs whose error is limited by the reference ringed.
void plot_work_precision(const std::vector<nlohmann::json>& precision_results, const PlotOptions& options);

// "Where the error lives": each particle's error at the finest level against ξ, log y, from CSV
// files with the header particle,xi,err_position,err_velocity[,err_temperature][,err_mass].
// One file: one panel, one colour per variable. Several: one panel per variable, one colour per
// file. Past 40 000 particles a file is thinned (every k-th particle, plus each ξ bin's smallest
// and largest error), and a note under the axes says so.
void plot_error_vs_xi(const std::vector<std::string>& per_particle_csv, const PlotOptions& options);

// L2 error against time at the finest level, log y, from CSV files with the header
// t,l2_position,l2_velocity[,l2_temperature][,l2_mass]. Panels and colours as plot_error_vs_xi.
void plot_error_history(const std::vector<std::string>& history_csv, const PlotOptions& options);

}  // namespace dlpverify
