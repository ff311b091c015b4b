// The measured variables of `dlpverify analyze` as the user names them (docs/analyze.md):
// --variable NAME=F1,F2,… or the [[variable]] tables of a TOML file.

#include <toml++/toml.h>

#include "dlpverify/errors.hpp"
#include "exchange/run_set.hpp"
#include "io/input_file.hpp"

namespace dlpverify::exchange {

namespace {

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  for (;;) {
    const auto comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

// A variable needs a name and at least one field, none named twice.
void check_spec(const VariableSpec& spec, const std::string& option, const std::string& value) {
  if (spec.name.empty()) throw InputError(option, value, "names no variable");
  if (spec.fields.empty()) throw InputError(option, value, "names no field");
  for (std::size_t i = 0; i < spec.fields.size(); ++i) {
    if (spec.fields[i].empty()) throw InputError(option, value, "has an empty field name");
    for (std::size_t j = 0; j < i; ++j)
      if (spec.fields[i] == spec.fields[j]) throw InputError(option, value, "names the field " + spec.fields[i] + " twice");
  }
}

}  // namespace

VariableSpec parse_variable(const std::string& text) {
  const auto equals = text.find('=');
  if (equals == std::string::npos) throw InputError("variable", text, "must be NAME=FIELD,FIELD,… (e.g. position=x,y,z)");
  VariableSpec spec{text.substr(0, equals), split_commas(text.substr(equals + 1)), ""};
  check_spec(spec, "variable", text);
  return spec;
}

std::vector<VariableSpec> read_variables_file(const std::string& path) {
  const std::string text = read_input_file("variables file", path, input_limit::variables);
  toml::table file;
  try {
    file = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InputError("variables file", path, std::string("is not TOML: ") + std::string(e.description()));
  }
  for (const auto& [key, node] : file)
    if (key.str() != "variable") throw InputError("variables file", path, "has the key " + std::string(key.str()) + "; only [[variable]] tables");
  const toml::array* tables = file["variable"].as_array();
  if (!tables || tables->empty()) throw InputError("variables file", path, "has no [[variable]] table");
  std::vector<VariableSpec> specs;
  for (const toml::node& node : *tables) {
    const toml::table* table = node.as_table();
    if (!table) throw InputError("variables file", path, "variable is not a table: write [[variable]]");
    VariableSpec spec;
    for (const auto& [key, value] : *table) {
      const std::string k(key.str());
      if (k == "name" && value.is_string()) spec.name = *value.value<std::string>();
      else if (k == "unit" && value.is_string()) spec.unit = *value.value<std::string>();
      else if (k == "fields" && value.is_array()) {
        for (const toml::node& field : *value.as_array()) {
          if (!field.is_string()) throw InputError("variables file", path, "variable " + spec.name + ": fields must be strings");
          spec.fields.push_back(*field.value<std::string>());
        }
      } else {
        throw InputError("variables file", path, "variable key " + k + " is not name (string), fields (strings) or unit (string)");
      }
    }
    check_spec(spec, "variables file", path + " [[variable]] " + spec.name);
    specs.push_back(std::move(spec));
  }
  return specs;
}

}  // namespace dlpverify::exchange
