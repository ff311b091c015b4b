#include "simd/vector_math.hpp"

#include <algorithm>

#if defined(__x86_64__) && (defined(__AVX512F__) || defined(__AVX2__) || defined(__SSE2__))
#include <immintrin.h>
#endif
#include <sleef.h>

namespace dlpverify::simd {

namespace {

// One vector type and its SLEEF routines per instruction set (SLEEF's names carry the ISA).
#if defined(__AVX512F__)
constexpr int kLanes = 8;
constexpr const char* kIsa = "avx512f";
using Vector = __m512d;
inline Vector load(const double* p) { return _mm512_loadu_pd(p); }
inline void store(double* p, Vector v) { _mm512_storeu_pd(p, v); }
inline Vector broadcast(double x) { return _mm512_set1_pd(x); }
inline Vector vector_cbrt(Vector x) { return Sleef_cbrtd8_u10avx512f(x); }
inline Vector vector_pow(Vector x, Vector e) { return Sleef_powd8_u10avx512f(x, e); }
#elif defined(__AVX2__) && defined(__FMA__)
constexpr int kLanes = 4;
constexpr const char* kIsa = "avx2";
using Vector = __m256d;
inline Vector load(const double* p) { return _mm256_loadu_pd(p); }
inline void store(double* p, Vector v) { _mm256_storeu_pd(p, v); }
inline Vector broadcast(double x) { return _mm256_set1_pd(x); }
inline Vector vector_cbrt(Vector x) { return Sleef_cbrtd4_u10avx2(x); }
inline Vector vector_pow(Vector x, Vector e) { return Sleef_powd4_u10avx2(x, e); }
#elif defined(__SSE2__)
constexpr int kLanes = 2;
constexpr const char* kIsa = "sse2";
using Vector = __m128d;
inline Vector load(const double* p) { return _mm_loadu_pd(p); }
inline void store(double* p, Vector v) { _mm_storeu_pd(p, v); }
inline Vector broadcast(double x) { return _mm_set1_pd(x); }
inline Vector vector_cbrt(Vector x) { return Sleef_cbrtd2_u10sse2(x); }
inline Vector vector_pow(Vector x, Vector e) { return Sleef_powd2_u10sse2(x, e); }
#else
constexpr int kLanes = 1;
constexpr const char* kIsa = "scalar";
using Vector = double;
inline Vector load(const double* p) { return *p; }
inline void store(double* p, Vector v) { *p = v; }
inline Vector broadcast(double x) { return x; }
inline Vector vector_cbrt(Vector x) { return Sleef_cbrt_u10(x); }
inline Vector vector_pow(Vector x, Vector e) { return Sleef_pow_u10(x, e); }
#endif

// Applies op to whole vectors of x, then to the tail padded with 1.0 (a value every routine
// takes), so that each element is computed by the same vector code wherever it sits.
template <class Op>
void map(const double* x, double* out, int n, Op op) {
  int i = 0;
  for (; i + kLanes <= n; i += kLanes) store(out + i, op(load(x + i)));
  if (i == n) return;
  double padded[kLanes];
  std::fill_n(padded, kLanes, 1.0);
  std::copy(x + i, x + n, padded);
  store(padded, op(load(padded)));
  std::copy_n(padded, n - i, out + i);
}

}  // namespace

const char* isa() { return kIsa; }
int lanes() { return kLanes; }

void cbrt(const double* x, double* out, int n) {
  map(x, out, n, [](Vector v) { return vector_cbrt(v); });
}

void pow(const double* x, double exponent, double* out, int n) {
  const Vector e = broadcast(exponent);
  map(x, out, n, [e](Vector v) { return vector_pow(v, e); });
}

}  // namespace dlpverify::simd
