// The work-precision loop (convergence/work_precision.hpp) on a tiny cloud: a lattice sphere
// R_out = 3 (Δ = 1e-4 m, u_s = 100 m/s), drag only, constant C_D, for 0.01 s, measured against
// the closed form of docs/model.md §4.3.
#include <boost/test/unit_test.hpp>

#include "dlpverify/closed_form.hpp"
#include "problems/dlp/problem.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "dlpverify/norms.hpp"
#include "dlpverify/work_precision.hpp"
#include "problems/dlp/exact/cloud_solution.hpp"
#include "problems/dlp/exact/drag.hpp"
#include "integrators/sundials/cvode_integrator.hpp"
#include "integrators/registry.hpp"
#include "dlpverify/errors.hpp"
#include "problems/dlp/cloud.hpp"
#include "problems/dlp/rates.hpp"

namespace unit_work_precision {

using namespace dlpverify;
using namespace dlpverify::dlp;

namespace {

struct TinyDrag {
  Lattice lattice{Shape::sphere, 3, 1, 1e-4};
  Launch launch{100.0};
  std::unique_ptr<DlpProblem> problem = std::make_unique<DlpProblem>(find_case("drag"), Parameters{}, lattice, launch);
  double t0 = problem->initial_time();
  double t_end = 0.01;
  State initial = problem->initial_state();
  State exact = closed_form(*problem, initial, t_end);
  std::vector<Variable> variables = problem->variables();

  // CVODE to t0 + t_end with atol = rtol × each field's size and no step limit but t_end.
  PrecisionRun cvode(CvodeMethod method, double rtol) const {
    CvodeSettings settings;
    settings.method = method;
    settings.rtol = rtol;
    settings.atol = absolute_tolerances(*problem, initial, rtol);
    return {method == CvodeMethod::adams ? "adams" : "bdf", rtol, std::nullopt, [this, settings](SolverStatistics& statistics) {
              CvodeIntegrator integrator(settings);
              State state = initial;
              integrator.advance(*problem, state, t0, t_end, 1);
              statistics = integrator.statistics();
              return state;
            }};
  }

  PrecisionRun fixed_step(const std::string& name, long steps) const {
    const double dt = t_end / static_cast<double>(steps);
    return {name, std::nullopt, dt, [this, name, dt, steps](SolverStatistics& statistics) {
              const auto integrator = make_integrator(name);
              State state = initial;
              integrator->advance(*problem, state, t0, dt, steps);
              statistics = integrator->statistics();
              return state;
            }};
  }

  WorkPrecisionResult run(const std::vector<PrecisionRun>& runs) const {
    return run_work_precision(runs, exact, {}, variables);
  }

  WorkPrecisionDescription description() const {
    WorkPrecisionDescription d;
    d.case_name = "drag";
    d.reference = "exact";
    d.reference_detail = "docs/model.md §4.3";
    d.particles = initial.rows();
    d.t0 = t0;
    d.t_end = t_end;
    d.options = {{"outer", 3}};
    d.provenance = {{"version", "test"}, {"git_commit", "none"}, {"command_line", "unit test"}};
    return d;
  }
};

// A run that returns the reference itself, reporting the given statistics.
PrecisionRun echo(const State& state, nlohmann::json reported) {
  return {"echo", 1e-6, std::nullopt, [state, reported](SolverStatistics& statistics) {
            statistics = reported.get<SolverStatistics>();
            return state;
          }};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(work_precision)

BOOST_AUTO_TEST_CASE(adams_error_falls_as_rtol_tightens) {
  const TinyDrag drag;
  const WorkPrecisionResult result =
      drag.run({drag.cvode(CvodeMethod::adams, 1e-4), drag.cvode(CvodeMethod::adams, 1e-10)});
  BOOST_TEST_REQUIRE(result.runs.size() == 2u);
  BOOST_TEST_REQUIRE(result.variables[0].name == "position");
  const double loose = result.runs[0].norms[0].l2, tight = result.runs[1].norms[0].l2;
  BOOST_TEST_MESSAGE("adams position L2: rtol 1e-4 " << loose << ", rtol 1e-10 " << tight);
  BOOST_TEST(loose > 0.0);
  BOOST_TEST(tight * 1e3 <= loose, "six decades of rtol buy at least three of position error");
  // Tighter tolerances cost more.
  BOOST_TEST(result.runs[1].steps > result.runs[0].steps);
  BOOST_TEST(result.runs[1].rhs_evals > result.runs[0].rhs_evals);
  for (const auto& run : result.runs) {
    BOOST_TEST(run.rtol.has_value());
    BOOST_TEST(!run.dt.has_value());
    BOOST_TEST(run.wall_seconds >= 0.0);
    BOOST_TEST(!run.reference_limited, "a closed form has no error of its own to be limited by");
    BOOST_TEST(std::get<std::string>(run.solver_statistics.extras.at("method")) == "adams");
  }
}

BOOST_AUTO_TEST_CASE(bdf_counts_its_jacobian_rhs_evaluations) {
  const TinyDrag drag;
  const WorkPrecisionResult result = drag.run({drag.cvode(CvodeMethod::bdf, 1e-6)});
  const auto& run = result.runs.front();
  const long plain = run.solver_statistics.rhs_evals.value();
  const long jacobian = run.solver_statistics.rhs_evals_jacobian.value();
  BOOST_TEST(jacobian > 0);
  BOOST_TEST(run.rhs_evals == plain + jacobian);
}

BOOST_AUTO_TEST_CASE(rk2_reports_two_rhs_evaluations_per_step) {
  const TinyDrag drag;
  const WorkPrecisionResult result = drag.run({drag.fixed_step("rk2", 20), drag.fixed_step("rk2", 40)});
  for (const auto& run : result.runs) {
    BOOST_TEST(run.method == "rk2");
    BOOST_TEST(run.rhs_evals == 2 * run.steps);
    BOOST_TEST(run.dt.has_value());
    BOOST_TEST(!run.rtol.has_value());
    BOOST_TEST(*run.dt * static_cast<double>(run.steps) == drag.t_end, boost::test_tools::tolerance(1e-14));
  }
  BOOST_TEST(result.runs[0].steps == 20);
  BOOST_TEST(result.runs[1].steps == 40);
  // Second order: halving dt divides the position error by about 4 (docs/model.md §3).
  const double ratio = result.runs[0].norms[0].l2 / result.runs[1].norms[0].l2;
  BOOST_TEST(std::log2(ratio) == 2.0, boost::test_tools::tolerance(0.1));
}

BOOST_AUTO_TEST_CASE(json_has_the_keys_the_issue_lists) {
  const TinyDrag drag;
  const WorkPrecisionResult result = drag.run({drag.cvode(CvodeMethod::adams, 1e-6), drag.cvode(CvodeMethod::bdf, 1e-6),
                                               drag.fixed_step("rk2", 20)});
  const nlohmann::json j = to_json(drag.description(), result);
  for (const char* key : {"case", "reference", "reference_detail", "particles", "t_end", "runs", "options", "provenance"})
    BOOST_TEST(j.contains(key), "top-level key " << key);
  BOOST_TEST(j["particles"].get<long long>() == drag.initial.rows());
  BOOST_TEST_REQUIRE(j["runs"].size() == 3u);
  const char* methods[] = {"adams", "bdf", "rk2"};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& run = j["runs"][i];
    BOOST_TEST(run["method"].get<std::string>() == methods[i]);
    for (const char* key : {"rhs_evals", "steps", "wall_s", "l2_position", "l2_velocity", "rel_l2_position",
                            "rel_l2_velocity"})
      BOOST_TEST(run.contains(key), "run " << i << " key " << key);
    // rtol for the adaptive runs, dt for the fixed-step ones: never both.
    BOOST_TEST(run.contains("rtol") == (i < 2));
    BOOST_TEST(run.contains("dt") == (i == 2));
    // The relative norm divides by the solution's own size (docs/model.md §5).
    BOOST_TEST(run["rel_l2_position"].get<double>() ==
                   run["l2_position"].get<double>() / run["norms_position"]["solution_l2"].get<double>(),
               boost::test_tools::tolerance(1e-14));
  }
  BOOST_TEST(j["runs"][2]["rhs_evals"].get<long>() == 2 * j["runs"][2]["steps"].get<long>());
}

BOOST_AUTO_TEST_CASE(json_and_csv_cover_temperature_and_mass_when_active) {
  // The loop is physics-agnostic: any state and any variable groups will do.
  const TinyDrag drag;
  const std::vector<Variable> variables{
      {"position", X, 3, "m"}, {"velocity", VX, 3, "m/s"}, {"temperature", TEMPERATURE, 1, "K"}, {"mass", MASS, 1, "kg"}};
  State perturbed = drag.exact;
  perturbed.col(TEMPERATURE) += 1.0;
  const WorkPrecisionResult result =
      run_work_precision({echo(perturbed, {{"steps", 7}, {"rhs_evals", 9}})}, drag.exact, {}, variables);
  const auto& run = result.runs.front();
  BOOST_TEST(run.steps == 7);
  BOOST_TEST(run.rhs_evals == 9);
  BOOST_TEST(run.norms[0].l2 == 0.0);  // position untouched
  BOOST_TEST(run.norms[2].l2 == std::sqrt(static_cast<double>(drag.initial.rows())), boost::test_tools::tolerance(1e-12));

  const nlohmann::json j = to_json(drag.description(), result);
  for (const char* key : {"l2_temperature", "rel_l2_temperature", "l2_mass", "rel_l2_mass"})
    BOOST_TEST(j["runs"][0].contains(key), "key " << key);

  const std::string csv = format_csv(drag.description(), result);
  BOOST_TEST(csv.rfind("# dlpverify test (commit none, ?): work-precision, case", 0) == 0u);  // io/provenance.hpp csv_header
  BOOST_TEST(csv.find("# command: unit test\n") != std::string::npos);
  BOOST_TEST(csv.find("method,rtol,dt,steps,rhs_evals,wall_s,l2_position,rel_l2_position") != std::string::npos);
  BOOST_TEST(csv.find("l2_mass") != std::string::npos);

  const std::string table = format_table(drag.description(), result);
  BOOST_TEST(table.find("L2 temperature") != std::string::npos);
  BOOST_TEST(table.find("rtol 1.000e-06") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(runs_near_the_reference_error_are_flagged) {
  const TinyDrag drag;
  State perturbed = drag.exact;
  perturbed.col(X) += 1e-9;
  // The reference's own position error ~1e-9 · √N: a run that far off measures the reference.
  const double position_error = 1e-9 * std::sqrt(static_cast<double>(drag.initial.rows()));
  const auto limited = run_work_precision({echo(perturbed, {{"steps", 1}, {"rhs_evals", 1}})}, drag.exact,
                                          {position_error, 0.0}, drag.variables);
  BOOST_TEST(limited.runs[0].reference_limited);
  BOOST_TEST(limited.runs[0].reference_margin[0] == 1.0, boost::test_tools::tolerance(1e-6));  // x up to 0.6 m: ulp(x) / 1e-9 ~ 1e-7
  const auto trusted = run_work_precision({echo(perturbed, {{"steps", 1}, {"rhs_evals", 1}})}, drag.exact,
                                          {position_error / 1000.0, 0.0}, drag.variables);
  BOOST_TEST(!trusted.runs[0].reference_limited);
}

BOOST_AUTO_TEST_CASE(a_solver_failure_names_the_run) {
  const TinyDrag drag;
  const PrecisionRun failing{"bdf", 1e-5, std::nullopt, [](SolverStatistics&) -> State {
                               throw SolverError("CVode failed: CV_TOO_MUCH_WORK");
                             }};
  BOOST_CHECK_EXCEPTION(drag.run({failing}), SolverError, [](const SolverError& e) {
    return std::string(e.what()) == "bdf at rtol 1e-05: CVode failed: CV_TOO_MUCH_WORK";
  });
  // A solver that does not count its work cannot be placed on the work axis.
  BOOST_CHECK_THROW(drag.run({echo(drag.exact, {{"steps", 3}})}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(tolerance_sweep_runs_from_rtol_max_down_to_rtol_min) {
  const std::vector<double> decades = tolerance_sweep(1e-3, 1e-12, 1);
  BOOST_TEST_REQUIRE(decades.size() == 10u);
  for (std::size_t i = 0; i < decades.size(); ++i)
    BOOST_TEST(decades[i] == std::pow(10.0, -3.0 - static_cast<double>(i)), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(decades.back() == 1e-12);  // exactly, as written

  const std::vector<double> thirds = tolerance_sweep(1e-3, 1e-4, 3);
  BOOST_TEST_REQUIRE(thirds.size() == 4u);
  BOOST_TEST(thirds[1] == 1e-3 / std::cbrt(10.0), boost::test_tools::tolerance(1e-11));
  BOOST_TEST(thirds[3] == 1e-4);

  // rtol_min off the grid: the grid stops at its last point above it.
  BOOST_TEST(tolerance_sweep(1e-3, 5e-5, 1) == (std::vector<double>{1e-3, 1e-4}), boost::test_tools::per_element());
  BOOST_TEST(tolerance_sweep(1e-6, 1e-6, 4) == (std::vector<double>{1e-6}), boost::test_tools::per_element());
  BOOST_CHECK_THROW(tolerance_sweep(1e-6, 1e-3, 1), std::invalid_argument);
  BOOST_CHECK_THROW(tolerance_sweep(1e-3, 1e-6, 0), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_work_precision
