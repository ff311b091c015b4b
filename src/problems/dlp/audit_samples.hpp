// What the audit of the DLP closed forms runs on (docs/model.md §4, last paragraph): a small
// sample of each case's own cloud, and the source paper's published formulas beside the
// corrected ones, which must be seen failing (docs/model.md §9).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "problems/dlp/problem.hpp"

namespace dlpverify::dlp {

// The seed sphere's launch scaled down to R_out 4 (with the particle at rest at the centre), or
// for vertical motion the seed's own z axis, whose slow particles cross their apex.
std::unique_ptr<DlpProblem> audit_sample(const Case& test_case, const Parameters& parameters);

struct PublishedFormula {
  std::string name;    // "Kuhl & Grote eq. 23"
  std::string source;  // what it claims and why it is wrong
  std::unique_ptr<DlpProblem> sample;
};

// The source paper's eqs. 23 (drag) and 26 (drag + gravity) on the physics they claim to solve.
std::vector<PublishedFormula> published_formulas(const Parameters& parameters);

}  // namespace dlpverify::dlp
