// Binary64 arithmetic that stays exact under any compiler flags an embedder
// builds the decoder with (spec 6.4, 12.4-12.7, 13.2, 13.9: one rounding per
// operation, no fused multiply-add, no extended precision).
//
// A build flag such as -ffp-contract=off holds only in our own CMake build;
// GCC ignores `#pragma STDC FP_CONTRACT`, and clang's -ffp-contract=fast
// fuses in the back end whatever the pragmas say. So every product the spec
// defines goes through mul(), whose result the compiler must treat as an
// opaque, already rounded value: it cannot fuse it into a following addition.
// What no barrier can repair (-ffast-math, x87 extended precision) stops the
// build instead.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>

#if defined(__FAST_MATH__)
#error "qmc's decoder needs IEEE 754 arithmetic (spec 6.4): build it without -ffast-math"
#endif
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0 && FLT_EVAL_METHOD != -1
#error "qmc's decoder needs binary64 evaluation (spec 6.4): on 32-bit x86 build it with -msse2 -mfpmath=sse"
#endif
#if defined(_MSC_VER) && !defined(__clang__)
#pragma fp_contract(off)
#pragma float_control(precise, on)
#endif

namespace qmc {

// x, as a value the optimizer knows nothing about: the product or sum that
// made it has been rounded to binary64 and cannot be fused with what follows.
inline double rounded(double x) {
#if defined(__wasm__)
  // WebAssembly's base instruction set has no fused multiply-add.
#elif (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || (defined(__i386__) && defined(__SSE2__)))
  __asm__("" : "+x"(x));
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__aarch64__)
  __asm__("" : "+w"(x));
#elif defined(__GNUC__) || defined(__clang__)
  __asm__("" : "+m"(x));
#else
  volatile double opaque = x;
  x = opaque;
#endif
  return x;
}

// a * b rounded once to binary64, never fused into an addition.
inline double mul(double a, double b) { return rounded(a * b); }

// floor(x / 2^s) for any sign (spec 15.7, 15.12, 15.13): the arithmetic
// right shift, which C++20 defines and which every C++17 compiler this builds
// with implements (checked here, so that one which did not would not build).
static_assert((int64_t(-5) >> 1) == -3 && (int64_t(-1) >> 40) == -1, "needs an arithmetic right shift");
inline int64_t floor_shift(int64_t x, int s) { return x >> s; }

// The number of bits of x > 0 (floor(log2 x) + 1); bit_length (position_coding.h) takes 0 too.
inline int bit_length64(uint64_t x) {
#if defined(__GNUC__) || defined(__clang__)
  return 64 - __builtin_clzll(x);
#else
  int n = 0;
  for (; x != 0; x >>= 1) ++n;
  return n;
#endif
}

// floor(n / d) for any sign of n, d > 0 (spec 14.3.3, 15.12, 15.13).
inline int64_t floor_div(int64_t n, int64_t d) {
  const int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

// Spec 15.12 and 15.13: the six components of a and b shifted right (floor
// division by 2^s) by the smallest s that brings them all into
// -2^14 .. 2^14 - 1, so that products of three of them fit in 64 bits.
inline void shift_into_15_bits(int64_t a[3], int64_t b[3]) {
  int64_t largest = 0;  // of x >= 0 and -x - 1 < 0: floor(x / 2^s) fits iff largest >> s does
  for (int i = 0; i < 3; ++i)
    for (const int64_t x : {a[i], b[i]}) largest = std::max(largest, x < 0 ? -x - 1 : x);
  const int s = largest < (int64_t(1) << 14) ? 0 : bit_length64(uint64_t(largest)) - 14;
  for (int i = 0; i < 3; ++i) {
    a[i] = floor_shift(a[i], s);
    b[i] = floor_shift(b[i], s);
  }
}

// The largest r with r r <= x, for 0 <= x < 2^62 (spec 15.12, 15.13). The
// correction makes it exact whatever the floating-point square root returns.
inline int64_t integer_sqrt(int64_t x) {
  int64_t r = int64_t(std::sqrt(double(x)));
  while (r > 0 && r * r > x) --r;
  while ((r + 1) * (r + 1) <= x) ++r;
  return r;
}

}  // namespace qmc
