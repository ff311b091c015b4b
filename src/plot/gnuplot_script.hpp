// A gnuplot script in which no outside text is ever a command.
//
// ─── Why ────────────────────────────────────────────────────────────────────────────────────────
// gnuplot runs shell commands: system("…"), `…` (backquotes, expanded even inside double-quoted
// strings), `!cmd`, `load`/`call`, `set print "|cmd"`, `set output "|cmd"`, and data sources
// named "< cmd". Titles, case and integrator names, legend labels and file names come from the
// user (a JSON file, a CSV header, a command-line title), so none of it may be pasted into a
// command — quoting and escaping are not enough (a backquote or a doubled quote gets through).
//
// ─── How ────────────────────────────────────────────────────────────────────────────────────────
// A script has two channels, and only the first is ever parsed as commands:
//
//   commands   written by this program alone. command() admits printable ASCII only and refuses
//              ` @ | < ! \ and the words system, shell, load, call, print, cd, save, pipe —
//              a tripwire: someone pasting text into a command later gets a logic_error in tests,
//              not a shell. Non-ASCII prose (Δt, ξ, ‖e‖) cannot go here either, so every label,
//              ours or the user's, takes the second channel.
//   text       every string shown in the figure. text(s) stores s as one line of the datablock
//              $TEXT and returns the expression T(k) that yields it:
//
//                  $TEXT << EOD
//                  >x"; system("touch /tmp/pwned"); print "
//                  EOD
//                  T(k) = substr($TEXT[k], 2, strlen($TEXT[k]))
//                  set title T(1) noenhanced
//
//              gnuplot stores datablock lines verbatim (no backquote, macro or escape
//              expansion) and $TEXT[k] (gnuplot 5.4) returns line k as a string value, which
//              is drawn, never evaluated. Each line starts with '>' so that no line can equal the
//              terminator EOD (gnuplot ends a datablock at a line starting with it), and control
//              characters (newline above all) become spaces so that a label stays on its line;
//              invalid UTF-8 becomes U+FFFD so the cairo terminals draw it.
//   tables     numbers, written by us with %.17g into datablocks $D1, $D2 …
//
// User labels are drawn `noenhanced`, so ^ _ { } @ & in a name print as themselves.
// The output file is never named in a command either: gnuplot runs in the output's folder and
// writes to a temporary name this program makes from [A-Za-z0-9.-] (gnuplot_process.hpp).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace dlpverify::plot {

class GnuplotScript {
 public:
  // One command line of our own. Throws std::logic_error when it holds anything but printable
  // ASCII or one of the refused characters and words above.
  void command(std::string_view line);
  // The check command() makes, for a line written elsewhere (the terminal and output lines).
  static std::string checked_command(std::string_view line);

  // Any text at all, to be drawn: returns the gnuplot expression that yields it ("T(3)").
  std::string text(std::string_view user_text);

  // A table of numbers as a datablock; returns its name ("$D2"). Non-finite values become NaN
  // (gnuplot skips them).
  std::string table(const std::vector<std::vector<double>>& rows);

  // Datablocks first, then the commands, each line ending in '\n'.
  std::string render() const;

  // The exact datablock line stored for `user_text` (without the leading '>'): what gnuplot draws.
  static std::string sanitize(std::string_view user_text);

 private:
  std::vector<std::string> texts_;
  std::map<std::string, int> text_index_;
  std::vector<std::string> tables_;  // rendered bodies
  std::vector<std::string> commands_;
};

// %.17g, or NaN when not finite: a number as our commands and tables write it.
std::string number(double value);

}  // namespace dlpverify::plot
