// Units in results. The reports write every variable's unit and the unit of time (of t0, t_end,
// each Δt and a history's t); a reader takes them from the file. Results written before units
// were recorded name their variables only: they carry the units those names imply, the built-in
// cases' variables (docs/model.md §5, §7.1), and their time is in seconds.
#pragma once

#include <string>
#include <vector>

namespace dlpverify {

// "m" for position, "m/s" velocity, "K" temperature, "kg" mass, "Pa" pressure; "" for any other
// name (a variable of a problem's own has no implied unit).
std::string implied_unit(const std::string& variable);
// The names with an implied unit, in that order.
const std::vector<std::string>& implied_variables();
// The unit of time of a result that does not name one.
inline const std::string kImpliedTimeUnit = "s";
// The word for the members of a result that does not name it (written before "member_noun"),
// the built-in cases' particles.
inline const std::string kImpliedMemberNoun = "particles";

// "" (none) and "1" (a ratio, a count, a scaled quantity) put no unit on an axis.
bool dimensionless(const std::string& unit);

// The units line of the CSV results (--history, --per-particle), before the header:
//     # units: 1,rad,J,rad,J
// one field per column in the header's order ("1": dimensionless, empty: none). It is written
// only when some column's unit differs from `implied`, the units a reader assumes for a file
// without the line, so the built-in cases' files stay as they were (their first line is the
// header). A ',' or a line break in a unit would move the fields: it is written as a space.
std::string units_line(const std::vector<std::string>& units, const std::vector<std::string>& implied);

}  // namespace dlpverify
