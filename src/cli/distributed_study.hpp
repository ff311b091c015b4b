// A convergence study or a work-precision sweep under mpirun (docs/mpi.md): what it may be asked
// to run, and the journal's progress shared by every rank. Serially (one
// rank) each is the identity.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "dlpverify/reference.hpp"
#include "dlpverify/study.hpp"
#include "dlpverify/work_precision.hpp"
#include "harness/distribution.hpp"
#include "harness/rank_share.hpp"
#include "io/stop_signal.hpp"

namespace dlpverify::cli {

// Refuses (InputError naming the option) what does not yet run on more than one rank: an
// integrator that is neither a per-member Runge–Kutta method nor CVODE or ARKODE ERK (whose sums
// span the ranks), an integrator reference that is not a per-member method (the others take norms
// over the whole population inside their steps), and a manufactured reference.
void check_distributable(const std::string& integrator, const ReferenceSettings& reference);

// Rank 0's journal progress on every rank: the levels it resumes from are sent to the others, a
// stop is asked of every rank together (a signal seen by any rank stops all after the level under
// way), and only rank 0 records. When rank 0 keeps a journal (`journaled`), `signals` catches
// SIGINT/SIGTERM on the other ranks, as the journal does on rank 0.
StudyProgress shared_progress(StudyProgress own, bool journaled, const std::vector<Variable>& variables,
                              std::unique_ptr<StopOnSignal>& signals);
// The same for the runs of a work-precision sweep (precision).
Progress<PrecisionRunResult> shared_progress(Progress<PrecisionRunResult> own, bool journaled,
                                             const std::vector<Variable>& variables,
                                             std::unique_ptr<StopOnSignal>& signals);

}  // namespace dlpverify::cli
