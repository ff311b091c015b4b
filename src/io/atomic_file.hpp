// Output files are written whole or not at all: to a temporary file beside the target, flushed,
// then renamed over it. A crash or a full disk leaves the old file (or none), never half a file.
#pragma once

#include <string>

namespace dlpverify {

// Throws InputError naming `option` when `path` cannot be an output file (a directory, or under
// something that is not a folder), OutputError when its folder is not writable. Nothing is created.
void check_output_path(const std::string& option, const std::string& path);

// Writes `content` to `path` atomically, making its folder if needed. Throws OutputError on failure.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace dlpverify
