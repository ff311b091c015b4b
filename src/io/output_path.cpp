#include "io/output_path.hpp"

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <linux/magic.h>
#include <sys/statfs.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"
#include "io/journal_file.hpp"
#include "io/printable.hpp"

namespace dlpverify {

namespace fs = std::filesystem;

namespace {

const char* describe(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory: return "a directory";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

// The name of the kernel file system `folder` is on when it is one that holds no files of ours
// (a write there fails, or worse, talks to the kernel), else nullptr.
const char* pseudo_file_system(const fs::path& folder) {
  struct statfs info {};
  if (::statfs(folder.c_str(), &info) != 0) return nullptr;
  static const std::pair<unsigned long, const char*> kinds[] = {
      {PROC_SUPER_MAGIC, "procfs"},     {SYSFS_MAGIC, "sysfs"},         {DEVPTS_SUPER_MAGIC, "devpts"},
      {CGROUP_SUPER_MAGIC, "cgroupfs"}, {CGROUP2_SUPER_MAGIC, "cgroup2"}, {DEBUGFS_MAGIC, "debugfs"},
      {TRACEFS_MAGIC, "tracefs"},       {SECURITYFS_MAGIC, "securityfs"}, {BPF_FS_MAGIC, "bpffs"},
      {PSTOREFS_MAGIC, "pstore"},       {EFIVARFS_MAGIC, "efivarfs"},   {BINFMTFS_MAGIC, "binfmt_misc"},
      {SELINUX_MAGIC, "selinuxfs"}};
  for (const auto& [magic, name] : kinds)
    if (static_cast<unsigned long>(info.f_type) == magic) return name;
  return nullptr;
}

// The folder `target` is written in. No command creates a folder: a missing one is bad input,
// through a link as for a plain path (as root, a write would create it anywhere).
fs::path folder_of(const fs::path& target) { return target.parent_path().empty() ? fs::path(".") : target.parent_path(); }

// Whether a file can be made in `folder`: access() alone says yes to root on a read-only bind
// mount's neighbours, an immutable folder or a FUSE file system, so one is made and removed.
int try_create_in(const fs::path& folder) {
  if (::access(folder.c_str(), W_OK) != 0) return errno;
  std::string pattern = (folder / ".dlpverify-probe.XXXXXX").string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) return errno;
  ::close(fd);
  ::unlink(name.data());
  return 0;
}

}  // namespace

OutputTarget output_target(const std::string& path) {
  if (path == "-" || path == "/dev/stdout") return OutputTarget::standard_output;
  if (path == "/dev/null") return OutputTarget::discard;
  return OutputTarget::file;
}

fs::path link_target(const std::string& option, const std::string& path) {
  fs::path target(path);
  std::error_code ec;
  for (int links = 0; fs::is_symlink(fs::symlink_status(target, ec)); ++links) {
    if (links == 40) throw InputError(option, path, "is a loop of symbolic links (40 followed)");
    const fs::path next = fs::read_symlink(target, ec);
    if (ec) throw InputError(option, path, "its symbolic link cannot be read: " + ec.message());
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target;
}

void check_output_path(const std::string& option, const std::string& path) {
  if (path.empty()) throw InputError(option, "\"\"", "empty file name");
  if (output_target(path) != OutputTarget::file) return;
  const fs::path target = link_target(option, path);
  const std::string via = target == fs::path(path) ? "" : " (a link to " + printable(target.string()) + ")";
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(target, ec);
  if (status.type() == fs::file_type::directory) throw InputError(option, path, "is a directory" + via + ", not a file");
  if (fs::exists(status) && status.type() != fs::file_type::regular)
    throw InputError(option, path,
                     std::string("is ") + describe(status.type()) + via +
                         ", not a regular file: refusing to replace it (- writes to standard output, /dev/null discards)");
  // A journal holds an unfinished study's levels (or a suite's studies): replaced, they are lost.
  if (status.type() == fs::file_type::regular && is_study_journal(target.string()))
    throw InputError(option, path,
                     "is a study's journal" + via +
                         ": refusing to replace it and lose its finished levels (continue that study with --resume, "
                         "or move the journal away)");
  const fs::path folder = folder_of(target);
  if (!fs::exists(folder, ec))
    throw InputError(option, path, "its folder " + printable(folder.string()) + " does not exist; no command creates a folder" + via);
  if (!fs::is_directory(folder, ec))
    throw InputError(option, path, "its folder " + printable(folder.string()) + " is not a directory");
  if (const char* kind = pseudo_file_system(folder))
    throw InputError(option, path, "its folder " + printable(folder.string()) + " is on " + kind + ", which holds no files");
  // Unwritable is an output failure (exit 4), found before any work is done.
  if (const int error = try_create_in(folder); error != 0)
    throw OutputError(option + " = " + printable(path) + ": cannot write into folder " + printable(folder.string()) +
                      " (" + std::strerror(error) + ")");
}

}  // namespace dlpverify
