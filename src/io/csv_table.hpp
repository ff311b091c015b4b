// Numeric CSV tables with a header line: the per-particle errors (particle,xi,err_<variable>…)
// and the error histories (t,l2_<variable>…,ref_l2_<variable>…) the study writes for its finest
// level, with their units line when they have one (io/result_units.hpp).
#pragma once

#include <istream>
#include <string>
#include <vector>

namespace dlpverify {

struct CsvTable {
  std::string path;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row]
  std::vector<std::string> units;           // one per column from a "# units:" line; empty: none


  // The column's values; throws std::out_of_range when there is no such column.
  const std::vector<double>& column(const std::string& name) const;
  bool has(const std::string& name) const;
  std::size_t rows() const { return values.empty() ? 0 : values.front().size(); }
};

// Reads `path`: lines starting with '#' and blank lines before the header are skipped, but for
// a units line "# units: u1,u2,…", which must have a field per column; the header must start with `required` (in that order) and may go on with any of `optional`, each
// at most once; every row must hold one number per column (nan and inf are numbers too).
// Throws InputError naming the file and line for anything else.
CsvTable read_csv_table(const std::string& path, const std::vector<std::string>& required,
                        const std::vector<std::string>& optional);
// The same from a stream; `path` names it in the table and in errors.
CsvTable read_csv_table(std::istream& in, const std::string& path, const std::vector<std::string>& required,
                        const std::vector<std::string>& optional);
// The same for a header whose columns after `required` are <prefix><name> for one of `prefixes`
// and any non-empty name (a variable of the file's own, "err_angle"), each at most once.
CsvTable read_prefixed_csv_table(std::istream& in, const std::string& path, const std::vector<std::string>& required,
                                 const std::vector<std::string>& prefixes);

}  // namespace dlpverify
