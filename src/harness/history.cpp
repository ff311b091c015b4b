#include "dlpverify/history.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "io/result_units.hpp"

namespace dlpverify {

std::vector<HistoryPoint> record_history(const State& initial, const std::vector<Variable>& variables,
                                         double dt, long steps, int outputs, const AdvanceSteps& advance,
                                         const ReferenceAt& reference_at, const Measure& measure) {
  std::vector<HistoryPoint> history;
  const long count = std::clamp<long>(outputs, 1, std::max(steps, 1L));
  State state = initial;
  long done = 0;
  for (long k = 1; k <= count; ++k) {
    const long target = steps * k / count;  // whole steps, the last exactly `steps`
    advance(state, static_cast<double>(done) * dt, dt, target - done);
    done = target;
    const double tau = static_cast<double>(done) * dt;
    const State reference = measure ? measure(reference_at(tau), tau) : reference_at(tau);
    const State measured = measure ? measure(state, tau) : state;
    HistoryPoint point{tau, {}, {}};
    for (const Variable& v : variables) {
      const ErrorNorms norms = error_norms(measured, reference, v);
      point.l2.push_back(norms.l2);
      point.reference_l2.push_back(norms.reference_l2);
    }
    history.push_back(std::move(point));
  }
  return history;
}

std::string format_history(const std::vector<HistoryPoint>& history, const std::vector<Variable>& variables,
                           const std::string& time_unit) {
  std::ostringstream out;
  std::vector<std::string> units{time_unit}, implied{kImpliedTimeUnit};
  for (int block = 0; block < 2; ++block)  // l2_ and ref_l2_ columns
    for (const Variable& v : variables) {
      units.push_back(v.unit);
      implied.push_back(implied_unit(v.name));
    }
  out << units_line(units, implied);
  out << "t";
  for (const Variable& v : variables) out << ",l2_" << v.name;
  for (const Variable& v : variables) out << ",ref_l2_" << v.name;
  out << "\n";
  char number[32];
  for (const HistoryPoint& point : history) {
    std::snprintf(number, sizeof number, "%.17g", point.tau);
    out << number;
    for (double value : point.l2) {
      std::snprintf(number, sizeof number, ",%.17g", value);
      out << number;
    }
    for (double value : point.reference_l2) {
      std::snprintf(number, sizeof number, ",%.17g", value);
      out << number;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace dlpverify
