#include "cli/failure.hpp"

#include <iostream>
#include <new>
#include <utility>

#include "dlpverify/level_stop.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

std::string input_error_line(const InputError& e) {
  static const std::pair<const char*, const char*> options[] = {
      {"time step", "--dt"},           {"step ratio", "--ratio"},          {"duration", "--t-end"},
      {"case", "--case"},              {"integrator", "--integrator"},     {"reference", "--reference"},
      {"relative tolerance", "--rtol"}, {"absolute tolerance", "--atol"},  {"CVODE step limit", "--max-steps"},
      {"reference pressure P0", "--p-ref"},     {"reference temperature T0", "--t-ref"},
      {"molar mass M_g", "--molar-mass"},      {"reference density rho0", "--rho0"},
      {"ratio of specific heats gamma", "--gamma"}, {"van der Waals a", "--vdw-a"},
      {"van der Waals b", "--vdw-b"},          {"van der Waals constants a, b", "--vdw-a, --vdw-b"},
      {"parcels", "--parcels"},                {"path period", "--period"},
      {"deepest compression J_min, low end", "--j-min-low"}, {"deepest compression J_min, high end", "--j-min-high"},
      {"initial temperature spread", "--t-spread"},
      {"time steps", "--dt"},                  {"reference check", "--reference-check"},
      {"variable", "--variable"},              {"variables file", "--variables"},
      {"expected order", "--expect-order"},
      {"level search", "--levels"},           {"baseline", "--baseline"},
      {"levels", "--levels"},                  {"level search budget", "--budget"},
      {"order interval half-width", "--order-ci"},
      {"declared order", "--exec-order"},      {"program timeout", "--exec-timeout"},
      {"reference relative tolerance", "--reference-rtol"}, {"precision", "--precision"}};
  if (e.quantity().empty()) return e.what();
  std::string option = e.quantity();
  for (const auto& [quantity, name] : options)
    if (e.quantity() == quantity) option = name;
  return option + " = " + printable(e.value()) + ": " + e.reason();
}

std::string verdict_exit_codes() {
  return "exit " + std::to_string(kExitDone) + " pass, " + std::to_string(kExitCheckFailed) + " fail, " +
         std::to_string(kExitInconclusive) + " inconclusive";
}

void report(const std::string& line) { std::cerr << "dlpverify: " << printable(line, 400) << "\n"; }

Failure failure_of(std::exception_ptr failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const InputError& e) {
    return {kExitBadInput, input_error_line(e)};
  } catch (const OutputError& e) {
    return {kExitOutputFailed, e.what()};
  } catch (const SolverError& e) {
    return {kExitSolverFailed, e.what()};
  } catch (const LevelAbandoned& e) {
    // A study without a journal of its own (a suite's tolerance sweep) stopped by a signal.
    return {kExitStoppedBySignal, e.what()};
  } catch (const std::bad_alloc&) {
    return {kExitSolverFailed, "out of memory (try a smaller --outer or --parcels)"};
  } catch (const std::exception& e) {
    return {kExitSolverFailed, e.what()};
  }
}

}  // namespace dlpverify::cli
