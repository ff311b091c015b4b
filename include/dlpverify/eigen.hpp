// Eigen's Core, included the one way every header of dlpverify includes it.
//
// GCC 12's AVX-512 intrinsic headers give their "undefined" vectors a self-initialisation
// (`__m512d __Y = __Y;` in _mm512_undefined_pd), which -Wmaybe-uninitialized reports in every
// function where Eigen's packet math is inlined (GCC bug 105593): a false positive in a system
// header, shown against our code. The pragma covers those intrinsic headers alone, included here
// before Eigen includes them (their include guards make this the only inclusion); the code that
// inlines them stays checked.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#endif

#include <Eigen/Core>
