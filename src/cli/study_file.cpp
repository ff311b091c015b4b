#include "cli/study_file.hpp"

#include <filesystem>
#include <fstream>

#include "dlpverify/errors.hpp"
#include "io/printable.hpp"

namespace dlpverify::cli {

namespace {
// The study file named in args, or "" when there is none.
std::string study_file_path(const std::vector<std::string>& args) {
  std::string path;
  int given = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--config") {
      if (i + 1 >= args.size()) throw InputError("--config: needs a file name");
      path = args[i + 1];
      ++given;
    } else if (args[i].rfind("--config=", 0) == 0) {
      path = args[i].substr(9);
      ++given;
    }
  }
  if (given > 1) throw InputError("--config", path, "given more than once; a study reads one file");
  return path;
}
}  // namespace

std::vector<std::string> study_file_options(const CLI::App& subcommand, const std::string& path, std::istream& text) {
  std::vector<CLI::ConfigItem> items;
  try {
    items = CLI::ConfigTOML().from_config(text);
  } catch (const std::exception& e) {
    throw InputError("--config", path, "cannot be read: " + printable(e.what()));
  }
  std::vector<std::string> options;
  for (const CLI::ConfigItem& item : items) {
    if (!item.parents.empty())
      throw InputError("--config", path, "has a section [" + printable(item.parents.front()) + "]; keys stand at the top level");
    if (item.name == "config") throw InputError("--config", path, "a study file cannot name another study file");
    if (subcommand.get_option_no_throw("--" + item.name) == nullptr)
      throw InputError("--config", path, "unknown key '" + printable(item.name) + "' (keys are the long option names)");
    if (item.inputs.size() != 1)
      throw InputError("--config", path, "key '" + printable(item.name) + "' needs exactly one value");
    options.push_back("--" + item.name + "=" + item.inputs.front());
  }
  return options;
}

std::vector<std::string> expand_study_file(const CLI::App& subcommand, const std::vector<std::string>& args) {
  const std::string path = study_file_path(args);
  if (path.empty()) return args;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError("--config", path, "no such study file");
  std::ifstream in(path);
  if (!in) throw InputError("--config", path, "cannot be read");
  std::vector<std::string> expanded = study_file_options(subcommand, path, in);
  expanded.insert(expanded.end(), args.begin(), args.end());
  return expanded;
}

}  // namespace dlpverify::cli
