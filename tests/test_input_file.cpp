// A user's input file is a regular file of bounded size, checked on its descriptor: a FIFO with
// no writer is refused at once (the open does not block), a device or a folder is refused, a file
// above its kind's limit is refused before a byte is read.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "dlpverify/errors.hpp"
#include "io/input_file.hpp"

namespace unit_input_file {

namespace fs = std::filesystem;
using namespace dlpverify;

namespace {

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("dlpverify-input-" + std::to_string(::getpid()));
  Scratch() { fs::create_directories(dir); }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
};

// The reason of the InputError that reading `path` throws, or "" when it reads.
std::string refusal(const std::string& path, std::uintmax_t limit) {
  try {
    read_input_file("tableau file", path, limit);
  } catch (const InputError& e) {
    BOOST_TEST(e.quantity() == "tableau file");
    BOOST_TEST(e.value() == path);
    return e.reason();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(input_file)

BOOST_AUTO_TEST_CASE(a_regular_file_is_read_whole) {
  Scratch s;
  const std::string text = "stages = 2\n" + std::string(100000, 'x');
  BOOST_TEST(read_input_file("tableau file", s.write("t.toml", text), input_limit::tableau) == text);
  BOOST_TEST(read_input_file("tableau file", s.write("empty.toml", ""), input_limit::tableau).empty());
}

BOOST_AUTO_TEST_CASE(a_fifo_device_or_folder_is_refused_without_blocking) {
  Scratch s;
  const std::string fifo = (s.dir / "fifo").string();
  BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  BOOST_TEST(refusal(fifo, input_limit::tableau) == "is a FIFO, not a regular file");
  BOOST_TEST(refusal("/dev/zero", input_limit::tableau) == "is a device, not a regular file");
  BOOST_TEST(refusal(s.dir.string(), input_limit::tableau) == "is a folder, not a regular file");
  const fs::path link = s.dir / "zero.toml";
  fs::create_symlink("/dev/zero", link);  // a link is followed, and what it names is checked
  BOOST_TEST(refusal(link.string(), input_limit::tableau) == "is a device, not a regular file");
}

BOOST_AUTO_TEST_CASE(a_file_above_its_limit_is_refused) {
  Scratch s;
  const std::string path = s.write("big.toml", std::string(1025, 'x'));
  BOOST_TEST(refusal(path, 1024) == "is 1025 bytes, above the limit of 1024 bytes");
  BOOST_TEST(refusal(path, 1025).empty());
  BOOST_TEST(refusal(s.write("huge.toml", std::string((1u << 20) + 1, 'x')), input_limit::study_file) ==
             "is 1048577 bytes, above the limit of 1 MiB");
}

BOOST_AUTO_TEST_CASE(a_missing_or_empty_name_is_refused) {
  Scratch s;
  BOOST_TEST(refusal((s.dir / "none.toml").string(), input_limit::tableau) == "cannot be read: no such file");
  BOOST_CHECK_THROW(read_input_file("--config", "", input_limit::study_file), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_input_file
