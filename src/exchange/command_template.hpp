// The command of `--integrator exec:COMMAND`, split into words once and filled in per level.
//
// Without a shell the command is split like a shell would split it, and nothing else: words are
// separated by blanks, '…' quotes literally, "…" quotes with \" and \\ as escapes, a backslash
// outside quotes escapes the next character. No globbing, no variables, no redirection. The
// placeholders {input} {output} {dt} {steps} {t0} {t_end} {threads} are replaced inside each word
// after the split, so a path with blanks stays one argument ({rtol} and {atol} of a study by
// tolerance are filled into the command before, case_study/tolerance.cpp). With a shell (--exec-shell) the
// filled-in command goes whole to /bin/sh -c, each value quoted for the shell where its placeholder
// stands, so it is read back as it is, one word, whatever it holds (a temporary folder named
// "t;touch X;" runs no touch): outside quotes a value of other characters than letters, digits and
// _@%+=:,./- goes in '…' (a ' in it as '\''); inside '…' its ' become '\''; inside "…" a
// backslash goes before its $ ` " and \ characters.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace dlpverify::exchange {

// The words of `command`; throws ExchangeError for an unclosed quote or an empty command.
std::vector<std::string> split_command(const std::string& command);

// `text` with every {name} of `values` replaced by its value; any other {…} is left as it is.
std::string fill_placeholders(const std::string& text, const std::map<std::string, std::string>& values);

// The argv to run: the command's words filled in, or {"/bin/sh", "-c", filled command} with the
// values quoted for the shell.
std::vector<std::string> command_argv(const std::string& command, bool shell,
                                      const std::map<std::string, std::string>& values);

// A double as the shortest text that reads back to the same double ("0.0005", not
// 0.00050000000000000001).
std::string exact_text(double value);

}  // namespace dlpverify::exchange
