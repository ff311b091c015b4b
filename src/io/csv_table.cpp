#include "io/csv_table.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <functional>
#include <memory>
#include <stdexcept>

#include "dlpverify/errors.hpp"
#include "io/printable.hpp"
#include "io/input_file.hpp"

namespace dlpverify {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    std::string field = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto first = field.find_first_not_of(" \t");
    const auto last = field.find_last_not_of(" \t\r");
    fields.push_back(first == std::string::npos ? std::string() : field.substr(first, last - first + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ",") + n;
  return text;
}

}  // namespace

const std::vector<double>& CsvTable::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::out_of_range("no column " + name + " in " + path);
  return values[static_cast<std::size_t>(it - columns.begin())];
}

bool CsvTable::has(const std::string& name) const { return std::find(columns.begin(), columns.end(), name) != columns.end(); }

CsvTable read_csv_table(const std::string& path, const std::vector<std::string>& required,
                        const std::vector<std::string>& optional) {
  std::ifstream in;
  try {
    in = open_input_stream("CSV file", path, input_limit::result);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.reason());
  }
  return read_csv_table(in, path, required, optional);
}

namespace {

// The table, its columns after `required` each accepted by `accepts` and named at most once;
// `expected` describes the header in errors.
CsvTable read_table(std::istream& in, const std::string& path, const std::vector<std::string>& required,
                    const std::function<bool(const std::string&)>& accepts, const std::string& expected) {
  CsvTable table;
  table.path = path;
  static const std::string kUnits = "# units:";

  std::string line;
  long line_number = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (!have_header) {
      if (line.rfind(kUnits, 0) == 0) table.units = split(line.substr(kUnits.size()));
      if (line.front() == '#') continue;
      table.columns = split(line);
      if (!table.units.empty() && table.units.size() != table.columns.size())
        throw InputError(path + " line " + std::to_string(line_number) + ": " + std::to_string(table.columns.size()) +
                         " columns, the units line has " + std::to_string(table.units.size()) + " fields");
      for (std::size_t c = 0; c < required.size(); ++c)
        if (c >= table.columns.size() || table.columns[c] != required[c])
          throw InputError(path + " line " + std::to_string(line_number) + ": header must be " + expected);
      for (std::size_t c = required.size(); c < table.columns.size(); ++c) {
        const auto& name = table.columns[c];
        const bool known = accepts(name);
        const bool repeated = std::find(table.columns.begin(), table.columns.begin() + static_cast<long>(c), name) !=
                              table.columns.begin() + static_cast<long>(c);
        const std::string where = path + " line " + std::to_string(line_number) + ": column " + std::to_string(c + 1);
        if (repeated) throw InputError(where + " (" + printable(name) + ") names a column given before it; each is named once");
        if (!known) throw InputError(where + " (" + printable(name) + ") is not one of " + expected);
      }
      table.values.assign(table.columns.size(), {});
      have_header = true;
      continue;
    }
    const auto fields = split(line);
    if (fields.size() != table.columns.size())
      throw InputError(path + " line " + std::to_string(line_number) + ": " + std::to_string(fields.size()) +
                       " fields, the header has " + std::to_string(table.columns.size()));
    for (std::size_t c = 0; c < fields.size(); ++c) {
      double value = 0.0;
      const char* first = fields[c].data();
      const char* last = first + fields[c].size();
      if (!fields[c].empty() && *first == '+') ++first;
#ifdef DLPVERIFY_PLANT_BUGS
      // Planted bug (test-only build, tests/planted): a field that does not start with a digit is
      // checked for a doubled sign in a copy of exactly its length, by its second character and
      // without checking that there is one: a field of one such character ("-") reads past it.
      if (!fields[c].empty()) {
        const std::unique_ptr<char[]> copy(new char[fields[c].size()]);
        fields[c].copy(copy.get(), fields[c].size());
        if (!std::isdigit(static_cast<unsigned char>(copy[0])) && copy[1] == copy[0])
          throw InputError(path + " line " + std::to_string(line_number) + ": a doubled sign");
      }
#endif
      const auto [end, error] = std::from_chars(first, last, value);
      if (fields[c].empty() || error != std::errc() || end != last)
        throw InputError(path + " line " + std::to_string(line_number) + ": " + table.columns[c] + " = \"" +
                         fields[c] + "\" is not a number");
      table.values[c].push_back(value);
    }
  }
  if (in.bad()) throw InputError(path + ": read error");
  if (!have_header) throw InputError(path + ": empty, expected a header " + expected);
  return table;
}

}  // namespace

CsvTable read_csv_table(std::istream& in, const std::string& path, const std::vector<std::string>& required,
                        const std::vector<std::string>& optional) {
  const std::string expected = joined(required) + (optional.empty() ? "" : "[," + joined(optional) + "]");
  return read_table(
      in, path, required,
      [&optional](const std::string& name) { return std::find(optional.begin(), optional.end(), name) != optional.end(); },
      expected);
}

CsvTable read_prefixed_csv_table(std::istream& in, const std::string& path, const std::vector<std::string>& required,
                                 const std::vector<std::string>& prefixes) {
  std::string expected = joined(required);
  for (const auto& prefix : prefixes) expected += "," + prefix + "<variable>…";
  return read_table(
      in, path, required,
      [&prefixes](const std::string& name) {
        return std::any_of(prefixes.begin(), prefixes.end(), [&name](const std::string& prefix) {
          return name.size() > prefix.size() && name.rfind(prefix, 0) == 0;
        });
      },
      expected);
}

}  // namespace dlpverify
