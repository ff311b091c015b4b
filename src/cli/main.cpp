// The dlpverify command: the one error boundary. Every failure becomes one line on stderr and a
// documented exit code: 0 done, 1 a check failed, 2 bad input, 3 a solver failed, 4 an output
// could not be written, 5 a check could not decide (docs/verification.md, "Exit codes").
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/audit_command.hpp"
#include "cli/command_line.hpp"
#include "cli/compress_command.hpp"
#include "cli/failure.hpp"
#include "cli/plot_command.hpp"
#include "cli/problems.hpp"
#include "cli/precision_command.hpp"
#include "cli/study_command.hpp"
#include "cli/suite_command.hpp"
#include "integrators/registry.hpp"
#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/printable.hpp"
#include "io/progress.hpp"
#include "io/standard_output.hpp"
#include "harness/distribution.hpp"
#ifdef DLPVERIFY_MPI
#include "mpi/nvector_distributed.hpp"
#include "mpi/session.hpp"
#include "sundials/population_vector.hpp"
#endif

namespace {

using namespace dlpverify;
using cli::failure_of;
using cli::Failure;
using cli::report;

void print_cases() {
  std::printf("%-13s %-9s %s\n", "case", "reference", "terms on");
  for (const cli::CaseEntry& c : cli::all_cases()) {
    std::printf("%-13s %-9s %s\n", c.name.c_str(), c.closed_form ? "exact" : "cvode", c.terms.c_str());
    std::printf("%-23s %s\n", "", c.summary.c_str());
    std::printf("%-23s %s\n", "", c.reference_detail.c_str());
    std::printf("%-23s defaults: t-end %g s, dt %g s, %d levels\n", "", c.defaults.t_end, c.defaults.dt, c.defaults.levels);
  }
  std::printf("\n%-43s %5s  %s\n", "integrator", "order", "what");
  for (const auto& i : cli::known_study_integrators())
    std::printf("%-43s %5s  %s\n", i.name.c_str(), i.order > 0 ? std::to_string(i.order).c_str() : "var", i.summary.c_str());
  std::printf("\n%-46s %5s  %s\n", "adaptive integrator (--tolerances)", "order", "what");
  for (const auto& i : adaptive_integrators())
    std::printf("%-46s %5s  %s\n", i.name.c_str(), i.order > 0 ? std::to_string(i.order).c_str() : "var", i.summary.c_str());
  std::printf("%-46s %5s  %s\n", "exec:COMMAND", "var", "your own program with {rtol} (and {atol}) in COMMAND");
}

std::string join(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) line += (i ? " " : "") + std::string(argv[i]);
  return line;
}

int run(int argc, char** argv) {
  cli::CommandLine line;
  try {
    line.parse(line.with_study_file({argv + 1, argv + argc}));
  } catch (const CLI::ParseError& e) {
    return line.app.exit(e);  // --help, --version (parse() turns every other ParseError into InputError)
  }

  // Under mpirun the ranks share a study's members (docs/mpi.md); other commands run on one process.
  if (distribution().ranks() > 1 && !line.converge->parsed() && !line.check->parsed() && !line.precision->parsed() &&
      !line.app.get_subcommands().empty())
    throw InputError("command", line.app.get_subcommands().front()->get_name(),
                     "runs on one process; under mpirun only converge, check and precision share out the members "
                     "(docs/mpi.md)");
  const std::string command_line = join(argc, argv);
  // The progress of long work (io/progress.hpp), for the commands that have --quiet: a line rewritten
  // in place on a terminal, whole lines in a CI's log.
  const bool long_work = line.converge->parsed() || line.check->parsed() || line.precision->parsed() ||
                         line.compress->parsed();
  const bool shown = long_work && !line.quiet && distribution().rank() == 0;
  progress::enable(!shown                               ? progress::Mode::off
                   : progress::stderr_is_terminal()     ? progress::Mode::terminal
                   : progress::stderr_is_ci_log()       ? progress::Mode::log
                                                        : progress::Mode::off);
  if (line.converge->parsed()) return cli::run_converge_command(line.converge_options, command_line);
  if (line.check->parsed()) return cli::run_check_command(line.check_options, command_line);
  if (line.precision->parsed()) return cli::run_precision_command(line.precision_options, command_line);
  if (line.audit->parsed()) return cli::run_audit_command(line.audit_options, command_line);
  if (line.plot->parsed()) return cli::run_plot_command(line.plot_command);
  if (line.bench->parsed()) return cli::run_bench_command(line.bench_options, command_line);
  if (line.stagger->parsed()) return cli::run_stagger_command(line.stagger_options, command_line);
  if (line.compress->parsed()) return cli::run_compress_command(line.compress_options, command_line);
  if (line.tableau->parsed()) return cli::run_tableau_command(line.tableau_options, command_line);
  if (line.compare->parsed()) return cli::run_compare_command(line.compare_options, command_line);
  if (line.sharpness->parsed()) return cli::run_sharpness_command(line.sharpness_options, command_line);
  if (line.analyze->parsed()) return cli::run_analyze_command(line.analyze_options, command_line);
  if (line.suite->parsed()) return cli::run_suite_command(line.suite_options, command_line);
  print_cases();
  return kExitDone;
}

}  // namespace

#ifdef DLPVERIFY_MPI
// Every rank runs the command on its share; they end together with one outcome, which rank 0
// prints (src/mpi/session.hpp).
int run_under_mpi(int argc, char** argv) {
  mpi::Session session(argc, argv);
  sun::install_rank_spanning_vector(mpi::distributed_vector);  // CVODE's and ARKODE's sums over every rank
  mpi::Outcome outcome;
  try {
    outcome = session.finish(run(argc, argv));
  } catch (const mpi::PeerFailed& e) {
    outcome = e.outcome();
  } catch (...) {
    const Failure failure = failure_of(std::current_exception());
    outcome = session.fail(failure.code, failure.line);
  }
  if (!outcome.line.empty()) report(outcome.line);  // ranks other than 0 print to /dev/null
  return outcome.code;
}
#endif

int main(int argc, char** argv) {
  report_file_size_limit_as_error();
#ifdef DLPVERIFY_MPI
  if (mpi::launched_by_mpi()) return run_under_mpi(argc, argv);
#endif
  try {
    require_open_standard_output();
    const int code = run(argc, argv);
    check_standard_output();  // the console table on a full disk is an output not written
    return code;
  } catch (...) {
    const Failure failure = failure_of(std::current_exception());
    report(failure.line);
    return failure.code;
  }
}
