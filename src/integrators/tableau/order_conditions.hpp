// The order conditions of an explicit or diagonally implicit Runge–Kutta method, evaluated
// numerically (Butcher's rooted trees; Hairer, Nørsett & Wanner, Solving ODEs I, §II.2; the sums
// over j run to i, so a DIRK's diagonal counts as the conditions require):
//
//   row sums          c_i = Σ_j a_ij                         (the stage times of a problem with t)
//   tree t, |t| ≤ 6   Φ(t) = Σ_i b_i Φ_i(t) = 1/γ(t),
//                     Φ_i(τ) = 1,  Φ_i([t_1 … t_m]) = Π_k Σ_j a_ij Φ_j(t_k),
//                     γ(τ) = 1,    γ([t_1 … t_m]) = |t| Π_k γ(t_k)
//
// A method has order p on every smooth autonomous problem iff Φ(t) = 1/γ(t) for all trees of
// |t| ≤ p; on a problem with explicit time (y' = f(t, y), autonomised with t' = 1) the stage times
// must also be the row sums when p ≥ 2 (for p = 1, Σ b_i = 1 suffices whatever the nodes). The
// trees use Σ_j a_ij where a formula shows c_i, so a slipped node shows in its row sum alone.
//
// Written by hand: no Debian library enumerates rooted trees or returns a tableau's conditions one
// by one. SUNDIALS' ARKodeButcherTable_CheckOrder (up to order 6) gives only the order reached and
// prints its findings to a FILE*, with a tolerance of its own; the tableau command names each
// condition with its residual, and the study's warning names the failed one.
#pragma once

#include <string>
#include <vector>

#include "integrators/tableau/tableau_file.hpp"

namespace dlpverify {

// A rooted tree as its children, each a tree (canonical: children sorted).
struct RootedTree {
  std::vector<RootedTree> children;
  int order() const;    // |t|, its number of nodes
  long density() const; // γ(t)
  bool operator<(const RootedTree& other) const;
  bool operator==(const RootedTree& other) const;
};

// Every rooted tree of order 1 … max_order (≤ 10), by order, each once (1, 1, 2, 4, 9, 20, …).
std::vector<RootedTree> rooted_trees(int max_order);

struct OrderCondition {
  std::string name;      // "row sum c_2", "order 3: Σ b_i c_i² = 1/3"
  int order = 0;         // the order that needs it: a row sum counts for order 2
  double value = 0.0;    // Φ(t), or Σ_j a_ij for a row sum
  double expected = 0.0; // 1/γ(t), or c_i
  double residual = 0.0; // value − expected
  double tolerance = 0.0;     // round-off of the sum: 1e-12 × the sum of its terms' magnitudes
  bool to_round_off = false;  // |residual| ≤ tolerance
  bool met = false;           // to round-off, or to the digits a printed table keeps: |residual| ≤ 1e-10 × that sum
  std::string failure() const;  // "row sum c_2 = 0.6 but Σ_j a_2j = 0.5"; for a tree, its value beside 1/γ
};

// The row sums of the tableau, one per stage.
std::vector<OrderCondition> row_sum_conditions(const RuntimeTableau& tableau);
// The tree conditions of the weights b_i (`embedded`: the embedded weights b̂_i) for |t| ≤ max_order.
std::vector<OrderCondition> tree_conditions(const RuntimeTableau& tableau, int max_order, bool embedded = false);

// The highest p ≤ max_order with every condition of order ≤ p met (row sums count for p ≥ 2);
// 0 when Σ b_i ≠ 1.
int achieved_order(const std::vector<OrderCondition>& conditions, int max_order);

// What a tableau is checked against: the row sums and the trees up to min(6, order + 1) for b,
// and for the embedded weights when there are some.
struct TableauCheck {
  std::vector<OrderCondition> row_sums, trees, embedded_trees;
  int max_order = 0, embedded_max_order = 0;  // the orders checked, min(6, claimed + 1)
  int order = 0, embedded_order = 0;          // achieved (≤ the orders checked)
  int order_claimed = 0, embedded_order_claimed = 0;  // the file's (embedded: 0 when none)
  // The conditions the claims rely on (row sums when order ≥ 2, trees up to the claimed orders)
  // that fail, in the order printed.
  std::vector<const OrderCondition*> failed_claims() const;
};
TableauCheck check_tableau(const RuntimeTableau& tableau);

}  // namespace dlpverify
