// Users' Butcher tableaux (src/integrators): the TOML reader, the order conditions and the
// run-time Runge–Kutta integrator, each against values the code under test does not compute:
//
//   trees      the number of rooted trees of order 1 … 7 is 1, 1, 2, 4, 9, 20, 48 (OEIS A000081;
//              37 conditions through order 6), the bushy tree's density γ is n, the tall one's n!;
//   orders     the textbook methods meet exactly their published orders: Euler 1, midpoint and
//              Heun 2, Kutta's third-order 3, classical RK4 4 (and not 5), Dormand–Prince 5 (not 6)
//              with its embedded 4 (not 5), and every ARKODE explicit table the order SUNDIALS
//              names it by (its q, up to the 6 checked here);
//   slip       the midpoint rule with c₂ = 0.6 meets every tree condition to order 2 and fails the
//              row sum of c₂ alone, which the warning names;
//   reader     every malformed file is an InputError naming the file and the key;
//   bits       the files of the midpoint rule and RK4 give the built-in rk2 and rk4 bit for bit on
//              the DLP drag case (the same operations in the same order);
//   nodes      on y' = 2t the midpoint file is exact, t² (the rule integrates a line exactly), and
//              the slipped file is off by 0.2 Δt (t_end − t0) (each step adds 1.2 Δt² for Δt²).
#include <boost/test/unit_test.hpp>

#include <arkode/arkode_butcher_erk.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"
#include "integrators/tableau/order_conditions.hpp"
#include "integrators/tableau/tableau_file.hpp"
#include "integrators/tableau/tableau_report.hpp"
#include "integrators/tableau/tableau_integrator.hpp"
#include "integrators/sundials/arkode_erk_integrator.hpp"
#include "sundials/sundials_support.hpp"

namespace unit_tableau_file {

using namespace dlpverify;

namespace {

RuntimeTableau make(std::vector<std::vector<double>> a, std::vector<double> b, std::vector<double> c, int order,
                    std::vector<double> b_embedded = {}, int embedded_order = 0) {
  RuntimeTableau t;
  t.name = "test";
  t.source = "test.toml";
  t.a = std::move(a);
  t.b = std::move(b);
  t.c = std::move(c);
  t.order = order;
  t.b_embedded = std::move(b_embedded);
  t.embedded_order = embedded_order;
  return t;
}

// The order met when checking every condition up to order 6.
int order_to_six(const RuntimeTableau& t, bool embedded = false) {
  std::vector<OrderCondition> all = row_sum_conditions(t);
  const std::vector<OrderCondition> trees = tree_conditions(t, 6, embedded);
  all.insert(all.end(), trees.begin(), trees.end());
  return achieved_order(all, 6);
}

RuntimeTableau dormand_prince() {
  return make({{0, 0, 0, 0, 0, 0, 0},
               {1.0 / 5, 0, 0, 0, 0, 0, 0},
               {3.0 / 40, 9.0 / 40, 0, 0, 0, 0, 0},
               {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0, 0},
               {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0, 0},
               {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0, 0},
               {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0}},
              {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
              {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1}, 5,
              {5179.0 / 57600, 0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40}, 4);
}

std::string source(const std::string& file) { return std::string(DLPVERIFY_SOURCE_DIR) + "/examples/tableaux/" + file; }

// The quantity of the InputError that parsing `text` throws, or "" when it parses.
std::string refusal(const std::string& text) {
  try {
    parse_tableau(text, "user.toml");
  } catch (const InputError& e) {
    return e.quantity();
  }
  return "";
}

const char* const kMidpoint = "name = \"midpoint\"\norder = 2\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n";

// y' = 2t, one field, 70 members (a block of 64 and a partial one); y(t) = t² from y(t0) = t0².
class Ramp final : public Problem {
 public:
  std::string name() const override { return "ramp-in-t"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  std::vector<Variable> variables() const override { return {{"y", 0, 1, "1"}}; }
  Eigen::Index members() const override { return 70; }
  double initial_time() const override { return 0.25; }
  State initial_state() const override { return State::Constant(70, 1, 0.25 * 0.25); }
  void rhs(double t, Eigen::Index, int count, const double* const*, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = 2.0 * t;
  }
};

std::unique_ptr<Problem> small_drag() {
  cli::ProblemOptions o;
  o.case_name = "drag";
  o.outer = 4;  // 257 particles: four full blocks of 64 and a partial one
  cli::fill_case_defaults(o);
  return cli::make_problem(o);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tableau_file)

BOOST_AUTO_TEST_CASE(rooted_tree_counts_and_densities) {
  const std::vector<RootedTree> trees = rooted_trees(7);
  std::map<int, int> per_order;
  for (const RootedTree& t : trees) ++per_order[t.order()];
  const int expected[] = {0, 1, 1, 2, 4, 9, 20, 48};
  for (int n = 1; n <= 7; ++n) BOOST_TEST(per_order[n] == expected[n], "order " << n);
  BOOST_TEST(rooted_trees(6).size() == 37u);
  for (std::size_t i = 0; i < trees.size(); ++i)
    for (std::size_t j = i + 1; j < trees.size(); ++j) BOOST_TEST(!(trees[i] == trees[j]), "trees " << i << ", " << j);
  // Bushy [τ … τ]: γ = n; tall [[…[τ]…]]: γ = n!.
  long factorial = 1;
  for (int n = 1; n <= 7; ++n) {
    factorial *= n;
    RootedTree bushy, tall;
    bushy.children.assign(static_cast<std::size_t>(n - 1), RootedTree{});
    for (int k = 1; k < n; ++k) tall = RootedTree{{tall}};
    BOOST_TEST(bushy.density() == n);
    BOOST_TEST(tall.density() == factorial);
  }
  // Names read as the textbook writes the conditions.
  const RuntimeTableau rk4 = read_tableau_file(source("rk4.toml"));
  std::vector<std::string> names;
  for (const OrderCondition& c : tree_conditions(rk4, 4)) names.push_back(c.name);
  for (const char* name : {"order 1: Σ b_i = 1", "order 2: Σ b_i c_i = 1/2", "order 3: Σ b_i c_i² = 1/3",
                           "order 3: Σ b_i a_ij c_j = 1/6", "order 4: Σ b_i a_ij a_jk c_k = 1/24"})
    BOOST_TEST((std::find(names.begin(), names.end(), name) != names.end()), name);
}

BOOST_AUTO_TEST_CASE(textbook_methods_meet_their_orders) {
  BOOST_TEST(order_to_six(make({{0}}, {1}, {0}, 1)) == 1);
  BOOST_TEST(order_to_six(make({{0, 0}, {0.5, 0}}, {0, 1}, {0, 0.5}, 2)) == 2);
  BOOST_TEST(order_to_six(make({{0, 0}, {1, 0}}, {0.5, 0.5}, {0, 1}, 2)) == 2);
  BOOST_TEST(order_to_six(make({{0, 0, 0}, {0.5, 0, 0}, {-1, 2, 0}}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, {0, 0.5, 1}, 3)) == 3);
  BOOST_TEST(order_to_six(read_tableau_file(source("rk4.toml"))) == 4);
  const RuntimeTableau dp = dormand_prince();
  BOOST_TEST(order_to_six(dp) == 5);
  BOOST_TEST(order_to_six(dp, true) == 4);
  const TableauCheck check = check_tableau(dp);
  BOOST_TEST(check.order == 5);
  BOOST_TEST(check.embedded_order == 4);
  BOOST_TEST(check.failed_claims().empty());
  const TableauCheck pair = check_tableau(read_tableau_file(source("bogacki-shampine.toml")));
  BOOST_TEST(pair.order == 3);
  BOOST_TEST(pair.embedded_order == 2);
  BOOST_TEST(pair.failed_claims().empty());
}

// SUNDIALS names each table by its order q (ARKODE_DORMAND_PRINCE_7_4_5: q = 5); the trees must
// find that order (or at least 6, the highest checked), and the embedding's p where it has one.
BOOST_AUTO_TEST_CASE(arkode_tables_meet_their_published_orders) {
  int tables = 0;
  for (const ArkodeTableInfo& info : arkode_erk_tables()) {
    sun::ButcherTable table(ARKodeButcherTable_LoadERKByName(info.name.c_str()));
    BOOST_TEST_REQUIRE(table.get() != nullptr, info.name);
    const int s = table->stages;
    std::vector<std::vector<double>> a(static_cast<std::size_t>(s), std::vector<double>(static_cast<std::size_t>(s)));
    std::vector<double> b(static_cast<std::size_t>(s)), c(static_cast<std::size_t>(s)), d;
    for (int i = 0; i < s; ++i) {
      for (int j = 0; j < s; ++j) a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = table->A[i][j];
      b[static_cast<std::size_t>(i)] = table->b[i];
      c[static_cast<std::size_t>(i)] = table->c[i];
      if (table->d) d.push_back(table->d[i]);
    }
    const RuntimeTableau t = make(a, b, c, info.order, d, d.empty() ? 0 : info.embedding_order);
    BOOST_TEST(order_to_six(t) == std::min(6, info.order), info.name);
    if (!d.empty()) BOOST_TEST(order_to_six(t, true) == std::min(6, info.embedding_order), info.name << " embedded");
    ++tables;
  }
  BOOST_TEST(tables >= 10);
}

BOOST_AUTO_TEST_CASE(slipped_node_fails_its_row_sum_alone) {
  const RuntimeTableau slipped = read_tableau_file(source("midpoint-slipped-c2.toml"));
  const TableauCheck check = check_tableau(slipped);
  BOOST_TEST(check.order == 1);
  BOOST_TEST(achieved_order(check.trees, 3) == 2);  // what an autonomous problem sees
  const std::vector<const OrderCondition*> failed = check.failed_claims();
  BOOST_TEST_REQUIRE(failed.size() == 1u);
  BOOST_TEST(failed.front()->name == "row sum c_2");
  BOOST_TEST(failed.front()->residual == 0.5 - 0.6);
  BOOST_TEST(tableau_warning(slipped) ==
             "tableau " + slipped.source + ": row sum c_2 = 0.6 but Σ_j a_2j = 0.5");
  BOOST_TEST(tableau_warning(read_tableau_file(source("midpoint.toml"))).empty());
  // The warning waits for the first advance (bad input found after making the integrator stays
  // one line), then is written once per file, however often a study makes and runs it.
  std::ostringstream warnings;
  const Ramp problem;
  for (int made = 0; made < 2; ++made) {
    const auto integrator = make_tableau_integrator(source("midpoint-slipped-c2.toml"), warnings);
    if (made == 0) BOOST_TEST(warnings.str().empty());
    for (int run = 0; run < 2; ++run) {
      State y = problem.initial_state();
      integrator->advance(problem, y, problem.initial_time(), 0.01, 2);
    }
  }
  BOOST_TEST(warnings.str() == "dlpverify: warning: tableau " + slipped.source + ": row sum c_2 = 0.6 but Σ_j a_2j = 0.5\n");
}

BOOST_AUTO_TEST_CASE(malformed_files_name_the_key) {
  BOOST_TEST(refusal(kMidpoint) == "");
  const RuntimeTableau m = parse_tableau(kMidpoint, "user.toml");
  BOOST_TEST(m.name == "midpoint");
  BOOST_TEST(m.order == 2);
  BOOST_TEST(m.a[1][0] == 0.5);
  // Integers are numbers too.
  BOOST_TEST(refusal("name = \"euler\"\norder = 1\nc = [0]\nb = [1]\nA = [[0]]\n") == "");
  const std::string head = "name = \"m\"\norder = 2\n";
  const std::pair<std::string, std::string> cases[] = {
      {"order = 2\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: name"},
      {"name = \"m\"\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: order"},
      {head + "b = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: c"},
      {head + "c = [0.0, 0.5]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: b"},
      {head + "c = [0.0, 0.5]\nb = [0.0, 1.0]\n", "tableau user.toml: A"},
      {head + "c = [0.0, 0.5, 1.0]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: c"},
      {head + "c = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0]]\n", "tableau user.toml: A"},
      {head + "c = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5]]\n", "tableau user.toml: A[2]"},
      {head + "c = [0.0, 0.5]\nb = [0.0, \"one\"]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: b[2]"},
      {head + "c = [0.0, nan]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: c[2]"},
      {head + "c = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [inf, 0.0]]\n", "tableau user.toml: A[2][1]"},
      {head + "c = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.5, 0.2], [0.5, 0.5]]\n", "tableau user.toml: A[1][2]"},
      {head + "c = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.1], [0.5, 0.0]]\n", "tableau user.toml: A[1][2]"},
      {head + "c = 0.5\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: c"},
      {"name = \"m\"\norder = -2\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: order"},
      {"name = \"m\"\norder = 2.5\nc = [0.0, 0.5]\nb = [0.0, 1.0]\nA = [[0.0, 0.0], [0.5, 0.0]]\n", "tableau user.toml: order"},
      {std::string(kMidpoint) + "b_embedded = [1.0, 0.0]\n", "tableau user.toml: embedded_order"},
      {std::string(kMidpoint) + "embedded_order = 1\n", "tableau user.toml: b_embedded"},
      {std::string(kMidpoint) + "b_embedded = [1.0]\nembedded_order = 1\n", "tableau user.toml: b_embedded"},
      {std::string(kMidpoint) + "stages = 2\n", "tableau user.toml: stages"},
      {"name = \"m\"\norder = 2\nc = [0.0, 0.5\n", "tableau user.toml"},
  };
  for (const auto& [text, quantity] : cases) BOOST_TEST(refusal(text) == quantity, text);
  BOOST_CHECK_THROW(read_tableau_file("no-such-file-dlpverify.toml"), InputError);
}

// The same coefficients, the same operations: the file's method is the built-in one, bit for bit.
BOOST_AUTO_TEST_CASE(files_give_the_built_in_bits) {
  const auto problem = small_drag();
  for (const auto& [file, built_in] : {std::pair{"midpoint.toml", "rk2"}, std::pair{"rk4.toml", "rk4"}}) {
    const auto from_file = cli::make_study_integrator("tableau:" + source(file), CvodeSettings{}, "drag");
    const auto reference = cli::make_study_integrator(built_in, CvodeSettings{}, "drag");
    State y = problem->initial_state(), z = problem->initial_state();
    const double dt = 2.5e-4;
    from_file->advance(*problem, y, problem->initial_time(), dt, 40);
    reference->advance(*problem, z, problem->initial_time(), dt, 40);
    BOOST_TEST(from_file->order() == reference->order(), file);
    BOOST_TEST((y - problem->initial_state()).abs().maxCoeff() > 0.0, file << ": the state moved");
    BOOST_TEST((y == z).all(), file << " and " << built_in << " differ by " << (y - z).abs().maxCoeff());
    BOOST_TEST((from_file->statistics() == reference->statistics()), file);
  }
}

// y' = 2t from t0 = 0.25 over 1, N = 64 steps: midpoint exact; slipped c₂ = 0.6 adds 0.2 Δt² a step.
BOOST_AUTO_TEST_CASE(stages_are_taken_at_their_nodes) {
  const Ramp problem;
  const long steps = 64;
  const double dt = 1.0 / 64.0, t_end = 1.25;
  for (const auto& [file, expected] :
       {std::pair{"midpoint.toml", t_end * t_end}, std::pair{"midpoint-slipped-c2.toml", t_end * t_end + 0.2 * dt}}) {
    TableauIntegrator integrator(read_tableau_file(source(file)));
    State y = problem.initial_state();
    integrator.advance(problem, y, problem.initial_time(), dt, steps);
    BOOST_TEST((y - expected).abs().maxCoeff() <= 1e-14, file << ": " << y(0, 0) << " against " << expected);
  }
}

// The verdict of `dlpverify tableau`: Heun's rule passes at order 2; claimed as order 3 it fails
// on b·c² = 1/3 (b·c² = 1/2 for c = (0, 1)), and a condition above a claim is "not met", not FAIL.
BOOST_AUTO_TEST_CASE(the_tableau_verdict_fails_only_a_claimed_condition) {
  const RuntimeTableau heun = make({{0.0, 0.0}, {1.0, 0.0}}, {0.5, 0.5}, {0.0, 1.0}, 2);
  const TableauVerdict pass = judge_tableau(heun);
  BOOST_TEST(pass.passed);
  BOOST_TEST(pass.report.at("order_met").get<int>() == 2);
  BOOST_TEST(pass.table.find("not met") != std::string::npos);  // order-3 conditions, above the claim
  BOOST_TEST(pass.table.find("FAIL") == std::string::npos);
  RuntimeTableau claimed_three = heun;
  claimed_three.order = 3;
  const TableauVerdict fail = judge_tableau(claimed_three);
  BOOST_TEST(!fail.passed);
  BOOST_TEST(fail.report.at("passed").get<bool>() == false);
  BOOST_TEST(fail.report.at("verdict").get<std::string>().rfind("FAIL: ", 0) == 0u);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_tableau_file
