// What an output path names, and whether a study may write there — decided before any work.
//
// Three names are not files: `-` and `/dev/stdout` mean standard output, `/dev/null` means
// discard (the output is not even produced). Any other path must name a regular file, or
// nothing yet: an existing device, FIFO, socket or directory is refused, never replaced. A
// symbolic link is written through: its target (followed link by link) is what gets replaced,
// and the link stays a link.
#pragma once

#include <filesystem>
#include <string>

namespace dlpverify {

enum class OutputTarget { file, standard_output, discard };

// By name alone: "-" and "/dev/stdout" → standard_output, "/dev/null" → discard, else file.
OutputTarget output_target(const std::string& path);

// The file a write to `path` replaces: `path` with the symbolic links of its last component
// followed (a relative link from the link's folder). Throws InputError naming `option` after 40
// links (a loop).
std::filesystem::path link_target(const std::string& option, const std::string& path);

// Throws InputError naming `option` when `path` cannot be an output file: it names (or links to)
// something that is not a regular file, its nearest existing folder is not a folder, or that
// folder lies on a kernel file system that holds no files (/proc, /sys, …); OutputError when
// the folder is not writable (tried by creating and removing a file in it). Nothing is left.
void check_output_path(const std::string& option, const std::string& path);

}  // namespace dlpverify
