// Outputs that never destroy what they replace (issue 9): the atomic writer and the output-path
// check (io/atomic_file.hpp, io/output_path.hpp).
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"

using namespace dlpverify;
namespace fs = std::filesystem;

namespace {

// A fresh folder, removed with everything in it.
struct Folder {
  fs::path path;
  Folder() {
    std::string pattern = (fs::temp_directory_path() / "dlpverify-output-XXXXXX").string();
    path = ::mkdtemp(pattern.data());
  }
  ~Folder() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  int entries() const { return static_cast<int>(std::distance(fs::directory_iterator(path), fs::directory_iterator())); }
};

std::string content_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(output_files)

// A FIFO where the output goes: refused by the check (InputError) and by the writer itself
// (OutputError), which leaves it a FIFO and no temporary file beside it.
BOOST_AUTO_TEST_CASE(writer_never_replaces_a_fifo) {
  const Folder folder;
  const std::string fifo = folder / "out.json";
  BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  BOOST_CHECK_THROW(check_output_path("--json", fifo), InputError);
  BOOST_CHECK_THROW(write_file_atomically(fifo, "{}\n"), OutputError);
  BOOST_TEST(fs::is_fifo(fifo));
  BOOST_TEST(folder.entries() == 1);
}

// The path passed its check as a regular file, then became a FIFO before the study ended: the
// writer refuses at the last moment.
BOOST_AUTO_TEST_CASE(writer_checks_again_at_the_end) {
  const Folder folder;
  const std::string path = folder / "out.csv";
  std::ofstream(path) << "old\n";
  BOOST_CHECK_NO_THROW(check_output_path("--csv", path));
  fs::remove(path);
  BOOST_REQUIRE(::mkfifo(path.c_str(), 0644) == 0);
  BOOST_CHECK_THROW(write_file_atomically(path, "new\n"), OutputError);
  BOOST_TEST(fs::is_fifo(path));
  BOOST_TEST(folder.entries() == 1);
}

// A link is written through: the target gets the content, the link stays a link; a dangling
// link's target is made.
BOOST_AUTO_TEST_CASE(writer_writes_through_links) {
  const Folder folder;
  std::ofstream(folder / "target.json") << "old\n";
  fs::create_symlink("target.json", folder / "link.json");
  write_file_atomically(folder / "link.json", "new\n");
  BOOST_TEST(fs::is_symlink(folder / "link.json"));
  BOOST_TEST(content_of(folder / "target.json") == "new\n");
  fs::create_symlink("made.json", folder / "dangling.json");
  write_file_atomically(folder / "dangling.json", "made\n");
  BOOST_TEST(fs::is_symlink(folder / "dangling.json"));
  BOOST_TEST(content_of(folder / "made.json") == "made\n");
  BOOST_TEST(folder.entries() == 4);
}

// The names that are not files: standard output and discard; everything else is a file.
BOOST_AUTO_TEST_CASE(special_names) {
  BOOST_TEST((output_target("-") == OutputTarget::standard_output));
  BOOST_TEST((output_target("/dev/stdout") == OutputTarget::standard_output));
  BOOST_TEST((output_target("/dev/null") == OutputTarget::discard));
  BOOST_TEST((output_target("./-") == OutputTarget::file));
  BOOST_TEST((output_target("/dev/stderr") == OutputTarget::file));
  BOOST_CHECK_NO_THROW(write_output("/dev/null", "nothing\n"));
}

BOOST_AUTO_TEST_SUITE_END()
