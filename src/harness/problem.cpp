#include "dlpverify/problem.hpp"

#include <cmath>

#include "dlpverify/errors.hpp"
#include "harness/field_groups.hpp"

namespace dlpverify {

State Problem::closed_form(const State& /*initial*/, double /*tau*/) const {
  throw InputError("reference", "exact", "case " + name() + " has no closed form; use a CVODE reference");
}

std::vector<FieldBlock> Problem::staggered_blocks() const {
  std::vector<FieldBlock> blocks;
  const std::vector<Field> all = fields();
  for (int f = 0; f < static_cast<int>(all.size()); ++f) blocks.push_back({all[static_cast<std::size_t>(f)].name, f, 1});
  return blocks;
}

std::vector<double> Problem::kink_times(const State& initial) const {
  return std::vector<double>(static_cast<std::size_t>(initial.rows()), std::nan(""));
}

// Without a problem's own knowledge: the shortest |y_f| / |f_f| over the member's fields.
double Problem::time_scale(const State& state, Eigen::Index p, double tau) const {
  const int fields = field_count();
  std::vector<double> y(fields), rate(fields);
  std::vector<const double*> in(fields);
  std::vector<double*> out(fields);
  for (int f = 0; f < fields; ++f) {
    y[f] = state(p, f);
    in[f] = &y[f];
    out[f] = &rate[f];
  }
  rhs(initial_time() + tau, p, 1, in.data(), out.data());
  double scale = std::numeric_limits<double>::infinity();
  for (int f = 0; f < fields; ++f)
    if (y[f] != 0.0 && rate[f] != 0.0) scale = std::min(scale, std::abs(y[f] / rate[f]));
  if (std::isfinite(scale)) return scale;
  return tau != 0.0 ? std::abs(tau) : 1.0;
}

ProblemDescription Problem::description() const {
  ProblemDescription d{"problem", {}, {}, {}};
  for (const auto& [key, value] : parameters().items()) {
    if (value.is_number()) d.parameters.push_back({key, value.get<double>(), ""});
    if (value.is_string()) d.settings.emplace_back(key, value.get<std::string>());
  }
  return d;
}

std::vector<Variable> field_groups(const Problem& problem) {
  const std::vector<Field> fields = problem.fields();
  std::vector<Variable> groups;
  for (const Variable& v : problem.variables())  // the variables made of fields, not of derived columns
    if (v.first_field + v.fields <= static_cast<int>(fields.size())) groups.push_back(v);
  std::vector<bool> covered(fields.size(), false);
  for (const Variable& v : groups)
    for (int f = v.first_field; f < v.first_field + v.fields; ++f) covered[static_cast<std::size_t>(f)] = true;
  for (std::size_t f = 0; f < fields.size(); ++f)
    if (!covered[f]) groups.push_back({fields[f].name, static_cast<int>(f), 1, fields[f].unit});
  return groups;
}

std::vector<double> field_scales(const Problem& problem, const State& state) {
  std::vector<double> scales(static_cast<std::size_t>(problem.field_count()), 1.0);
  for (const Variable& group : field_groups(problem)) {
    double largest = 0.0;
    if (state.rows() > 0) largest = state.middleCols(group.first_field, group.fields).abs().maxCoeff();
    if (!(largest > 0.0) || !std::isfinite(largest)) largest = 1.0;  // zero everywhere: 1 in SI units
    for (int f = group.first_field; f < group.first_field + group.fields; ++f) scales[static_cast<std::size_t>(f)] = largest;
  }
  return scales;
}

void check_shape(const Problem& problem, const State& state, const std::string& what) {
  if (state.rows() != problem.members() || state.cols() != problem.field_count())
    throw InputError(what, std::to_string(state.rows()) + " x " + std::to_string(state.cols()),
                     "the problem has " + std::to_string(problem.members()) + " members of " +
                         std::to_string(problem.field_count()) + " fields");
}

}  // namespace dlpverify
