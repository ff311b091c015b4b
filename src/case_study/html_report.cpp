#include "case_study/html_report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "io/format.hpp"
#include "io/markup.hpp"
#include "plot/plot.hpp"

namespace dlpverify::case_study {

namespace {

using nlohmann::json;
using Result = VariableVerdict::Result;

std::string text(const std::string& s) { return markup_text(s); }

// report[key], or null when the report has no such key (a const json's [] must not miss).
const json& at(const json& report, const std::string& key) {
  static const json none;
  const auto found = report.is_object() ? report.find(key) : report.end();
  return report.is_object() && found != report.end() ? *found : none;
}

// A JSON value as the page shows it: strings as they are, numbers to 4 significant digits.
std::string shown(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return printf_string("%.4g", v.get<double>());
  if (v.is_null()) return "-";
  return v.dump();
}

// The page's one style sheet, inline. Verdict colours with text that says the verdict too (no
// meaning by colour alone); print keeps the colours and breaks between studies.
const char* const kStyle = R"(
body{font-family:system-ui,sans-serif;margin:1.5rem auto;max-width:72rem;padding:0 1rem;color:#1a1a1a}
h1{font-size:1.5rem;margin:0}h2{font-size:1.2rem;margin:2rem 0 .5rem}h3{font-size:1rem;margin:1rem 0 .3rem}
table{border-collapse:collapse;font-size:.85rem;margin:.4rem 0}td,th{border:1px solid #ccc;padding:.2rem .5rem;text-align:left;vertical-align:top}
td.num{text-align:right;font-variant-numeric:tabular-nums}
.verdict{padding:.8rem 1rem;border-radius:.3rem;border:2px solid}
.pass{background:#e6f4ea;border-color:#1e7e34}.fail{background:#fdecea;border-color:#b02a1a}
.inconclusive{background:#fff4e0;border-color:#9a6200}.error{background:#f1e6fa;border-color:#6a1b9a}
.tag{font-weight:bold}figure{margin:.5rem 0}figure svg{max-width:100%;height:auto}
code,pre{font-family:ui-monospace,monospace;font-size:.8rem}pre{white-space:pre-wrap;background:#f6f6f6;padding:.5rem}
@media print{body{max-width:none}section.study{break-before:page}.verdict{-webkit-print-color-adjust:exact;print-color-adjust:exact}}
)";

const char* result_class(Result r) { return r == Result::pass ? "pass" : r == Result::fail ? "fail" : "inconclusive"; }
const char* result_word(Result r) { return r == Result::pass ? "PASS" : r == Result::fail ? "FAIL" : "INCONCLUSIVE"; }

// The style class of a study's exit code.
const char* verdict_class(int exit_code) {
  return exit_code == kExitDone ? "pass" : exit_code == kExitCheckFailed ? "fail" : exit_code == kExitInconclusive ? "inconclusive" : "error";
}

// "2.023 [2.002, 2.045]".
std::string fitted(const OrderFit& fit) {
  if (!fit.valid) return "-";
  std::string t = printf_string("%.3f", fit.value);
  if (std::isfinite(fit.ci_low) && std::isfinite(fit.ci_high)) t += printf_string(" [%.3f, %.3f]", fit.ci_low, fit.ci_high);
  return t;
}

// Every occurrence of `from` in `s` replaced by `to`.
std::string replaced(std::string s, const std::string& from, const std::string& to) {
  for (std::string::size_type at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

// The figure of error against Δt, drawn by gnuplot as SVG, without its XML prologue, its ids
// (gnuplot names its point symbols and plots alike in every figure) prefixed by "figN-" so that
// the figures of one page keep theirs.
std::string figure(const json& report, int n) {
  std::string svg = plot_convergence({report}, PlotOptions{"figure.svg", "", "--html", false, {}});
  const std::string::size_type start = svg.find("<svg");
  if (start == std::string::npos) return "";
  const std::string prefix = printf_string("fig%d-", n);
  svg = svg.substr(start);
  for (const char* quote : {"'", "\""}) {
    svg = replaced(svg, std::string("id=") + quote, std::string("id=") + quote + prefix);
    svg = replaced(svg, std::string("href=") + quote + "#", std::string("href=") + quote + "#" + prefix);
  }
  svg = replaced(svg, "url(#", "url(#" + prefix);
  // gnuplot numbers its plots anew in each panel of a multiplot (gnuplot_plot_1 in each): every
  // definition of an id after its first gets "-2", "-3", …, so that an id names one element; a
  // reference keeps the first, the one it resolved to.
  std::map<std::string, int> seen;
  for (std::string::size_type at = svg.find(" id="); at != std::string::npos; at = svg.find(" id=", at + 1)) {
    const std::string::size_type open = at + 4;
    if (open >= svg.size() || (svg[open] != '"' && svg[open] != '\'')) continue;
    const std::string::size_type close = svg.find(svg[open], open + 1);
    if (close == std::string::npos) break;
    const std::string id = svg.substr(open + 1, close - open - 1);
    if (const int k = ++seen[id]; k > 1) svg.insert(close, "-" + std::to_string(k));
  }
  return svg;
}

// An id for a study's section: its name with every character but letters, digits, - and _ as -.
std::string anchor(const std::string& name) {
  std::string id = "study-";
  for (const char c : name) id += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '-';
  return id;
}

// Each study's id, in the suite's order: anchor(name), and where an earlier study took it (`a b`
// and `a-b` both read study-a-b) the first of anchor(name)-2, -3, … that no study has taken, so
// that every link of the summary leads to its own study.
std::vector<std::string> anchors(const std::vector<SuiteStudy>& studies) {
  std::set<std::string> taken;
  for (const SuiteStudy& s : studies) taken.insert(anchor(s.name));
  std::set<std::string> given;
  std::vector<std::string> ids;
  for (const SuiteStudy& s : studies) {
    const std::string own = anchor(s.name);
    std::string id = own;
    for (int n = 2; given.count(id) || (id != own && taken.count(id)); ++n) id = own + "-" + std::to_string(n);
    given.insert(id);
    taken.insert(id);
    ids.push_back(id);
  }
  return ids;
}

void add_verdicts(std::string& page, const CaseOutcome& o) {
  page += "<table><tr><th>variable</th><th>expected</th><th>fitted [95% interval]</th><th>verdict</th><th>finding</th></tr>\n";
  for (const VariableVerdict& v : o.verdicts)
    page += "<tr class=\"" + std::string(result_class(v.result)) + "\"><td>" + text(v.variable) + "</td><td class=\"num\">" +
            text(value_text(v.expected)) + "</td><td class=\"num\">" + fitted(v.fit) + "</td><td class=\"tag\">" +
            result_word(v.result) + "</td><td>" + text(v.finding) + "</td></tr>\n";
  page += "</table>\n";
}

// Every level: Δt, steps, each variable's L2 error, pairwise order and status; the rule of every
// status but `ok` listed after the table.
void add_levels(std::string& page, const json& report) {
  const json& variables = at(report, "variables");
  const std::string unit = shown(at(report, "time_unit"));
  page += "<table><tr><th>level</th><th>Δt [" + text(unit) + "]</th><th>steps</th>";
  for (const json& v : variables) {
    const std::string name = text(v.get<std::string>());
    page += "<th>L2 " + name + "</th><th>order</th><th>status</th>";
  }
  page += "</tr>\n";
  std::string excluded;
  for (const json& level : at(report, "levels")) {
    page += "<tr><td class=\"num\">" + shown(at(level, "level")) + "</td><td class=\"num\">" + shown(at(level, "dt")) +
            "</td><td class=\"num\">" + shown(at(level, "steps")) + "</td>";
    for (const json& v : variables) {
      const std::string name = v.get<std::string>();
      const json& status = at(at(level, "status_by_variable"), name);
      const std::string word = status.is_object() ? status.value("status", "") : "";
      page += "<td class=\"num\">" + shown(at(level, "l2_" + name)) + "</td><td class=\"num\">" +
              shown(at(level, "order_" + name)) + "</td><td>" + text(word) + "</td>";
      if (!word.empty() && word != "ok")
        excluded += "<li>level " + shown(at(level, "level")) + ", " + text(name) + ": " + text(word) + " — " +
                    text(status.value("rule", "")) + "</li>\n";
    }
    page += "</tr>\n";
  }
  page += "</table>\n<h3>Levels left out of the fit</h3>\n";
  page += excluded.empty() ? "<p>None: every level is in the asymptotic range.</p>\n" : "<ul>\n" + excluded + "</ul>\n";
}

void add_reference(std::string& page, const json& report) {
  page += "<h3>Reference</h3>\n<p>" + text(shown(at(report, "reference"))) + ": " +
          text(shown(at(report, "reference_detail"))) + "</p>\n<table><tr><th>variable</th><th>estimated error</th>"
          "<th>trust margin (finest error / reference error, 100 needed)</th></tr>\n";
  for (const json& v : at(report, "variables")) {
    const std::string name = v.get<std::string>();
    const json& error = at(at(report, "reference_error"), name);
    const json& margin = at(at(report, "reference_margin"), name);
    page += "<tr><td>" + text(name) + "</td><td class=\"num\">" + (error.is_null() ? "0 (a closed form)" : shown(error)) +
            "</td><td class=\"num\">" + (margin.is_null() ? "unbounded" : shown(margin)) + "</td></tr>\n";
  }
  page += "</table>\n";
}

void add_provenance(std::string& page, const json& provenance) {
  page += "<h3>Provenance</h3>\n<table>\n";
  for (const char* key : {"version", "git_commit", "compiler", "flags", "build_type", "sundials", "eigen", "gsl", "host",
                          "threads", "date", "command_line"})
    if (provenance.is_object() && provenance.contains(key))
      page += "<tr><th>" + std::string(key) + "</th><td><code>" + text(shown(provenance[key])) + "</code></td></tr>\n";
  page += "</table>\n";
}

void add_study(std::string& page, const SuiteStudy& s, const std::string& id, bool own_heading, int n) {
  const char* css = verdict_class(s.exit_code());
  const std::string word = study_verdict_word(s.exit_code());
  page += "<section class=\"study\" id=\"" + id + "\">\n";
  if (own_heading) page += "<h2>" + text(s.name) + ": <span class=\"tag\">" + word + "</span></h2>\n";
  if (!s.outcome) {
    page += "<p class=\"verdict " + std::string(css) + "\">" + text(s.error) + "</p>\n</section>\n";
    return;
  }
  const json& r = s.outcome->report;
  page += "<p>case " + text(shown(at(r, "case"))) + " · integrator " + text(shown(at(r, "integrator"))) + " · " +
          text(shown(at(r, "particles"))) + " " + text(shown(at(r, "member_noun"))) + " · t_end " + text(shown(at(r, "t_end"))) +
          " " + text(shown(at(r, "time_unit"))) + " · ratio " + text(shown(at(r, "ratio"))) + "</p>\n";
  add_verdicts(page, *s.outcome);
  // A passing study of a suite folds its figure, levels and provenance: what failed stays in view.
  const bool folded = own_heading && s.exit_code() == kExitDone;
  if (folded) page += "<details><summary>figure, levels, reference, provenance</summary>\n";
  page += "<figure>" + figure(r, n) + "</figure>\n<h3>Levels</h3>\n";
  add_levels(page, r);
  add_reference(page, r);
  add_provenance(page, at(r, "provenance"));
  if (folded) page += "</details>\n";
  page += "</section>\n";
}

}  // namespace

std::string html_report(const std::string& title, const std::vector<SuiteStudy>& studies) {
  const int code = suite_exit_code(studies);
  const char* css = verdict_class(code);
  const std::string word = study_verdict_word(code);
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                     "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>dlpverify: " +
                     text(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
  page += "<header id=\"verdict\" class=\"verdict " + std::string(css) + "\">\n<h1>" + word + ": " + text(title) + "</h1>\n";
  page += "<p>" + text(suite_counts(studies)) + "</p>\n";
  // The studies in the order they are listed: failed, no verdict, inconclusive, passed (each
  // group in the suite's order), so that a failure is at the top of a long suite.
  const std::vector<std::string> ids = anchors(studies);
  std::vector<std::size_t> order(studies.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return suite_rank(studies[a]) < suite_rank(studies[b]); });
  const char* groups[] = {"failed", "no verdict", "inconclusive"};
  for (int rank = 0; rank < 3; ++rank) {
    std::string names;
    for (std::size_t i : order)
      if (suite_rank(studies[i]) == rank)
        names += (names.empty() ? "" : ", ") + std::string("<a href=\"#") + ids[i] + "\">" +
                 text(studies[i].name) + "</a>";
    if (!names.empty()) page += "<p class=\"names\">" + std::string(groups[rank]) + ": " + names + "</p>\n";
  }
  page += "</header>\n";
  if (studies.size() > 1) {
    page += "<h2>Summary</h2>\n<table><tr><th>study</th><th>verdict</th><th>time [s]</th></tr>\n";
    for (std::size_t i : order) {
      const SuiteStudy& s = studies[i];
      page += "<tr class=\"" + std::string(verdict_class(s.exit_code())) + "\"><td><a href=\"#" + ids[i] + "\">" +
              text(s.name) + "</a></td><td class=\"tag\">" + study_verdict_word(s.exit_code()) +
              printf_string("</td><td class=\"num\">%.2f</td></tr>\n", s.seconds);
    }
    page += "</table>\n";
  }
  for (std::size_t i : order) add_study(page, studies[i], ids[i], studies.size() > 1, static_cast<int>(i));
  return page + "</body>\n</html>\n";
}

}  // namespace dlpverify::case_study
