// The binarisation of a signed residual over the adaptive binary range
// coder (spec/qmc-format.md section 13.5.6), shared by the geometry-image
// planes (13.5) and the predicted positions (14.4). One template runs on
// both sides, so encoder and decoder cannot drift apart.
#pragma once

#include <cstdint>

namespace qmc {

// A residual as sign and magnitude (the caller bounds the magnitude).
struct SignedResidual {
  uint32_t magnitude = 0;
  bool negative = false;
};

// The class c = bit length of a magnitude (0..k), as unary bits "c > i"
// with probabilities cls[i] (spec 13.5.6).
template <class Coder>
int code_magnitude_class(Coder* coder, uint16_t* cls, int k, uint32_t magnitude) {
  int value_class = 0;
  for (uint32_t v = magnitude; v != 0; v >>= 1) ++value_class;
  int c = 0;
  while (c < k && coder->code(value_class > c, &cls[c])) ++c;
  return c;
}

// The c - 1 bits below the leading one of a class-c magnitude (c >= 1), the
// first two adaptive per class (mantissa[c]), the rest at 1/2 (13.5.6).
template <class Coder>
uint32_t code_magnitude_bits(Coder* coder, uint16_t (*mantissa)[3], int c, uint32_t value) {
  uint32_t magnitude = 1;
  for (int j = c - 2; j >= 0; --j) {
    const int bit = int((value >> j) & 1);
    const int position = c - 2 - j;
    int got;
    if (position == 0)
      got = coder->code(bit, &mantissa[c][0]);
    else if (position == 1)
      got = coder->code(bit, &mantissa[c][1 + (magnitude & 1)]);
    else
      got = coder->code_direct(bit);
    magnitude = (magnitude << 1) | uint32_t(got);
  }
  return magnitude;
}

// What follows a residual's class c (13.5.6): for c >= 1 the sign, then the
// bits below the leading one; the residual (0 for c = 0).
template <class Coder>
SignedResidual code_sign_and_bits(Coder* coder, uint16_t* sign, uint16_t (*mantissa)[3], int c, SignedResidual value) {
  SignedResidual out;
  if (c == 0) return out;
  out.negative = coder->code(value.negative, sign) != 0;
  out.magnitude = code_magnitude_bits(coder, mantissa, c, value.magnitude);
  return out;
}

// Codes one residual: its class, then for c >= 1 the sign, then the bits
// below the leading one (spec 13.5.6; section 14.4 uses it with its own
// probabilities). Coder is RangeEncoder (value is coded) or RangeDecoder
// (value is ignored and the decoded residual returned).
template <class Coder>
SignedResidual code_class_residual(Coder* coder, uint16_t* cls, uint16_t* sign, uint16_t (*mantissa)[3], int k,
                                   SignedResidual value) {
  return code_sign_and_bits(coder, sign, mantissa, code_magnitude_class(coder, cls, k, value.magnitude), value);
}

}  // namespace qmc
