// Running gnuplot (Debian's gnuplot-nox: cairo terminals, no display needed) on a GnuplotScript
// and putting its figure in place atomically.
//
//   output.png → pngcairo · output.svg → svg · output.pdf → pdfcairo · anything else: InputError
//
// gnuplot is started by io/process.hpp (no shell; its default settings, so no ~/.gnuplot is read)
// in the output's folder, and fed through gnuplot-iostream's Gnuplot stream over a pipe. It writes to a temporary file there that this program created with mkstemp under
// a name of its own, ".dlpverify-plot-XXXXXX" — the only file name gnuplot ever sees, so the
// user's path, whatever it holds, never reaches a command. When gnuplot exits with status 0 and
// the file is not empty, the file is made 0644 (less umask), synced and renamed over the target;
// otherwise it is removed and a SolverError carries gnuplot's first error message in one line.
#pragma once

#include <string>

#include "plot/gnuplot_script.hpp"

namespace dlpverify::plot {

enum class FigureFormat { png, svg, pdf };

// The format an output file name asks for (by its extension, in any case). Throws InputError
// naming `option` for any other extension.
FigureFormat figure_format(const std::string& option, const std::string& path);

// Canvas size in pixels at 96 dpi (a PDF gets the same size in inches / 96), and the font size
// in points: the three formats look alike.
struct Canvas {
  int width = 1100;
  int height = 760;
  double font_points = 13.0;
};

// The three terminals draw one figure at different scales; measured against pngcairo (canvas
// size equal, 96 dpi): svg text 0.75×, points 1.63×; pdfcairo text 0.67×, points 1.37×, lines
// 0.56×. These factors undo that, so a figure looks the same in every format: every font size
// is multiplied by `font` (the terminal's, and any a command sets), the terminal's line width by
// `line`, and every point size by the gnuplot variable PS, which the preamble sets to `point`.
struct TerminalScale {
  double font, line, point;
};
TerminalScale terminal_scale(FigureFormat format);

// Renders `script` into `output` (see the banner). Throws InputError (bad name or folder, naming
// `option`) before starting anything, SolverError when gnuplot is missing or fails.
void render_figure(const GnuplotScript& script, const Canvas& canvas, const std::string& output,
                   const std::string& option);

}  // namespace dlpverify::plot
