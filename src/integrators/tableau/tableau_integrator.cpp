#include "integrators/tableau/tableau_integrator.hpp"

#include <algorithm>
#include <mutex>
#include <set>
#include <vector>

#include "dlpverify/errors.hpp"
#include "dlpverify/first_failure.hpp"
#include "dlpverify/level_stop.hpp"
#include "dlpverify/runge_kutta.hpp"
#include "harness/distribution.hpp"
#include "integrators/sundials/arkode_dirk_integrator.hpp"
#include "integrators/tableau/order_conditions.hpp"
#include "io/format.hpp"
#include "io/printable.hpp"

namespace dlpverify {

namespace {

// The block buffers of one thread: y, the stage argument and the s stage rates, F fields × kBlock
// members each, with the field pointers the right-hand side takes.
class Block {
 public:
  Block(int stages, int fields, int block) : storage_(static_cast<std::size_t>((stages + 2) * fields * block)) {
    pointers_.resize(static_cast<std::size_t>(stages + 2));
    for (int buffer = 0; buffer < stages + 2; ++buffer)
      for (int f = 0; f < fields; ++f)
        pointers_[static_cast<std::size_t>(buffer)].push_back(storage_.data() + (buffer * fields + f) * block);
  }
  double* const* y() { return pointers_[0].data(); }
  double* const* stage() { return pointers_[1].data(); }
  double* const* k(int i) { return pointers_[static_cast<std::size_t>(2 + i)].data(); }

 private:
  std::vector<double> storage_;
  std::vector<std::vector<double*>> pointers_;
};

// One step of the tableau for the block's `count` members: runge_kutta_step's stages and update
// (runge_kutta.hpp), with the coefficients read at run time; every field is active.
void step(const RuntimeTableau& tableau, const Problem& problem, Eigen::Index first, int count,
          const std::vector<int>& fields, double t, double dt, Block& block) {
  const int stages = tableau.stages();
  const auto k = [&block](int j) { return block.k(j); };
  for (int i = 0; i < stages; ++i) {
    double* const* stage = i == 0 ? block.y() : block.stage();  // the first stage is y itself
    if (i > 0) runge_kutta_stage(tableau.a[static_cast<std::size_t>(i)], i, dt, fields, count, block.y(), stage, k);
    problem.rhs(t + tableau.c[static_cast<std::size_t>(i)] * dt, first, count, stage, block.k(i));
  }
  runge_kutta_update(tableau.b, stages, dt, fields, count, block.y(), k);
}

// A tableau's integrator that names the conditions its file misses on `warnings`, at its first
// advance() and once per file and process: a study makes its integrator more than once and may
// stop at bad input before stepping, whose one line then stays the only one.
class WarnedTableau final : public Integrator, public ButcherMethod {
 public:
  WarnedTableau(std::unique_ptr<Integrator> integrator, std::string file, std::string warning, std::ostream& warnings)
      : integrator_(std::move(integrator)), file_(std::move(file)), warning_(std::move(warning)), warnings_(warnings) {}
  std::string name() const override { return integrator_->name(); }
  int order() const override { return integrator_->order(); }
  void advance(const Problem& problem, State& state, double t0, double dt, long steps) override {
    warn();
    integrator_->advance(problem, state, t0, dt, steps);
  }
  SolverStatistics statistics() const override { return integrator_->statistics(); }
  // A study in extended precision steps the explicit file's coefficients itself: it warns too.
  ButcherCoefficients butcher() const override {
    const auto* method = dynamic_cast<const ButcherMethod*>(integrator_.get());
    if (method == nullptr) refuse_double_only(name());
    warn();
    return method->butcher();
  }
  bool has_explicit_tableau() const override { return dynamic_cast<const ButcherMethod*>(integrator_.get()) != nullptr; }

 private:
  void warn() const {
    static std::mutex mutex;
    static std::set<std::string> warned;  // the files this process has warned about
    const std::lock_guard<std::mutex> lock(mutex);
    if (warned.insert(file_).second) warnings_ << "dlpverify: warning: " << printable(warning_, 400) << std::endl;
  }

  std::unique_ptr<Integrator> integrator_;
  std::string file_, warning_;
  std::ostream& warnings_;
};

}  // namespace

TableauIntegrator::TableauIntegrator(RuntimeTableau tableau) : tableau_(std::move(tableau)) {
  for (std::size_t i = 0; i < tableau_.a.size(); ++i)
    if (tableau_.a[i][i] != 0.0)
      throw InputError("tableau " + tableau_.source + ": A[" + std::to_string(i + 1) + "][" + std::to_string(i + 1) + "]",
                       printf_string("%.17g", tableau_.a[i][i]),
                       "a diagonally implicit method: make_tableau_integrator steps it through ARKStep");
}

void TableauIntegrator::advance(const Problem& problem, State& state, double t0, double dt, long steps) {
  check_step(dt, steps);
  const Eigen::Index members = state.rows();
  const int fields = static_cast<int>(state.cols());
  const Eigen::Index blocks = (members + kBlock - 1) / kBlock;
  std::vector<int> every_field(static_cast<std::size_t>(fields));
  for (int f = 0; f < fields; ++f) every_field[static_cast<std::size_t>(f)] = f;
  FirstFailure failure;  // a problem's rhs may throw; it must not leave the parallel region
#pragma omp parallel
  {
    Block block(tableau_.stages(), fields, kBlock);
#pragma omp for schedule(static)
    for (Eigen::Index b = 0; b < blocks; ++b) {
      const Eigen::Index first = b * kBlock;
      const int count = static_cast<int>(std::min<Eigen::Index>(kBlock, members - first));
      for (int f = 0; f < fields; ++f) std::copy_n(state.col(f).data() + first, count, block.y()[f]);
      try {
        for (long n = 0; n < steps; ++n) {
          abandon_level_if_stop_requested();
          step(tableau_, problem, first, count, every_field, t0 + static_cast<double>(n) * dt, dt, block);
        }
      } catch (...) {
        failure.capture();
      }
      for (int f = 0; f < fields; ++f) std::copy_n(block.y()[f], count, state.col(f).data() + first);
    }
  }
  failure.rethrow();
  statistics_ = SolverStatistics{};
  statistics_.steps = steps;
  statistics_.rhs_evals = steps * static_cast<long>(tableau_.stages());
}

std::string tableau_warning(const RuntimeTableau& tableau) {
  const TableauCheck check = check_tableau(tableau);
  const std::vector<const OrderCondition*> failed = check.failed_claims();
  if (failed.empty()) return "";
  std::string line = "tableau " + tableau.source + ": " + failed.front()->failure();
  if (failed.size() > 1) line += " (and " + std::to_string(failed.size() - 1) + " more; dlpverify tableau lists them)";
  return line;
}

std::unique_ptr<Integrator> make_tableau_integrator(const std::string& path, std::ostream& warnings) {
  RuntimeTableau tableau = read_tableau_file(path);
  std::string warning = tableau_warning(tableau), file = tableau.source;
  std::unique_ptr<Integrator> integrator;
  if (!tableau.implicit()) {
    integrator = std::make_unique<TableauIntegrator>(std::move(tableau));
  } else {
    // Newton's test spans the population: a rank's share would solve to other bits than the whole.
    if (distribution().ranks() > 1)
      throw InputError("integrator", kTableauPrefix + path,
                       "a diagonally implicit tableau steps the whole population on one rank (its Newton iterations "
                       "span every member): run it without mpirun");
    integrator = std::make_unique<ArkodeDirkIntegrator>(kTableauPrefix + tableau.source, tableau.order,
                                                        DirkTable{tableau.c, tableau.b, tableau.a});
  }
  if (warning.empty()) return integrator;
  return std::make_unique<WarnedTableau>(std::move(integrator), std::move(file), std::move(warning), warnings);
}

IntegratorTraits tableau_traits(const RuntimeTableau& tableau) {
  if (!tableau.implicit()) return runge_kutta_traits();
  IntegratorTraits traits;
  traits.reach = IntegratorTraits::Reach::whole_population;
  traits.state_vectors = true;
  // ARKStep keeps each stage's implicit derivative and solution: 2 s copies (measured under
  // ulimit -v, drag R_out 20: 108 copies for 50 stages, 32 for Crouzeix's 3, 26 + 2 s bounding both).
  traits.stage_vectors = 2 * tableau.stages();
  return traits;
}

}  // namespace dlpverify
