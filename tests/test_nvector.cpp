// dlpverify's compiled N_Vector (src/sundials/nvector_compiled.hpp) against SUNDIALS' own serial
// vector, operation by operation, on random data (fixed seed): element-wise operations bit for
// bit, reductions to 1e-14 relative (a threaded sum may add in another order); serial and
// threaded variants, clones, and a wrapped array that is neither copied nor freed.
#include <boost/test/unit_test.hpp>

#include <nvector/nvector_serial.h>

#include <cmath>
#include <random>
#include <vector>

#include "sundials/nvector_compiled.hpp"
#include "sundials/sundials_support.hpp"

using namespace dlpverify;

namespace {

constexpr sunindextype kLength = 10007;  // above the threading threshold, not a multiple of a SIMD width

struct Pair {  // the same values in a stock serial vector and in ours
  sun::Vector stock, ours;
};

Pair random_pair(SUNContext context, bool threaded, std::mt19937_64& random, double low = -2.0, double high = 3.0) {
  std::uniform_real_distribution<double> value(low, high);
  Pair p{sun::Vector(N_VNew_Serial(kLength, context)), sun::Vector(sun::new_compiled_vector(kLength, threaded, context))};
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
  for (bool threaded : {false, true}) {
    BOOST_TEST_CONTEXT((threaded ? "threaded" : "serial")) {
      std::mt19937_64 random(20261123);
      Pair x = random_pair(context, threaded, random), y = random_pair(context, threaded, random);
      Pair w = random_pair(context, threaded, random, 0.1, 2.0), z = random_pair(context, threaded, random);
      Pair id = random_pair(context, threaded, random, -1.0, 1.0);
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
      Pair y2 = random_pair(context, threaded, random), z2 = random_pair(context, threaded, random);
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

  N_Vector copy = N_VClone(wrapped);
  BOOST_REQUIRE(copy != nullptr);
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

BOOST_AUTO_TEST_SUITE_END()
