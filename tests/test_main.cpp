// The one translation unit that defines the Boost.Test module (and so main()) of unit_tests.
// Every other tests/test_*.cpp includes <boost/test/unit_test.hpp> without BOOST_TEST_MODULE.
// BOOST_TEST_DYN_LINK is set by tests/CMakeLists.txt: the shared Boost.Test library is linked.
#define BOOST_TEST_MODULE dlpverify unit tests
#include <boost/test/unit_test.hpp>
