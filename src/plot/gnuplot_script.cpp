#include "plot/gnuplot_script.hpp"

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <strings.h>

#include <gnuplot-iostream.h>
#include <nlohmann/json.hpp>

#include "io/output_path.hpp"
#include "dlpverify/errors.hpp"
#include "io/format.hpp"
#include "io/process.hpp"

namespace dlpverify::plot {

std::string number(double value) { return std::isfinite(value) ? printf_string("%.17g", value) : "NaN"; }

namespace {

// The tripwire of the banner: `line` when it may be a command of ours. The words make gnuplot
// reach outside the figure (a shell, a script, a file, a plugin) or wait; '$' starts a datablock.
std::string checked(std::string_view line) {
  static const std::regex refused(
      R"([^ -~]|[`@|<!\\]|^\$|\b(system|shell|load|call|print|cd|save|pipe|import|pause)\b)");
  const std::string text(line);
  if (std::smatch found; std::regex_search(text, found, refused))
    throw std::logic_error("gnuplot command refused at \"" + found.str() + "\" (text goes through text()): " + text);
  return text;
}

std::string terminal(FigureFormat format, int width, int height) {
  const std::string size = format == FigureFormat::pdf ? number(width / 96.0) + "in," + number(height / 96.0) + "in"
                                                       : std::to_string(width) + "," + std::to_string(height);
  const char* name = format == FigureFormat::png ? "pngcairo" : format == FigureFormat::svg ? "svg" : "pdfcairo";
  return std::string("set terminal ") + name + " enhanced size " + size +
         " font \"DejaVu Sans,13\" linewidth 1.3 rounded" +
         (format == FigureFormat::svg ? " background rgb \"white\"" : "");
}

// gnuplot's error in one line: the message after "line 0: " (a line of the piped script), else
// the last line it wrote, or how it ended.
std::string first_error(const std::string& log, std::string last) {
  static const std::regex message(R"(^\s*line \d+: ([^\r\n]*))", std::regex::ECMAScript | std::regex::multiline);
  if (std::smatch found; std::regex_search(log, found, message)) return found[1];
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);)
    if (line.find_first_not_of(" \t\r^") != std::string::npos) last = line;
  return last.empty() ? "it failed without a message" : last;
}

}  // namespace

std::string GnuplotScript::sanitize(std::string_view user_text) {
  // Invalid UTF-8 becomes U+FFFD: nlohmann::json's strict decoder (no overlong forms, no
  // surrogates) replaces it when dumping. 2000 bytes are enough for any title; a megabyte is not one.
  const nlohmann::json text = std::string(user_text.substr(0, 2000));
  std::string line =
      nlohmann::json::parse(text.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)).get<std::string>();
  for (char& c : line)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';  // a newline or NUL would end the datablock line
  // gnuplot's SVG escapes < and & but not >, and "]]>" is not allowed in XML text: a word joiner
  // (U+2060, drawn as nothing) parts it.
  for (std::size_t at = line.find("]]>"); at != std::string::npos; at = line.find("]]>", at + 5))
    line.insert(at + 2, "\u2060");
  return line;
}

void GnuplotScript::command(std::string_view line) { commands_.push_back(checked(line)); }

std::string GnuplotScript::text(std::string_view user_text) {
  std::string line = sanitize(user_text);
  const auto [it, inserted] = text_index_.try_emplace(line, static_cast<int>(texts_.size()) + 1);
  if (inserted) texts_.push_back(std::move(line));
  return "T(" + std::to_string(it->second) + ")";
}

std::string GnuplotScript::table(const std::vector<std::vector<double>>& rows) {
  std::string body;
  for (const auto& row : rows) {
    for (double value : row) body += number(value) + " ";
    body += '\n';
  }
  tables_.push_back(std::move(body));
  return "$D" + std::to_string(tables_.size());
}

std::string GnuplotScript::render() const {
  std::string out = "$TEXT << EOD\n";
  for (const auto& line : texts_) out += ">" + line + "\n";
  out += "EOD\nT(k) = substr($TEXT[k], 2, strlen($TEXT[k]))\n";
  for (std::size_t t = 0; t < tables_.size(); ++t)
    out += "$D" + std::to_string(t + 1) + " << EOD\n" + tables_[t] + "EOD\n";
  for (const auto& line : commands_) out += line + "\n";
  return out;
}

FigureFormat figure_format(const std::string& option, const std::string& path) {
  if (output_target(path) != OutputTarget::file) return FigureFormat::png;  // standard output: PNG
  const std::string extension = std::filesystem::path(path).extension().string();
  for (const auto& [name, format] :
       {std::pair{".png", FigureFormat::png}, {".svg", FigureFormat::svg}, {".pdf", FigureFormat::pdf}})
    if (strcasecmp(extension.c_str(), name) == 0) return format;
  throw InputError(option, path, "a figure must end in .png, .svg or .pdf");
}

std::string render_figure(const GnuplotScript& script, int width, int height, const std::string& output,
                   const std::string& option) {
  const FigureFormat format = figure_format(option, output);
  check_output_path(option, output);
  if (output_target(output) == OutputTarget::discard) return {};  // /dev/null: nothing to draw
  // `set output` without a name: the figure goes to gnuplot's stdout, which run_process keeps.
  const std::string preamble = checked("set encoding utf8") + "\n" + checked(terminal(format, width, height)) + "\n" +
                               checked("set output") + "\n";
  const ProcessResult gnuplot = run_process({"gnuplot", "--default-settings"}, [&](std::FILE* stream) {
    Gnuplot gp(stream);  // closes the stream when it goes
    gp << preamble << script.render();
    gp.flush();
    return static_cast<bool>(gp);
  });
  if (gnuplot.signal == SIGXFSZ)  // its output (kept in a memory file) passed the file-size limit
    throw OutputError("cannot write " + output + ": the figure is larger than the file-size limit (ulimit -f)");
  if (!gnuplot.success)
    throw SolverError("gnuplot failed on " + output + ": " + first_error(gnuplot.errors, gnuplot.ending));
  if (gnuplot.output.empty()) throw SolverError("gnuplot failed on " + output + ": it drew nothing");
  return gnuplot.output;
}

}  // namespace dlpverify::plot
