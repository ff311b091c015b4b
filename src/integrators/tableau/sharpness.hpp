// How sharp a verification is (docs/verification.md, "How sharp is the check"): every coefficient
// of a Butcher tableau — each a_ij below the diagonal, each b_i, each c_i — is perturbed alone,
//   x → x (1 + δ)   (x ≠ 0, relative)        x → δ   (x = 0, absolute),
// and each mutant is checked three ways: the tableau's own order conditions (order_conditions.hpp),
// the study's fitted order against the claimed order, and the study's error constant against the
// unperturbed tableau's (harness/constant_gate.hpp). A mutant no study on the case catches is run
// again on an alternative study (the manufactured reference, which sees the stage times c_i). The
// share of mutants caught is a mutation score of the user's own verification.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dlpverify/study.hpp"
#include "integrators/tableau/tableau_file.hpp"

namespace dlpverify {

class Integrator;

// One coefficient moved.
struct TableauMutation {
  std::string coefficient;   // "a_21", "b_1", "c_2" (1-based, as the order conditions name them)
  double original = 0.0;
  double perturbed = 0.0;
  bool absolute = false;     // the coefficient was zero: moved to δ
  RuntimeTableau tableau;    // the mutant
};

// Every single-coefficient mutant of `tableau` by δ, in the order a (by row), b, c.
std::vector<TableauMutation> tableau_mutations(const RuntimeTableau& tableau, double delta);

// What one study said of a mutant, per measured variable.
struct StudyCatch {
  bool order = false;       // a fitted order missed the claimed order ± tolerance (or none was measured)
  bool constant = false;    // an error constant left the unperturbed one's band
  std::vector<std::string> variables;
  std::vector<std::optional<double>> fitted_order;  // none: exact to round-off or no order measured
  std::vector<double> constant_ratio;               // C / C_unperturbed; NaN when either has none
  bool caught() const { return order || constant; }
};

struct MutationVerdict {
  TableauMutation mutation;
  std::string condition;                 // the first order condition the mutant fails; empty: none
  StudyCatch study;                      // on the case, against its reference
  std::optional<StudyCatch> alternative; // run only when the study missed it
  bool caught_by_conditions() const { return !condition.empty(); }
  bool caught() const { return caught_by_conditions() || study.caught() || (alternative && alternative->caught()); }
};

// A study of an integrator on a fixed case, plan and reference.
using IntegratorStudy = std::function<StudyResult(Integrator&)>;

struct SharpnessSettings {
  double delta = 1e-2;
  double order_tolerance = 0.1;     // as check's --order-tolerance
  double constant_tolerance = 0.05; // as check's --constant-tolerance
};

struct SharpnessReport {
  SharpnessSettings settings;
  StudyResult unperturbed;                     // the study of the tableau as written
  std::optional<StudyResult> unperturbed_alternative;  // run once a mutant needs the alternative
  std::vector<MutationVerdict> mutations;
  int caught_by_study() const;      // mutants the case's study catches (order or constant)
  int caught() const;               // mutants some check catches
};

// Every mutant checked: `study` runs the case, `alternative` (may be empty) the study a missed
// mutant is tried on. The expected order is the tableau's claimed order.
SharpnessReport measure_sharpness(const RuntimeTableau& tableau, const SharpnessSettings& settings,
                                  const IntegratorStudy& study, const IntegratorStudy& alternative);

}  // namespace dlpverify
