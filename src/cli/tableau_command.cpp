#include "cli/tableau_command.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/errors.hpp"
#include "integrators/tableau/order_conditions.hpp"
#include "integrators/tableau/tableau_file.hpp"
#include "io/atomic_file.hpp"
#include "io/format.hpp"
#include "io/output_path.hpp"
#include "io/printable.hpp"
#include "io/provenance.hpp"
#include "io/file_identity.hpp"

namespace dlpverify::cli {

namespace {

// Columns a UTF-8 text takes on a terminal: its code points, less the combining circumflex of b̂.
std::size_t columns(const std::string& text) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char byte = static_cast<unsigned char>(text[i]);
    if ((byte & 0xC0) != 0x80) ++n;
    if (byte == 0xCC && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x82) --n;
  }
  return n;
}

std::string padded(const std::string& text, std::size_t width) {
  const std::size_t n = columns(text);
  return text + std::string(n < width ? width - n : 1, ' ');
}

// A condition the claim relies on and misses is FAIL; one above the claimed order is only "not met".
const char* verdict(const OrderCondition& c, int claimed) { return c.met ? "ok" : c.order <= claimed ? "FAIL" : "not met"; }

void add_rows(std::string& table, nlohmann::json& rows, const std::vector<OrderCondition>& conditions, int claimed,
              std::size_t width) {
  for (const OrderCondition& c : conditions) {
    table += printf_string("%s%-24.16g %-24.16g %-10.2e %s\n", padded(c.name, width).c_str(), c.expected, c.value,
                           c.residual, verdict(c, claimed));
    rows.push_back({{"condition", c.name},   {"order", c.order},         {"wanted", c.expected}, {"has", c.value},
                    {"residual", c.residual}, {"tolerance", c.tolerance}, {"verdict", verdict(c, claimed)}});
  }
}

std::string claim_line(const char* what, int claimed, int met, int checked) {
  std::string line = std::string(what) + " " + std::to_string(claimed) + " claimed, " + std::to_string(met) + " met";
  line += " (conditions checked up to order " + std::to_string(checked) + ")";
  if (claimed > 6) line += "; orders above 6 are not checked";
  return line;
}

}  // namespace

CLI::App* add_tableau_command(CLI::App& app, TableauOptions& options) {
  CLI::App* command = app.add_subcommand(
      "tableau", "Check a Butcher tableau file (TOML) against its row sums and order conditions up to order 6 "
                 "(exit 0 its claimed order is met, 1 not)");
  command->add_option("file", options.file, "The tableau: name, order, c, b, A [, b_embedded, embedded_order]")->required();
  command->add_option("--json", options.json_file, "Write every condition and the verdict as JSON");
  return command;
}

int run_tableau_command(const TableauOptions& options, const std::string& command_line) {
  refuse_shared_files({{"tableau file", options.file}}, {{"--json", options.json_file}});
  if (!options.json_file.empty()) check_output_path("--json", options.json_file);
  const bool json_on_stdout = !options.json_file.empty() && output_target(options.json_file) == OutputTarget::standard_output;
  const RuntimeTableau tableau = read_tableau_file(options.file);
  const TableauCheck check = check_tableau(tableau);

  std::string table = printf_string("tableau %s (%s): %d stages, order %d", printable(tableau.name).c_str(),
                                    printable(tableau.source).c_str(), tableau.stages(), tableau.order);
  if (!tableau.b_embedded.empty()) table += printf_string(", embedded order %d", tableau.embedded_order);
  table += "\n\n";
  std::size_t width = 12;
  for (const auto* list : {&check.row_sums, &check.trees, &check.embedded_trees})
    for (const OrderCondition& c : *list) width = std::max(width, columns(c.name) + 2);
  table += printf_string("%s%-24s %-24s %-10s %s\n", padded("condition", width).c_str(), "wanted", "has", "residual", "verdict");
  nlohmann::json rows = nlohmann::json::array();
  add_rows(table, rows, check.row_sums, std::max(tableau.order, tableau.embedded_order), width);
  add_rows(table, rows, check.trees, tableau.order, width);
  add_rows(table, rows, check.embedded_trees, tableau.embedded_order, width);

  table += "\n" + claim_line("order", tableau.order, check.order, check.max_order) + "\n";
  // The trees alone: the order an autonomous problem (no explicit t) sees, whatever the nodes.
  const int autonomous = achieved_order(check.trees, check.max_order);
  if (autonomous != check.order)
    table += printf_string("  on an autonomous problem (no explicit t; the row sums do not matter there): %d\n", autonomous);
  if (!tableau.b_embedded.empty())
    table += claim_line("embedded order", tableau.embedded_order, check.embedded_order, check.embedded_max_order) + "\n";

  const std::vector<const OrderCondition*> failed = check.failed_claims();
  std::string outcome;
  if (failed.empty()) {
    outcome = std::string("PASS: the claimed order") + (tableau.b_embedded.empty() ? " is" : "s are") + " met, to round-off";
  } else {
    outcome = "FAIL: " + failed.front()->failure();
    if (failed.size() > 1) outcome += " (and " + std::to_string(failed.size() - 1) + " more)";
  }
  table += outcome + "\n";

  if (!options.json_file.empty()) {
    nlohmann::json j{{"tableau", tableau.name},
                     {"file", tableau.source},
                     {"stages", tableau.stages()},
                     {"order_claimed", tableau.order},
                     {"order_met", check.order},
                     {"order_met_autonomous", autonomous},
                     {"conditions", rows},
                     {"passed", failed.empty()},
                     {"verdict", outcome},
                     {"provenance", provenance(command_line)}};
    if (!tableau.b_embedded.empty()) {
      j["embedded_order_claimed"] = tableau.embedded_order;
      j["embedded_order_met"] = check.embedded_order;
    }
    write_output(options.json_file, json_text(j, 2) + "\n");
  }
  if (!json_on_stdout) std::fputs(table.c_str(), stdout);  // after the output: nothing printed if it fails
  std::fflush(stdout);
  return failed.empty() ? kExitDone : kExitCheckFailed;
}

}  // namespace dlpverify::cli
