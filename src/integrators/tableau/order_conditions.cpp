#include "integrators/tableau/order_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

#include "dlpverify/errors.hpp"

namespace dlpverify {

namespace {

// Round-off of the evaluated sums: Φ(t) nests at most 6 levels, each a recursive sum of at most s
// terms times at most 6 factors, so its rounding error is below about 6 s·u times |Φ|(t), Φ with
// every coefficient by its magnitude (Higham, Accuracy and Stability, §3.1): 1.3e-14 for 20
// stages. Coefficients typed to 17 digits add an ulp each. 1e-12 leaves a factor of 75 over that
// worst case and is still far below any slip a convergence study could see.
constexpr double kRelativeTolerance = 1e-12;
// Tables from the literature are often printed to 11–12 digits (Cash's DIRK 5(2)4 and 5(3)4, as
// SUNDIALS stores them, hold their conditions to 1.5e-11). A residual r of a condition of order q
// adds about r Δt^(q−1) to a study's relative error, so below 1e-10 the method keeps its order in any
// study whose errors stay above 1e-10, within two or three decades of double precision's floor:
// such a condition is met, to the digits stored. (SUNDIALS' own checker allows √ε ≈ 1.5e-8.)
constexpr double kStoredDigitsTolerance = 1e-10;

// Judges c by the residual against the sum's magnitude (every term by its absolute value).
void judge(OrderCondition& c, double magnitude) {
  c.tolerance = kRelativeTolerance * magnitude;
  c.to_round_off = std::fabs(c.residual) <= c.tolerance;
  c.met = std::fabs(c.residual) <= kStoredDigitsTolerance * magnitude;
}

std::string text(double v, int digits) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

const char* power(int n) {
  static const char* const powers[] = {"", "", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  return n < 10 ? powers[n] : "^n";
}

// The factors of Φ_index(t) as a formula: c_i² a_ij c_j …, with fresh index letters.
std::string formula(const RootedTree& t, char index, char& next) {
  std::string f;
  int leaves = 0;
  for (const RootedTree& child : t.children) leaves += child.children.empty();
  if (leaves > 0) f += std::string(" c_") + index + power(leaves);
  for (const RootedTree& child : t.children) {
    if (child.children.empty()) continue;
    const char j = next++;
    f += std::string(" a_") + index + j + formula(child, j, next);
  }
  return f;
}

// Φ_i(t) for every stage i, with |a_ij| in place of a_ij when `magnitude` (the terms' size).
std::vector<double> stage_weights(const RootedTree& t, const std::vector<std::vector<double>>& a, bool magnitude) {
  const std::size_t s = a.size();
  std::vector<double> phi(s, 1.0);
  for (const RootedTree& child : t.children) {
    const std::vector<double> inner = stage_weights(child, a, magnitude);
    for (std::size_t i = 0; i < s; ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j <= i; ++j) sum += (magnitude ? std::fabs(a[i][j]) : a[i][j]) * inner[j];
      phi[i] *= sum;
    }
  }
  return phi;
}

}  // namespace

int RootedTree::order() const {
  int n = 1;
  for (const RootedTree& child : children) n += child.order();
  return n;
}

long RootedTree::density() const {
  long gamma = order();
  for (const RootedTree& child : children) gamma *= child.density();
  return gamma;
}

bool RootedTree::operator<(const RootedTree& other) const {
  const int n = order(), m = other.order();
  if (n != m) return n < m;
  return std::lexicographical_compare(children.begin(), children.end(), other.children.begin(), other.children.end());
}

bool RootedTree::operator==(const RootedTree& other) const { return !(*this < other) && !(other < *this); }

std::vector<RootedTree> rooted_trees(int max_order) {
  if (max_order < 1 || max_order > 10) throw InputError("tree order", std::to_string(max_order), "must lie in [1, 10]");
  // by_order[n]: the trees of order n. A tree of order n is a root over a multiset of trees of
  // total order n − 1; a multiset is enumerated once as a non-increasing sequence of (order, index).
  std::vector<std::vector<RootedTree>> by_order(static_cast<std::size_t>(max_order) + 1);
  by_order[1].push_back(RootedTree{});
  for (int n = 2; n <= max_order; ++n) {
    std::vector<RootedTree>& trees = by_order[static_cast<std::size_t>(n)];
    std::vector<RootedTree> children;
    const std::function<void(int, int, std::size_t)> extend = [&](int remaining, int top_order, std::size_t top_index) {
      if (remaining == 0) {
        RootedTree t{children};
        std::sort(t.children.begin(), t.children.end());
        trees.push_back(std::move(t));
        return;
      }
      for (int k = std::min(remaining, top_order); k >= 1; --k) {
        const std::vector<RootedTree>& of_k = by_order[static_cast<std::size_t>(k)];
        const std::size_t last = k == top_order ? top_index : of_k.size() - 1;
        for (std::size_t index = 0; index <= last; ++index) {
          children.push_back(of_k[index]);
          extend(remaining - k, k, index);
          children.pop_back();
        }
      }
    };
    extend(n - 1, n - 1, by_order[static_cast<std::size_t>(n - 1)].size() - 1);
    std::sort(trees.begin(), trees.end());
  }
  std::vector<RootedTree> all;
  for (const std::vector<RootedTree>& trees : by_order) all.insert(all.end(), trees.begin(), trees.end());
  return all;
}

std::string OrderCondition::failure() const {
  if (name.rfind("row sum", 0) == 0) {
    const std::string i = name.substr(name.find("c_") + 2);
    return name + " = " + text(expected, 10) + " but Σ_j a_" + i + "j = " + text(value, 10);
  }
  return name + " but is " + text(value, 10) + " (residual " + text(residual, 3) + ")";
}

std::vector<OrderCondition> row_sum_conditions(const RuntimeTableau& tableau) {
  std::vector<OrderCondition> conditions;
  for (int i = 0; i < tableau.stages(); ++i) {
    const std::vector<double>& row = tableau.a[static_cast<std::size_t>(i)];
    double sum = 0.0, magnitude = 0.0;
    for (int j = 0; j <= i; ++j) {
      sum += row[static_cast<std::size_t>(j)];
      magnitude += std::fabs(row[static_cast<std::size_t>(j)]);
    }
    OrderCondition c;
    c.name = "row sum c_" + std::to_string(i + 1);
    c.order = 2;
    c.value = sum;
    c.expected = tableau.c[static_cast<std::size_t>(i)];
    c.residual = c.value - c.expected;
    judge(c, magnitude + std::fabs(c.expected));
    conditions.push_back(std::move(c));
  }
  return conditions;
}

std::vector<OrderCondition> tree_conditions(const RuntimeTableau& tableau, int max_order, bool embedded) {
  const std::vector<double>& b = embedded ? tableau.b_embedded : tableau.b;
  std::vector<OrderCondition> conditions;
  for (const RootedTree& t : rooted_trees(max_order)) {
    const std::vector<double> phi = stage_weights(t, tableau.a, false);
    const std::vector<double> size = stage_weights(t, tableau.a, true);
    double value = 0.0, magnitude = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      value += b[i] * phi[i];
      magnitude += std::fabs(b[i]) * size[i];
    }
    const long gamma = t.density();
    char next = 'j';
    OrderCondition c;
    c.order = t.order();
    c.name = std::string(embedded ? "embedded " : "") + "order " + std::to_string(c.order) + ": Σ " +
             (embedded ? "b̂_i" : "b_i") + formula(t, 'i', next) + " = " + (gamma == 1 ? "1" : "1/" + std::to_string(gamma));
    c.value = value;
    c.expected = 1.0 / static_cast<double>(gamma);
    c.residual = value - c.expected;
    judge(c, magnitude + c.expected);
    conditions.push_back(std::move(c));
  }
  return conditions;
}

int achieved_order(const std::vector<OrderCondition>& conditions, int max_order) {
  int p = 0;
  for (int q = 1; q <= max_order; ++q) {
    for (const OrderCondition& c : conditions)
      if (c.order <= q && !c.met) return p;
    p = q;
  }
  return p;
}

std::vector<const OrderCondition*> TableauCheck::failed_claims() const {
  std::vector<const OrderCondition*> failed;
  const int claimed = std::max(order_claimed, embedded_order_claimed);
  for (const OrderCondition& c : row_sums)
    if (!c.met && claimed >= c.order) failed.push_back(&c);
  for (const OrderCondition& c : trees)
    if (!c.met && c.order <= order_claimed) failed.push_back(&c);
  for (const OrderCondition& c : embedded_trees)
    if (!c.met && c.order <= embedded_order_claimed) failed.push_back(&c);
  return failed;
}

TableauCheck check_tableau(const RuntimeTableau& tableau) {
  TableauCheck check;
  check.order_claimed = tableau.order;
  check.embedded_order_claimed = tableau.embedded_order;
  check.row_sums = row_sum_conditions(tableau);
  check.max_order = std::min(6, tableau.order + 1);
  check.trees = tree_conditions(tableau, check.max_order);
  std::vector<OrderCondition> all = check.row_sums;
  all.insert(all.end(), check.trees.begin(), check.trees.end());
  check.order = achieved_order(all, check.max_order);
  if (!tableau.b_embedded.empty()) {
    check.embedded_max_order = std::min(6, tableau.embedded_order + 1);
    check.embedded_trees = tree_conditions(tableau, check.embedded_max_order, true);
    std::vector<OrderCondition> embedded = check.row_sums;
    embedded.insert(embedded.end(), check.embedded_trees.begin(), check.embedded_trees.end());
    check.embedded_order = achieved_order(embedded, check.embedded_max_order);
  }
  return check;
}

}  // namespace dlpverify
