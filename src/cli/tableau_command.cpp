#include "cli/tableau_command.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "dlpverify/errors.hpp"
#include "integrators/order_conditions.hpp"
#include "integrators/tableau_file.hpp"
#include "io/printable.hpp"

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
void print_rows(const std::vector<OrderCondition>& conditions, int claimed, std::size_t width) {
  for (const OrderCondition& c : conditions)
    std::printf("%s%-24.16g %-24.16g %-10.2e %s\n", padded(c.name, width).c_str(), c.expected, c.value, c.residual,
                c.met ? "ok" : c.order <= claimed ? "FAIL" : "not met");
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
  return command;
}

int run_tableau_command(const TableauOptions& options) {
  const RuntimeTableau tableau = read_tableau_file(options.file);
  const TableauCheck check = check_tableau(tableau);

  std::printf("tableau %s (%s): %d stages, order %d", printable(tableau.name).c_str(), printable(tableau.source).c_str(),
              tableau.stages(), tableau.order);
  if (!tableau.b_embedded.empty()) std::printf(", embedded order %d", tableau.embedded_order);
  std::printf("\n\n");
  std::size_t width = 12;
  for (const auto* list : {&check.row_sums, &check.trees, &check.embedded_trees})
    for (const OrderCondition& c : *list) width = std::max(width, columns(c.name) + 2);
  std::printf("%s%-24s %-24s %-10s %s\n", padded("condition", width).c_str(), "wanted", "has", "residual", "verdict");
  print_rows(check.row_sums, std::max(tableau.order, tableau.embedded_order), width);
  print_rows(check.trees, tableau.order, width);
  print_rows(check.embedded_trees, tableau.embedded_order, width);

  // The trees alone: the order an autonomous problem (no explicit t) sees, whatever the nodes.
  std::printf("\n%s\n", claim_line("order", tableau.order, check.order, check.max_order).c_str());
  const int autonomous = achieved_order(check.trees, check.max_order);
  if (autonomous != check.order)
    std::printf("  on an autonomous problem (no explicit t; the row sums do not matter there): %d\n", autonomous);
  if (!tableau.b_embedded.empty())
    std::printf("%s\n", claim_line("embedded order", tableau.embedded_order, check.embedded_order, check.embedded_max_order).c_str());

  const std::vector<const OrderCondition*> failed = check.failed_claims();
  if (failed.empty()) {
    std::printf("PASS: the claimed order%s met, to round-off\n", tableau.b_embedded.empty() ? " is" : "s are");
    return kExitDone;
  }
  std::printf("FAIL: %s", failed.front()->failure().c_str());
  if (failed.size() > 1) std::printf(" (and %zu more)", failed.size() - 1);
  std::printf("\n");
  return kExitCheckFailed;
}

}  // namespace dlpverify::cli
