// The exchange of exec: integrators (docs/exchange.md): an exchange file reads back bit for bit,
// in member order; what is wrong in an output is named; the command splits like a shell's words
// without a shell; placeholders are filled inside words; the stderr tail keeps the last lines.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "dlpverify/dlp.hpp"
#include "exchange/command_runner.hpp"
#include "exchange/command_template.hpp"
#include "exchange/exchange_file.hpp"
#include "integrators/exec/exec_integrator.hpp"

namespace unit_exchange {

using namespace dlpverify;
using namespace dlpverify::exchange;

namespace {

std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("dlpverify-test-exchange-" + name)).string();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(exchange)

BOOST_AUTO_TEST_CASE(file_reads_back_bit_for_bit) {
  const auto problem = dlp::make_problem("full", {.outer = 3});
  State state = problem->initial_state();
  state(5, 3) = std::nextafter(1.0, 2.0);  // a value that only an exact round trip keeps
  const std::string path = temporary_path("roundtrip.h5");
  write_exchange_file(path, *problem, state, {.t0 = 1e-4, .dt = 5e-4, .steps = 20, .threads = 2});
  State back;
  read_exchange_fields(path, *problem, back);
  std::filesystem::remove(path);
  BOOST_REQUIRE_EQUAL(back.rows(), state.rows());
  BOOST_REQUIRE_EQUAL(back.cols(), state.cols());
  BOOST_TEST((back == state).all());
}

BOOST_AUTO_TEST_CASE(missing_output_is_named) {
  const auto problem = dlp::make_problem("drag", {.outer = 2});
  State state;
  try {
    read_exchange_fields(temporary_path("never-written.h5"), *problem, state);
    BOOST_FAIL("no error");
  } catch (const ExchangeError& e) {
    BOOST_TEST(std::string(e.what()).find("wrote no output file") != std::string::npos);
  }
}

// The domain of a program's settings, at its edges: a declared order in [0, 20], a timeout in
// (0, 1e7] seconds; refused when the integrator is made, before any program runs.
BOOST_AUTO_TEST_CASE(exec_settings_refused_by_their_quantity) {
  const auto refusal = [](int order, double timeout) -> std::string {
    try {
      ExecIntegrator integrator(ExecSettings{.command = "true", .order = order, .timeout_seconds = timeout});
    } catch (const InputError& e) {
      return e.quantity();
    }
    return "none";
  };
  BOOST_TEST(refusal(0, 1e7) == "none");
  BOOST_TEST(refusal(20, 1.0) == "none");
  BOOST_TEST(refusal(-1, 1.0) == "declared order");
  BOOST_TEST(refusal(21, 1.0) == "declared order");
  BOOST_TEST(refusal(2, 0.0) == "program timeout");
  BOOST_TEST(refusal(2, std::nextafter(1e7, 1e8)) == "program timeout");
  BOOST_TEST(refusal(2, std::nan("")) == "program timeout");
}

BOOST_AUTO_TEST_CASE(command_splits_into_words) {
  using W = std::vector<std::string>;
  BOOST_TEST(split_command("prog  a\tb") == (W{"prog", "a", "b"}));
  BOOST_TEST(split_command("prog 'a b' \"c \\\"d\\\"\" e\\ f") == (W{"prog", "a b", "c \"d\"", "e f"}));
  BOOST_TEST(split_command("prog '' x") == (W{"prog", "", "x"}));
  BOOST_TEST(split_command("prog $HOME *.h5 a;b") == (W{"prog", "$HOME", "*.h5", "a;b"}));  // no expansion
  BOOST_CHECK_THROW(split_command("prog 'open"), ExchangeError);
  BOOST_CHECK_THROW(split_command("   "), ExchangeError);
}

BOOST_AUTO_TEST_CASE(placeholders_fill_inside_words) {
  const std::map<std::string, std::string> values{{"input", "/t/in put.h5"}, {"dt", "0.001"}};
  const auto argv = command_argv("prog --in={input} {dt} {unknown}", false, values);
  BOOST_TEST(argv == (std::vector<std::string>{"prog", "--in=/t/in put.h5", "0.001", "{unknown}"}));
  BOOST_TEST(command_argv("a {dt}; b", true, values) == (std::vector<std::string>{"/bin/sh", "-c", "a 0.001; b"}));
  // The shortest %g text that reads back to the same double: 17 digits only where 16 do not do.
  BOOST_TEST(exact_text(0.1) == "0.1");
  BOOST_TEST(exact_text(5e-4) == "0.0005");
  BOOST_TEST(exact_text(0.1 + 0.2) == "0.30000000000000004");
  BOOST_TEST(exact_text(5e-4 / 3.0) == "0.00016666666666666666");
  BOOST_TEST(std::stod(exact_text(5e-4 / 3.0)) == 5e-4 / 3.0);
}

BOOST_AUTO_TEST_CASE(stderr_tail_keeps_last_lines) {
  BOOST_TEST(last_lines("one\ntwo\n\n  three \nfour\n", 3) == "two | three | four");
  BOOST_TEST(last_lines("only", 3) == "only");
  BOOST_TEST(last_lines("\n\n", 3) == "");
}

// No outcome depends on the machine's speed: the programs that must end by themselves get the
// command's default hour; the one that must time out would sleep 30 s, and the timer never fires
// before its 0.2 s but for the 1 ms resolution of the wait (seconds counts from before the start).
BOOST_AUTO_TEST_CASE(runner_reports_status_and_timeout) {
  const CommandResult ok = run_command({"/bin/sh", "-c", "echo fine >&2"}, 3600.0);
  BOOST_TEST(ok.success);
  BOOST_TEST(ok.last_lines == "fine");
  const CommandResult bad = run_command({"/bin/sh", "-c", "echo broken >&2; exit 4"}, 3600.0);
  BOOST_TEST(!bad.success);
  BOOST_TEST(bad.ending == "exited with status 4");
  const CommandResult slow = run_command({"/bin/sh", "-c", "sleep 30"}, 0.2);
  BOOST_TEST(!slow.success);
  BOOST_TEST(slow.ending == "timed out after 0.2 s");
  BOOST_TEST(slow.seconds >= 0.199);
  BOOST_TEST(slow.seconds < 30.0);
  BOOST_CHECK_THROW(run_command({"/nonexistent/program"}, 1.0), ExchangeError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_exchange
