#include "plot/gnuplot_script.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <gnuplot-iostream.h>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/process.hpp"

namespace dlpverify::plot {

namespace {

// Words that make gnuplot reach outside the figure (a shell, a script, a file, a plugin) or wait.
constexpr std::array kRefusedWords = {"system", "shell", "load", "call", "print", "cd", "save", "pipe", "import", "pause"};

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The tripwire of the banner: returns `line` when it may be a command of ours.
std::string checked(std::string_view line) {
  const auto refuse = [&](const std::string& why) {
    throw std::logic_error("gnuplot command refused (" + why + "): " + std::string(line));
  };
  for (char c : line) {
    if (c < 0x20 || c > 0x7E) refuse("not printable ASCII: text goes through text()");
    if (std::string_view("`@|<!\\").find(c) != std::string_view::npos) refuse(std::string("character ") + c);
  }
  for (std::size_t i = 0, j = 0; i < line.size(); i = j + 1) {
    for (j = i; j < line.size() && word_char(line[j]);) ++j;
    for (const char* refused : kRefusedWords)
      if (line.substr(i, j - i) == refused) refuse("word " + std::string(refused));
  }
  if (!line.empty() && line.front() == '$') refuse("datablocks come from table()");
  return std::string(line);
}

// Length of the valid UTF-8 sequence at s[i], or 0: overlong forms, surrogates and code points
// past U+10FFFF are not valid.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned lead = byte(i);
  if (lead < 0x80) return 1;
  const std::size_t n = lead >= 0xC2 && lead <= 0xDF ? 2 : lead >= 0xE0 && lead <= 0xEF ? 3 : lead >= 0xF0 && lead <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  unsigned code = lead & (0x7Fu >> n);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  const bool invalid = (n == 3 && code < 0x800) || (n == 4 && (code < 0x10000 || code > 0x10FFFF)) || (code >= 0xD800 && code <= 0xDFFF);
  return invalid ? 0 : n;
}

std::string terminal(FigureFormat format, int width, int height) {
  const std::string style = " font \"DejaVu Sans,13\" linewidth 1.3 rounded";
  const std::string pixels = " size " + std::to_string(width) + "," + std::to_string(height);
  switch (format) {
    case FigureFormat::png: return "set terminal pngcairo enhanced color" + pixels + style;
    case FigureFormat::svg: return "set terminal svg enhanced" + pixels + style + " background rgb \"white\"";
    case FigureFormat::pdf: break;
  }
  char inches[64];
  std::snprintf(inches, sizeof inches, " size %.3fin,%.3fin", width / 96.0, height / 96.0);
  return "set terminal pdfcairo enhanced color" + std::string(inches) + style;
}

// gnuplot's first error in one line, without its "line 0: " (a line of a piped script) and the
// echoed command above it; warnings are passed over.
std::string first_error(const std::string& log, const std::string& ending) {
  std::string other;
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) {
    const auto first = line.find_first_not_of(" \t^"), last = line.find_last_not_of(" \t\r");
    if (first == std::string::npos) continue;
    line = line.substr(first, last - first + 1);
    if (line.rfind("warning", 0) == 0) continue;
    if (line.rfind("line ", 0) == 0 && line.find(": ") != std::string::npos) return line.substr(line.find(": ") + 2);
    if (other.empty()) other = line;
  }
  return !other.empty() ? other : !ending.empty() ? ending : "it failed without a message";
}

}  // namespace

std::string number(double value) {
  if (!std::isfinite(value)) return "NaN";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string GnuplotScript::sanitize(std::string_view user_text) {
  constexpr std::size_t kMaxBytes = 2000;  // long enough for any title; a megabyte is not one
  std::string line;
  for (std::size_t i = 0; i < user_text.size() && line.size() < kMaxBytes;) {
    const std::size_t n = utf8_length(user_text, i);
    const unsigned char c = static_cast<unsigned char>(user_text[i]);
    if (n == 0)
      line += "\xEF\xBF\xBD";  // U+FFFD
    else if (n == 1 && (c < 0x20 || c == 0x7F))
      line += ' ';  // no newline, carriage return or NUL may end the datablock line
    else
      line.append(user_text.substr(i, n));
    i += std::max<std::size_t>(n, 1);
  }
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
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c > 0) body += ' ';
      body += number(row[c]);
    }
    body += '\n';
  }
  tables_.push_back(std::move(body));
  return "$D" + std::to_string(tables_.size());
}

std::string GnuplotScript::render() const {
  std::string out = "$TEXT << EOD\n";
  for (const auto& line : texts_) out += ">" + line + "\n";
  out += "EOD\nT(k) = substr($TEXT[k], 2, strlen($TEXT[k]))\n";
  for (std::size_t t = 0; t < tables_.size(); ++t) out += "$D" + std::to_string(t + 1) + " << EOD\n" + tables_[t] + "EOD\n";
  for (const auto& line : commands_) out += line + "\n";
  return out;
}

FigureFormat figure_format(const std::string& option, const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".png") return FigureFormat::png;
  if (extension == ".svg") return FigureFormat::svg;
  if (extension == ".pdf") return FigureFormat::pdf;
  throw InputError(option, path, "a figure must end in .png, .svg or .pdf");
}

void render_figure(const GnuplotScript& script, int width, int height, const std::string& output, const std::string& option) {
  const FigureFormat format = figure_format(option, output);
  check_output_path(option, output);
  // `set output` without a name: the figure goes to gnuplot's stdout, which run_process keeps.
  const std::string preamble =
      checked("set encoding utf8") + "\n" + checked(terminal(format, width, height)) + "\n" + checked("set output") + "\n";
  const ProcessResult gnuplot = run_process({"gnuplot", "--default-settings"}, [&](std::FILE* stream) {
    Gnuplot gp(stream);  // closes the stream when it goes
    gp << preamble << script.render();
    gp.flush();
    return static_cast<bool>(gp);
  });
  if (!gnuplot.success) throw SolverError("gnuplot failed on " + output + ": " + first_error(gnuplot.errors, gnuplot.ending));
  if (gnuplot.output.empty()) throw SolverError("gnuplot failed on " + output + ": it drew nothing");
  write_file_atomically(output, gnuplot.output);
}

}  // namespace dlpverify::plot
