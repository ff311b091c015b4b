// A gnuplot script in which no outside text is ever a command, and the one way it becomes a file.
//
// gnuplot runs shell commands (system("…"), `…` even inside double quotes, !cmd, load, set output
// "|cmd", data from "< cmd"), and titles, names and file names come from the user; quoting does
// not stop a backquote. So commands are ours alone, and command() is a tripwire refusing all but
// printable ASCII without ` @ | < ! \ and the words that reach outside the figure (system, shell,
// load, call, print, cd, save, pipe, import, pause). Every string drawn (ours too: Δt, ξ) goes
// through text(), which stores it as a line of the datablock $TEXT and returns its expression:
//
//     $TEXT << EOD
//     >x"; system("touch /tmp/pwned"); print "
//     EOD
//     T(k) = substr($TEXT[k], 2, strlen($TEXT[k]))
//     set title T(1) noenhanced
//
// gnuplot keeps datablock lines verbatim (no backquote, macro or escape expansion) and $TEXT[k]
// is a string value, drawn, never evaluated. The '>' keeps a line from being the "EOD" that ends
// the datablock, control characters become spaces so a text stays on its line, invalid UTF-8
// becomes U+FFFD. The output's name never reaches gnuplot: it writes the figure to its stdout.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace dlpverify::plot {

class GnuplotScript {
 public:
  void command(std::string_view line);           // ours; std::logic_error when the tripwire trips
  std::string text(std::string_view user_text);  // any text, to be drawn: returns "T(3)"
  // A table of numbers as a datablock; returns its name ("$D2"). Non-finite values become NaN.
  std::string table(const std::vector<std::vector<double>>& rows);
  std::string render() const;  // datablocks, then commands, each line ending in '\n'
  // The datablock line stored for `user_text`, without its '>': what gnuplot draws.
  static std::string sanitize(std::string_view user_text);

 private:
  std::vector<std::string> texts_, tables_, commands_;
  std::map<std::string, int> text_index_;  // one line per distinct text
};

std::string number(double value);  // %.17g, or NaN when not finite: a number in a command or table

// From the output's extension, in any case; throws InputError naming `option` for any other.
enum class FigureFormat { png, svg, pdf };
FigureFormat figure_format(const std::string& option, const std::string& path);

// Runs "gnuplot --default-settings" (no shell, no ~/.gnuplot) on the script through gnuplot-iostream,
// on width × height pixels (PDF: 96 an inch), and returns what it drew, in the format of `output`'s
// extension, for the caller's OutputSet; nothing is drawn (empty) for /dev/null. Throws InputError
// (a bad name or folder) before starting, SolverError with gnuplot's error.
std::string render_figure(const GnuplotScript& script, int width, int height, const std::string& output,
                   const std::string& option);

}  // namespace dlpverify::plot
