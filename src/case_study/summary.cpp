#include "case_study/summary.hpp"

#include <algorithm>

#include "io/format.hpp"

namespace dlpverify::case_study {

namespace {

using Result = VariableVerdict::Result;

// Where a variable's row goes: failures, inconclusive, passes (a study's rank: suite_rank).
int variable_rank(Result r) { return r == Result::fail ? 0 : r == Result::inconclusive ? 2 : 3; }

// The indices of `items` stably sorted by `rank`.
template <class T, class Rank>
std::vector<std::size_t> ranked(const std::vector<T>& items, Rank rank) {
  std::vector<std::size_t> order(items.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(items[a]) < rank(items[b]); });
  return order;
}

// Appended piece by piece here: GCC 12 misreads "…" + std::string&& (a false -Wrestrict).
std::string row(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const std::string& cell : cells) {
    line += ' ';
    line += markdown_cell(cell);
    line += " |";
  }
  line += '\n';
  return line;
}

}  // namespace

std::string markdown_cell(const std::string& text) {
  std::string cell;
  for (const char c : text) {
    switch (c) {
      case '\n': case '\r': cell += ' '; break;
      case '&': cell += "&amp;"; break;
      case '<': cell += "&lt;"; break;
      case '>': cell += "&gt;"; break;
      case '|': case '\\': case '*': case '_': case '`': case '[': case ']': case '#': case '~':
        cell += '\\';
        cell += c;
        break;
      default: cell += c;
    }
  }
  return cell;
}

std::string check_summary(const SuiteStudy& study) {
  std::string text = "### dlpverify check ";
  text += markdown_cell(study.name);
  text += ": ";
  text += study_verdict_word(study.exit_code());
  text += "\n\n| verdict | variable | expected | fitted [95% interval] | reason |\n|---|---|---|---|---|\n";
  if (!study.outcome) return text + row({study_verdict_word(study.code), "-", "-", "-", study.error});
  const std::vector<VariableVerdict>& verdicts = study.outcome->verdicts;
  for (const std::size_t i : ranked(verdicts, [](const VariableVerdict& v) { return variable_rank(v.result); })) {
    const VariableVerdict& v = verdicts[i];
    text += row({variable_verdict_word(v.result), v.variable, value_text(v.expected), fitted_text(v.fit), reason_of(v.finding)});
  }
  return text;
}

std::string suite_summary(const std::vector<SuiteStudy>& studies) {
  std::string text = "### dlpverify suite: ";
  text += study_verdict_word(suite_exit_code(studies));
  text += "\n\n";
  text += markdown_cell(suite_counts(studies));
  text += "\n\n| verdict | study | variables |\n|---|---|---|\n";
  for (const std::size_t i : ranked(studies, suite_rank)) {
    const SuiteStudy& s = studies[i];
    std::string detail;
    if (!s.outcome) detail = s.error;
    for (const VariableVerdict& v : s.outcome ? s.outcome->verdicts : std::vector<VariableVerdict>{}) {
      // A study that did not pass: the reasons of the variables that did not; one that did: the orders.
      if (s.exit_code() != kExitDone && v.result == Result::pass) continue;
      if (!detail.empty()) detail += "; ";
      detail += v.variable;
      detail += ' ';
      if (s.exit_code() == kExitDone) {
        detail += fitted_text(v.fit);
      } else {
        detail += variable_verdict_word(v.result);
        detail += ", ";
        detail += reason_of(v.finding);
      }
    }
    text += row({study_verdict_word(s.exit_code()), s.name, detail});
  }
  return text;
}

}  // namespace dlpverify::case_study
