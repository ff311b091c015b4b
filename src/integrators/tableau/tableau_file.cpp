#include "integrators/tableau/tableau_file.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "dlpverify/errors.hpp"
#include "io/input_file.hpp"

namespace dlpverify {

namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// "tableau FILE: KEY", the quantity every error of the file names.
struct Where {
  const std::string& source;
  InputError error(const std::string& key, const std::string& value, const std::string& reason) const {
    return InputError("tableau " + source + ": " + key, value, reason);
  }
};

const char* type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date or time";
    default: return "not a number";
  }
}

// The value as the file gives it, for the error line.
std::string node_text(const toml::node& node) {
  std::ostringstream text;
  if (node.is_string()) text << '"' << *node.value<std::string>() << '"';
  else if (node.is_array()) text << "[...]";
  else if (node.is_table()) text << "{...}";
  else if (node.is_floating_point()) text << number_text(*node.value<double>());
  else if (node.is_integer()) text << *node.value<std::int64_t>();
  else if (node.is_boolean()) text << (*node.value<bool>() ? "true" : "false");
  else text << "(a date or time)";
  return text.str();
}

// A TOML float or integer, finite.
double number(const Where& where, const std::string& key, const toml::node& node) {
  if (!node.is_number()) throw where.error(key, node_text(node), std::string("is ") + type_name(node) + ", not a number");
  const double v = node.is_integer() ? static_cast<double>(*node.value<std::int64_t>()) : *node.value<double>();
  if (!std::isfinite(v)) throw where.error(key, number_text(v), "must be finite");
  return v;
}

const toml::node& required(const Where& where, const toml::table& table, const std::string& key) {
  const toml::node* node = table.get(key);
  if (!node) throw where.error(key, "(missing)", "is required");
  return *node;
}

std::vector<double> vector(const Where& where, const std::string& key, const toml::node& node) {
  const toml::array* array = node.as_array();
  if (!array) throw where.error(key, node_text(node), std::string("is ") + type_name(node) + ", not an array of numbers");
  std::vector<double> values;
  for (std::size_t i = 0; i < array->size(); ++i)
    values.push_back(number(where, key + "[" + std::to_string(i + 1) + "]", *array->get(i)));
  return values;
}

int order_value(const Where& where, const std::string& key, const toml::node& node) {
  if (!node.is_integer()) throw where.error(key, node_text(node), std::string("is ") + (node.is_floating_point() ? "a float" : type_name(node)) + ", not a whole number");
  const std::int64_t p = *node.value<std::int64_t>();
  if (p < 1 || p > 100) throw where.error(key, std::to_string(p), "must be a whole number in [1, 100]");
  return static_cast<int>(p);
}

void require_length(const Where& where, const std::string& key, std::size_t length, std::size_t stages) {
  if (length != stages)
    throw where.error(key, std::to_string(length) + " entries",
                      "must have one per stage: " + std::to_string(stages) + " (the length of b)");
}

}  // namespace

RuntimeTableau parse_tableau(const std::string& text, const std::string& source) {
  const Where where{source};
  toml::table table;
  try {
    table = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError("tableau " + source, "line " + std::to_string(e.source().begin.line),
                     "not TOML: " + std::string(e.description()));
  }
  static const std::set<std::string> known = {"name", "order", "c", "b", "A", "b_embedded", "embedded_order"};
  for (const auto& [key, node] : table)
    if (!known.count(std::string(key.str())))
      throw where.error(std::string(key.str()), node_text(node), "unknown key (known: name, order, c, b, A, b_embedded, embedded_order)");

  RuntimeTableau t;
  t.source = source;
  const toml::node& name = required(where, table, "name");
  if (!name.is_string()) throw where.error("name", node_text(name), std::string("is ") + type_name(name) + ", not a string");
  t.name = *name.value<std::string>();
  if (t.name.empty()) throw where.error("name", "\"\"", "must not be empty");
  t.order = order_value(where, "order", required(where, table, "order"));

  t.b = vector(where, "b", required(where, table, "b"));
  const std::size_t s = t.b.size();
  if (s == 0) throw where.error("b", "[]", "must have at least one stage");
  if (s > kMaxTableauStages)
    throw where.error("b", std::to_string(s) + " stages",
                      "at most " + std::to_string(kMaxTableauStages) + " stages (the work grows with their square)");
  t.c = vector(where, "c", required(where, table, "c"));
  require_length(where, "c", t.c.size(), s);

  const toml::node& a_node = required(where, table, "A");
  const toml::array* rows = a_node.as_array();
  if (!rows) throw where.error("A", node_text(a_node), std::string("is ") + type_name(a_node) + ", not an array of rows");
  require_length(where, "A", rows->size(), s);
  for (std::size_t i = 0; i < s; ++i) {
    const std::string row_key = "A[" + std::to_string(i + 1) + "]";
    std::vector<double> row = vector(where, row_key, *rows->get(i));
    require_length(where, row_key, row.size(), s);
    for (std::size_t j = i + 1; j < s; ++j)
      if (row[j] != 0.0)
        throw where.error("A[" + std::to_string(i + 1) + "][" + std::to_string(j + 1) + "]", number_text(row[j]),
                          "must be zero above the diagonal (an explicit or diagonally implicit method)");
    t.a.push_back(std::move(row));
  }

  const toml::node* embedded = table.get("b_embedded");
  const toml::node* embedded_order = table.get("embedded_order");
  if (embedded && !embedded_order) throw where.error("embedded_order", "(missing)", "is required with b_embedded");
  if (embedded_order && !embedded) throw where.error("b_embedded", "(missing)", "is required with embedded_order");
  if (embedded) {
    t.b_embedded = vector(where, "b_embedded", *embedded);
    require_length(where, "b_embedded", t.b_embedded.size(), s);
    t.embedded_order = order_value(where, "embedded_order", *embedded_order);
  }
  return t;
}

RuntimeTableau read_tableau_file(const std::string& path) {
  return parse_tableau(read_input_file("tableau file", path, input_limit::tableau), path);
}

}  // namespace dlpverify
