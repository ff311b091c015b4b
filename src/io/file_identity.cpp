#include "io/file_identity.hpp"

#include <filesystem>

#include <sys/stat.h>

#include "dlpverify/errors.hpp"
#include "io/output_path.hpp"
#include "io/printable.hpp"

namespace dlpverify {

namespace fs = std::filesystem;

std::optional<FileIdentity> file_identity(const std::string& path) {
  if (path.empty() || output_target(path) != OutputTarget::file) return std::nullopt;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return FileIdentity{st.st_dev, st.st_ino, ""};
  // Not there yet: the file a write would create is the last link's target, in its folder.
  fs::path target;
  try {
    target = link_target("path", path);
  } catch (const InputError&) {
    return std::nullopt;  // a loop of links: the output check refuses it
  }
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (::stat(folder.c_str(), &st) != 0) return std::nullopt;
  return FileIdentity{st.st_dev, st.st_ino, target.filename().string()};
}

void refuse_shared_files(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  std::vector<std::pair<FileIdentity, const NamedPath*>> seen;
  for (const NamedPath& input : inputs)
    if (const auto id = file_identity(input.path)) seen.emplace_back(*id, &input);
  const std::size_t input_count = seen.size();
  for (const NamedPath& output : outputs) {
    const auto id = file_identity(output.path);
    if (!id) continue;
    for (std::size_t i = 0; i < seen.size(); ++i) {
      if (!(seen[i].first == *id)) continue;
      const NamedPath& other = *seen[i].second;
      const bool input = i < input_count;
      throw InputError(output.name, printable(output.path),
                       (input ? "is the input " : "is the same file as ") + other.name + " " + printable(other.path) +
                           (input ? " (a run never writes over what it reads)" : " (a run writes each file once)"));
    }
    seen.emplace_back(*id, &output);
  }
}

}  // namespace dlpverify
