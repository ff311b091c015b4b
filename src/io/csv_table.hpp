// Numeric CSV tables with a header line: the per-particle errors
// (particle,xi,err_position,err_velocity[,err_temperature][,err_mass]) and the error histories
// (t,l2_position,l2_velocity[,l2_temperature][,l2_mass]) the study writes for its finest level.
#pragma once

#include <istream>
#include <string>
#include <vector>

namespace dlpverify {

struct CsvTable {
  std::string path;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]

  // The column's values; throws std::out_of_range when there is no such column.
  const std::vector<double>& column(const std::string& name) const;
  bool has(const std::string& name) const;
  std::size_t rows() const { return values.empty() ? 0 : values.front().size(); }
};

// Reads `path`: lines starting with '#' and blank lines before the header are skipped; the
// header must start with `required` (in that order) and may go on with any of `optional`, each
// at most once; every row must hold one number per column (nan and inf are numbers too).
// Throws InputError naming the file and line for anything else.
CsvTable read_csv_table(const std::string& path, const std::vector<std::string>& required,
                        const std::vector<std::string>& optional);
// The same from a stream; `path` names it in the table and in errors.
CsvTable read_csv_table(std::istream& in, const std::string& path, const std::vector<std::string>& required,
                        const std::vector<std::string>& optional);

}  // namespace dlpverify
