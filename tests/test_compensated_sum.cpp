// Exact sums at scale (src/harness/compensated_sum.hpp): 10⁸ terms of a sum known in closed form
// to 1e-14, where naive summation loses digits; and the error norms' bits independent of the
// number of threads.
#include <boost/test/unit_test.hpp>

#include <omp.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "dlpverify/norms.hpp"
#include "harness/compensated_sum.hpp"

namespace unit_compensated_sum {

using namespace dlpverify;

namespace {

constexpr Eigen::Index kTerms = 100'000'000;
constexpr double kBig = 134217728.0;  // 2^27: its ulp is 2^-25 ≈ 3e-8

// Term i of a sum whose value is known in closed form: 2^27 first, −2^27 last, and between them
// the telescoping terms 1/((j + 1)(j + 2)) = 1/(j + 1) − 1/(j + 2), j = 0 … n − 3, whose sum is
// 1 − 1/(n − 1). Each term is rounded once or twice when it is formed (relative error ≤ 2ε, all
// positive), so the exact sum of the terms as doubles is within 2ε of the closed form. Added to
// 2^27, every term below half its ulp (j > 8000) vanishes: naive summation keeps 1 − 1/8000 at
// best, a relative error of ~1e-4, and summation in blocks does not save it.
double term(Eigen::Index i) {
  if (i == 0) return kBig;
  if (i == kTerms - 1) return -kBig;
  const auto j = static_cast<double>(i - 1);
  return 1.0 / ((j + 1.0) * (j + 2.0));
}

// Sets the OpenMP thread count for one scope.
class Threads {
 public:
  explicit Threads(int n) : previous_(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~Threads() { omp_set_num_threads(previous_); }
  Threads(const Threads&) = delete;
  Threads& operator=(const Threads&) = delete;

 private:
  int previous_;
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_sums)

// Σ = 1 − 1/(n − 1) exactly (the ±2^27 cancel); the compensated blocked sum must hold 1e-14
// relative, where the naive running sum of the same terms is ~1e-4 off (asserted: the test means
// something only if naive summation fails it).
BOOST_AUTO_TEST_CASE(ten_to_the_eighth_terms_of_known_sum) {
  const double exact = 1.0 - 1.0 / static_cast<double>(kTerms - 1);
  const double compensated = blocked_sum(kTerms, [](Eigen::Index first, Eigen::Index count, NeumaierSum& partial) {
    for (Eigen::Index i = first; i < first + count; ++i) partial.add(term(i));
  });
  double naive = 0.0;
  for (Eigen::Index i = 0; i < kTerms; ++i) naive += term(i);
  const double compensated_error = std::abs(compensated - exact) / exact;
  const double naive_error = std::abs(naive - exact) / exact;
  BOOST_TEST_MESSAGE("10^8 terms: compensated relative error " << compensated_error << ", naive " << naive_error);
  BOOST_TEST(naive_error > 1e-14);
  BOOST_TEST(compensated_error < 1e-14);
}

// Neumaier's case that Kahan's algorithm gets wrong: 1 + 1e100 + 1 − 1e100 = 2.
BOOST_AUTO_TEST_CASE(neumaier_keeps_the_smaller_operand) {
  NeumaierSum s;
  for (double x : {1.0, 1e100, 1.0, -1e100}) s.add(x);
  BOOST_TEST(s.value() == 2.0);
}

// The same error norms, to the bit, on 1, 2 and 3 threads: 100,003 members (25 blocks of 4096
// and a partial one) of random data, position-like (3 fields) and scalar.
BOOST_AUTO_TEST_CASE(thread_count_changes_no_bit) {
  const Eigen::Index members = 100'003;
  std::mt19937_64 random(20261123);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  State numerical(members, 4), reference(members, 4);
  for (Eigen::Index p = 0; p < members; ++p)
    for (int f = 0; f < 4; ++f) {
      reference(p, f) = uniform(random) * std::pow(10.0, 8.0 * uniform(random));  // 16 decades of magnitude
      numerical(p, f) = reference(p, f) * (1.0 + 1e-6 * uniform(random));
    }
  for (const Variable& v : {Variable{"position", 0, 3, "m"}, Variable{"temperature", 3, 1, "K"}}) {
    std::vector<ErrorNorms> by_threads;
    for (int threads : {1, 2, 3}) {
      const Threads scope(threads);
      by_threads.push_back(error_norms(numerical, reference, v));
    }
    for (std::size_t k = 1; k < by_threads.size(); ++k) {
      BOOST_TEST(same_bits(by_threads[k].l2, by_threads[0].l2), v.name << ", " << k + 1 << " threads");
      BOOST_TEST(same_bits(by_threads[k].reference_l2, by_threads[0].reference_l2), v.name << ", " << k + 1 << " threads");
      BOOST_TEST(same_bits(by_threads[k].max, by_threads[0].max), v.name << ", " << k + 1 << " threads");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_compensated_sum
