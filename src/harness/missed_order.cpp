#include "dlpverify/missed_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <vector>

#include <Eigen/Eigenvalues>

#include "dlpverify/evaluate_rhs.hpp"
#include "dlpverify/solution_features.hpp"
#include "io/format.hpp"

namespace dlpverify {

std::string to_string(MissReason reason) {
  switch (reason) {
    case MissReason::stability: return "stability";
    case MissReason::round_off: return "round-off";
    case MissReason::reference_accuracy: return "reference-accuracy";
    case MissReason::kink: return "kink";
    case MissReason::inner_iteration: return "inner-iteration";
  }
  return "?";
}

namespace {

// A step beyond the fastest time scale: Δt·ρ(J) above this is not yet asymptotic (the explicit
// methods' real stability limits are 2 for Euler, 2 for RK2 and 2.79 for RK4; their error series
// converges only for Δt·ρ well below them).
constexpr double kResolvedStep = 1.0;

bool missed(const CheckVerdict& verdict, std::size_t v) {
  const Finding* order = verdict.find(v, Criterion::order);
  return order && order->result() != FindingResult::pass;
}

// Whether an unstable level of variable v shows instability: an error that is not finite, or a step
// beyond the fastest time scale (Δt·ρ(J) > 1), or no ρ(J) to tell. With Δt·ρ(J) ≤ 1 the step is
// well inside every explicit method's stability region (Euler's and RK2's reach 2 on the real
// axis, RK4's 2.79): an error as large as the solution there is a large error, not a growing one.
bool shows_instability(const StudyResult& study, std::size_t v, std::size_t k, const MissContext& c) {
  const LevelResult& level = study.levels[k];
  if (v < level.norms.size() && !std::isfinite(level.norms[v].l2)) return true;
  return !(c.spectral_radius > 0.0) || level.dt * c.spectral_radius > kResolvedStep;
}

// Unstable levels that show instability, and the fitted window's coarsest level when Δt·ρ(J) > 1 there.
void stability(const StudyResult& study, std::size_t v, const MissContext& c, std::vector<MissExplanation>& out) {
  const OrderAnalysis& a = study.orders[v];
  std::vector<int> unstable;
  std::string products;
  for (std::size_t k = 0; k < a.status.size(); ++k)
    if (a.status[k] == LevelStatus::unstable && shows_instability(study, v, k, c)) {
      unstable.push_back(static_cast<int>(k));
      if (c.spectral_radius > 0.0) products += printf_string(" %.3g", study.levels[k].dt * c.spectral_radius);
    }
  const std::string rho = printf_string("rho(J) ~ %.3g at t0", c.spectral_radius);
  if (!unstable.empty()) {
    std::string text = std::string("levels ") + levels_text(unstable) + " unstable or pre-asymptotic (" +
                       a.rule[unstable.front()] + ")";
    if (c.spectral_radius > 0.0) text += "; dt*rho(J) =" + products + " (" + rho + ")";
    out.push_back({MissReason::stability, text});
    return;
  }
  if (a.fit.levels.empty() || c.spectral_radius <= 0.0) return;
  const double product = study.levels[static_cast<std::size_t>(a.fit.levels.front())].dt * c.spectral_radius;
  if (product > kResolvedStep)
    out.push_back({MissReason::stability,
                   printf_string("pre-asymptotic: the coarsest fitted level %d has dt*rho(J) = %.3g > %.0f (", a.fit.levels.front(),
                                 product, kResolvedStep) + rho + ")"});
}

// Pairwise orders still converging when the search stopped: the extrapolated order, or why none.
void pre_asymptotic(std::size_t v, const MissContext& c, std::vector<MissExplanation>& out) {
  if (v >= c.extrapolation.size() || c.extrapolation[v].empty()) return;
  out.push_back({MissReason::stability, "the search stopped with the order unsettled: " + c.extrapolation[v]});
}

void round_off(const StudyResult& study, std::size_t v, std::vector<MissExplanation>& out) {
  const OrderAnalysis& a = study.orders[v];
  std::vector<int> levels;
  for (std::size_t k = 0; k < a.status.size(); ++k)
    if (a.status[k] == LevelStatus::round_off) levels.push_back(static_cast<int>(k));
  if (levels.empty()) return;
  out.push_back({MissReason::round_off,
                 std::string("levels ") + levels_text(levels) + " at the round-off floor (" + a.rule[levels.front()] + ")"});
}

void reference(const StudyResult& study, std::size_t v, std::vector<MissExplanation>& out) {
  if (study.reference.margin[v] >= kMinimumReferenceMargin) return;
  out.push_back({MissReason::reference_accuracy,
                 printf_string("the finest level's error is only %.3g x the reference's estimated error %.3e (needs %.0f x)",
                               study.reference.margin[v], study.reference.error[v], kMinimumReferenceMargin)});
}

void kink(const StudyResult& study, const MissContext& c, std::vector<MissExplanation>& out) {
  if (c.kinks_inside == 0) return;
  out.push_back({MissReason::kink,
                 printf_string("%d of %zu members have a kink (only once differentiable) at %.4g … %.4g after t0, inside "
                               "the study's %.4g: a step across it errs at low order",
                               c.kinks_inside, static_cast<std::size_t>(c.members), c.first_kink, c.last_kink,
                               study.plan.t_end)});
}

void inner_iteration(const StudyResult& study, std::vector<MissExplanation>& out) {
  std::vector<int> levels;
  long failures = 0;
  for (const LevelResult& level : study.levels) {
    const long n = level.solver_statistics.nonlinear_convergence_failures.value_or(0);
    if (n > 0) levels.push_back(level.level);
    failures += n;
  }
  if (levels.empty()) return;
  out.push_back({MissReason::inner_iteration,
                 printf_string("%ld nonlinear convergence failures on levels ", failures) + levels_text(levels)});
}

// Central differences balance truncation (h²) and rounding (ε/h) at h = ε^(1/3) × the value's size.
double difference_step(double value, double scale) {
  return std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(value), scale);
}

// f of member p alone at its state y (one value per field): a block of one member.
Eigen::VectorXd member_rhs(const Problem& problem, double t, Eigen::Index p, const Eigen::VectorXd& y) {
  Eigen::VectorXd f(y.size());
  std::vector<const double*> in(static_cast<std::size_t>(y.size()));
  std::vector<double*> out(in.size());
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    in[static_cast<std::size_t>(j)] = &y[j];
    out[static_cast<std::size_t>(j)] = &f[j];
  }
  problem.rhs(t, p, 1, in.data(), out.data());
  return f;
}

// Member p's F × F block of ∂f/∂y, column j from f(y ± h_j e_j).
Eigen::MatrixXd member_jacobian(const Problem& problem, double t, Eigen::Index p, const Eigen::VectorXd& y,
                                const std::vector<double>& scales) {
  Eigen::MatrixXd jacobian(y.size(), y.size());
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    Eigen::VectorXd plus = y, minus = y;
    const double h = difference_step(y[j], scales[static_cast<std::size_t>(j)]);
    plus[j] += h;
    minus[j] -= h;
    jacobian.col(j) = (member_rhs(problem, t, p, plus) - member_rhs(problem, t, p, minus)) / (plus[j] - minus[j]);
  }
  return jacobian;
}

// Every member's bound ρ ≤ ‖J_p‖∞ (its largest absolute row sum), from 2F evaluations of the whole
// population: perturbing field j of every member at once gives column j of every member's block.
Eigen::ArrayXd row_sum_bounds(const Problem& problem, double t, const State& state, const std::vector<double>& scales) {
  State row_sums = State::Zero(state.rows(), state.cols()), f_plus, f_minus;
  for (Eigen::Index j = 0; j < state.cols(); ++j) {
    State plus = state, minus = state;
    for (Eigen::Index p = 0; p < state.rows(); ++p) {
      const double h = difference_step(state(p, j), scales[static_cast<std::size_t>(j)]);
      plus(p, j) += h;
      minus(p, j) -= h;
    }
    evaluate_rhs(problem, t, plus, f_plus);
    evaluate_rhs(problem, t, minus, f_minus);
    const Eigen::ArrayXd width = plus.col(j) - minus.col(j);
    row_sums += ((f_plus - f_minus).colwise() / width).abs();
  }
  return row_sums.rowwise().maxCoeff();
}

}  // namespace

double spectral_radius(const Problem& problem, double t, const State& state) {
  const std::vector<double> scales = field_scales(problem, state);
  const Eigen::ArrayXd bounds = row_sum_bounds(problem, t, state, scales);
  if (!bounds.allFinite()) return std::numeric_limits<double>::quiet_NaN();
  // The members by their bound, largest first: a member whose bound is below the largest |λ|
  // found so far cannot raise it, so few blocks are solved.
  std::vector<Eigen::Index> order(static_cast<std::size_t>(state.rows()));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  std::sort(order.begin(), order.end(), [&bounds](Eigen::Index a, Eigen::Index b) { return bounds[a] > bounds[b]; });
  double radius = 0.0;
  for (const Eigen::Index p : order) {
    if (bounds[p] <= radius) break;
    const Eigen::MatrixXd jacobian = member_jacobian(problem, t, p, state.row(p).transpose(), scales);
    // A general real matrix's eigenvalues (Eigen's real Schur form): ± pairs and complex pairs
    // count by their modulus.
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(jacobian, false);
    if (!jacobian.allFinite() || solver.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
    radius = std::max(radius, solver.eigenvalues().cwiseAbs().maxCoeff());
  }
  return radius;
}

MissContext miss_context(const Problem& problem, double t_end) {
  MissContext c;
  const State initial = problem.initial_state();
  c.members = initial.rows();
  c.spectral_radius = spectral_radius(problem, problem.initial_time(), initial);
  for (double kink : kink_times(problem, initial)) {
    if (!(kink > 0.0 && kink <= t_end)) continue;  // NaN: no kink
    c.first_kink = c.kinks_inside == 0 ? kink : std::min(c.first_kink, kink);
    c.last_kink = std::max(c.last_kink, kink);
    ++c.kinks_inside;
  }
  return c;
}

std::vector<std::vector<MissExplanation>> explain_missed_orders(const StudyResult& study, const CheckVerdict& verdict,
                                                                const MissContext& context) {
  std::vector<std::vector<MissExplanation>> reasons(study.orders.size());
  for (std::size_t v = 0; v < study.orders.size(); ++v) {
    if (!missed(verdict, v)) continue;
    stability(study, v, context, reasons[v]);
    pre_asymptotic(v, context, reasons[v]);
    round_off(study, v, reasons[v]);
    reference(study, v, reasons[v]);
    kink(study, context, reasons[v]);
    inner_iteration(study, reasons[v]);
  }
  return reasons;
}

std::string format_missed_orders(const StudyResult& study, const std::vector<std::vector<MissExplanation>>& reasons) {
  std::ostringstream out;
  for (std::size_t v = 0; v < reasons.size(); ++v)
    for (const MissExplanation& reason : reasons[v])
      out << "  why: " << study.plan.variables[v].name << ": " << to_string(reason.reason) << " — " << reason.text << "\n";
  return out.str();
}

nlohmann::json to_json(const StudyResult& study, const MissContext& context,
                       const std::vector<std::vector<MissExplanation>>& reasons) {
  nlohmann::json products = nlohmann::json::array(), by_variable = nlohmann::json::object();
  for (const LevelResult& level : study.levels) products.push_back(level.dt * context.spectral_radius);
  for (std::size_t v = 0; v < reasons.size(); ++v) {
    if (reasons[v].empty()) continue;
    nlohmann::json list = nlohmann::json::array();
    for (const MissExplanation& reason : reasons[v]) list.push_back({{"reason", to_string(reason.reason)}, {"text", reason.text}});
    by_variable[study.plan.variables[v].name] = list;
  }
  return {{"spectral_radius", context.spectral_radius > 0.0 ? nlohmann::json(context.spectral_radius) : nlohmann::json()},
          {"dt_spectral_radius", context.spectral_radius > 0.0 ? products : nlohmann::json()},
          {"reasons", by_variable}};
}

}  // namespace dlpverify
