#include "dlpverify/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/solution_features.hpp"
#include "dlpverify/splitting.hpp"
#include "harness/distribution.hpp"
#include "harness/field_groups.hpp"

namespace dlpverify {

std::vector<Variable> Problem::variables() const {
  std::vector<Variable> each;
  const std::vector<Field> all = fields();
  for (int f = 0; f < static_cast<int>(all.size()); ++f)
    each.push_back({all[static_cast<std::size_t>(f)].name, f, 1, all[static_cast<std::size_t>(f)].unit});
  return each;
}

bool has_closed_form(const Problem& problem) { return problem.capability<ClosedForm>() != nullptr; }

bool is_manufactured(const Problem& problem) {
  const ClosedForm* form = problem.capability<ClosedForm>();
  return form && form->manufactured();
}

State closed_form(const Problem& problem, const State& initial, double tau) {
  const ClosedForm* exact = problem.capability<ClosedForm>();
  if (!exact) throw InputError("reference", "exact", "case " + problem.name() + " has no closed form; use a CVODE reference");
  check_shape(problem, initial, "initial state");
  return exact->solution(0, initial, tau);
}

std::string reference_detail(const Problem& problem) {
  const ClosedForm* exact = problem.capability<ClosedForm>();
  return exact ? exact->formula() : "no closed form";
}

std::vector<FieldBlock> staggered_blocks(const Problem& problem) {
  if (const StaggeredBlocks* own = problem.capability<StaggeredBlocks>()) return own->staggered_blocks();
  std::vector<FieldBlock> blocks;
  const std::vector<Field> all = problem.fields();
  for (int f = 0; f < static_cast<int>(all.size()); ++f) blocks.push_back({all[static_cast<std::size_t>(f)].name, f, 1});
  return blocks;
}

std::vector<double> kink_times(const Problem& problem, const State& initial) {
  if (const SolutionKinks* kinks = problem.capability<SolutionKinks>()) return kinks->kink_times(0, initial);
  return std::vector<double>(static_cast<std::size_t>(initial.rows()), std::nan(""));
}

// Without the problem's own knowledge: the shortest |y_f| / |f_f| over the member's fields.
double time_scale(const Problem& problem, Eigen::Index member, const double* y, double tau) {
  if (const TimeScale* own = problem.capability<TimeScale>()) return own->time_scale(member, y, tau);
  const int fields = problem.field_count();
  std::vector<double> value(y, y + fields), rate(static_cast<std::size_t>(fields));
  std::vector<const double*> in(static_cast<std::size_t>(fields));
  std::vector<double*> out(static_cast<std::size_t>(fields));
  for (std::size_t f = 0; f < static_cast<std::size_t>(fields); ++f) {
    in[f] = &value[f];
    out[f] = &rate[f];
  }
  problem.rhs(problem.initial_time() + tau, member, 1, in.data(), out.data());
  double scale = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < static_cast<std::size_t>(fields); ++f)
    if (value[f] != 0.0 && rate[f] != 0.0) scale = std::min(scale, std::abs(value[f] / rate[f]));
  if (std::isfinite(scale)) return scale;
  return tau != 0.0 ? std::abs(tau) : 1.0;
}

nlohmann::json case_parameters(const Problem& problem) {
  const CaseReport* report = problem.capability<CaseReport>();
  return report ? report->parameters() : nlohmann::json::object();
}

MemberNouns member_nouns(const Problem& problem) {
  const MemberNoun* noun = problem.capability<MemberNoun>();
  return noun ? noun->member_nouns() : MemberNouns{};
}

std::string count_text(long long count, const MemberNouns& nouns) {
  return std::to_string(count) + " " + (count == 1 ? nouns.one : nouns.many);
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
    largest = distribution().max(largest);  // over every process's members (harness/distribution.hpp)
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
