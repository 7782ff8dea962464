// The model shared by the plane encoder and decoder of geometry images
// (spec/qmc-format.md section 13.5):
// the order-preserving float mapping, the pixel predictors with their edge
// rules, the activity context, and the binarisation of a residual over the
// range coder. The binarisation is one template run by both sides, so the
// two cannot drift apart.
#pragma once

#include <algorithm>
#include <cstdint>

#include "common/residual_code.h"

namespace qmc {

// Predictor ids of the plane payload's first byte.
enum PlanePredictor : uint8_t {
  kPredictNone = 0,           // 0
  kPredictLeft = 1,           // a
  kPredictMed = 2,            // LOCO-I median edge detector
  kPredictParallelogram = 3,  // a + b - c
  kPredictQuadratic = 4,      // a + 2b - 2c - bb + cc, exact on quadratic surfaces
};
inline constexpr int kPlanePredictorCount = 5;

// Activity buckets of the context (bit length of the weighted neighbour
// residual magnitudes, capped).
inline constexpr int kPlaneBuckets = 20;
inline constexpr int kPlaneMaxClass = 32;  // magnitude classes 0..32

// binary32 bits <-> an unsigned key in the same order as the values (-NaN
// below -inf, -0 just below +0, +NaN above +inf); a bijection on 32 bits.
inline uint32_t float_bits_to_ordered(uint32_t bits) {
  return (bits & 0x80000000u) ? ~bits : bits ^ 0x80000000u;
}
inline uint32_t ordered_to_float_bits(uint32_t key) {
  return (key & 0x80000000u) ? key ^ 0x80000000u : ~key;
}

// Prediction of pixel (x, y) from the values (already in the ordered domain)
// of earlier pixels of a width-wide raster; `top` = 2^k - 1.
inline uint32_t predict_sample(const uint32_t* v, uint32_t width, uint32_t x, uint32_t y, int predictor,
                               uint32_t top) {
  if (predictor == kPredictNone) return 0;
  const size_t i = size_t(y) * width + x;
  if (x == 0 && y == 0) return (top >> 1) + 1;
  // On the first row and column the quadratic predictor extrapolates
  // linearly along the edge; the others copy the neighbour.
  if (y == 0) {
    if (predictor != kPredictQuadratic || x < 2) return v[i - 1];
    return uint32_t(std::clamp<int64_t>(2 * int64_t(v[i - 1]) - v[i - 2], 0, int64_t(top)));
  }
  if (x == 0) {
    if (predictor != kPredictQuadratic || y < 2) return v[i - width];
    return uint32_t(std::clamp<int64_t>(2 * int64_t(v[i - width]) - v[i - 2 * size_t(width)], 0, int64_t(top)));
  }
  const int64_t a = v[i - 1], b = v[i - width], c = v[i - width - 1];
  switch (predictor) {
    case kPredictLeft:
      return uint32_t(a);
    case kPredictMed:
      if (c >= std::max(a, b)) return uint32_t(std::min(a, b));
      if (c <= std::min(a, b)) return uint32_t(std::max(a, b));
      return uint32_t(a + b - c);
    default:
      break;
  }
  int64_t p = a + b - c;
  if (predictor == kPredictQuadratic && y >= 2) {
    // The parallelogram's error is the mixed second difference, which the
    // row above repeats on a smooth surface.
    const int64_t bb = v[i - 2 * size_t(width)], cc = v[i - 2 * size_t(width) - 1];
    p += b - c - bb + cc;
  }
  return uint32_t(std::clamp<int64_t>(p, 0, int64_t(top)));
}

// Context bucket of a pixel from the residual magnitudes of its left (ma),
// above (mb), above-left (mc) and above-right (md) neighbours; 0 for a
// neighbour outside the image.
inline int plane_bucket(uint32_t ma, uint32_t mb, uint32_t mc, uint32_t md) {
  uint64_t t = 2 * uint64_t(ma) + 2 * uint64_t(mb) + mc + md;
  int len = 0;
  while (t != 0 && len < kPlaneBuckets - 1) {
    ++len;
    t >>= 1;
  }
  return len;
}

// Adaptive probabilities of the residual binarisation, all starting at 1024.
struct PlaneResidualModel {
  uint16_t cls[kPlaneBuckets][kPlaneMaxClass];  // "class > i" per bucket and i
  uint16_t sign[kPlaneBuckets];
  uint16_t mantissa[kPlaneMaxClass + 1][3];  // first bit; second bit after a 0; after a 1
  PlaneResidualModel();
};

inline PlaneResidualModel::PlaneResidualModel() {
  std::fill(&cls[0][0], &cls[0][0] + sizeof(cls) / sizeof(uint16_t), uint16_t(1024));
  std::fill(sign, sign + kPlaneBuckets, uint16_t(1024));
  std::fill(&mantissa[0][0], &mantissa[0][0] + sizeof(mantissa) / sizeof(uint16_t), uint16_t(1024));
}

// A plane's residual (13.5.6). The decoder's magnitude may exceed 2^(k-1)
// on bad input; the caller checks.
template <class Coder>
SignedResidual code_residual(Coder* coder, PlaneResidualModel* m, int bucket, int k, SignedResidual value) {
  return code_class_residual(coder, m->cls[bucket], &m->sign[bucket], m->mantissa, k, value);
}

}  // namespace qmc
