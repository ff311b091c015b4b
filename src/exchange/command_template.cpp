#include "exchange/command_template.hpp"


#include "exchange/exchange_file.hpp"
#include "io/format.hpp"

namespace dlpverify::exchange {

std::vector<std::string> split_command(const std::string& command) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  for (std::size_t i = 0; i < command.size(); ++i) {
    const char c = command[i];
    if (c == ' ' || c == '\t' || c == '\n') {
      if (in_word) words.push_back(word), word.clear(), in_word = false;
      continue;
    }
    in_word = true;
    if (c == '\\' && i + 1 < command.size()) {
      word += command[++i];
    } else if (c == '\'' || c == '"') {
      std::size_t j = i + 1;
      for (; j < command.size() && command[j] != c; ++j) {
        if (c == '"' && command[j] == '\\' && j + 1 < command.size() &&
            (command[j + 1] == '"' || command[j + 1] == '\\'))
          ++j;
        word += command[j];
      }
      if (j >= command.size())
        throw ExchangeError(std::string("the command has an unclosed ") + (c == '"' ? "double" : "single") + " quote");
      i = j;
    } else {
      word += c;
    }
  }
  if (in_word) words.push_back(word);
  if (words.empty()) throw ExchangeError("the command is empty");
  return words;
}

std::string fill_placeholders(const std::string& text, const std::map<std::string, std::string>& values) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    if (text[i] == '{') {
      const std::size_t close = text.find('}', i);
      if (close != std::string::npos) {
        const auto found = values.find(text.substr(i + 1, close - i - 1));
        if (found != values.end()) {
          out += found->second;
          i = close + 1;
          replaced = true;
        }
      }
    }
    if (!replaced) out += text[i++];
  }
  return out;
}

namespace {

// Where a placeholder stands in a shell command: which quotes are open there.
enum class Quoting { none, single, double_ };

bool needs_no_quotes(const std::string& value) {
  return !value.empty() && value.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                   "0123456789_@%+=:,./-") == std::string::npos;
}

// `value` inside '…': each ' closes the quote, is escaped and opens it again.
std::string inside_single_quotes(const std::string& value) {
  std::string out;
  for (const char c : value) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out;
}

// `value` written so that the shell reads it back as it is, one word, where `quoting` is open.
std::string shell_quoted(const std::string& value, Quoting quoting) {
  if (quoting == Quoting::single) return inside_single_quotes(value);
  // Built by appending: GCC 12 warns falsely (-Wrestrict, its bug 105329) on "'" + std::string&&.
  std::string out;
  if (quoting == Quoting::none) {
    if (needs_no_quotes(value)) return value;
    out += '\'';
    out += inside_single_quotes(value);
    out += '\'';
    return out;
  }
  for (const char c : value) {  // inside "…": the four characters special there, escaped
    if (c == '$' || c == '`' || c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

// `command` with its placeholders filled in for /bin/sh: each value quoted for the quotes open
// where its placeholder stands ('…', "…" or none; a backslash escapes outside '…').
std::string fill_for_shell(const std::string& command, const std::map<std::string, std::string>& values) {
  std::string out;
  Quoting quoting = Quoting::none;
  for (std::size_t i = 0; i < command.size();) {
    const char c = command[i];
    if (c == '{') {
      const std::size_t close = command.find('}', i);
      const auto found = close == std::string::npos ? values.end() : values.find(command.substr(i + 1, close - i - 1));
      if (found != values.end()) {
        out += shell_quoted(found->second, quoting);
        i = close + 1;
        continue;
      }
    }
    if (c == '\\' && quoting != Quoting::single && i + 1 < command.size()) {
      out += command.substr(i, 2);
      i += 2;
      continue;
    }
    if (c == '\'' && quoting != Quoting::double_) quoting = quoting == Quoting::single ? Quoting::none : Quoting::single;
    if (c == '"' && quoting != Quoting::single) quoting = quoting == Quoting::double_ ? Quoting::none : Quoting::double_;
    out += c;
    ++i;
  }
  return out;
}

}  // namespace

std::vector<std::string> command_argv(const std::string& command, bool shell,
                                      const std::map<std::string, std::string>& values) {
  if (shell) return {"/bin/sh", "-c", fill_for_shell(command, values)};
  std::vector<std::string> argv = split_command(command);
  for (std::string& word : argv) word = fill_placeholders(word, values);
  return argv;
}

std::string exact_text(double value) { return shortest_text(value); }

}  // namespace dlpverify::exchange
