// The signed integers of GFAC (spec/qmc-format.md section 13.8): a zero flag,
// a sign, an adaptive unary exponent and adaptive mantissa bits on the range
// coder of section 13.5. Triangle corners of a topology-preserving image
// (seed 002) sit a few pixels from each other, so the values are small and
// the zero flag and the first exponent bits carry most of the information.
#pragma once

#include <cstdint>

#include "common/range_coder.h"

namespace qmc {

inline constexpr int kGimFaceExponentLimit = 18;  // e = 18 is bad_symbol
inline constexpr int kGimFaceContextSets = 6;     // dx0 dy0 dx1 dy1 dx2 dy2

struct GimSignedContexts {
  uint16_t zero = kRangeProbabilityInit, sign = kRangeProbabilityInit;
  uint16_t exponent[kGimFaceExponentLimit];
  uint16_t mantissa[kGimFaceExponentLimit];
  GimSignedContexts() {
    for (int i = 0; i < kGimFaceExponentLimit; ++i) exponent[i] = mantissa[i] = kRangeProbabilityInit;
  }
};

// |value| < 2^18.
inline void encode_gim_signed(RangeEncoder* rc, GimSignedContexts* c, int32_t value) {
  if (rc->code(value != 0, &c->zero) == 0) return;
  rc->code(value < 0, &c->sign);
  const uint32_t m = uint32_t(value < 0 ? -int64_t(value) : value);
  int e = 0;
  while ((m >> (e + 1)) != 0) rc->code(1, &c->exponent[e++]);
  rc->code(0, &c->exponent[e]);
  for (int i = e - 1; i >= 0; --i) rc->code(int(m >> i) & 1, &c->mantissa[i]);
}

// False when the exponent reaches kGimFaceExponentLimit (bad_symbol).
inline bool decode_gim_signed(RangeDecoder* rc, GimSignedContexts* c, int32_t* value) {
  if (rc->code(0, &c->zero) == 0) {
    *value = 0;
    return true;
  }
  const int negative = rc->code(0, &c->sign);
  int e = 0;
  while (rc->code(0, &c->exponent[e]) == 1)
    if (++e == kGimFaceExponentLimit) return false;
  int32_t m = 1;
  for (int i = e - 1; i >= 0; --i) m = 2 * m + rc->code(0, &c->mantissa[i]);
  *value = negative ? -m : m;
  return true;
}

}  // namespace qmc
