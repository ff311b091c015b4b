// Error text a terminal shows but never obeys (issue 9): io/printable.hpp.
#include <boost/test/unit_test.hpp>

#include <string>

#include "io/printable.hpp"

namespace unit_printable {

using namespace dlpverify;

BOOST_AUTO_TEST_SUITE(printable_text)

// Control characters escaped, UTF-8 kept, malformed UTF-8 (a lone byte, an overlong form, a
// surrogate) escaped byte by byte, C1 controls (U+009B is an 8-bit CSI) escaped.
BOOST_AUTO_TEST_CASE(printable_escapes_controls) {
  BOOST_TEST(printable("drag-rk2.toml") == "drag-rk2.toml");
  BOOST_TEST(printable("Δt = 5e-4 · é") == "Δt = 5e-4 · é");
  BOOST_TEST(printable("\x1b[2J\a") == "\\x1b[2J\\x07");
  BOOST_TEST(printable(std::string("a\0b", 3)) == "a\\x00b");
  BOOST_TEST(printable("a\nb\tc\rd\x7f") == "a\\nb\\tc\\rd\\x7f");
  BOOST_TEST(printable("\xff\xfe") == "\\xff\\xfe");
  BOOST_TEST(printable("\xc0\xaf") == "\\xc0\\xaf");
  BOOST_TEST(printable("\xed\xa0\x80") == "\\xed\\xa0\\x80");
  BOOST_TEST(printable("\xc2\x9b" "31m") == "\\xc2\\x9b31m");
  BOOST_TEST(printable("\xe2\x80") == "\\xe2\\x80");  // a sequence cut short by the end
}

// Cut at 80 characters shown (a multi-byte character counts one, an escape its four), with "…".
BOOST_AUTO_TEST_CASE(printable_cuts_long_values) {
  const std::string eighty(80, 'x');
  BOOST_TEST(printable(eighty) == eighty);
  BOOST_TEST(printable(eighty + "y") == std::string(79, 'x') + "…");
  std::string accents;
  for (int i = 0; i < 100; ++i) accents += "é";
  std::string expected;
  for (int i = 0; i < 79; ++i) expected += "é";
  BOOST_TEST(printable(accents) == expected + "…");
  BOOST_TEST(printable(std::string(78, 'x') + "\x1b" "abc") == std::string(78, 'x') + "…");
  BOOST_TEST(printable("abcdef", 4) == "abc…");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_printable
