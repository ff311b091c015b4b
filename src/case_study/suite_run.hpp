// A suite run: its studies several at once within a number of threads, a journal beside --json
// that an interrupted suite resumes from, a stop on SIGINT or SIGTERM after the studies under way,
// and its outputs written together (docs/cli.md, "dlpverify suite").
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "case_study/suite.hpp"
#include "study/journal.hpp"

namespace dlpverify::case_study {

struct SuiteRequest {
  std::vector<std::string> files;  // the study files, in the summary's order
  // Studies at once (0: one per thread). Each study that does not set its own threads gets
  // `threads` / `jobs` of them, at least 1; with one job the study runs as `check` would.
  int jobs = 1;
  int threads = 0;  // OpenMP threads in all; 0: OpenMP's default (all cores)
  std::string junit_file, table_file, html_file, json_file, summary_file;  // outputs; empty: not written
  JournalStart start = JournalStart::fresh;  // the journal beside json_file: kept, resumed or started over
  std::string command_line;                  // for the --json result's provenance
};

// InputError naming --jobs (below 0 or above 4 a core) or --threads. A suite runs on one process
// (the command refuses mpirun).
void validate(const SuiteRequest& request);

// Runs study `index` of the request's files and tells how it ended; it throws nothing for the
// study's own failures.
using StudyRunner = std::function<SuiteStudy(std::size_t index)>;
// Told of each study as it ends (one at a time, from the thread that ran it): `finished` of
// `total` are done, those taken from the journal included.
using StudyEnded = std::function<void(const SuiteStudy& study, std::size_t finished, std::size_t total)>;

struct SuiteOutcome {
  std::vector<SuiteStudy> studies;  // in the order of the files
  std::string table;                // the summary (suite_table)
  int exit_code = kExitDone;        // suite_exit_code, or 128 + N when signal N stopped the suite
};

// Runs the studies not already in the journal, then writes the outputs and removes the journal.
// A signal stops it after the studies under way (or a journaled study after its level): no output
// is written, the journal keeps every finished study, and exit_code is 128 + the signal.
// InputError (the journal refuses), OutputError (an output or the journal cannot be written).
SuiteOutcome run_suite(const SuiteRequest& request, const StudyRunner& run, const StudyEnded& ended);

}  // namespace dlpverify::case_study
