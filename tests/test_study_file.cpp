// Study files (--config) are TOML, read by toml++: every hostile example of issue 33 is refused
// with the line (and, for malformed TOML, the column) or read exactly as written; each key's TOML
// type must be its option's. Empty values on the command line and options that do nothing in
// the chosen mode are refused too (cli/command_line.cpp, cli/idle_options.cpp).
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "cli/command_line.hpp"
#include "cli/study_file.hpp"
#include "dlpverify/errors.hpp"

namespace unit_study_file {

namespace {

using dlpverify::InputError;
using dlpverify::cli::CommandLine;
using Words = std::vector<std::string>;

Words options_of(const std::string& text, const std::string& command = "converge") {
  CommandLine line;
  return dlpverify::cli::study_file_options(*line.study_subcommand(command), "study.toml", std::string_view(text));
}

// The error line of reading `text`, or "" when it is read.
std::string refusal(const std::string& text, const std::string& command = "converge") {
  try {
    options_of(text, command);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool holds(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The error line of parsing `words` after the study file `text` (none when empty), or "".
std::string parse_refusal(const Words& words, const std::string& text = "") {
  CommandLine line;
  try {
    Words all = text.empty() ? Words{} : options_of(text, words.front());
    all.insert(all.begin(), words.front());
    all.insert(all.end(), words.begin() + 1, words.end());
    line.parse(all);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(study_file)

BOOST_AUTO_TEST_CASE(malformed_toml_is_refused_with_line_and_column) {
  const std::string unquoted = refusal("outer = 4\ncase = drag\n");
  BOOST_TEST(holds(unquoted, "--config = study.toml: not TOML at line 2, column 8"), unquoted);
  const std::string unterminated = refusal("case = \"drag\n");
  BOOST_TEST(holds(unterminated, "not TOML at line 1, column"), unterminated);
  BOOST_TEST(holds(refusal("outer = 4\nouter = 5\n"), "not TOML at line 2"));  // a key given twice
}

BOOST_AUTO_TEST_CASE(empty_strings_are_refused) {
  const std::string title = refusal("title = \"\"\ncsv = \"x.csv\"\n");
  BOOST_TEST(holds(title, "line 1: title = \"\" is empty"), title);
  const std::string dt = refusal("dt = \"\"\n");
  BOOST_TEST(holds(dt, "line 1: dt = \"\" is a string; --dt takes a number"), dt);
}

BOOST_AUTO_TEST_CASE(a_flag_takes_a_boolean_only) {
  BOOST_TEST(holds(refusal("quiet = \"yes\""), "quiet = \"yes\" is a string; --quiet takes true or false"));
  BOOST_TEST(holds(refusal("quiet = 1"), "quiet = 1 is an integer; --quiet takes true or false"));
  BOOST_TEST(options_of("quiet = true") == Words{"--quiet=true"});
  BOOST_TEST(options_of("quiet = false") == Words{"--quiet=false"});
}

BOOST_AUTO_TEST_CASE(numbers_take_toml_numbers_and_text_takes_strings) {
  const std::string quoted = refusal("dt = \"0.001\"");
  BOOST_TEST(holds(quoted, "dt = \"0.001\" is a string; --dt takes a number (a TOML integer or float, unquoted)"), quoted);
  const std::string fractional = refusal("outer = 4.0");
  BOOST_TEST(holds(fractional, "outer = 4.0 is a float; --outer takes a whole number"), fractional);
  BOOST_TEST(holds(refusal("case = 3"), "case = 3 is an integer; --case takes text in double quotes"));
  BOOST_TEST(holds(refusal("dt = true"), "is a boolean; --dt takes a number"));
  BOOST_TEST(holds(refusal("t-end = 1979-05-27"), "is a date or time"));
  BOOST_TEST(options_of("dt = 1\nouter = 4\ncase = \"drag\"") == (Words{"--dt=1", "--outer=4", "--case=drag"}));
  // levels and gamma take a number or a word.
  BOOST_TEST(options_of("levels = 4\ngamma = 1.4") == (Words{"--levels=4", "--gamma=1.4"}));
  BOOST_TEST(options_of("levels = \"auto\"\ngamma = \"diatomic\"") == (Words{"--levels=auto", "--gamma=diatomic"}));
}

BOOST_AUTO_TEST_CASE(values_are_read_exactly_as_written) {
  // A value starting with '-' or holding '=' stays the value; a float reads back to its bits.
  CommandLine line;
  Words words = options_of("title = \"--csv=x.csv\"\nplot = \"f.svg\"\ndt = 0.1\nus = -2.5e-3\n");
  words.insert(words.begin(), "converge");
  line.parse(words);
  BOOST_TEST(line.converge_options.outputs.title == "--csv=x.csv");
  BOOST_TEST(line.converge_options.outputs.csv_file.empty());
  BOOST_TEST(*line.converge_options.levels.dt == 0.1);
  BOOST_TEST(line.converge_options.problem.expansion_speed == -2.5e-3);
}

BOOST_AUTO_TEST_CASE(keys_keep_the_file_order) {
  BOOST_TEST(options_of("outer = 4\ncase = \"burn\"\ndt = 0.001") == (Words{"--outer=4", "--case=burn", "--dt=0.001"}));
  // The first bad key written is the one named.
  BOOST_TEST(holds(refusal("zeta = 1\nalpha = 2"), "line 1: unknown key 'zeta'"));
}

BOOST_AUTO_TEST_CASE(sections_arrays_unknown_keys_and_nesting_are_refused) {
  BOOST_TEST(holds(refusal("outer = 4\n[study]\nlevels = 3\n"), "line 2: 'study' is a section or table"));
  BOOST_TEST(holds(refusal("study.levels = 3"), "'study' is a section or table"));
  BOOST_TEST(holds(refusal("levels = [2, 3]"), "line 1: levels is an array; --levels takes one value"));
  BOOST_TEST(holds(refusal("timestep = 0.001"), "unknown key 'timestep'"));
  BOOST_TEST(holds(refusal("\"dt=5\" = 3"), "unknown key 'dt=5'"));
  BOOST_TEST(holds(refusal("help = true"), "unknown key 'help'"));
  BOOST_TEST(holds(refusal("config = \"other.toml\""), "cannot name another study file"));
  BOOST_TEST(holds(refusal("expect-order = 2"), "unknown key 'expect-order'"));  // converge has none
  BOOST_TEST(refusal("expect-order = 2", "check").empty());
}

// An option given several times takes an array, one word per value in order; an empty array, or
// an array for an option of one value, is refused.
BOOST_AUTO_TEST_CASE(an_option_given_several_times_takes_an_array) {
  BOOST_TEST(options_of("expect-order = [2, \"energy=3\"]", "check") ==
             (Words{"--expect-order=2", "--expect-order=energy=3"}));
  BOOST_TEST(options_of("expect-order = 2.5", "check") == (Words{"--expect-order=2.5"}));
  BOOST_TEST(holds(refusal("expect-order = []", "check"), "line 1: expect-order = [] is empty"));
  BOOST_TEST(holds(refusal("expect-order = [2, true]", "check"), "expect-order = true is a boolean"));
  BOOST_TEST(holds(refusal("outer = [4, 5]", "check"), "outer is an array; --outer takes one value"));
  // On the command line after the file, a value for the same variable takes its place.
  BOOST_TEST(parse_refusal({"check", "--expect-order", "velocity=x"}, "expect-order = [2]") ==
             "--expect-order = velocity=x: must be an order P, or NAME=P for a variable of its own order");
}

BOOST_AUTO_TEST_CASE(an_empty_command_line_value_is_refused) {
  for (const Words& words : {Words{"converge", "--json", ""}, Words{"converge", "--dt", ""},
                             Words{"converge", "--threads", ""}, Words{"check", "--expect-order", "2", "--baseline", ""},
                             Words{"bench", "--outer", ""}, Words{"converge", "--dt=", "0.001"}}) {
    const std::string line = parse_refusal(words);
    const std::string option = words[words.size() - 2] == "--dt=" ? "--dt" : words[words.size() - 2];
    BOOST_TEST(holds(line, option + " = '': is empty"), line);
  }
}

BOOST_AUTO_TEST_CASE(an_option_that_does_nothing_is_refused) {
  BOOST_TEST(holds(parse_refusal({"converge", "--integrator", "cvode", "--tolerances", "1e-3:1e-5", "--levels", "3"}),
                   "--levels = 3: does nothing in a study by --tolerances"));
  BOOST_TEST(holds(parse_refusal({"converge", "--levels", "4", "--budget", "60"}), "--budget = 60: does nothing without --levels auto"));
  BOOST_TEST(holds(parse_refusal({"converge", "--order-ci", "0.1"}), "--order-ci = 0.1: does nothing"));
  BOOST_TEST(holds(parse_refusal({"stagger", "--dt", "0.5", "--block-tol", "w1=1e-6"}), "--block-tol = w1=1e-6: does nothing without --adaptive"));
  BOOST_TEST(parse_refusal({"stagger", "--dt", "0.5", "--adaptive", "--block-tol", "w1=1e-6"}).empty());
  BOOST_TEST(holds(parse_refusal({"converge", "--exec-timeout", "5"}), "--exec-timeout = 5: does nothing without an exec: program"));
  BOOST_TEST(holds(parse_refusal({"converge", "--history-outputs", "7"}), "does nothing without --history"));
  BOOST_TEST(holds(parse_refusal({"converge", "--method", "bdf"}), "--method = bdf: does nothing unless --integrator cvode"));
  BOOST_TEST(parse_refusal({"converge", "--integrator", "cvode", "--method", "bdf", "--rtol", "1e-8"}).empty());
  BOOST_TEST(parse_refusal({"converge", "--integrator", "arkode-adaptive:ARKODE_HEUN_EULER_2_1_2", "--tolerances",
                            "1e-3:1e-5", "--atol", "1e-9"}).empty());
  BOOST_TEST(holds(parse_refusal({"check", "--expect-order", "2", "--expect-proportionality", "1"}), "does nothing without --tolerances"));
  BOOST_TEST(holds(parse_refusal({"check", "--integrator", "cvode", "--tolerances", "1e-3:1e-5", "--baseline", "b.json"}),
                   "--baseline = b.json: does nothing in a study by --tolerances"));
}

BOOST_AUTO_TEST_CASE(a_study_file_key_counts_as_given_and_the_final_values_choose_the_mode) {
  // The file asks for the search and bounds it; a typed --levels 3 ends the search: its budget does nothing.
  BOOST_TEST(holds(parse_refusal({"converge", "--levels", "3"}, "levels = \"auto\"\nbudget = 60"), "--budget = 60: does nothing"));
  // The file's fixed levels, overridden by a typed --levels auto: the typed budget bounds the search.
  BOOST_TEST(parse_refusal({"converge", "--levels", "auto", "--budget", "60"}, "levels = 4").empty());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_study_file
