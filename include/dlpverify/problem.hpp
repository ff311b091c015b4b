/// @file
/// A problem: a population of N independent members (particles, gas parcels, …), each carrying
/// F named fields. The harness, the integrators and the SUNDIALS adapters know a problem only
/// through this interface: fields and measured variables by name, the initial state, the
/// right-hand side over a block of members, and (where one exists) a closed form.
///
/// The state is an N × F column-major array: field f of member p at f·N + p, each field a
/// contiguous column, the whole population one buffer a SUNDIALS N_Vector wraps without copying.
/// The right-hand side takes a block of members in structure-of-arrays form (F field pointers ×
/// `count` members): one virtual call per block, never per member, and the loop over the block's
/// members is the loop a SIMD kernel vectorises.
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "dlpverify/eigen.hpp"
#include <nlohmann/json.hpp>

/// dlpverify's library: problems, integrators, convergence and work-precision studies, reports.
namespace dlpverify {

/// members × fields, column-major (Eigen's default).
using State = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic>;

/// One named field every member carries.
struct Field {
  std::string name;  ///< "x", "vx", "T", …
  std::string unit;  ///< SI: "m", "m/s", "K", …
};

/// A group of consecutive fields measured together, e.g. {"position", 0, 3, "m"}: its norm for a
/// member is the Euclidean norm over the group's fields.
struct Variable {
  std::string name;     ///< "position", "velocity", …
  int first_field = 0;  ///< index of its first field
  int fields = 1;       ///< number of consecutive fields in the group
  std::string unit;     ///< SI unit of its norm
};

/// Consecutive fields a staggered solver solves together while it holds the others frozen
/// (docs/model.md §7.3), e.g. a second-order equation's value and rate.
struct FieldBlock {
  std::string name;     ///< for messages
  int first_field = 0;  ///< index of its first field
  int fields = 1;       ///< number of consecutive fields in the block
};

/// A physical parameter, for a program outside dlpverify: its name, SI value and unit ("1" when it
/// has none).
struct Parameter {
  std::string name;    ///< as the exchange file names it
  double value = 0.0;  ///< in SI units
  std::string unit;    ///< SI, "1" when dimensionless
};

/// What a program outside dlpverify needs to set itself up for this problem (the exchange file of
/// docs/exchange.md): which problem it is, every physical parameter, and the settings that are words
/// rather than numbers — the active terms ("drag" = "constant" | "reynolds" | "off", "gravity" = "on"
/// | "off", …) and the like; and what each member carries besides its fields (a gas parcel's J_min).
struct ProblemDescription {
  std::string problem;  ///< "dlp", "gas", …
  std::vector<Parameter> parameters;                          ///< every physical parameter
  std::vector<std::pair<std::string, std::string>> settings;  ///< the settings that are words: (name, value)
  std::vector<std::pair<Field, Eigen::ArrayXd>> member_data;  ///< one value per member
};

/// A problem's own stepper for a block of members through one built-in Runge–Kutta tableau, its
/// rates inlined into the stage loops (fused_runge_kutta.hpp): `steps` steps from t0 by dt of the
/// `count` members at y[f][0 … count). Empty (run == nullptr) when the problem has none.
struct FusedSteps {
  /// Steps `count` members at y[f][0 … count) `steps` times from t0 by dt, with the constants `rates`.
  void (*run)(const void* rates, double* const* y, int count, double t0, double dt, long steps) = nullptr;
  const void* rates = nullptr;  ///< the problem's constants, for run
  explicit operator bool() const { return run != nullptr; }  ///< whether the problem has a stepper
  /// run(rates, y, count, t0, dt, steps).
  void operator()(double* const* y, int count, double t0, double dt, long steps) const { run(rates, y, count, t0, dt, steps); }
};

/// Study defaults under which a case's expected order shows.
struct StudyDefaults {
  double t_end = 0.0;  ///< duration after t0 [s]
  double dt = 0.0;     ///< coarsest step [s]
  int levels = 0;      ///< number of Δt levels
};

/// A population of N independent members with F fields each, as the harness, the integrators and
/// the SUNDIALS adapters see it (this file's description).
class Problem {
 public:
  virtual ~Problem() = default;

  /// The case this problem instance is, e.g. "drag" (for reports).
  virtual std::string name() const = 0;
  /// The F fields of every member, in column order.
  virtual std::vector<Field> fields() const = 0;
  /// What a study measures, in report order: groups of the columns of measured() (by default the
  /// fields themselves).
  virtual std::vector<Variable> variables() const = 0;
  /// The measured columns of a state at t0 + tau: the fields themselves, or also quantities derived
  /// from them (a gas parcel's pressure from its temperature and compression). Norms, orders and
  /// references compare measured states; the integrators never see them. Taken by value: a caller
  /// done with its state moves it in, and a problem that measures its fields returns it, no copy.
  virtual State measured(State state, double /*tau*/) const { return state; }

  /// Number of members N.
  virtual Eigen::Index members() const = 0;
  /// The start time t0 of every study, and the state there (N × F).
  virtual double initial_time() const = 0;
  virtual State initial_state() const = 0;  ///< N × F, at initial_time()

  /// dy/dt at time t of the members first … first + count − 1: field f of the block's member i
  /// is y[f][i] (and dydt[f][i]). Called concurrently from several threads on disjoint blocks.
  virtual void rhs(double t, Eigen::Index first, int count, const double* const* y, double* const* dydt) const = 0;

  /// The closed form, where the problem has one: the state at t0 + tau from `initial`.
  virtual bool has_closed_form() const { return false; }
  virtual State closed_form(const State& initial, double tau) const;  ///< throws when there is none
  /// Where the closed form comes from (its formula), or why there is none.
  virtual std::string reference_detail() const { return has_closed_form() ? "closed form" : "no closed form"; }

  /// Each member's time of a kink in its solution (a point where it is only once differentiable,
  /// e.g. a particle's apex under drag and gravity), or NaN when it has none. A tight reference
  /// restarts there, and an ODE-residual stencil that straddles one is skipped.
  virtual std::vector<double> kink_times(const State& initial) const;
  /// The time over which member p's state changes appreciably at `state` (its fastest rate's time
  /// scale; +∞ when nothing limits it): the ODE residual's finite-difference step follows it.
  /// tau is the time since t0 (a fallback scale where nothing else sets one).
  virtual double time_scale(const State& state, Eigen::Index p, double tau) const;

  /// The fields whose rate is zero at every state and time for this problem (e.g. a particle's
  /// temperature when heat transfer is off): an integrator may carry them unchanged, as exact
  /// arithmetic would (y + h·0 = y). By default none.
  virtual std::vector<bool> inert_fields() const { return std::vector<bool>(static_cast<std::size_t>(field_count()), false); }

  /// A stepper with the rates inlined for the tableau at `tableau` (&tableau::midpoint, …:
  /// runge_kutta.hpp) and blocks of `block` members, giving the bits that stepping through rhs
  /// gives; or an empty one (the default), and the integrator calls rhs once per block and stage.
  virtual FusedSteps fused_steps(const void* /*tableau*/, int /*block*/) const { return {}; }

  /// The blocks a staggered solver iterates over, in its order (Gauss–Seidel uses each block's new
  /// values in the next). By default each field is a block of its own.
  virtual std::vector<FieldBlock> staggered_blocks() const;
  /// A linear decay an implicit fixed-point iteration treats exactly, as the seed's implicit
  /// cooling update keeps convection in its denominator: f(y) = −λ∘y + g(y), with λ ≥ 0 constant
  /// per member and field. Writes λ of the members first … first + count − 1 (lambda[f][i]) and
  /// returns true, or returns false (the default) when the problem separates none.
  virtual bool linear_decay(Eigen::Index /*first*/, int /*count*/, double* const* /*lambda*/) const { return false; }

  /// Physical parameters for provenance, and what the case reports besides errors (branch counts,
  /// invariants) from the initial state and the finest level's state at t0 + t_end.
  virtual nlohmann::json parameters() const { return nlohmann::json::object(); }
  /// The problem for a program outside dlpverify (docs/exchange.md). By default: "problem", the
  /// numbers of parameters() without units, and its strings as settings.
  virtual ProblemDescription description() const;
  /// What the case reports besides errors (branch counts, invariants), from the initial state and
  /// the finest level's state at t0 + t_end; by default an empty object.
  virtual nlohmann::json diagnostics(const State& /*initial*/, const State& /*finest*/, double /*t_end*/) const {
    return nlohmann::json::object();
  }

  /// Number of fields F (fields().size()).
  int field_count() const { return static_cast<int>(fields().size()); }
};

/// The size of each field of a state, for absolute tolerances: the fields of one measured
/// variable share the largest magnitude over the group (a position's x, y and z alike), a field
/// outside every variable has its own (a variable of derived columns counts for none), and a
/// field that is zero everywhere gets 1 (SI unit).
std::vector<double> field_scales(const Problem& problem, const State& state);

/// Checks that a state belongs to a problem (N × F), naming what differs; throws InputError.
void check_shape(const Problem& problem, const State& state, const std::string& what);

}  // namespace dlpverify
