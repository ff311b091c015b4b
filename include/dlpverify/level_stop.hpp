/// @file
/// A level under way, abandoned when a stop is asked. While a command listens for SIGINT and
/// SIGTERM (a study with its journal, a suite), a CI runner that cancels a job sends SIGTERM and,
/// seconds later, SIGKILL: finishing the level under way could take minutes, so every integrator
/// the tool owns asks level_stop_requested() once a step (inside a parallel region through
/// FirstFailure) and throws LevelAbandoned. The command then ends as a stop between levels does:
/// the journal keeps the levels finished, the outputs are left as they were. False whenever no
/// such command listens, so a caller of the library never sees it, and under mpirun, where every
/// rank must end a level together.
#pragma once

#include <stdexcept>

namespace dlpverify {

/// Thrown by an integrator's step loop when level_stop_requested(): the level is not finished.
class LevelAbandoned : public std::runtime_error {
 public:
  LevelAbandoned() : std::runtime_error("the level under way was abandoned at a stop signal") {}
};

/// Whether a stop signal arrived while a command listens for it on one process.
bool level_stop_requested() noexcept;

/// Throws LevelAbandoned when level_stop_requested(): called once per step.
inline void abandon_level_if_stop_requested() {
  if (level_stop_requested()) throw LevelAbandoned();
}

}  // namespace dlpverify
