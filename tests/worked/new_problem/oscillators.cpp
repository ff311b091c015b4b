// The family file of the worked new problem (CMakeLists.txt beside): the damped oscillators of
// examples/own-integrator/oscillator.hpp as a family of the command, written as
// src/families/NAME.cpp would be. It has no options of its own (a family with options adds their
// struct to ProblemOptions, src/families/problem_options.hpp, and declares them in options()).
#include "../../../examples/own-integrator/oscillator.hpp"
#include "families/family.hpp"

namespace dlpverify::families {

namespace {

constexpr int kOscillators = 1000;
const char* const kCase = "damped-oscillators";

class OscillatorFamily final : public Family {
 public:
  std::string name() const override { return "oscillators"; }
  std::string title() const override { return "the damped oscillators"; }

  std::vector<CaseEntry> cases() const override {
    return {{kCase, "oscillators", "1000 damped harmonic oscillators, omega from 1 to 2 rad/s, zeta 0.1",
             "x, v", DampedOscillators(kOscillators).formula(), true, {.t_end = 1.0, .dt = 0.05, .levels = 5}}};
  }

  std::vector<FamilyOption> options(ProblemOptions& /*o*/) const override { return {}; }
  void validate(const ProblemOptions& /*o*/) const override {}

  ProblemSize size(const ProblemOptions& /*o*/) const override {
    return {kOscillators, 2, "--case", kCase};
  }

  std::unique_ptr<Problem> make(const ProblemOptions& /*o*/) const override {
    return std::make_unique<DampedOscillators>(kOscillators);
  }

  BaselineAudit audit(const ProblemOptions& /*o*/, const std::string& case_name, double t_end) const override {
    const DampedOscillators sample(kOscillators);
    return named_audit(case_name, false, sample.formula(), sample, t_end);
  }

  std::vector<BaselineAudit> default_audits() const override {
    const DampedOscillators sample(kOscillators);
    return {named_audit(kCase, false, sample.formula(), sample, 1.0)};
  }
};

}  // namespace

const Family& oscillators_family() {
  static const OscillatorFamily family;
  return family;
}

}  // namespace dlpverify::families
