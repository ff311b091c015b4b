// Every wrapper of a problem passes every capability through (dlpverify/problem.hpp): a wrapper
// that forgets one, or forgets to shift one to its own members, fails here.
//
// - Completeness: the capability interfaces declared in the sources (every `class X : public
//   Capability` under include/dlpverify/ and src/) are exactly kCapabilities below, so a new
//   capability is a failure until it is listed and checked here.
// - For every wrapper (one line each in wrappers()), every capability C and every problem
//   providing C: the wrapper provides C unless it declares C declined (with its reason), and then
//   it does not; a passed-through C gives the whole problem's values on the same members (the
//   wrapper's member k being the whole's member first + k), computed on the whole problem, not
//   through the wrapper. A C the wrapper declares its own need only be there. measured() and the
//   initial state are held to the same (the gas problem's pressure depends on the member).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <typeindex>
#include <vector>

#include "dlp_support.hpp"
#include "dlpverify/case_report.hpp"
#include "dlpverify/closed_form.hpp"
#include "dlpverify/extended.hpp"
#include "dlpverify/manufactured.hpp"
#include "dlpverify/member_coordinate.hpp"
#include "harness/case_diagnostics.hpp"
#include "harness/compensated_sum.hpp"
#include "harness/distribution.hpp"
#include "dlpverify/initial_members.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "dlpverify/solution_features.hpp"
#include "dlpverify/splitting.hpp"
#include "dlpverify/exchange_description.hpp"
#include "harness/sub_population.hpp"
#include "problems/dlp/diagnostics.hpp"
#include "problems/gas/problem.hpp"
#include "problems/thermal/cooling.hpp"
#include "problems/thermal/coupled.hpp"

namespace unit_capabilities {

using namespace dlpverify;
using namespace dlpverify::dlp;

namespace {

// ---- the capabilities --------------------------------------------------------------------------

using Capabilities = std::tuple<ClosedForm, SolutionKinks, TimeScale, InertFields, FusedStepper, StaggeredBlocks,
                                LinearDecay, CaseReport, TimeUnit, MemberNoun, ExchangeDescription, InitialMembers,
                                MemberCoordinate, SweepContraction, ExtendedRhs>;

template <class C>
constexpr const char* kName = nullptr;
template <> constexpr const char* kName<ClosedForm> = "ClosedForm";
template <> constexpr const char* kName<SolutionKinks> = "SolutionKinks";
template <> constexpr const char* kName<TimeScale> = "TimeScale";
template <> constexpr const char* kName<InertFields> = "InertFields";
template <> constexpr const char* kName<FusedStepper> = "FusedStepper";
template <> constexpr const char* kName<StaggeredBlocks> = "StaggeredBlocks";
template <> constexpr const char* kName<LinearDecay> = "LinearDecay";
template <> constexpr const char* kName<CaseReport> = "CaseReport";
template <> constexpr const char* kName<TimeUnit> = "TimeUnit";
template <> constexpr const char* kName<MemberNoun> = "MemberNoun";
template <> constexpr const char* kName<ExchangeDescription> = "ExchangeDescription";
template <> constexpr const char* kName<InitialMembers> = "InitialMembers";
template <> constexpr const char* kName<MemberCoordinate> = "MemberCoordinate";
template <> constexpr const char* kName<SweepContraction> = "SweepContraction";
template <> constexpr const char* kName<ExtendedRhs> = "ExtendedRhs";

// Calls visit.template operator()<C>() for every C of Capabilities.
template <class Visit>
void for_each_capability(Visit&& visit) {
  [&]<class... C>(std::tuple<C...>*) { (visit.template operator()<C>(), ...); }(static_cast<Capabilities*>(nullptr));
}

std::set<std::string> listed_names() {
  std::set<std::string> names;
  for_each_capability([&]<class C>() { names.insert(kName<C>); });
  return names;
}

// ---- the problems they come from ---------------------------------------------------------------

// Particles on the z axis, half rising and half falling, with spread speeds, temperatures and
// masses: the vertical drag-and-gravity case has an apex (a kink) for the rising ones.
Cloud vertical_cloud(int n) {
  const double m0 = Parameters{}.mass0();
  Cloud cloud(n);
  for (int p = 0; p < n; ++p) {
    const double s = static_cast<double>(p) / n;
    const double vz = (p % 2 == 0 ? 1.0 : -1.0) * (0.5 + 20.0 * s);
    cloud.set_particle(p, {0.0, 0.0, 0.1 * p, 0.0, 0.0, vz, 900.0 + 500.0 * s, m0 * (0.6 + 0.4 * s)});
  }
  return cloud;
}

gas::Material air() {
  return gas::Material::from_molar({.P0 = 101325.0, .T0 = 300.0, .molar_mass = 0.02897, .gamma = 1.4});
}

// Of the test's own: the capabilities whose every built-in provider ignores the member index
// (no built-in time scale or kink time differs by member alone), made to differ per member, so
// that a wrapper that forgets to shift them fails. Member p of N decays at λ_p = 1 + p,
// y′ = −λ_p y, with time scale 1/λ_p and a kink at τ = 1/λ_p.
class PerMember final : public Problem, public TimeScale, public SolutionKinks {
 public:
  PerMember() {
    provide<TimeScale>(*this);
    provide<SolutionKinks>(*this);
  }
  std::string name() const override { return "per-member"; }
  std::vector<Field> fields() const override { return {{"y", "1"}}; }
  Eigen::Index members() const override { return 12; }
  State initial_state() const override { return State::Constant(12, 1, 1.0); }
  void rhs(double, Eigen::Index first, int count, const double* const* y, double* const* dydt) const override {
    for (int i = 0; i < count; ++i) dydt[0][i] = -lambda(first + i) * y[0][i];
  }
  double time_scale(Eigen::Index member, const double*, double) const override { return 1.0 / lambda(member); }
  std::vector<double> kink_times(Eigen::Index first, const State& initial) const override {
    std::vector<double> kinks;
    for (Eigen::Index k = 0; k < initial.rows(); ++k) kinks.push_back(1.0 / lambda(first + k));
    return kinks;
  }

 private:
  static double lambda(Eigen::Index p) { return 1.0 + static_cast<double>(p); }
};

// A problem and a time τ after its t0 at which to compare states.
struct Source {
  std::string name;
  const Problem* problem;
  double tau;
};

// Problems of 12 members that differ member by member; the built-in ones together provide every
// capability (the test case every_capability_has_a_source checks).
struct Sources {
  test::PhysicsProblem drag{{Parameters{}, find_case("drag").terms}, test::varied_cloud(12, 3), 0.0,
                            find_case("drag").solution};
  test::PhysicsProblem vertical{{Parameters{}, find_case("drag-gravity-vertical").terms}, vertical_cloud(12), 0.0,
                                find_case("drag-gravity-vertical").solution};
  gas::GasProblem adiabat{"adiabat", air(), {.parcels = 12, .j_min_low = 0.3, .j_min_high = 0.9, .period = 1e-3,
                                          .temperature_spread = 0.2}};
  thermal::CoolingProblem cooling{"cooling", thermal::CoolingPhysics{},
                                  thermal::CoolingPopulation{12, 50e-6, 200e-6, 0.3, 0.9, 800.0, 1500.0}};
  thermal::CoupledSystem coupled{"stagger-3x3", 3, {2.0, 0.5, 1.0}, 12};
  PerMember per_member;

  std::vector<Source> all() const {
    return {{"drag", drag.problem.get(), 0.05},
            {"drag-gravity-vertical", vertical.problem.get(), 0.05},
            {"gas adiabat", &adiabat, 2e-4},
            {"cooling", &cooling, 0.05},
            {"stagger-3x3", &coupled, 0.3},
            {"per-member", &per_member, 0.1}};
  }
};

// ---- the wrappers ------------------------------------------------------------------------------

// A wrapper of a problem: how to make it, which of the whole's members its member 0 is, the
// capabilities it declines (with the reason), those it provides of its own (not the whole's),
// and those it provides always: the whole's passed through, or a default where the whole has none.
struct Wrapper {
  std::string name;
  std::function<std::unique_ptr<Problem>(const Problem&)> wrap;
  Eigen::Index first = 0;
  std::map<std::type_index, std::string> declined;
  std::set<std::type_index> own;
  std::set<std::type_index> always;
};

// Members 5 … 5 + 6 of the 12: a block that starts elsewhere than 0, so an adapter that forgets
// to shift by its first member gives another member's values.
constexpr Eigen::Index kFirst = 5, kCount = 6;

// Every wrapper of a Problem in the library, one line each.
std::vector<Wrapper> wrappers() {
  return {
      {"SubPopulation", [](const Problem& p) { return std::make_unique<SubPopulation>(p, kFirst, kCount); }, kFirst, {}, {}, {}},
      // A rank's slab under mpirun (study/journal.hpp shares its progress): rank 1 of 2, which holds the one
      // norm block of these 12 members, from member 0 (harness/distribution.hpp).
      {"rank slab",
       [](const Problem& p) {
         const MemberRange own = own_members(p.members(), 1, 2);
         return std::make_unique<SubPopulation>(p, own.first, own.count);
       },
       0, {}, {}, {}},
      {"ManufacturedProblem", [](const Problem& p) { return std::make_unique<ManufacturedProblem>(p, 1.0); }, 0,
       {{typeid(FusedStepper), "a fused stepper bypasses rhs, and so the source"},
        {typeid(SolutionKinks), "the manufactured solution is smooth"},
        {typeid(ExchangeDescription), "a program outside dlpverify evaluates its right-hand side without the source"},
        {typeid(InitialMembers), "ŷ is built from the whole population it is given (refused under mpirun)"},
        {typeid(ExtendedRhs), "the manufactured source is evaluated in double"}},
       {typeid(ClosedForm), typeid(CaseReport), typeid(TimeScale)},  // ŷ; its parameters; min(the problem's, 1/ω_p)
       {typeid(InertFields), typeid(StaggeredBlocks), typeid(TimeUnit), typeid(MemberNoun)}},
  };
}

// ---- what "the same values" means for each capability ------------------------------------------

// a == b, NaN equal to NaN (a member without a kink).
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// Rows [first, first + count) of `whole` equal `part`, bit for bit; names the first difference.
void check_rows(const State& part, const State& whole, Eigen::Index first, const std::string& what) {
  BOOST_TEST_REQUIRE(part.cols() == whole.cols(), what << ": columns");
  BOOST_TEST_REQUIRE(first + part.rows() <= whole.rows(), what << ": rows");
  for (Eigen::Index c = 0; c < part.cols(); ++c)
    for (Eigen::Index k = 0; k < part.rows(); ++k)
      if (!same(part(k, c), whole(first + k, c))) {
        BOOST_ERROR(what << ": member " << k << " (the whole's " << first + k << ") column " << c << ": "
                         << part(k, c) << " != " << whole(first + k, c));
        return;
      }
}

template <class C>
void check_same(const Problem& whole, const Problem& wrapped, Eigen::Index first, double tau, const std::string& what);

// The closed form of the wrapper's members k … equals the whole's of members first + k … from the
// same states (bit for bit), and the whole's closed form of the whole population, rows first …,
// to round-off: a closed form through a matrix product (the 3 × 3 coupled system's exp(A t))
// may round a member differently when asked for a different number of members.
template <>
void check_same<ClosedForm>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double tau,
                            const std::string& what) {
  const ClosedForm& mine = *wrapped.capability<ClosedForm>();
  const ClosedForm& theirs = *whole.capability<ClosedForm>();
  const Eigen::Index n = wrapped.members();
  const State block = whole.initial_state().middleRows(first, n);
  for (Eigen::Index k : {Eigen::Index{0}, Eigen::Index{1}}) {
    const State part = block.bottomRows(n - k);
    check_rows(mine.solution(k, part, tau), theirs.solution(first + k, part, tau), 0,
               what + " solution from member " + std::to_string(k));
  }
  const State all = theirs.solution(0, whole.initial_state(), tau);
  const State own = mine.solution(0, wrapped.initial_state(), tau);
  BOOST_TEST_REQUIRE(own.cols() == all.cols(), what);
  for (Eigen::Index c = 0; c < own.cols(); ++c)
    for (Eigen::Index k = 0; k < n; ++k)
      BOOST_TEST(std::abs(own(k, c) - all(first + k, c)) <= 1e-14 * std::abs(all(first + k, c)),
                 what << " member " << k << " column " << c << ": " << own(k, c) << " != " << all(first + k, c));
  BOOST_TEST(mine.formula() == theirs.formula(), what);
  BOOST_TEST(mine.manufactured() == theirs.manufactured(), what);
}

template <>
void check_same<SolutionKinks>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double,
                               const std::string& what) {
  const std::vector<double> mine = wrapped.capability<SolutionKinks>()->kink_times(0, wrapped.initial_state());
  const std::vector<double> theirs = whole.capability<SolutionKinks>()->kink_times(0, whole.initial_state());
  BOOST_TEST_REQUIRE(mine.size() == static_cast<std::size_t>(wrapped.members()), what);
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const double whole_k = theirs.at(static_cast<std::size_t>(first) + k);
    BOOST_TEST(same(mine[k], whole_k), what << " member " << k << ": " << mine[k] << " != " << whole_k);
  }
}

// Member k's time scale at its own initial state.
template <>
void check_same<TimeScale>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double tau,
                           const std::string& what) {
  const State y = wrapped.initial_state();
  for (Eigen::Index k = 0; k < wrapped.members(); ++k) {
    const Eigen::VectorXd row = y.row(k).transpose();
    const double mine = wrapped.capability<TimeScale>()->time_scale(k, row.data(), tau);
    const double theirs = whole.capability<TimeScale>()->time_scale(first + k, row.data(), tau);
    BOOST_TEST(same(mine, theirs), what << " member " << k << ": " << mine << " != " << theirs);
  }
}

template <>
void check_same<InertFields>(const Problem& whole, const Problem& wrapped, Eigen::Index, double, const std::string& what) {
  BOOST_TEST(wrapped.capability<InertFields>()->inert_fields() == whole.capability<InertFields>()->inert_fields(), what);
}

// The same stepper for every built-in tableau it may be asked for.
template <>
void check_same<FusedStepper>(const Problem& whole, const Problem& wrapped, Eigen::Index, double, const std::string& what) {
  for (const void* t : {static_cast<const void*>(&tableau::midpoint), static_cast<const void*>(&tableau::rk4)})
    for (int block : {1, 64}) {
      const FusedSteps mine = wrapped.capability<FusedStepper>()->fused_steps(t, block);
      const FusedSteps theirs = whole.capability<FusedStepper>()->fused_steps(t, block);
      BOOST_TEST((mine.run == theirs.run && mine.rates == theirs.rates), what << " block " << block);
    }
}

template <>
void check_same<StaggeredBlocks>(const Problem& whole, const Problem& wrapped, Eigen::Index, double,
                                 const std::string& what) {
  const std::vector<FieldBlock> mine = wrapped.capability<StaggeredBlocks>()->staggered_blocks();
  const std::vector<FieldBlock> theirs = whole.capability<StaggeredBlocks>()->staggered_blocks();
  BOOST_TEST_REQUIRE(mine.size() == theirs.size(), what);
  for (std::size_t b = 0; b < mine.size(); ++b)
    BOOST_TEST((mine[b].name == theirs[b].name && mine[b].first_field == theirs[b].first_field &&
                mine[b].fields == theirs[b].fields),
               what << " block " << b);
}

// λ of the wrapper's members (one block from its member 0) equals the whole's λ (one block of
// the whole population), rows first ….
template <>
void check_same<LinearDecay>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double,
                             const std::string& what) {
  const auto lambda = [](const Problem& p) {
    State l = State::Zero(p.members(), p.field_count());
    std::vector<double*> columns;
    for (Eigen::Index f = 0; f < l.cols(); ++f) columns.push_back(l.col(f).data());
    p.capability<LinearDecay>()->linear_decay(0, static_cast<int>(p.members()), columns.data());
    return l;
  };
  check_rows(lambda(wrapped), lambda(whole), first, what + " lambda");
}

// The same parameters and reductions, the whole's member terms of the same members (rows
// first …), bit for bit, and the same diagnostics of the same reduced quantities.
template <>
void check_same<CaseReport>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double tau,
                            const std::string& what) {
  const CaseReport& mine = *wrapped.capability<CaseReport>();
  const CaseReport& theirs = *whole.capability<CaseReport>();
  BOOST_TEST(mine.parameters() == theirs.parameters(), what);
  BOOST_TEST((mine.diagnostic_reductions() == theirs.diagnostic_reductions()), what);
  const State initial = wrapped.initial_state();
  const Eigen::ArrayXXd terms = mine.member_terms(0, initial, initial, tau);
  check_rows(terms, theirs.member_terms(first, initial, initial, tau), 0, what + " member terms");
  const std::vector<double> reduced(mine.diagnostic_reductions().size(), 1.0);
  BOOST_TEST(mine.diagnostics(reduced, tau) == theirs.diagnostics(reduced, tau), what);
}

template <>
void check_same<TimeUnit>(const Problem& whole, const Problem& wrapped, Eigen::Index, double, const std::string& what) {
  BOOST_TEST(wrapped.capability<TimeUnit>()->time_unit() == whole.capability<TimeUnit>()->time_unit(), what);
}

template <>
void check_same<MemberNoun>(const Problem& whole, const Problem& wrapped, Eigen::Index, double, const std::string& what) {
  const MemberNouns mine = wrapped.capability<MemberNoun>()->member_nouns();
  const MemberNouns theirs = whole.capability<MemberNoun>()->member_nouns();
  BOOST_TEST((mine.one == theirs.one && mine.many == theirs.many), what);
}

// The wrapper's members built alone are the whole's initial state, rows first …, bit for bit, and
// so are the whole's own from a member other than 0.
template <>
void check_same<InitialMembers>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double,
                                const std::string& what) {
  const Eigen::Index n = wrapped.members();
  const State all = whole.initial_state();
  check_rows(wrapped.capability<InitialMembers>()->initial_members(0, n), all, first, what + " members alone");
  check_rows(whole.capability<InitialMembers>()->initial_members(first + 1, n - 1), all, first + 1,
             what + " the whole's members alone");
}

// The whole's extended rates of the same members from the same states, bit for bit.
template <>
void check_same<ExtendedRhs>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double tau,
                             const std::string& what) {
  const Eigen::Index n = wrapped.members();
  const int fields = whole.field_count();
  const ExtendedState y(whole.initial_state().middleRows(first, n));
  ExtendedState mine(n, fields), theirs(n, fields);
  std::vector<const Extended*> in;
  std::vector<Extended*> out_mine, out_theirs;
  for (int f = 0; f < fields; ++f) in.push_back(y.col(f)), out_mine.push_back(mine.col(f)), out_theirs.push_back(theirs.col(f));
  wrapped.capability<ExtendedRhs>()->extended_rhs(Extended(tau), 0, static_cast<int>(n), in.data(), out_mine.data());
  whole.capability<ExtendedRhs>()->extended_rhs(Extended(tau), first, static_cast<int>(n), in.data(), out_theirs.data());
  check_rows(mine.high(), theirs.high(), 0, what + " extended rates, leading part");
  check_rows(mine.low(), theirs.low(), 0, what + " extended rates, trailing part");
}

// The whole's coordinates of the same members, bit for bit, asked from member 0 and from member 1.
template <>
void check_same<MemberCoordinate>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double,
                                  const std::string& what) {
  const Eigen::Index n = wrapped.members();
  const Eigen::ArrayXd all = whole.capability<MemberCoordinate>()->member_coordinate(0, whole.members());
  check_rows(State(wrapped.capability<MemberCoordinate>()->member_coordinate(0, n)), State(all), first, what + " coordinates");
  check_rows(State(wrapped.capability<MemberCoordinate>()->member_coordinate(1, n - 1)), State(all), first + 1,
             what + " coordinates from member 1");
}

// The same radii at steps below, at and above the limit, and the same formulas.
template <>
void check_same<SweepContraction>(const Problem& whole, const Problem& wrapped, Eigen::Index, double,
                                  const std::string& what) {
  const SweepContraction& mine = *wrapped.capability<SweepContraction>();
  const SweepContraction& theirs = *whole.capability<SweepContraction>();
  for (const double dt : {0.1, theirs.step_limit(), 3.0}) {
    BOOST_TEST(mine.jacobi_radius(dt) == theirs.jacobi_radius(dt), what << " at dt " << dt);
    BOOST_TEST(mine.gauss_seidel_radius(dt) == theirs.gauss_seidel_radius(dt), what << " at dt " << dt);
  }
  BOOST_TEST(mine.step_limit() == theirs.step_limit(), what);
  BOOST_TEST(mine.radius_exponent() == theirs.radius_exponent(), what);
  BOOST_TEST(mine.jacobi_radius_formula() == theirs.jacobi_radius_formula(), what);
  BOOST_TEST(mine.gauss_seidel_radius_formula() == theirs.gauss_seidel_radius_formula(), what);
  BOOST_TEST(mine.step_limit_formula() == theirs.step_limit_formula(), what);
}

// The whole's description with each member's data cut to the wrapper's members.
template <>
void check_same<ExchangeDescription>(const Problem& whole, const Problem& wrapped, Eigen::Index first, double,
                                     const std::string& what) {
  const ProblemDescription mine = wrapped.capability<ExchangeDescription>()->description();
  const ProblemDescription theirs = whole.capability<ExchangeDescription>()->description();
  BOOST_TEST(mine.problem == theirs.problem, what);
  BOOST_TEST_REQUIRE(mine.parameters.size() == theirs.parameters.size(), what);
  for (std::size_t i = 0; i < mine.parameters.size(); ++i)
    BOOST_TEST((mine.parameters[i].name == theirs.parameters[i].name && mine.parameters[i].value == theirs.parameters[i].value &&
                mine.parameters[i].unit == theirs.parameters[i].unit),
               what << " parameter " << theirs.parameters[i].name);
  BOOST_TEST((mine.settings == theirs.settings), what);
  BOOST_TEST_REQUIRE(mine.member_data.size() == theirs.member_data.size(), what);
  for (std::size_t i = 0; i < mine.member_data.size(); ++i) {
    BOOST_TEST(mine.member_data[i].first.name == theirs.member_data[i].first.name, what);
    BOOST_TEST_REQUIRE(mine.member_data[i].second.size() == wrapped.members(), what);
    check_rows(State(mine.member_data[i].second), State(theirs.member_data[i].second), first,
               what + " member data " + theirs.member_data[i].first.name);
  }
}

// ---- the sources a capability is declared in ---------------------------------------------------

// Names X of every `class X [final] : public Capability` in include/dlpverify/*.hpp and src/**/*.hpp.
std::set<std::string> declared_names() {
  namespace fs = std::filesystem;
  const fs::path root(DLPVERIFY_SOURCE_DIR);
  std::vector<fs::path> headers;
  for (const fs::directory_entry& e : fs::directory_iterator(root / "include" / "dlpverify"))
    if (e.path().extension() == ".hpp") headers.push_back(e.path());
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(root / "src"))
    if (e.is_regular_file() && e.path().extension() == ".hpp") headers.push_back(e.path());
  const std::regex declaration(R"(class\s+(\w+)\s*(final\s*)?:\s*public\s+Capability\b)");
  std::set<std::string> names;
  for (const fs::path& h : headers) {
    std::ifstream in(h);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (std::sregex_iterator m(s.begin(), s.end(), declaration), end; m != end; ++m) names.insert((*m)[1].str());
  }
  return names;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(capabilities)

BOOST_AUTO_TEST_CASE(the_list_is_every_capability_declared) {
  const std::set<std::string> declared = declared_names();
  BOOST_TEST(declared.size() >= 10u);  // the scan found the headers
  for (const std::string& name : declared)
    BOOST_TEST(listed_names().count(name) == 1u, name << " is a capability this test does not check: add it");
  for (const std::string& name : listed_names())
    BOOST_TEST(declared.count(name) == 1u, name << " is listed here but no longer declared");
}

BOOST_AUTO_TEST_CASE(every_capability_has_a_source) {
  const Sources sources;
  for_each_capability([&]<class C>() {
    int providers = 0;
    for (const Source& s : sources.all())
      providers += s.problem != &sources.per_member && s.problem->capability<C>() != nullptr;
    BOOST_TEST(providers > 0, "no built-in problem here provides " << kName<C>);
  });
  // The sources' members differ where a shift matters: a kink, a per-member rate.
  const std::vector<double> kinks = kink_times(*sources.vertical.problem, sources.vertical.problem->initial_state());
  int kinked = 0;
  for (Eigen::Index k = kFirst; k < kFirst + kCount; ++k) kinked += std::isfinite(kinks[static_cast<std::size_t>(k)]);
  BOOST_TEST(kinked > 0, "no member of the block has a kink");
}

BOOST_AUTO_TEST_CASE(every_wrapper_passes_every_capability_through) {
  const Sources sources;
  for (const Wrapper& w : wrappers())
    for (const Source& s : sources.all()) {
      const std::unique_ptr<Problem> wrapped = w.wrap(*s.problem);
      for_each_capability([&]<class C>() {
        const std::string what = w.name + " of " + s.name + ", " + kName<C>;
        const C* mine = wrapped->capability<C>();
        if (w.declined.count(typeid(C))) {
          BOOST_TEST(mine == nullptr, what << " is declined (" << w.declined.at(typeid(C)) << ") but provided");
        } else if (w.own.count(typeid(C)) || (w.always.count(typeid(C)) && !s.problem->capability<C>())) {
          BOOST_TEST(mine != nullptr, what << ": its own is missing");
        } else if (!s.problem->capability<C>()) {
          BOOST_TEST(mine == nullptr, what << " is provided though the whole problem has none");
        } else {
          BOOST_TEST(mine != nullptr, what << " is dropped");
          if (mine) check_same<C>(*s.problem, *wrapped, w.first, s.tau, what);
        }
      });
    }
}

// The initial state and the measured columns of the wrapper's members equal the whole's, rows
// first … (the gas problem's pressure depends on each parcel's path).
BOOST_AUTO_TEST_CASE(every_wrapper_measures_its_members_as_the_whole) {
  const Sources sources;
  for (const Wrapper& w : wrappers())
    for (const Source& s : sources.all()) {
      const std::unique_ptr<Problem> wrapped = w.wrap(*s.problem);
      check_rows(wrapped->initial_state(), s.problem->initial_state(), w.first, w.name + " of " + s.name + " initial state");
      const State whole = s.problem->measured(s.problem->initial_state(), s.tau, 0);
      check_rows(wrapped->measured(wrapped->initial_state(), s.tau, 0), whole, w.first, w.name + " of " + s.name + " measured");
      // and from a member inside the block, as a solver working on a part of the wrapper asks
      const State part = wrapped->initial_state().bottomRows(wrapped->members() - 1);
      check_rows(wrapped->measured(part, s.tau, 1), whole, w.first + 1, w.name + " of " + s.name + " measured from 1");
    }
}

// Under mpirun each rank reduces the diagnostics of its own slab of whole norm blocks and the
// partials are combined in block order (harness/case_diagnostics.hpp): the partials of two
// SubPopulations split at a block boundary, concatenated, reduce to the whole's bit for bit, and
// the sums agree with a long-double sum of the same terms to a few ulps (Neumaier's bound).
BOOST_AUTO_TEST_CASE(diagnostics_of_a_split_population_are_the_whole_s) {
  constexpr Eigen::Index n = 2 * kSumBlock + 100;
  test::PhysicsProblem cloud{{Parameters{}, find_case("similarity").terms}, test::varied_cloud(static_cast<int>(n), 7)};
  cloud.test_case.diagnostics = &dlp::diagnostics::similarity_energy;
  const gas::GasProblem adiabat{"adiabat", air(), {.parcels = n, .j_min_low = 0.3, .j_min_high = 0.9, .period = 1e-3,
                                                   .temperature_spread = 0.2}};
  const thermal::CoolingProblem cooling{"cooling", thermal::CoolingPhysics{},
                                        thermal::CoolingPopulation{n, 50e-6, 200e-6, 0.3, 0.9, 800.0, 1500.0}};
  const double tau = 2e-4;
  for (const auto& [name, problem] : std::vector<std::pair<std::string, const Problem*>>{
           {"similarity", cloud.problem.get()}, {"gas adiabat", &adiabat}, {"cooling", &cooling}}) {
    BOOST_TEST_CONTEXT(name) {
      const CaseReport& report = *problem->capability<CaseReport>();
      const std::vector<MemberReduction> reductions = report.diagnostic_reductions();
      const State initial = problem->initial_state();
      const State finest = initial * 0.999;  // a state that differs from the initial one in every member
      const std::vector<double> whole = reduced_diagnostics(reductions, diagnostic_partials(report, 0, initial, finest, tau));

      const SubPopulation first(*problem, 0, kSumBlock), second(*problem, kSumBlock, n - kSumBlock);
      std::vector<double> partials = diagnostic_partials(*first.capability<CaseReport>(), 0, initial.topRows(kSumBlock),
                                                         finest.topRows(kSumBlock), tau);
      const std::vector<double> more = diagnostic_partials(*second.capability<CaseReport>(), 0, initial.bottomRows(n - kSumBlock),
                                                           finest.bottomRows(n - kSumBlock), tau);
      partials.insert(partials.end(), more.begin(), more.end());
      const std::vector<double> split = reduced_diagnostics(reductions, partials);

      BOOST_TEST_REQUIRE(split.size() == reductions.size());
      const Eigen::ArrayXXd terms = report.member_terms(0, initial, finest, tau);
      for (std::size_t q = 0; q < reductions.size(); ++q) {
        BOOST_TEST(std::memcmp(&split[q], &whole[q], sizeof(double)) == 0, "quantity " << q << ": " << split[q] << " != " << whole[q]);
        if (reductions[q] != MemberReduction::sum) continue;
        long double exact = 0.0L;
        for (Eigen::Index p = 0; p < n; ++p) exact += terms(p, static_cast<Eigen::Index>(q));
        BOOST_TEST(split[q] == static_cast<double>(exact), boost::test_tools::tolerance(1e-15));
      }
      BOOST_TEST(case_diagnostics(*problem, initial, finest, tau) == report.diagnostics(split, tau));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_capabilities
