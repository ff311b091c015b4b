// Paths by identity, not by spelling: `x`, `./x`, `$PWD/x` and a link to `x` are one file.
//
// A path that reaches an existing file (its links followed) is that file's device and inode; a
// path whose file does not exist yet is its folder's device and inode and its name, so two
// spellings of one new output are one file too. Standard output (`-`, `/dev/stdout`) and
// `/dev/null` are no file. docs/cli.md, "What a path may name".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace dlpverify {

/// The file a path names: the device and inode of the file, or of its folder and the name in it.
struct FileIdentity {
  dev_t device = 0;  ///< the file's device, or its folder's when it does not exist
  ino_t inode = 0;   ///< the file's inode, or its folder's
  std::string name;  ///< empty when the file exists; else its name in that folder
  bool operator==(const FileIdentity&) const = default;
};

/// The identity of the file a write to, or a read of, `path` reaches (links followed); nullopt
/// for standard output, /dev/null, an empty path, or a path whose folder does not exist.
std::optional<FileIdentity> file_identity(const std::string& path);

/// An input or output of a run, as the user named it: the option (or the input's kind) and the path.
struct NamedPath {
  std::string name;  ///< the option, e.g. --json, or the input's kind, e.g. "tableau file"
  std::string path;  ///< as given
};

/// Throws InputError naming the output when an output is one of the inputs, or another output,
/// however either is spelled: a run never writes over what it reads, nor twice to one file.
void refuse_shared_files(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

}  // namespace dlpverify
