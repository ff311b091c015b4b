#include "plot/gnuplot_process.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gnuplot-iostream.h>

#include "io/atomic_file.hpp"
#include "io/process.hpp"
#include "dlpverify/errors.hpp"

namespace dlpverify::plot {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

TerminalScale terminal_scale(FigureFormat format) {
  switch (format) {
    case FigureFormat::png: return {1.0, 1.0, 1.0};
    case FigureFormat::svg: return {1.333, 1.0, 0.613};
    case FigureFormat::pdf: return {1.49, 1.5, 0.73};
  }
  return {1.0, 1.0, 1.0};
}

namespace {

std::string terminal_commands(FigureFormat format, const Canvas& canvas) {
  const TerminalScale scale = terminal_scale(format);
  const std::string common = " font \"DejaVu Sans," + number(std::round(canvas.font_points * scale.font * 10) / 10) +
                             "\" linewidth " + number(1.3 * scale.line) + " rounded";
  const std::string pixels = " size " + std::to_string(canvas.width) + "," + std::to_string(canvas.height);
  std::string terminal;
  switch (format) {
    case FigureFormat::png: terminal = "set terminal pngcairo enhanced color" + pixels + common; break;
    case FigureFormat::svg: terminal = "set terminal svg enhanced" + pixels + common + " background rgb \"white\""; break;
    case FigureFormat::pdf: {
      char inches[64];
      std::snprintf(inches, sizeof inches, " size %.3fin,%.3fin", canvas.width / 96.0, canvas.height / 96.0);
      terminal = std::string("set terminal pdfcairo enhanced color") + inches + common;
      break;
    }
  }
  return GnuplotScript::checked_command(terminal) + "\n" + GnuplotScript::checked_command("PS = " + number(scale.point)) + "\n";
}

// Removes the temporary figure unless it was renamed into place.
struct TemporaryFigure {
  std::string path;
  ~TemporaryFigure() {
    if (!path.empty()) ::unlink(path.c_str());
  }
};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r^");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// gnuplot's first error in one line: "line 0: undefined function: foo" loses its "line 0: "
// (a line number in a piped script), warnings are passed over while there is an error.
std::string first_error(const std::string& log) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= log.size()) {
    const auto end = log.find('\n', start);
    const std::string line = trim(log.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (!line.empty()) lines.push_back(line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  for (const auto& line : lines) {
    if (line.rfind("warning", 0) == 0) continue;
    if (line.rfind("line ", 0) == 0) {
      const auto colon = line.find(": ");
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  }
  for (const auto& line : lines)
    if (line.rfind("warning", 0) != 0) return line;
  return lines.empty() ? std::string() : lines.front();
}

}  // namespace

FigureFormat figure_format(const std::string& option, const std::string& path) {
  const std::string extension = lower(fs::path(path).extension().string());
  if (extension == ".png") return FigureFormat::png;
  if (extension == ".svg") return FigureFormat::svg;
  if (extension == ".pdf") return FigureFormat::pdf;
  throw InputError(option, path, "a figure must end in .png, .svg or .pdf");
}

void render_figure(const GnuplotScript& script, const Canvas& canvas, const std::string& output, const std::string& option) {
  const FigureFormat format = figure_format(option, output);
  check_output_path(option, output);

  const fs::path target(output);
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (!fs::is_directory(folder, ec)) throw OutputError("cannot write " + output + ": cannot make its folder");

  // The one file name gnuplot sees: ours, from [A-Za-z0-9.-], relative to its working folder.
  const std::string temporary_name_pattern = ".dlpverify-plot-XXXXXX";
  std::string pattern = (folder / temporary_name_pattern).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  TemporaryFigure temporary;
  {
    const int fd = ::mkstemp(name.data());
    if (fd < 0) throw OutputError("cannot write " + output + ": " + std::strerror(errno));
    temporary.path = name.data();
    ::close(fd);
  }
  const std::string temporary_name = fs::path(temporary.path).filename().string();
  for (char c : temporary_name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-')
      throw std::logic_error("unsafe temporary figure name " + temporary_name);

  const std::string preamble = GnuplotScript::checked_command("set encoding utf8") + "\n" + terminal_commands(format, canvas) +
                               GnuplotScript::checked_command("set output '" + temporary_name + "'") + "\n";

  // --default-settings: no ~/.gnuplot is read.
  const ProcessResult run = run_program({"gnuplot", "--default-settings"}, folder.string(), [&](std::FILE* stream) {
    Gnuplot gp(stream);  // owns the stream and closes it
    gp << preamble << script.render() << "unset output\n";
    gp.flush();
    return static_cast<bool>(gp);
  });
  if (!run.started) throw SolverError("cannot run gnuplot (install gnuplot-nox): " + run.spawn_error);
  if (!run.exited || run.exit_status != 0 || !run.input_written) {
    std::string message = first_error(run.standard_error);
    if (message.empty()) {
      if (run.signal != 0)
        message = "killed by signal " + std::to_string(run.signal);
      else if (run.exit_status == 127)
        message = "could not be run (install gnuplot-nox)";
      else if (!run.input_written)
        message = "stopped reading its script";
      else
        message = "exited with status " + std::to_string(run.exit_status);
    }
    throw SolverError("gnuplot failed on " + output + ": " + message);
  }

  struct stat info {};
  if (::stat(temporary.path.c_str(), &info) != 0 || info.st_size == 0)
    throw SolverError("gnuplot failed on " + output + ": it wrote an empty figure");
  const mode_t mask = ::umask(0);
  ::umask(mask);
  bool ok = ::chmod(temporary.path.c_str(), 0666 & ~mask) == 0;
  if (const int figure = ::open(temporary.path.c_str(), O_RDONLY | O_CLOEXEC); figure >= 0) {
    ok = ::fsync(figure) == 0 && ok;
    ::close(figure);
  } else {
    ok = false;
  }
  if (!ok || std::rename(temporary.path.c_str(), output.c_str()) != 0)
    throw OutputError("cannot write " + output + ": " + std::strerror(errno));
  temporary.path.clear();  // in place: keep it
}

}  // namespace dlpverify::plot
