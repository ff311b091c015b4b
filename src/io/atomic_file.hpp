// Output files are written whole or not at all: to a temporary file beside the target, flushed,
// then renamed over it. A crash or a full disk leaves the old file (or none), never half a file.
// Only a regular file (or nothing) is ever replaced: a device, FIFO or socket on the path is
// refused at the last moment too, in case it appeared after check_output_path (output_path.hpp).
#pragma once

#include <string>

#include "io/output_path.hpp"

namespace dlpverify {

// Writes `content` to `path` atomically, making its folder if needed; through a symbolic link, to
// the link's target (the link stays). Throws OutputError on failure, and when `path` names (or
// links to) something that is not a regular file.
void write_file_atomically(const std::string& path, const std::string& content);

// Where an output option's path leads (output_target): standard output, nowhere, or
// write_file_atomically. Throws OutputError on failure.
void write_output(const std::string& path, const std::string& content);

}  // namespace dlpverify
