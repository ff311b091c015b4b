#include "exchange/run_set.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>

#include "dlpverify/errors.hpp"
#include "dlpverify/study.hpp"
#include "exchange/command_template.hpp"
#include "exchange/exchange_file.hpp"
#include "io/csv_table.hpp"
#include "io/format.hpp"
#include "io/input_file.hpp"

namespace dlpverify::exchange {

namespace {

// One file as read, before the runs are compared.
struct RunFile {
  std::string path;
  std::vector<Field> fields;  // without the id column
  State state;                // members × fields
  std::optional<Eigen::ArrayXd> ids;
  std::optional<double> t0, t_end;  // the end time t_end, not the duration
  std::optional<long> steps;
};

InputError run_error(const std::string& what, const std::string& path, const std::string& reason) {
  return InputError(what, path, reason);
}

RunFile read_hdf5(const std::string& path, const std::string& what) {
  ExchangeRun run;
  try {
    run = read_exchange_run(path);
  } catch (const ExchangeError& e) {
    throw run_error(what, path, e.what());
  }
  // Each time and count this file carries is checked here, so a bad one is blamed on its own file.
  for (const auto& [name, value] : {std::pair{"t0", run.t0}, {"t_end", run.t_end}, {"dt", run.dt}})
    if (value && !std::isfinite(*value)) throw run_error(what, path, std::string(name) + " = " + value_text(*value) + ": must be finite");
  if (run.dt && !(*run.dt > 0.0)) throw run_error(what, path, "dt = " + value_text(*run.dt) + ": must be positive");
  if (run.steps && *run.steps < 1)
    throw run_error(what, path, "steps = " + std::to_string(*run.steps) + ": must be a whole number of at least 1");
  RunFile file{path, std::move(run.fields), std::move(run.state), std::move(run.ids), run.t0, run.t_end, run.steps};
  // steps, or the step dt it was run at: steps = (t_end − t0) / dt, whole by the rule of level_steps.
  if (!file.steps && run.dt && file.t_end) {
    StudyPlan one;
    one.t_end = *file.t_end - file.t0.value_or(0.0);
    one.coarsest_dt = *run.dt;
    one.levels = 1;
    try {
      file.steps = level_steps(one).front();
    } catch (const InputError& e) {
      throw run_error(what, path, "its dt = " + value_text(*run.dt) + ": " + e.reason());
    }
  }
  return file;
}

// A CSV run: the header names the fields (and `id`), a "# units:" line may give their units.
RunFile read_csv(const std::string& path, const std::string& what) {
  std::ifstream in = open_input_stream(what, path, input_limit::run);
  CsvTable table;
  try {
    table = read_prefixed_csv_table(in, path, {}, {""});  // any names, each once
  } catch (const InputError& e) {
    throw run_error(what, path, e.what());
  }
  RunFile file;
  file.path = path;
  const auto rows = static_cast<Eigen::Index>(table.rows());
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const Eigen::Map<const Eigen::ArrayXd> column(table.values[c].data(), rows);
    for (Eigen::Index p = 0; p < rows; ++p)
      if (!std::isfinite(column[p]))
        throw run_error(what, path, "column " + table.columns[c] + " has a non-finite value at member " + std::to_string(p));
    if (table.columns[c] == "id") {
      file.ids = column;
      continue;
    }
    file.fields.push_back({table.columns[c], table.units.empty() ? "1" : table.units[c]});
    file.state.conservativeResize(rows, file.state.cols() + 1);
    file.state.col(file.state.cols() - 1) = column;
  }
  if (file.fields.empty()) throw run_error(what, path, "has no field (only an id column)");
  if (rows == 0) throw run_error(what, path, "has no member (a header and no row)");
  return file;
}

RunFile read_file(const std::string& path, const std::string& what) {
  check_input_file(what, path, input_limit::run);  // a FIFO or a device is refused before HDF5 opens it
  return is_hdf5_file(path) ? read_hdf5(path, what) : read_csv(path, what);
}

std::string names(const std::vector<Field>& fields) {
  std::string text;
  for (const Field& f : fields) text += (text.empty() ? "" : ",") + f.name;
  return text;
}

// A run (or the reference) must have the first run's fields, members and end time.
void require_same(const RunFile& first, const RunFile& run, const std::string& what, double duration) {
  for (const Field& f : first.fields)
    if (std::none_of(run.fields.begin(), run.fields.end(), [&f](const Field& g) { return g.name == f.name; }))
      throw run_error(what, run.path, "has no field " + f.name + ", which " + first.path + " has");
  for (const Field& f : run.fields)
    if (std::none_of(first.fields.begin(), first.fields.end(), [&f](const Field& g) { return g.name == f.name; }))
      throw run_error(what, run.path, "has a field " + f.name + ", which " + first.path + " has not");
  if (run.state.rows() != first.state.rows())
    throw run_error(what, run.path, "has " + std::to_string(run.state.rows()) + " members, " + first.path + " has " +
                                        std::to_string(first.state.rows()));
  if (run.ids.has_value() != first.ids.has_value())
    throw run_error(what, run.path, std::string(run.ids ? "has" : "has no") + " id column, " + first.path +
                                        (first.ids ? " has one" : " has none"));
  if (run.t_end && first.t_end && std::abs(*run.t_end - *first.t_end) > 1e-9 * duration)
    throw run_error(what, run.path, "ends at t_end = " + exact_text(*run.t_end) + ", " + first.path + " at " +
                                        exact_text(*first.t_end));
  if (run.t0 && first.t0 && std::abs(*run.t0 - *first.t0) > 1e-9 * duration)
    throw run_error(what, run.path, "starts at t0 = " + exact_text(*run.t0) + ", " + first.path + " at " +
                                        exact_text(*first.t0));
}

// Row of each member of `order` (the first run's ids) in `ids`; every id once in each.
std::vector<Eigen::Index> rows_by_id(const Eigen::ArrayXd& order, const Eigen::ArrayXd& ids, const std::string& what,
                                     const std::string& path, const std::string& first_path) {
  std::map<double, Eigen::Index> row;
  for (Eigen::Index p = 0; p < ids.size(); ++p)
    if (!row.emplace(ids[p], p).second) throw run_error(what, path, "has the id " + value_text(ids[p]) + " twice");
  std::vector<Eigen::Index> rows;
  for (Eigen::Index p = 0; p < order.size(); ++p) {
    const auto it = row.find(order[p]);
    if (it == row.end())
      throw run_error(what, path, "has no member of id " + value_text(order[p]) + ", which " + first_path + " has");
    rows.push_back(it->second);
  }
  return rows;
}

// The variables over the first run's fields: the user's, or each field its own.
std::vector<VariableSpec> resolve_variables(const RunFile& first, std::vector<VariableSpec> specs) {
  if (specs.empty())
    for (const Field& f : first.fields) specs.push_back({f.name, {f.name}, f.unit});
  for (std::size_t i = 0; i < specs.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (specs[i].name == specs[j].name)
        throw InputError("variable " + specs[i].name, specs[i].name, "is given twice (each names its own columns in the results)");
  for (VariableSpec& spec : specs) {
    std::string unit;
    for (const std::string& name : spec.fields) {
      const auto f = std::find_if(first.fields.begin(), first.fields.end(), [&name](const Field& g) { return g.name == name; });
      if (f == first.fields.end())
        throw InputError("variable " + spec.name, name, "is not a field of " + first.path + " (" + names(first.fields) + ")");
      if (!unit.empty() && f->unit != unit && spec.unit.empty())
        throw InputError("variable " + spec.name, name, "has the unit " + f->unit + ", another field of it " + unit +
                                                            "; give the variable's unit");
      unit = f->unit;
    }
    if (spec.unit.empty()) spec.unit = unit;
  }
  return specs;
}

// The measured columns: the variables' fields in order, members in `rows` order (empty: as stored).
State measured(const RunFile& run, const std::vector<VariableSpec>& specs, const std::vector<Eigen::Index>& rows) {
  Eigen::Index columns = 0;
  for (const VariableSpec& spec : specs) columns += static_cast<Eigen::Index>(spec.fields.size());
  State state(run.state.rows(), columns);
  Eigen::Index c = 0;
  for (const VariableSpec& spec : specs)
    for (const std::string& name : spec.fields) {
      const auto f = std::find_if(run.fields.begin(), run.fields.end(), [&name](const Field& g) { return g.name == name; });
      const auto column = run.state.col(f - run.fields.begin());
      for (Eigen::Index p = 0; p < state.rows(); ++p) state(p, c) = column[rows.empty() ? p : rows[static_cast<std::size_t>(p)]];
      ++c;
    }
  return state;
}

// The steps of each run: from the files (HDF5), or t_end / dt of --dt (CSV).
void fill_steps(std::vector<RunFile>& files, const RunRequest& request, double& duration) {
  const bool all_csv = std::all_of(files.begin(), files.end(), [](const RunFile& f) { return !f.t_end; });
  if (!request.dt.empty()) {
    if (!all_csv) throw InputError("time steps", value_text(request.dt.front()), "are for CSV runs; an HDF5 run carries its own steps");
    if (request.dt.size() != files.size())
      throw InputError("time steps", std::to_string(request.dt.size()) + " steps",
                       "must give one step per run (" + std::to_string(files.size()) + " runs)");
    if (!request.duration) throw InputError("duration", "(none)", "CSV runs need the duration they cover");
    duration = *request.duration;
    for (std::size_t i = 0; i < files.size(); ++i) {
      StudyPlan one;
      one.t_end = duration;
      one.coarsest_dt = request.dt[i];
      one.levels = 1;
      files[i].steps = level_steps(one).front();
    }
    return;
  }
  for (const RunFile& f : files) {
    if (!f.t_end)
      throw InputError("duration", "(none)", "run " + f.path + " carries no end time t_end; a CSV run needs the duration and its time steps given");
    if (!f.steps) throw InputError("run", f.path, "carries neither steps nor dt");
  }
  if (request.duration) throw InputError("duration", value_text(*request.duration), "is for CSV runs; an HDF5 run carries its own times");
  duration = *files.front().t_end - files.front().t0.value_or(0.0);
  if (!(duration > 0.0)) throw InputError("run", files.front().path, "ends at or before it starts (t_end - t0 = " + value_text(duration) + ")");
}

// Coarsest first, and one ratio r between neighbours: n_k = n_0 r^k whole (level_steps' rule).
void check_refinement(const std::vector<RunFile>& files, double duration) {
  if (files.size() < 2) throw InputError("runs", std::to_string(files.size()), "at least two runs are needed for an order");
  StudyPlan plan;
  plan.t_end = duration;
  plan.levels = static_cast<int>(files.size());
  plan.coarsest_dt = duration / static_cast<double>(*files[0].steps);
  plan.ratio = static_cast<double>(*files[1].steps) / static_cast<double>(*files[0].steps);
  if (!(plan.ratio > 1.0))
    throw InputError("run", files[1].path, "takes " + std::to_string(*files[1].steps) + " steps, as many as " + files[0].path);
  const std::vector<long> steps = level_steps(plan);
  for (std::size_t k = 0; k < files.size(); ++k)
    if (steps[k] != *files[k].steps)
      throw InputError("run", files[k].path, "takes " + std::to_string(*files[k].steps) + " steps; the runs refine by r = " +
                                                 value_text(plan.ratio) + ", which gives " + std::to_string(steps[k]));
}

}  // namespace

RunSet read_runs(const RunRequest& request) {
  std::vector<RunFile> files;
  for (const std::string& path : request.paths) files.push_back(read_file(path, "run"));
  if (files.empty()) throw InputError("runs", "(none)", "give the run files");
  RunSet set;
  fill_steps(files, request, set.duration);
  // Coarsest first (fewest steps); the first run given decides the member order and the fields.
  const RunFile& first_given = files.front();
  for (std::size_t i = 1; i < files.size(); ++i) require_same(first_given, files[i], "run", set.duration);
  std::vector<std::size_t> order(files.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&files](std::size_t a, std::size_t b) { return *files[a].steps < *files[b].steps; });
  std::vector<RunFile> sorted;
  for (std::size_t i : order) sorted.push_back(std::move(files[i]));
  check_refinement(sorted, set.duration);

  // Without a reference each run is measured against the next finer one: one level fewer.
  if (request.reference.empty() && sorted.size() < 3)
    throw InputError("runs", std::to_string(sorted.size()), "without a reference at least three runs are needed");
  std::optional<RunFile> reference;
  if (!request.reference.empty()) {
    reference = read_file(request.reference, "reference");
    require_same(sorted.front(), *reference, "reference", set.duration);
  }
  std::optional<RunFile> check;
  if (!request.reference_check.empty()) {
    if (!reference) throw InputError("reference check", request.reference_check, "checks a reference run; none is given");
    check = read_file(request.reference_check, "reference check");
    require_same(sorted.front(), *check, "reference check", set.duration);
    if (reference->steps && check->steps && *check->steps != 2 * *reference->steps)
      throw InputError("reference check", check->path, "takes " + std::to_string(*check->steps) +
                                                             " steps, not twice the reference's " +
                                                             std::to_string(*reference->steps));
  }
  const RunFile& first = sorted.front();
  const std::vector<VariableSpec> specs = resolve_variables(first, request.variables);
  const auto rows = [&](const RunFile& run, const std::string& what) {
    return first.ids ? rows_by_id(*first.ids, *run.ids, what, run.path, first.path) : std::vector<Eigen::Index>{};
  };
  for (const RunFile& run : sorted) {
    set.paths.push_back(run.path);
    set.steps.push_back(*run.steps);
    set.states.push_back(measured(run, specs, rows(run, "run")));
  }
  if (reference) set.reference = measured(*reference, specs, rows(*reference, "reference"));
  if (check) set.reference_check = measured(*check, specs, rows(*check, "reference check"));
  int column = 0;
  for (const VariableSpec& spec : specs) {
    set.variables.push_back({spec.name, column, static_cast<int>(spec.fields.size()), spec.unit});
    column += static_cast<int>(spec.fields.size());
  }
  set.t0 = first.t0.value_or(0.0);
  set.matched_by_id = first.ids.has_value();
  return set;
}

}  // namespace dlpverify::exchange
