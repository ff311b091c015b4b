#include "plot/gnuplot_script.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace dlpverify::plot {

namespace {

// Words that make gnuplot reach outside the figure (a shell, another script, a file or a plugin)
// or wait for a human.
constexpr std::array kRefusedWords = {"system", "shell", "load", "call", "print", "cd", "save", "pipe", "import", "pause"};

bool word_char(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; }

// Length of the valid UTF-8 sequence starting at s[i], or 0 when there is none.
std::size_t utf8_sequence(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  std::size_t length;
  unsigned int code;
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    code = lead & 0x1F;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    code = lead & 0x0F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    code = lead & 0x07;
  } else {
    return 0;
  }
  if (i + length > s.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  // Overlong forms, UTF-16 surrogates and code points past U+10FFFF are not UTF-8.
  if ((length == 3 && code < 0x800) || (length == 4 && (code < 0x10000 || code > 0x10FFFF)) ||
      (code >= 0xD800 && code <= 0xDFFF))
    return 0;
  return length;
}

}  // namespace

std::string number(double value) {
  if (!std::isfinite(value)) return "NaN";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string GnuplotScript::sanitize(std::string_view user_text) {
  // Long enough for any title; a megabyte of "title" is not one.
  constexpr std::size_t kMaxBytes = 2000;
  std::string line;
  for (std::size_t i = 0; i < user_text.size() && line.size() < kMaxBytes;) {
    const std::size_t length = utf8_sequence(user_text, i);
    if (length == 0) {
      line += "\xEF\xBF\xBD";  // U+FFFD replacement character
      ++i;
      continue;
    }
    const unsigned char c = static_cast<unsigned char>(user_text[i]);
    if (length == 1 && (c < 0x20 || c == 0x7F))
      line += ' ';  // no newline, carriage return or NUL may end the datablock line
    else
      line.append(user_text.substr(i, length));
    i += length;
  }
  return line;
}

void GnuplotScript::command(std::string_view line) { commands_.push_back(checked_command(line)); }

std::string GnuplotScript::checked_command(std::string_view line) {
  const auto refuse = [&](const std::string& why) {
    throw std::logic_error("gnuplot command refused (" + why + "): " + std::string(line));
  };
  for (char ch : line) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c > 0x7E) refuse("not printable ASCII: text goes through text()");
    if (ch == '`' || ch == '@' || ch == '|' || ch == '<' || ch == '!' || ch == '\\')
      refuse(std::string("character ") + ch);
  }
  for (std::size_t i = 0; i < line.size();) {
    if (!word_char(line[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < line.size() && word_char(line[j])) ++j;
    const std::string_view word = line.substr(i, j - i);
    for (const char* refused : kRefusedWords)
      if (word == refused) refuse("word " + std::string(word));
    i = j;
  }
  if (!line.empty() && line.front() == '$') refuse("datablocks come from table()");
  return std::string(line);
}

std::string GnuplotScript::text(std::string_view user_text) {
  std::string line = sanitize(user_text);
  auto [it, inserted] = text_index_.try_emplace(line, static_cast<int>(texts_.size()) + 1);
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

}  // namespace dlpverify::plot
