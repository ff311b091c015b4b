#include "integrators/tableau/tableau_report.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "integrators/tableau/order_conditions.hpp"
#include "integrators/tableau/stability.hpp"
#include "io/format.hpp"
#include "io/printable.hpp"

namespace dlpverify {

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
// One met to the digits a printed table keeps, not to round-off, says so.
const char* verdict(const OrderCondition& c, int claimed) {
  return c.to_round_off ? "ok" : c.met ? "ok to its digits" : c.order <= claimed ? "FAIL" : "not met";
}

// The conditions the claims rely on that hold to the table's digits only, and the largest of their
// residuals relative to the sum's magnitude (OrderCondition::tolerance is 1e-12 of it).
std::pair<int, double> held_to_digits(const TableauCheck& check) {
  int count = 0;
  double largest = 0.0;
  const int claimed = std::max(check.order_claimed, check.embedded_order_claimed);
  const auto count_in = [&](const std::vector<OrderCondition>& list, int order) {
    for (const OrderCondition& c : list)
      if (c.order <= order && c.met && !c.to_round_off) {
        ++count;
        largest = std::max(largest, std::fabs(c.residual) / c.tolerance * 1e-12);
      }
  };
  count_in(check.row_sums, claimed);
  count_in(check.trees, check.order_claimed);
  count_in(check.embedded_trees, check.embedded_order_claimed);
  return {count, largest};
}

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

TableauVerdict judge_tableau(const RuntimeTableau& tableau) {
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

  // Appended piece by piece: GCC 12 misreads "\n" + std::string&& here (a false -Wrestrict).
  table += "\n";
  table += claim_line("order", tableau.order, check.order, check.max_order) + "\n";
  // The trees alone: the order an autonomous problem (no explicit t) sees, whatever the nodes.
  const int autonomous = achieved_order(check.trees, check.max_order);
  if (autonomous != check.order)
    table += printf_string("  on an autonomous problem (no explicit t; the row sums do not matter there): %d\n", autonomous);
  if (!tableau.b_embedded.empty())
    table += claim_line("embedded order", tableau.embedded_order, check.embedded_order, check.embedded_max_order) + "\n";

  std::optional<TableauStability> stable;
  if (tableau.implicit()) {
    stable = tableau_stability(tableau);
    table += printf_string("stability on y' = lambda y: |R(inf)| = %.3g; A-stable: %s (max |R(iy)| = %.12g on the imaginary "
                           "axis, poles 1/a_ii %s); L-stable: %s\n",
                           stable->r_infinity, stable->a_stable ? "yes" : "no", stable->max_on_axis,
                           stable->poles_right ? "in the right half-plane" : "in the left half-plane",
                           stable->l_stable ? "yes" : "no");
  }

  const std::vector<const OrderCondition*> failed = check.failed_claims();
  std::string outcome;
  const auto [short_count, short_residual] = held_to_digits(check);
  if (failed.empty() && short_count == 0) {
    outcome = std::string("PASS: the claimed order") + (tableau.b_embedded.empty() ? " is" : "s are") + " met, to round-off";
  } else if (failed.empty()) {
    outcome = printf_string("PASS: the claimed order%s met, %d condition%s only to the digits the table keeps (relative "
                            "residual up to %.1e, not round-off): a study sees the order while its errors stay above "
                            "about %.0e of the solution",
                            tableau.b_embedded.empty() ? " is" : "s are", short_count, short_count > 1 ? "s" : "",
                            short_residual, short_residual);
  } else {
    outcome = "FAIL: " + failed.front()->failure();
    if (failed.size() > 1) outcome += " (and " + std::to_string(failed.size() - 1) + " more)";
  }
  table += outcome + "\n";

  TableauVerdict verdict;
  verdict.passed = failed.empty();
  verdict.table = std::move(table);
  verdict.report = {{"tableau", tableau.name},
                    {"file", tableau.source},
                    {"stages", tableau.stages()},
                    {"order_claimed", tableau.order},
                    {"order_met", check.order},
                    {"order_met_autonomous", autonomous},
                    {"conditions", rows},
                    {"passed", failed.empty()},
                    {"conditions_met_to_digits", short_count},
                    {"verdict", outcome}};
  if (stable)
    verdict.report["stability"] = {{"r_infinity", stable->r_infinity},
                                   {"max_on_imaginary_axis", stable->max_on_axis},
                                   {"a_stable", stable->a_stable},
                                   {"l_stable", stable->l_stable}};
  if (!tableau.b_embedded.empty()) {
    verdict.report["embedded_order_claimed"] = tableau.embedded_order;
    verdict.report["embedded_order_met"] = check.embedded_order;
  }
  return verdict;
}

}  // namespace dlpverify
