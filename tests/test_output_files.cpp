// Outputs that never destroy what they replace: the atomic writer, the outputs of one run
// committed together, and the output-path check (io/atomic_file.hpp, io/output_path.hpp).
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"
#include "io/atomic_file.hpp"

namespace unit_output_files {

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
  BOOST_CHECK_THROW(write_output(fifo, "{}\n"), OutputError);
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
  BOOST_CHECK_THROW(write_output(path, "new\n"), OutputError);
  BOOST_TEST(fs::is_fifo(path));
  BOOST_TEST(folder.entries() == 1);
}

// A link is written through: the target gets the content, the link stays a link; a dangling
// link's target is made.
BOOST_AUTO_TEST_CASE(writer_writes_through_links) {
  const Folder folder;
  std::ofstream(folder / "target.json") << "old\n";
  fs::create_symlink("target.json", folder / "link.json");
  write_output(folder / "link.json", "new\n");
  BOOST_TEST(fs::is_symlink(folder / "link.json"));
  BOOST_TEST(content_of(folder / "target.json") == "new\n");
  fs::create_symlink("made.json", folder / "dangling.json");
  write_output(folder / "dangling.json", "made\n");
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

// A run's outputs all land together: each new content in place, no temporary or kept old file
// left beside them.
BOOST_AUTO_TEST_CASE(set_commits_every_output) {
  const Folder folder;
  std::ofstream(folder / "a.json") << "old a\n";
  OutputSet set;
  set.add(folder / "a.json", "new a\n");
  set.add(folder / "b.csv", "new b\n");
  set.add("/dev/null", "discarded\n");
  BOOST_TEST(content_of(folder / "a.json") == "old a\n");  // nothing replaced before commit
  set.commit();
  BOOST_TEST(content_of(folder / "a.json") == "new a\n");
  BOOST_TEST(content_of(folder / "b.csv") == "new b\n");
  BOOST_TEST(folder.entries() == 2);
}

// An output that cannot be written (the file-size limit, as on a full disk) fails the set: the
// files written before it are left as they were and no temporary remains.
BOOST_AUTO_TEST_CASE(set_leaves_old_files_when_an_output_fails) {
  const Folder folder;
  std::ofstream(folder / "keep.json") << "old json\n";
  std::ofstream(folder / "pp.csv") << "old rows\n";
  rlimit saved{};
  BOOST_REQUIRE(::getrlimit(RLIMIT_FSIZE, &saved) == 0);
  report_file_size_limit_as_error();
  rlimit small = saved;
  small.rlim_cur = 4096;
  BOOST_REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
  bool failed = false;
  {
    OutputSet set;
    set.add(folder / "keep.json", "new json\n");
    try {
      set.add(folder / "pp.csv", std::string(8192, 'x'));
    } catch (const OutputError& e) {
      failed = std::string(e.what()).find("pp.csv") != std::string::npos;
    }
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  BOOST_TEST(failed);
  BOOST_TEST(content_of(folder / "keep.json") == "old json\n");
  BOOST_TEST(content_of(folder / "pp.csv") == "old rows\n");
  BOOST_TEST(folder.entries() == 2);
}

// A rename that fails during the commit (the last target became a folder after it was checked)
// puts back what the commit had replaced: the old file, or nothing where there was none.
BOOST_AUTO_TEST_CASE(set_rolls_back_a_failed_commit) {
  const Folder folder;
  std::ofstream(folder / "a.json") << "old a\n";
  std::ofstream(folder / "z.txt") << "old z\n";
  OutputSet set;
  set.add(folder / "a.json", "new a\n");
  set.add(folder / "new.csv", "new csv\n");
  set.add(folder / "z.txt", "new z\n");
  fs::remove(folder / "z.txt");
  fs::create_directory(folder / "z.txt");
  try {
    set.commit();
    BOOST_FAIL("the commit replaced a folder");
  } catch (const OutputError& e) {
    BOOST_TEST(std::string(e.what()).find("z.txt") != std::string::npos);
  }
  BOOST_TEST(content_of(folder / "a.json") == "old a\n");
  BOOST_TEST(!fs::exists(folder / "new.csv"));
  BOOST_TEST(fs::is_directory(folder / "z.txt"));
  BOOST_TEST(folder.entries() == 2);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_output_files
