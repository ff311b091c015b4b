#include "cli/study_file.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <optional>
#include <set>
#include <utility>

#include <toml++/toml.h>

#include "dlpverify/errors.hpp"
#include "io/input_file.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

namespace {

// What an option's value is, from its CLI11 declaration; a study file's key must be of that TOML type.
enum class Takes { flag, whole_number, number, text, number_or_word };

Takes what_option_takes(const CLI::Option& option) {
  if (option.get_expected_max() == 0) return Takes::flag;
  // Text options whose value may be a number: levels = 4 or "auto", gamma = 1.4 or "diatomic".
  static const std::set<std::string> number_or_word = {"levels", "gamma", "expect-order"};
  if (number_or_word.count(option.get_single_name())) return Takes::number_or_word;
  const std::string type = option.get_type_name();
  if (type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0) return Takes::whole_number;
  if (type.rfind("FLOAT", 0) == 0) return Takes::number;
  return Takes::text;
}

const char* expected_type(Takes takes) {
  switch (takes) {
    case Takes::flag: return "true or false (a TOML boolean, unquoted)";
    case Takes::whole_number: return "a whole number (a TOML integer, unquoted)";
    case Takes::number: return "a number (a TOML integer or float, unquoted)";
    case Takes::number_or_word: return "a number, or a word in double quotes";
    default: return "text in double quotes (a TOML string)";
  }
}

const char* type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date or time";
  }
}

std::string float_text(double value) {
  char text[40];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;  // the shortest text that reads back exact
  return std::string(text, end);
}

// The value as the option's text, or nullopt for a value of another TOML type than it takes.
std::optional<std::string> option_text(Takes takes, const toml::node& node) {
  const bool number = takes == Takes::number || takes == Takes::number_or_word;
  if (const auto* v = node.as_boolean(); v && takes == Takes::flag) return v->get() ? "true" : "false";
  if (const auto* v = node.as_integer(); v && (number || takes == Takes::whole_number)) return std::to_string(v->get());
  if (const auto* v = node.as_floating_point(); v && number) return float_text(v->get());
  if (const auto* v = node.as_string(); v && (takes == Takes::text || takes == Takes::number_or_word)) return v->get();
  return std::nullopt;
}

// The value as the file shows it, for an error line.
std::string shown(const toml::node& node) {
  if (const auto* v = node.as_string()) return '"' + printable(v->get()) + '"';
  if (const auto* v = node.as_integer()) return std::to_string(v->get());
  if (const auto* v = node.as_floating_point()) {
    const std::string text = float_text(v->get());  // 4.0 shown as written, not as 4
    return text.find_first_of(".eEna") == std::string::npos ? text + ".0" : text;
  }
  if (const auto* v = node.as_boolean()) return v->get() ? "true" : "false";
  return std::string("(") + type_name(node) + ")";
}

// "--key=value": one word, so a value starting with '-' or holding '=' stays the value (CLI11
// splits a word at its first '=', and the key, an option's name, holds none); one per value of an
// array, for an option that may be given several times (--expect-order 2 --expect-order energy=3).
std::vector<std::string> option_words(const CLI::App& subcommand, const std::string& path, const std::string& key,
                        const toml::node& node) {
  const std::string at = "line " + std::to_string(node.source().begin.line) + ": ";
  const std::string name = printable(key);
  if (node.is_table()) throw InputError("--config", path, at + "'" + name + "' is a section or table; keys stand at the top level");
  if (key == "config") throw InputError("--config", path, at + "a study file cannot name another study file");
  const CLI::Option* option = subcommand.get_option_no_throw("--" + key);
  if (option == nullptr || option == subcommand.get_help_ptr())
    throw InputError("--config", path, at + "unknown key '" + name + "' (keys are the long option names)");
  const bool repeats = option->get_multi_option_policy() == CLI::MultiOptionPolicy::TakeAll;
  if (node.is_array() && !repeats)
    throw InputError("--config", path, at + name + " is an array; --" + name + " takes one value");
  std::vector<std::string> words;
  const auto word = [&](const toml::node& value) {
    const Takes takes = what_option_takes(*option);
    const std::optional<std::string> text = option_text(takes, value);
    if (!text)
      throw InputError("--config", path, at + name + " = " + shown(value) + " is " + type_name(value) + "; --" + name +
                                             " takes " + expected_type(takes));
    if (text->empty()) throw InputError("--config", path, at + name + " = \"\" is empty; give a value or leave the key out");
    words.push_back("--" + key + "=" + *text);
  };
  if (const toml::array* values = node.as_array()) {  // an option given several times: each value, in order
    if (values->empty()) throw InputError("--config", path, at + name + " = [] is empty; give a value or leave the key out");
    for (const toml::node& value : *values) word(value);
  }
  else
    word(node);
  return words;
}

// The study file named in args, or nullopt when there is none.
std::optional<std::string> study_file_path(const std::vector<std::string>& args) {
  std::optional<std::string> path;
  int given = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--config") {
      if (i + 1 >= args.size()) throw InputError("--config: needs a file name");
      path = args[i + 1];
      ++given;
    } else if (args[i].rfind("--config=", 0) == 0) {
      path = args[i].substr(9);
      ++given;
    } else {
      continue;
    }
    if (path->empty()) throw InputError("--config", "''", "is empty; name a study file");
  }
  if (given > 1) throw InputError("--config", *path, "given more than once; a study reads one file");
  return path;
}

}  // namespace

std::vector<std::string> study_file_options(const CLI::App& subcommand, const std::string& path, std::string_view text) {
  toml::table table;
  try {
    table = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const toml::source_position& at = e.source().begin;
    throw InputError("--config", path, "not TOML at line " + std::to_string(at.line) + ", column " +
                                           std::to_string(at.column) + ": " + std::string(e.description()));
  }
  // In the file's order, so the first bad key named is the first one written.
  std::vector<std::pair<std::string, const toml::node*>> keys;
  for (const auto& [key, node] : table) keys.emplace_back(std::string(key.str()), &node);
  std::stable_sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) {
    const toml::source_position &pa = a.second->source().begin, &pb = b.second->source().begin;
    return std::pair(pa.line, pa.column) < std::pair(pb.line, pb.column);
  });
  std::vector<std::string> options;
  for (const auto& [key, node] : keys)
    for (std::string& word : option_words(subcommand, path, key, *node)) options.push_back(std::move(word));
  return options;
}

std::vector<std::string> study_file_options(const CLI::App& subcommand, const std::string& path, std::istream& text) {
  const std::string whole{std::istreambuf_iterator<char>(text), std::istreambuf_iterator<char>()};
  return study_file_options(subcommand, path, std::string_view(whole));
}

std::vector<std::string> expand_study_file(const CLI::App& subcommand, const std::vector<std::string>& args) {
  const std::optional<std::string> path = study_file_path(args);
  if (!path) return args;
  const std::string text = read_input_file("--config", *path, input_limit::study_file);
  std::vector<std::string> expanded = study_file_options(subcommand, *path, std::string_view(text));
  expanded.insert(expanded.end(), args.begin(), args.end());
  return expanded;
}

}  // namespace dlpverify::cli
