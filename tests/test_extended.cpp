// Extended precision's state (dlpverify/extended.hpp): a double-double value splits into its
// leading double and the remainder, exactly; a double state is an Extended one exactly.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "dlpverify/extended.hpp"

namespace unit_extended {

using namespace dlpverify;

BOOST_AUTO_TEST_SUITE(extended_precision)

// 1/3 in double-double is fl(1/3) + fl(1/3)·2^−54 (QD's normalised pair):
// high() is the nearest double, low() what it leaves, and their sum is the value, bit for bit.
BOOST_AUTO_TEST_CASE(a_value_splits_into_its_leading_double_and_the_rest) {
  ExtendedState s(2, 1);
  s(0, 0) = Extended(1.0) / 3.0;
  s(1, 0) = Extended(-2.0) / 7.0;
  const State high = s.high(), low = s.low();
  BOOST_TEST(high(0, 0) == 1.0 / 3.0);
  BOOST_TEST(low(0, 0) == std::ldexp(1.0 / 3.0, -54));  // 1/3 − fl(1/3) = 1/(3·2^54), to the nearest double
  for (Eigen::Index p = 0; p < 2; ++p) {
    BOOST_TEST((Extended(high(p, 0)) + low(p, 0) == s(p, 0)));
    BOOST_TEST(std::abs(low(p, 0)) <= 0.5 * std::nextafter(std::abs(high(p, 0)), INFINITY) - 0.5 * std::abs(high(p, 0)));
  }
  // A double state is an Extended one exactly: nothing is left over.
  State d(2, 2);
  d << 0.1, 1e300, -3.5, 7e-300;
  const ExtendedState e(d);
  BOOST_TEST((e.high() == d).all());
  BOOST_TEST((e.low() == 0.0).all());
  BOOST_TEST((e.rows_of(1, 1).high() == d.row(1)).all());
}

BOOST_AUTO_TEST_CASE(the_arithmetic_is_named_with_its_epsilon) {
  BOOST_TEST(to_string(Precision::double_precision) == "double");
  BOOST_TEST(to_string(Precision::extended) == "extended");
  BOOST_TEST(epsilon_of(Precision::double_precision) == std::ldexp(1.0, -52));
  BOOST_TEST(epsilon_of(Precision::extended) == std::ldexp(1.0, -104));
  BOOST_TEST(kExtendedEpsilon == dd_real::_eps, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_extended
