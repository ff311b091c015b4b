// A self-contained HTML report of one study (check --html) or of a suite (suite --html): the
// verdict first, then per study its variables' verdicts, the figure of error against Δt as inline
// SVG, the level table with every level's status, the reasons for the levels left out of the fit,
// the reference and its trust margin, and the provenance (commit, compiler, flags, library
// versions). One file: no script, no style sheet, font or image from elsewhere, so it reads
// offline, in a CI's artefact viewer, and on paper (docs/cli.md, "HTML report").
#pragma once

#include <string>
#include <vector>

#include "case_study/suite.hpp"

namespace dlpverify::case_study {

// The page titled `title` for `studies` (one for a check). A study without an outcome is shown
// with the line that ended it.
std::string html_report(const std::string& title, const std::vector<SuiteStudy>& studies);

}  // namespace dlpverify::case_study
