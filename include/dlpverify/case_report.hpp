/// @file
/// What a problem reports besides its errors: its physical parameters (for provenance and for a
/// program outside dlpverify), its diagnostics (branch counts, invariants), the unit of its time
/// and the word for its members. Capabilities (problem.hpp) the reports and the exchange use;
/// without them the reports carry no parameters or diagnostics, seconds and "members".
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dlpverify/problem.hpp"

namespace dlpverify {

/// How one of a case's diagnostic quantities combines over the members.
enum class MemberReduction {
  sum,  ///< Σ over the members (compensated, in fixed blocks: the same bits for any ranks and threads)
  min,  ///< the smallest member's
  max   ///< the largest member's
};

/// A problem's parameters and diagnostics, as JSON objects for the reports. The diagnostics are
/// reductions over the members (sums, minima, maxima), so that each process computes its share's
/// terms and no process holds the whole population (docs/mpi.md).
class CaseReport : public Capability {
 public:
  /// Physical parameters for provenance: names to SI numbers, or to words for settings.
  virtual nlohmann::json parameters() const = 0;
  /// How each quantity the diagnostics are computed from combines over the members, one per
  /// column of member_terms; empty when the case has no diagnostics.
  virtual std::vector<MemberReduction> diagnostic_reductions() const = 0;
  /// Each member's term of every quantity (a row per member, a column per quantity) for members
  /// first … first + initial.rows() − 1, from their initial state and the finest level's state at
  /// t0 + t_end.
  virtual Eigen::ArrayXXd member_terms(Eigen::Index first, const State& initial, const State& finest,
                                       double t_end) const = 0;
  /// What the case reports besides errors, from its quantities reduced over every member.
  virtual nlohmann::json diagnostics(const std::vector<double>& reduced, double t_end) const = 0;
};

/// The unit of a problem's time (of t0, t_end and every Δt), for the reports and the figures'
/// axes. Without it a problem's time is in seconds.
class TimeUnit : public Capability {
 public:
  /// "s", "1" when dimensionless, or any unit the problem's time is in.
  virtual std::string time_unit() const = 0;
};

/// What a problem's members are called in the reports, singular and plural.
struct MemberNouns {
  std::string one = "member";    ///< for one member
  std::string many = "members";  ///< for any other count
};

/// The reports' word for a problem's members ("particle", "parcel", "system"). Without it they are
/// members: "1 member", "9100 members".
class MemberNoun : public Capability {
 public:
  /// The problem's word for its members, singular and plural.
  virtual MemberNouns member_nouns() const = 0;
};

/// MemberNoun::member_nouns of `problem`, or member/members.
MemberNouns member_nouns(const Problem& problem);
/// `count` members in those words: "1 particle", "9100 particles".
std::string count_text(long long count, const MemberNouns& nouns);

/// CaseReport::parameters of `problem`, or an empty object.
nlohmann::json case_parameters(const Problem& problem);
/// CaseReport::diagnostics of `problem`, or an empty object, from the members this process holds
/// (`initial` and `finest`, all of `problem`'s members) reduced over every process. Collective
/// under mpirun: every process calls it, and every process gets the serial run's bits.
nlohmann::json case_diagnostics(const Problem& problem, const State& initial, const State& finest, double t_end);

}  // namespace dlpverify
