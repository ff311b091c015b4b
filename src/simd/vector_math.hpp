// Vector math over arrays: cube roots and powers in SIMD lanes, for right-hand sides whose
// block loops vectorise everything but these (the compiler vectorises +, ×, ÷ and, with
// -fno-math-errno, sqrt — all exactly rounded — but leaves pow and cbrt as scalar libm calls).
//
// SLEEF's 1-ulp functions (libsleef) at the widest vectors this build targets: AVX-512F, AVX2 or
// SSE2, chosen at compile time (the build uses -march=native unless DLPVERIFY_NATIVE=OFF). Every
// element, the tail too, goes through the same vector routine (the tail padded), so a value's
// result never depends on where it sits in the array: results are independent of block size and
// thread count. Accuracy against libm is measured in unit.vector_math (≤ 2 ulp).
#pragma once

namespace dlpverify::simd {

// The instruction set the vector routines use: "avx512f", "avx2", "sse2" or "scalar".
const char* isa();
// Doubles per vector of that instruction set.
int lanes();

// out[i] = ∛x[i] for i < n. out may be x.
void cbrt(const double* x, double* out, int n);
// out[i] = x[i]^exponent for i < n. out may be x.
void pow(const double* x, double exponent, double* out, int n);

}  // namespace dlpverify::simd
