// The placeholders of an exec: command under --exec-shell (command_template.hpp): /bin/sh reads
// each value back as it is, one word, whether its placeholder stands bare, in "…" or in '…', and
// whatever the value holds (blanks, ; ' " $ ` \, a newline); without a shell each value stays
// inside its word as it is. And a program's process tree ends with it (command_runner.hpp).
#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <csignal>
#include <unistd.h>

#include "exchange/command_runner.hpp"
#include "exchange/command_template.hpp"
#include "io/process.hpp"

namespace unit_command_quoting {

using namespace dlpverify;
using namespace dlpverify::exchange;

namespace {

// What /bin/sh prints for `command` filled in with {input} = value.
std::string shell_prints(const std::string& command, const std::string& value) {
  const ProcessResult run = run_process(command_argv(command, true, {{"input", value}}), [](std::FILE* stream) {
    return std::fclose(stream) == 0;
  });
  BOOST_TEST_REQUIRE(run.success, "sh failed: " << run.ending << ": " << run.errors);
  return run.output;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(command_quoting)

BOOST_AUTO_TEST_CASE(every_value_reads_back_as_one_word) {
  for (const std::string value : {"/t/a b/in.h5", "t;touch X;", "it's", "q\"$x`b\\c d", "", "new\nline",
                                  "$(echo run)", "a'b'\\'", "{input}", "0.001"}) {
    BOOST_TEST_CONTEXT("value [" << value << "]") {
      const std::string once = "<" + value + ">\n";
      BOOST_TEST(shell_prints("printf '<%s>\\n' {input}", value) == once);
      BOOST_TEST(shell_prints("printf '<%s>\\n' \"{input}\"", value) == once);
      BOOST_TEST(shell_prints("printf '<%s>\\n' '{input}'", value) == once);
      BOOST_TEST(shell_prints("printf '<%s>\\n' x{input}y \"x{input}y\" 'x{input}y'", value) ==
                 "<x" + value + "y>\n<x" + value + "y>\n<x" + value + "y>\n");
      // A quote escaped outside quotes opens none: the placeholder after it stands bare.
      BOOST_TEST(shell_prints("printf '<%s>\\n' \\'{input}", value) == "<'" + value + ">\n");
    }
  }
}

BOOST_AUTO_TEST_CASE(plain_values_go_in_bare) {
  const std::map<std::string, std::string> values{{"dt", "0.001"}, {"input", "/tmp/x-1/in.h5"}};
  BOOST_TEST(command_argv("a {dt} {input}; b", true, values) ==
             (std::vector<std::string>{"/bin/sh", "-c", "a 0.001 /tmp/x-1/in.h5; b"}));
  BOOST_TEST(command_argv("a {input}", true, {{"input", "t;x"}}) == (std::vector<std::string>{"/bin/sh", "-c", "a 't;x'"}));
}

BOOST_AUTO_TEST_CASE(without_a_shell_values_stay_in_their_words) {
  BOOST_TEST(command_argv("prog {input} --out={input}", false, {{"input", "t;touch X; 'q'"}}) ==
             (std::vector<std::string>{"prog", "t;touch X; 'q'", "--out=t;touch X; 'q'"}));
}

BOOST_AUTO_TEST_CASE(nothing_the_program_started_outlives_it) {
  // The program starts a grandchild in a session of its own (it leaves the program's process
  // group) that writes its pid, then exits at once: when run_command returns, that pid is gone.
  const std::string pid_file =
      (std::filesystem::temp_directory_path() / ("dlpverify-test-tree-" + std::to_string(::getpid()))).string();
  const CommandResult run =
      run_command({"/bin/sh", "-c", "(setsid sleep 1000 & echo $! > \"$1\")", "sh", pid_file}, 3600.0);
  BOOST_TEST(run.success);
  std::ifstream in(pid_file);
  long pid = 0;
  BOOST_TEST_REQUIRE(static_cast<bool>(in >> pid), "no pid in " << pid_file);
  std::filesystem::remove(pid_file);
  // Reaped by run_command: no /proc entry, not even a zombie's (the pid is not reused this soon).
  const bool left = std::filesystem::exists("/proc/" + std::to_string(pid));
  BOOST_TEST(!left, "the grandchild " << pid << " still exists");
  if (left) ::kill(static_cast<pid_t>(pid), SIGKILL);  // a failing test leaves nothing running
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_command_quoting
