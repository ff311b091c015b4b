#include "cli/distributed_study.hpp"

#include <utility>

#include "cli/problems.hpp"
#include "dlpverify/errors.hpp"
#include "harness/exact_record.hpp"

namespace dlpverify::cli {

namespace {

bool reaches_each_member(const std::string& integrator) {
  const std::optional<IntegratorTraits> traits = find_integrator_traits(integrator);
  return traits && traits->reach == IntegratorTraits::Reach::each_member;
}

}  // namespace

void check_distributable(const std::string& integrator, const ReferenceSettings& reference) {
  if (distribution().ranks() == 1) return;
  // A Runge–Kutta method steps each member on its own, so a rank's members take the serial run's
  // bits; CVODE and ARKODE step the rank's share in vectors whose sums span every rank
  // (CvodeSettings::across_ranks, src/mpi/nvector_distributed.hpp): the serial run's steps.
  if (integrator_traits(integrator).reach == IntegratorTraits::Reach::whole_population)
    throw InputError("integrator", integrator,
                     "steps the whole population at once; under mpirun use euler, heun, rk2, rk4, tableau:FILE, cvode, "
                     "arkode-erk:TABLE or, with --tolerances, arkode-adaptive:TABLE (docs/mpi.md)");
  // ManufacturedProblem builds ŷ from the problem it is given: a slab's ŷ is not the whole's.
  if (reference.kind == ReferenceKind::manufactured)
    throw InputError("reference", "manufactured",
                     "its manufactured solution is built from the whole population; under mpirun use the closed form, "
                     "cvode or integrator:SPEC@DT (docs/mpi.md)");
  if (reference.kind == ReferenceKind::integrator && reference.integrator &&
      !reaches_each_member(reference.integrator->name()))
    throw InputError("reference", "integrator:" + reference.integrator->name(),
                     "steps the whole population at once; under mpirun an integrator reference is euler, heun, rk2, "
                     "rk4 or tableau:FILE (docs/mpi.md)");
}

namespace {

// Rank 0's finished levels or runs on every rank (as records), and the stop asked of every rank.
template <class Finished, class ToRecord, class FromRecord>
Progress<Finished> shared(Progress<Finished> own_progress, bool journaled, const ToRecord& to_record,
                          const FromRecord& from_record, std::unique_ptr<StopOnSignal>& signals) {
  const Distribution& all = distribution();
  if (all.ranks() == 1) return own_progress;
  nlohmann::json sent = {{"journal", journaled}, {"done", nlohmann::json::array()}};
  for (const Finished& finished : own_progress.done) sent["done"].push_back(to_record(finished));
  const nlohmann::json received = nlohmann::json::parse(all.from_root(sent.dump()));
  Progress<Finished> progress;
  for (const nlohmann::json& record : received.at("done")) progress.done.push_back(from_record(record));
  if (all.rank() == 0)
    progress.finished = own_progress.finished;
  else if (received.at("journal").get<bool>())
    signals = std::make_unique<StopOnSignal>();
  const std::function<bool()> own_stop = own_progress.stop;
  const StopOnSignal* caught = signals.get();
  progress.stop = [own_stop, caught, &all] {
    return all.any((own_stop && own_stop()) || (caught && caught->signal() != 0));
  };
  return progress;
}

}  // namespace

StudyProgress shared_progress(StudyProgress own_progress, bool journaled, const std::vector<Variable>& variables,
                              std::unique_ptr<StopOnSignal>& signals) {
  return shared(
      std::move(own_progress), journaled, [&](const LevelResult& level) { return level_record(level, variables); },
      [&](const nlohmann::json& record) { return level_from_record(record, variables); }, signals);
}

Progress<PrecisionRunResult> shared_progress(Progress<PrecisionRunResult> own_progress, bool journaled,
                                             const std::vector<Variable>& variables,
                                             std::unique_ptr<StopOnSignal>& signals) {
  return shared(
      std::move(own_progress), journaled, [&](const PrecisionRunResult& run) { return run_record(run, variables); },
      [&](const nlohmann::json& record) { return run_from_record(record, variables); }, signals);
}

}  // namespace dlpverify::cli
