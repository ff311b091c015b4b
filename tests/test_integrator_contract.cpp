// The contract every integrator keeps (include/dlpverify/integrator.hpp), checked once for each
// name the registry knows (cli::known_study_integrators: the Runge–Kutta family, CVODE, every
// ARKODE explicit table, the implicit and gas schemes, exec:COMMAND, tableau:FILE), in the pattern of
// Boost.Odeint's integrate test, which runs each integrate function over a list of steppers. A
// new integrator is covered by registering it; an entry no case can run fails the test.
//
//   lands    advance(t0, Δt, n) ends at t0 + n·Δt: on a problem every method integrates exactly
//            (the DLP `similarity` case, y' constant), the state equals the closed form at n·Δt
//            to round-off, and one step more or less would be |v|·Δt away;
//   zero     zero steps leave the state as it was, bit for bit;
//   refuses  a time step of 0, −Δt, NaN or ∞ and a negative step count are refused with the
//            quantity named ("time step", "step count") and the state untouched;
//   counts   the statistics name the steps taken (n for a fixed step); a built-in Runge–Kutta
//            method and tableau:FILE evaluate the right-hand side once per stage, s·n times, s
//            read from the tableau itself; ARKODE's count is its own nfe, which also holds the
//            evaluations ARKODE makes beyond the stages (f(t0, y0) before the first step, and
//            for some tables one or more a step at each stop time), so more than s·n; CVODE
//            reports positive steps and evaluations and its rejected steps (error-test
//            failures, ≥ 0); others at least one evaluation a step where they report them;
//   threads  1, 2 and 3 OpenMP threads give the same bits (the DLP `drag` case: 4 blocks of
//            members, so threads split the work);
//   reach    an entry whose traits say it steps each member alone (IntegratorTraits::Reach::
//            each_member, what lets mpirun give a rank's share the serial bits) advances members
//            100 … 156 alone, as a SubPopulation, to the bits of the same rows of the whole run.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <omp.h>

#include "cli/problems.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/errors.hpp"
#include "dlpverify/integrator.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "harness/sub_population.hpp"
#include "integrators/sundials/arkode_erk_integrator.hpp"

namespace unit_integrator_contract {

using namespace dlpverify;

namespace {

// The registry's name with its placeholder filled: exec:COMMAND runs the Python example of an
// external integrator (explicit midpoint on the exchange file), tableau:FILE the midpoint file.
std::string runnable_name(const std::string& registered) {
  if (registered == "exec:COMMAND")
    return std::string("exec:/usr/bin/python3 ") + DLPVERIFY_SOURCE_DIR +
           "/examples/external/python/midpoint.py {input} {output}";
  if (registered == "tableau:FILE") return std::string("tableau:") + DLPVERIFY_SOURCE_DIR + "/examples/tableaux/midpoint.toml";
  return registered;
}

// A small problem of the case: the DLP lattice of R_out 4 (257 particles), 256 gas parcels.
std::unique_ptr<Problem> small_problem(const std::string& case_name) {
  cli::ProblemOptions o;
  o.case_name = case_name;
  o.outer = 4;
  o.gas.parcels = 256;
  cli::fill_case_defaults(o);
  return cli::make_problem(o);
}

// An integrator and the cases it is checked on: `exact`, whose closed form it must reproduce at
// the end of the run, and `busy`, for the threads (the DLP's when it takes them, else its own
// family's first case).
struct Subject {
  std::string name;
  std::unique_ptr<Integrator> integrator;
  std::string exact_case, busy_case;
  double dt = 0.0;  // [s]
};

Subject make_subject(const std::string& name) {
  // The DLP's 2 ms are its cases' scale; the gas parcels' paths have a period of 1 ms, and a step
  // of 1 µs keeps a first-order scheme's error over 8 steps far below the change over one step.
  struct Cases {
    const char *exact, *busy;
    double dt;
  };
  static const Cases kCases[] = {{"similarity", "drag", 2.5e-4}, {"adiabat-ideal", "adiabat-ideal", 1e-6}};
  for (const Cases& c : kCases) {
    try {
      return {name, cli::make_study_integrator(name, CvodeSettings{}, c.exact), c.exact, c.busy, c.dt};
    } catch (const InputError&) {
    }
  }
  return {name, nullptr, "", "", 0.0};
}

double max_abs_difference(const State& a, const State& b) { return (a - b).abs().maxCoeff(); }

bool bitwise_equal(const State& a, const State& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && (a == b).all();
}

// The quantity an advance() with this step is refused for, or "" when it is taken.
std::string refused_quantity(Subject& s, const Problem& problem, State& state, double dt, long steps) {
  try {
    s.integrator->advance(problem, state, problem.initial_time(), dt, steps);
  } catch (const InputError& e) {
    return e.quantity();
  }
  return "";
}

constexpr long kSteps = 8;

// The stages s of a Runge–Kutta method by its registered name, from its tableau (the built-in
// tableaux' b, SUNDIALS' table, examples/tableaux/midpoint.toml's two rows); none otherwise.
std::optional<long> runge_kutta_stages(const std::string& registered) {
  if (registered == "rk2") return static_cast<long>(tableau::midpoint.b.size());
  if (registered == "euler") return static_cast<long>(tableau::euler.b.size());
  if (registered == "heun") return static_cast<long>(tableau::heun.b.size());
  if (registered == "rk4") return static_cast<long>(tableau::rk4.b.size());
  if (registered == "tableau:FILE") return 2L;
  for (const ArkodeTableInfo& table : arkode_erk_tables())
    if (registered == "arkode-erk:" + table.name) return static_cast<long>(table.stages);
  return std::nullopt;
}

void check_lands(Subject& s, const std::string& registered) {
  const auto problem = small_problem(s.exact_case);
  const State initial = problem->initial_state();
  State y = initial;
  s.integrator->advance(*problem, y, problem->initial_time(), s.dt, kSteps);
  const State at_end = closed_form(*problem, initial, kSteps * s.dt);
  const double step_away = std::min(max_abs_difference(at_end, closed_form(*problem, initial, (kSteps + 1) * s.dt)),
                                    max_abs_difference(at_end, closed_form(*problem, initial, (kSteps - 1) * s.dt)));
  const double error = max_abs_difference(y, at_end);
  BOOST_TEST_CONTEXT(s.name << " on " << s.exact_case << ": error " << error << ", a step away " << step_away) {
    BOOST_TEST(step_away > 0.0);
    // Exact methods end within round-off; the gas schemes within their truncation error, which
    // is far below the change over one step.
    BOOST_TEST(error <= (s.exact_case == "similarity" ? 1e-9 : 0.05) * step_away);
  }
  const SolverStatistics stats = s.integrator->statistics();
  BOOST_TEST_CONTEXT(s.name << " statistics " << nlohmann::json(stats).dump()) {
    BOOST_REQUIRE(stats.steps.has_value());
    const long steps = *stats.steps;
    if (s.integrator->order() > 0) BOOST_TEST(steps == kSteps);  // a fixed step
    else BOOST_TEST(steps >= 1);
    if (const auto stages = runge_kutta_stages(registered)) {
      BOOST_REQUIRE(stats.rhs_evals.has_value());
      if (registered.rfind("arkode-erk:", 0) == 0) BOOST_TEST(*stats.rhs_evals > *stages * kSteps);
      else BOOST_TEST(*stats.rhs_evals == *stages * kSteps);
    } else if (registered == "cvode") {
      BOOST_REQUIRE(stats.rhs_evals.has_value());
      BOOST_TEST(*stats.rhs_evals > 0);
      BOOST_REQUIRE(stats.error_test_failures.has_value());
      BOOST_TEST(*stats.error_test_failures >= 0);
      BOOST_TEST(stats.nonlinear_iterations.has_value());
    } else if (stats.rhs_evals) {
      BOOST_TEST(*stats.rhs_evals >= steps);
    }
  }
}

void check_zero_steps_and_refusals(Subject& s) {
  const auto problem = small_problem(s.exact_case);
  const State initial = problem->initial_state();
  State y = initial;
  s.integrator->advance(*problem, y, problem->initial_time(), s.dt, 0);
  BOOST_TEST(bitwise_equal(y, initial), s.name << ": zero steps changed the state");
  const SolverStatistics stats = s.integrator->statistics();
  BOOST_TEST(stats.steps.value_or(0) == 0, s.name << ": " << nlohmann::json(stats).dump());
  for (const double dt : {0.0, -s.dt, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    BOOST_TEST(refused_quantity(s, *problem, y, dt, kSteps) == "time step", s.name << " took dt = " << dt);
  BOOST_TEST(refused_quantity(s, *problem, y, s.dt, -1) == "step count", s.name << " took -1 steps");
  BOOST_TEST(bitwise_equal(y, initial), s.name << ": a refused step changed the state");
}

void check_threads(Subject& s) {
  const auto problem = small_problem(s.busy_case);
  std::vector<State> ends;
  const int saved = omp_get_max_threads();
  for (const int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    State y = problem->initial_state();
    s.integrator->advance(*problem, y, problem->initial_time(), s.dt, kSteps);
    ends.push_back(std::move(y));
  }
  omp_set_num_threads(saved);
  BOOST_TEST(bitwise_equal(ends[0], ends[1]), s.name << " on " << s.busy_case << ": 1 and 2 threads differ");
  BOOST_TEST(bitwise_equal(ends[0], ends[2]), s.name << " on " << s.busy_case << ": 1 and 3 threads differ");
}

void check_reach(Subject& s, const IntegratorTraits& traits) {
  if (traits.reach != IntegratorTraits::Reach::each_member) return;
  const auto whole = small_problem(s.busy_case);
  constexpr Eigen::Index kFirst = 100, kCount = 57;
  BOOST_REQUIRE(whole->members() >= kFirst + kCount);
  State all = whole->initial_state();
  s.integrator->advance(*whole, all, whole->initial_time(), s.dt, kSteps);
  const SubPopulation share(*whole, kFirst, kCount);
  State own = share.initial_state();
  s.integrator->advance(share, own, share.initial_time(), s.dt, kSteps);
  BOOST_TEST(bitwise_equal(own, State(all.middleRows(kFirst, kCount))),
             s.name << " on " << s.busy_case << ": members alone differ from the same members in the whole run");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(integrator_contract)

BOOST_AUTO_TEST_CASE(every_registered_integrator_keeps_the_contract) {
  const std::vector<IntegratorInfo> registry = cli::known_study_integrators();
  BOOST_TEST(registry.size() >= 20u);  // rk2, euler, heun, rk4, cvode, the ARKODE tables, …
  for (const IntegratorInfo& info : registry) {
    Subject s = make_subject(runnable_name(info.name));
    BOOST_TEST_MESSAGE("contract: " << info.name);
    BOOST_TEST_CONTEXT("registry entry " << info.name) {
      BOOST_REQUIRE_MESSAGE(s.integrator, "no case of the contract test runs it: cover it in make_subject");
      // tableau:FILE is listed with order 0: its order is the file's (midpoint.toml: 2).
      BOOST_TEST(s.integrator->order() == (info.name == "tableau:FILE" ? 2 : info.order));
      check_zero_steps_and_refusals(s);
      check_lands(s, info.name);
      check_threads(s);
      check_reach(s, info.traits);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_integrator_contract
