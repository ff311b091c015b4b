// dlpverify's compiled N_Vector (src/sundials/nvector_compiled.hpp) against SUNDIALS' own serial
// vector, operation by operation, on random data (fixed seed): element-wise operations bit for
// bit, reductions to 1e-14 relative (a threaded sum may add in another order); serial and
// threaded variants, shaped or not, clones, and a wrapped array that is neither copied nor freed;
// a shaped vector's sums in (field, block of 4,096 members) order, whatever the threads, and
// the same bits when its members are split at a block boundary (as over MPI ranks).
#include <boost/test/unit_test.hpp>

#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "sundials/nvector_compiled.hpp"
#include "sundials/sundials_support.hpp"

namespace unit_nvector {

using namespace dlpverify;

namespace {

constexpr sunindextype kLength = 10007;  // above the threading threshold, not a multiple of a SIMD width

struct Pair {  // the same values in a stock serial vector and in ours
  sun::Vector stock, ours;
};

// `shaped`: ours told it holds kLength members of one field (3 blocks of the sums).
Pair random_pair(SUNContext context, bool threaded, bool shaped, std::mt19937_64& random, double low = -2.0,
                 double high = 3.0) {
  std::uniform_real_distribution<double> value(low, high);
  Pair p{sun::Vector(N_VNew_Serial(kLength, context)), sun::Vector(sun::new_compiled_vector(kLength, threaded, context))};
  if (shaped) sun::set_shape(p.ours.get(), kLength, 1);
  for (sunindextype i = 0; i < kLength; ++i)
    N_VGetArrayPointer(p.stock.get())[i] = N_VGetArrayPointer(p.ours.get())[i] = value(random);
  return p;
}

void same_entries(N_Vector a, N_Vector b) {
  const double* x = N_VGetArrayPointer(a);
  const double* y = N_VGetArrayPointer(b);
  sunindextype differ = 0;
  for (sunindextype i = 0; i < kLength; ++i) differ += !(x[i] == y[i] || (std::isnan(x[i]) && std::isnan(y[i])));
  BOOST_TEST(differ == 0);
}

void close(double a, double b) { BOOST_TEST(a == b, boost::test_tools::tolerance(1e-14)); }

}  // namespace

BOOST_AUTO_TEST_SUITE(nvector)

BOOST_AUTO_TEST_CASE(every_operation_matches_the_serial_vector) {
  sun::Context context;
  for (bool threaded : {false, true})
    for (bool shaped : {false, true}) {
      BOOST_TEST_CONTEXT((threaded ? "threaded" : "serial") << (shaped ? ", shaped" : "")) {
        std::mt19937_64 random(20261123);
        Pair x = random_pair(context, threaded, shaped, random), y = random_pair(context, threaded, shaped, random);
        Pair w = random_pair(context, threaded, shaped, random, 0.1, 2.0), z = random_pair(context, threaded, shaped, random);
        Pair id = random_pair(context, threaded, shaped, random, -1.0, 1.0);
        BOOST_TEST(N_VGetVectorID(x.ours.get()) == SUNDIALS_NVEC_CUSTOM);
        BOOST_TEST(N_VGetLength(x.ours.get()) == kLength);
        BOOST_TEST(sun::is_compiled_vector(x.ours.get()));

        auto both = [&](auto operation) {
          operation(x.stock.get(), y.stock.get(), w.stock.get(), id.stock.get(), z.stock.get());
          operation(x.ours.get(), y.ours.get(), w.ours.get(), id.ours.get(), z.ours.get());
          same_entries(z.stock.get(), z.ours.get());
        };
        both([](N_Vector a, N_Vector b, N_Vector, N_Vector, N_Vector c) { N_VLinearSum(1.5, a, -0.25, b, c); });
        both([](N_Vector, N_Vector, N_Vector, N_Vector, N_Vector c) { N_VConst(0.75, c); });
        both([](N_Vector a, N_Vector b, N_Vector, N_Vector, N_Vector c) { N_VProd(a, b, c); });
        both([](N_Vector a, N_Vector, N_Vector d, N_Vector, N_Vector c) { N_VDiv(a, d, c); });
        both([](N_Vector a, N_Vector, N_Vector, N_Vector, N_Vector c) { N_VScale(-3.0, a, c); });
        both([](N_Vector a, N_Vector, N_Vector, N_Vector, N_Vector c) { N_VAbs(a, c); });
        both([](N_Vector, N_Vector, N_Vector d, N_Vector, N_Vector c) { N_VInv(d, c); });
        both([](N_Vector a, N_Vector, N_Vector, N_Vector, N_Vector c) { N_VAddConst(a, 0.5, c); });
        both([](N_Vector a, N_Vector, N_Vector, N_Vector, N_Vector c) { N_VCompare(1.0, a, c); });
        both([](N_Vector, N_Vector, N_Vector d, N_Vector, N_Vector c) { BOOST_TEST(N_VInvTest(d, c) == SUNTRUE); });
        both([](N_Vector a, N_Vector b, N_Vector, N_Vector, N_Vector c) {  // z aliasing an input
          N_VScale(1.0, a, c);
          N_VLinearSum(2.0, c, 1.0, b, c);
        });
        both([](N_Vector a, N_Vector b, N_Vector d, N_Vector, N_Vector c) {
          double coefficients[3] = {0.5, -1.25, 2.0};
          N_Vector columns[3] = {a, b, d};
          N_VLinearCombination(3, coefficients, columns, c);
        });

        close(N_VDotProd(x.stock.get(), y.stock.get()), N_VDotProd(x.ours.get(), y.ours.get()));
        close(N_VMaxNorm(x.stock.get()), N_VMaxNorm(x.ours.get()));
        close(N_VWrmsNorm(x.stock.get(), w.stock.get()), N_VWrmsNorm(x.ours.get(), w.ours.get()));
        close(N_VWrmsNormMask(x.stock.get(), w.stock.get(), id.stock.get()),
              N_VWrmsNormMask(x.ours.get(), w.ours.get(), id.ours.get()));
        close(N_VMin(x.stock.get()), N_VMin(x.ours.get()));
        close(N_VWL2Norm(x.stock.get(), w.stock.get()), N_VWL2Norm(x.ours.get(), w.ours.get()));
        close(N_VL1Norm(x.stock.get()), N_VL1Norm(x.ours.get()));
        close(N_VDotProdLocal(x.stock.get(), y.stock.get()), N_VDotProdLocal(x.ours.get(), y.ours.get()));
        close(N_VMaxNormLocal(x.stock.get()), N_VMaxNormLocal(x.ours.get()));
        close(N_VMinLocal(x.stock.get()), N_VMinLocal(x.ours.get()));
        close(N_VL1NormLocal(x.stock.get()), N_VL1NormLocal(x.ours.get()));
        close(N_VWSqrSumLocal(x.stock.get(), w.stock.get()), N_VWSqrSumLocal(x.ours.get(), w.ours.get()));
        close(N_VWSqrSumMaskLocal(x.stock.get(), w.stock.get(), id.stock.get()),
              N_VWSqrSumMaskLocal(x.ours.get(), w.ours.get(), id.ours.get()));

        // Scale-add-multi: Z_j = a_j x + Y_j.
        double a[2] = {0.3, -0.7};
        Pair y2 = random_pair(context, threaded, shaped, random), z2 = random_pair(context, threaded, shaped, random);
        N_Vector stock_ys[2] = {y.stock.get(), y2.stock.get()}, stock_zs[2] = {z.stock.get(), z2.stock.get()};
        N_Vector our_ys[2] = {y.ours.get(), y2.ours.get()}, our_zs[2] = {z.ours.get(), z2.ours.get()};
        N_VScaleAddMulti(2, a, x.stock.get(), stock_ys, stock_zs);
        N_VScaleAddMulti(2, a, x.ours.get(), our_ys, our_zs);
        same_entries(z.stock.get(), z.ours.get());
        same_entries(z2.stock.get(), z2.ours.get());

        // A zero makes the inverse test false, as in SUNDIALS.
        N_VGetArrayPointer(w.stock.get())[17] = N_VGetArrayPointer(w.ours.get())[17] = 0.0;
        BOOST_TEST(N_VInvTest(w.stock.get(), z.stock.get()) == N_VInvTest(w.ours.get(), z.ours.get()));
      }
    }
}

BOOST_AUTO_TEST_CASE(clones_and_wrapped_arrays) {
  sun::Context context;
  std::vector<double> data(kLength, 2.0);
  N_Vector wrapped = sun::wrap_compiled_vector(data.data(), kLength, false, context);
  BOOST_REQUIRE(wrapped != nullptr);
  BOOST_TEST(N_VGetArrayPointer(wrapped) == data.data());  // no copy
  N_VScale(3.0, wrapped, wrapped);
  BOOST_TEST(data[kLength - 1] == 6.0);

  sun::set_shape(wrapped, kLength, 1);
  N_Vector copy = N_VClone(wrapped);
  BOOST_REQUIRE(copy != nullptr);
  BOOST_TEST(sun::shape_of(copy).members == kLength);  // a clone sums as its model
  BOOST_TEST(sun::shape_of(copy).fields == 1);
  BOOST_TEST(N_VGetVectorID(copy) == SUNDIALS_NVEC_CUSTOM);
  BOOST_TEST(N_VGetLength(copy) == kLength);
  BOOST_TEST(N_VGetArrayPointer(copy) != data.data());  // its own storage
  N_VScale(1.0, wrapped, copy);
  BOOST_TEST(N_VGetArrayPointer(copy)[5] == 6.0);
  N_Vector hollow = N_VCloneEmpty(wrapped);
  BOOST_TEST(N_VGetArrayPointer(hollow) == nullptr);
  N_VDestroy(hollow);
  N_VDestroy(copy);
  N_VDestroy(wrapped);  // must not free data
  BOOST_TEST(data[0] == 6.0);

  sunindextype real_words = 0, integer_words = 0;
  N_Vector owned = sun::new_compiled_vector(kLength, true, context);
  N_VSpace(owned, &real_words, &integer_words);
  BOOST_TEST(real_words == kLength);
  N_VDestroy(owned);
}

// A population of kMembers members × kFields fields: 3 blocks of the sums per field (4,096, 4,096
// and 1,808 members), so the (field, block) order differs from both the flat order and the
// threaded flat chunks of 4,096 entries (which straddle fields).
constexpr sunindextype kMembers = 10000;
constexpr int kFields = 3;
constexpr sunindextype kBlock = 4096;  // src/harness/compensated_sum.hpp, kSumBlock

std::vector<double> random_entries(std::size_t count, std::mt19937_64& random) {
  std::uniform_real_distribution<double> value(-2.0, 3.0);
  std::vector<double> entries(count);
  for (double& e : entries) e = value(random);
  return entries;
}

// Members first … first + count − 1 of the column-major population `whole`, column-major.
std::vector<double> slab_of(const std::vector<double>& whole, sunindextype first, sunindextype count) {
  std::vector<double> slab;
  for (int f = 0; f < kFields; ++f)
    slab.insert(slab.end(), whole.begin() + f * kMembers + first, whole.begin() + f * kMembers + first + count);
  return slab;
}

sun::Vector shaped(std::vector<double>& data, sunindextype members, int fields, bool threaded, SUNContext context) {
  sun::Vector v(sun::wrap_compiled_vector(data.data(), members * fields, threaded, context));
  sun::set_shape(v.get(), members, fields);
  return v;
}

BOOST_AUTO_TEST_CASE(shaped_sums_add_field_block_partials_in_order) {
  sun::Context context;
  std::mt19937_64 random(20261127);
  std::vector<double> xs = random_entries(kMembers * kFields, random), ys = random_entries(kMembers * kFields, random);
  double serial_dot = 0.0;
  for (bool threaded : {false, true}) {
    const sun::Vector x = shaped(xs, kMembers, kFields, threaded, context), y = shaped(ys, kMembers, kFields, threaded, context);
    const std::vector<double> partials = sun::partial_sums(sun::VectorSum::dot, x.get(), y.get(), nullptr, true);
    BOOST_REQUIRE(partials.size() == 9u);  // 3 fields × 3 blocks
    // Each partial is its (field, block)'s own one-pass sum: that range as a vector of one block.
    for (int f = 0; f < kFields; ++f)
      for (sunindextype b = 0; b < 3; ++b) {
        const sunindextype first = f * kMembers + b * kBlock, count = std::min(kBlock, kMembers - b * kBlock);
        const sun::Vector xb(sun::wrap_compiled_vector(xs.data() + first, count, false, context));
        const sun::Vector yb(sun::wrap_compiled_vector(ys.data() + first, count, false, context));
        sun::set_shape(xb.get(), count, 1);
        sun::set_shape(yb.get(), count, 1);
        BOOST_TEST(partials[static_cast<std::size_t>(f * 3 + b)] == N_VDotProd(xb.get(), yb.get()));
      }
    // The dot product adds them from 0 in that order.
    double in_order = 0.0;
    for (double p : partials) in_order += p;
    BOOST_TEST(N_VDotProd(x.get(), y.get()) == in_order);
    if (threaded) BOOST_TEST(N_VDotProd(x.get(), y.get()) == serial_dot);  // no bit from the threads
    serial_dot = N_VDotProd(x.get(), y.get());
  }
}

BOOST_AUTO_TEST_CASE(a_population_split_at_a_block_boundary_sums_the_same_bits) {
  sun::Context context;
  std::mt19937_64 random(20261128);
  std::vector<double> xs = random_entries(kMembers * kFields, random), ws = random_entries(kMembers * kFields, random);
  const sun::Vector x = shaped(xs, kMembers, kFields, false, context), w = shaped(ws, kMembers, kFields, false, context);
  // Two "ranks": members 0 … 8191 (2 blocks) and 8192 … 9999 (1 block), as own_members shares 3 blocks over 2.
  std::vector<double> x0 = slab_of(xs, 0, 2 * kBlock), w0 = slab_of(ws, 0, 2 * kBlock);
  std::vector<double> x1 = slab_of(xs, 2 * kBlock, kMembers - 2 * kBlock), w1 = slab_of(ws, 2 * kBlock, kMembers - 2 * kBlock);
  const sun::Vector sx0 = shaped(x0, 2 * kBlock, kFields, true, context), sw0 = shaped(w0, 2 * kBlock, kFields, true, context);
  const sun::Vector sx1 = shaped(x1, kMembers - 2 * kBlock, kFields, false, context);
  const sun::Vector sw1 = shaped(w1, kMembers - 2 * kBlock, kFields, false, context);
  const auto squares = sun::VectorSum::weighted_squares;
  const std::vector<double> p0 = sun::partial_sums(squares, sx0.get(), sw0.get(), nullptr, true);
  const std::vector<double> p1 = sun::partial_sums(squares, sx1.get(), sw1.get(), nullptr, true);
  BOOST_REQUIRE(p0.size() == 6u);
  BOOST_REQUIRE(p1.size() == 3u);
  std::vector<double> ordered;  // field by field, the first slab's blocks, then the second's
  for (int f = 0; f < kFields; ++f) {
    ordered.insert(ordered.end(), p0.begin() + 2 * f, p0.begin() + 2 * f + 2);
    ordered.push_back(p1[static_cast<std::size_t>(f)]);
  }
  BOOST_TEST(sun::ordered_total(ordered) == N_VWSqrSumLocal(x.get(), w.get()));
  // A slab without members gives no partial; one pass over the whole vector gives one.
  std::vector<double> none;
  const sun::Vector empty = shaped(none, 0, kFields, false, context);
  BOOST_TEST(sun::partial_sums(sun::VectorSum::l1, empty.get(), nullptr, nullptr, false).empty());
  BOOST_TEST(sun::partial_sums(sun::VectorSum::l1, x.get(), nullptr, nullptr, false).size() == 1u);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace unit_nvector
