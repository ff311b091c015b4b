// The closed-form references: the problem's exact solution, or the trajectory ŷ of a manufactured
// problem (dlpverify/manufactured.hpp), whose closed form it is. Exact up to rounding, so the
// error estimate is zero and no tighter reference exists.
#include <chrono>

#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/solution_features.hpp"
#include "references/source.hpp"

namespace dlpverify::references {

namespace {

const char* closed_form_hint(ReferenceKind kind) {
  return kind == ReferenceKind::manufactured
             ? "a manufactured reference needs the manufactured problem, whose closed form is its trajectory"
             : "use a CVODE or an integrator reference";
}

class ClosedFormReference final : public ReferenceSource {
 public:
  explicit ClosedFormReference(ReferenceKind kind) : kind_(kind) {}

  Reference compute(const Problem& problem, const State& initial, double t_end,
                    const std::vector<Variable>& variables) const override {
    const auto start = std::chrono::steady_clock::now();
    require_closed_form(problem);
    Reference reference;
    reference.state = closed_form(problem, initial, t_end);
    reference.kind = reference_kind_name(kind_);
    reference.detail = reference_detail(problem);
    reference.error_estimate.assign(variables.size(), 0.0);
    reference.statistics = {{"wall_s", seconds_since(start)}};
    return reference;
  }

  std::function<State(double tau)> trajectory(const Problem& problem, const State& initial) const override {
    require_closed_form(problem);
    return [&problem, &initial](double tau) { return closed_form(problem, initial, tau); };
  }

  std::optional<ReferenceSettings> tightened(double /*ratio*/) const override { return std::nullopt; }

 private:
  void require_closed_form(const Problem& problem) const {
    if (!has_closed_form(problem))
      throw InputError("reference", reference_kind_name(kind_),
                       "case " + problem.name() + " has no closed form; " + closed_form_hint(kind_));
  }

  ReferenceKind kind_;
};

}  // namespace

std::unique_ptr<ReferenceSource> closed_form_source(ReferenceKind kind) {
  return std::make_unique<ClosedFormReference>(kind);
}

}  // namespace dlpverify::references
