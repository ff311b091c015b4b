/// @file
/// A problem: a population of N independent members (particles, gas parcels, …), each carrying
/// F named fields, and the ODE y′ = f(t, y) every member obeys. This is the whole contract: the
/// harness and every integrator can run a study of any class that implements it.
///
/// The state is an N × F column-major array: field f of member p at f·N + p, each field a
/// contiguous column, the whole population one buffer a SUNDIALS N_Vector wraps without copying.
/// The right-hand side takes a block of members in structure-of-arrays form (F field pointers ×
/// `count` members): one virtual call per block, never per member.
///
/// What only some problems offer and only some consumers use (a closed form, shortcuts for the
/// Runge–Kutta integrators, a splitting for the implicit solvers, …) is a Capability, declared
/// beside its consumer; a problem provides it from its constructor and a consumer asks for it
/// with capability<C>() and works without it.
#pragma once

#include <string>
#include <typeindex>
#include <typeinfo>
#include <vector>

#include "dlpverify/eigen.hpp"

/// dlpverify's library: problems, integrators, convergence and work-precision studies, reports.
namespace dlpverify {

/// members × fields, column-major (Eigen's default).
using State = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic>;

/// One named field every member carries.
struct Field {
  std::string name;  ///< "x", "vx", "T", …
  std::string unit;  ///< SI: "m", "m/s", "K", …; "1" when dimensionless
};

/// A group of consecutive measured columns compared together, e.g. {"position", 0, 3, "m"}: its
/// norm for a member is the Euclidean norm over the group's columns.
struct Variable {
  std::string name;     ///< "position", "velocity", …
  int first_field = 0;  ///< index of its first column of measured()
  int fields = 1;       ///< number of consecutive columns in the group
  std::string unit;     ///< SI unit of its norm
};

/// An optional interface a problem may offer (the base of every capability).
class Capability {
 public:
  virtual ~Capability() = default;
};

/// A population of N independent members with F fields each: y′ = f(t, y) per member.
class Problem {
 public:
  Problem() = default;
  Problem(const Problem&) = delete;             ///< capabilities point into the problem
  Problem& operator=(const Problem&) = delete;  ///< capabilities point into the problem
  virtual ~Problem() = default;

  /// The case this problem instance is, e.g. "drag" (for reports).
  virtual std::string name() const = 0;
  /// The F fields of every member, in column order.
  virtual std::vector<Field> fields() const = 0;
  /// What a study measures, in report order: groups of the columns of measured(). By default each
  /// field is a variable of its own.
  virtual std::vector<Variable> variables() const;
  /// The measured columns at t0 + tau of members first … first + state.rows() − 1: the fields
  /// themselves (the default), or also quantities derived from them (a gas parcel's pressure).
  /// Norms, orders and references compare measured states, a reference's as well as a level's.
  virtual State measured(State state, double /*tau*/, Eigen::Index /*first*/ = 0) const { return state; }
  /// Number of members N.
  virtual Eigen::Index members() const = 0;
  /// The start time t0 of every study (0 by default).
  virtual double initial_time() const { return 0.0; }
  /// The state at initial_time(), N × F.
  virtual State initial_state() const = 0;
  /// dy/dt = f(t, y) of the members first … first + count − 1: field f of the block's member i is
  /// y[f][i] (and dydt[f][i]). Called concurrently from several threads on disjoint blocks.
  virtual void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const = 0;

  /// Number of fields F (fields().size()).
  int field_count() const { return static_cast<int>(fields().size()); }
  /// The capability C this problem provides, or nullptr (when it was not provided, even if the
  /// problem's class implements C).
  template <class C>
  const C* capability() const {
    for (const Provided& p : capabilities_)
      if (p.type == typeid(C)) return static_cast<const C*>(p.capability);
    return nullptr;
  }
  /// Every capability provided, in the order provided.
  std::vector<const Capability*> capabilities() const {
    std::vector<const Capability*> all;
    for (const Provided& p : capabilities_) all.push_back(p.capability);
    return all;
  }

 protected:
  /// Offers `c` (usually *this, or an adapter the problem owns) as its capability C.
  template <class C>
  void provide(const C& c) {
    capabilities_.push_back({std::type_index(typeid(C)), &static_cast<const Capability&>(c)});
  }

 private:
  struct Provided {
    std::type_index type;          // the interface C it was provided as
    const Capability* capability;  // its Capability base, static_cast back to C
  };
  std::vector<Provided> capabilities_;
};

/// The size of each field of a state, for absolute tolerances: the fields of one measured
/// variable share the largest magnitude over the group (a position's x, y and z alike), a field
/// outside every variable has its own (a variable of derived columns counts for none), and a
/// field that is zero everywhere gets 1 (SI unit).
std::vector<double> field_scales(const Problem& problem, const State& state);

/// Checks that a state belongs to a problem (N × F), naming what differs; throws InputError.
void check_shape(const Problem& problem, const State& state, const std::string& what);

}  // namespace dlpverify
