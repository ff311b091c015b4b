// Output files are written whole or not at all, and the outputs of one run together or not at all.
//
// Each output goes to a temporary file beside its target and is flushed to disk (fsync) when it is
// added to an OutputSet; only when every output of the run is on disk are they renamed into place.
// A full disk, a file-size limit or a gnuplot failure on any output leaves every old file as it
// was and no temporary behind. Only a regular file (or nothing) is ever replaced: a device, FIFO
// or socket on the path is refused at the last moment too, in case it appeared after
// check_output_path (output_path.hpp).
#pragma once

#include <string>
#include <vector>

#include "io/output_path.hpp"

namespace dlpverify {

class OutputSet {
 public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  // Removes every temporary file of an uncommitted set.
  ~OutputSet();

  // Adds the output `content` for `path` (output_target: a file, standard output, or /dev/null).
  // A file's content is written to its temporary and flushed now; standard output's is kept for
  // commit(). Throws OutputError naming the path when the temporary cannot be written (the
  // targets are untouched: the set is then discarded).
  void add(const std::string& path, const std::string& content);

  // Writes standard output's content, then renames every temporary onto its target (through a
  // symbolic link, onto the link's target; the link stays). Should a rename fail, the targets
  // renamed before it get their old files back. Throws OutputError naming the output that failed.
  void commit();

 private:
  struct Staged {
    std::string shown;      // the path as the user wrote it, printable, for messages
    std::string target;     // the regular file it replaces
    std::string temporary;  // the flushed new content, beside the target
  };
  std::vector<Staged> files_;
  std::vector<std::string> standard_output_;
  bool committed_ = false;
};

// One output written whole or not at all: an OutputSet of one.
void write_output(const std::string& path, const std::string& content);

// A write past the file-size limit (ulimit -f) fails with EFBIG instead of killing the process by
// SIGXFSZ, so that the run can leave every file as it was and say which output failed (exit 4).
void report_file_size_limit_as_error();

}  // namespace dlpverify
