// A gnuplot script in which no outside text is ever a command, and the one way it becomes a file.
//
// Why: gnuplot runs shell commands — system("…"), `…` (expanded even inside double quotes),
// `!cmd`, load/call, set print "|cmd", set output "|cmd", data from "< cmd". Titles, case,
// integrator and method names, labels and file names come from the user, so none of them may be
// pasted into a command: quoting does not stop a backquote.
//
// How: commands are ours alone. command() is a tripwire: it admits printable ASCII without
// ` @ | < ! \ and without the words system, shell, load, call, print, cd, save, pipe, import,
// pause, so pasting text into a command fails in the tests, not in a shell. Every string drawn
// (ours too: Δt and ξ are not ASCII) goes through text(), which stores it as one line of the
// datablock $TEXT and returns the expression T(k) that yields it:
//
//     $TEXT << EOD
//     >x"; system("touch /tmp/pwned"); print "
//     EOD
//     T(k) = substr($TEXT[k], 2, strlen($TEXT[k]))
//     set title T(1) noenhanced
//
// gnuplot keeps datablock lines verbatim (no backquote, macro or escape expansion) and $TEXT[k]
// is a string value, drawn, never evaluated. The leading '>' keeps any line from being the "EOD"
// that ends the datablock; control characters become spaces so a text stays on its line;
// invalid UTF-8 becomes U+FFFD, which cairo can draw. Numbers go in datablocks $D1, $D2 … .
// The output's name never reaches gnuplot either: it writes the figure to its stdout.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace dlpverify::plot {

class GnuplotScript {
 public:
  // One command line of ours; throws std::logic_error when the tripwire above trips.
  void command(std::string_view line);
  // Any text, to be drawn: returns the expression that yields it ("T(3)").
  std::string text(std::string_view user_text);
  // A table of numbers as a datablock; returns its name ("$D2"). Non-finite values become NaN.
  std::string table(const std::vector<std::vector<double>>& rows);
  // Datablocks first, then the commands, each line ending in '\n'.
  std::string render() const;
  // The datablock line stored for `user_text`, without its '>': what gnuplot draws.
  static std::string sanitize(std::string_view user_text);

 private:
  std::vector<std::string> texts_;
  std::map<std::string, int> text_index_;  // one line per distinct text
  std::vector<std::string> tables_;
  std::vector<std::string> commands_;
};

// %.17g, or NaN when not finite: a number as commands and tables write it.
std::string number(double value);

enum class FigureFormat { png, svg, pdf };

// The format the output's extension asks for (in any case): .png (pngcairo), .svg, .pdf
// (pdfcairo). Throws InputError naming `option` for any other.
FigureFormat figure_format(const std::string& option, const std::string& path);

// Runs gnuplot (argv "gnuplot --default-settings": no shell, no ~/.gnuplot) on the script through
// gnuplot-iostream, on a canvas of width × height pixels (a PDF: the same at 96 per inch), and
// writes what it drew to `output` with write_file_atomically: the figure whole or no file at all.
// Throws InputError (a bad name or folder, naming `option`) before starting gnuplot, and
// SolverError with gnuplot's first error in one line when it fails.
void render_figure(const GnuplotScript& script, int width, int height, const std::string& output,
                   const std::string& option);

}  // namespace dlpverify::plot
