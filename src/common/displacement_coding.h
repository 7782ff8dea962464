// LEVL displacement codes 2 and 4 (spec/qmc-format.md sections 12.7.1 and
// 12.7.2): each edge point's displacement m in -127..127 coded by 13.5.6's
// binarisation over the adaptive range coder, in contexts from the
// displacements already coded at the edge's two ends and from the edge
// before it; code 4's vertex corrections after them. Shared by the encoder
// and the decoder through one template.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "common/residual_code.h"

namespace qmc {

inline constexpr int kDisplacementBuckets = 9;
inline constexpr int kDisplacementClasses = 7;  // |m| <= 127

// The adaptive probabilities of one LEVL payload, all starting at 1024.
struct DisplacementModel {
  uint16_t cls[kDisplacementBuckets][kDisplacementClasses];
  uint16_t sign[5];
  uint16_t mantissa[kDisplacementClasses + 1][3];
  DisplacementModel() {
    std::fill(&cls[0][0], &cls[0][0] + sizeof(cls) / sizeof(uint16_t), uint16_t(1024));
    std::fill(sign, sign + 5, uint16_t(1024));
    std::fill(&mantissa[0][0], &mantissa[0][0] + sizeof(mantissa) / sizeof(uint16_t), uint16_t(1024));
  }
};

// 12.7.1: the context of an edge from the last displacements coded at its
// ends (last_a, last_b) and the displacement of the edge before it.
struct DisplacementContext {
  int bucket = 0, sign = 2;
  DisplacementContext(int last_a, int last_b, int previous) {
    uint32_t t = uint32_t(std::abs(last_a) + std::abs(last_b) + std::abs(previous));
    while (t != 0 && bucket < kDisplacementBuckets - 1) {
      ++bucket;
      t >>= 1;
    }
    sign = 2 + (last_a > 0) - (last_a < 0) + (last_b > 0) - (last_b < 0);
  }
};

// Codes one displacement (the decoder's value argument is ignored).
template <class Coder>
int code_displacement(Coder* coder, DisplacementModel* m, const DisplacementContext& c, int value) {
  const SignedResidual r = code_class_residual(coder, m->cls[c.bucket], &m->sign[c.sign], m->mantissa,
                                               kDisplacementClasses,
                                               SignedResidual{uint32_t(value < 0 ? -value : value), value < 0});
  return r.negative ? -int(r.magnitude) : int(r.magnitude);
}

// 12.7.2: one vertex correction of a level, an offset per axis in units of
// the chunk's correction_step.
struct VertexCorrection {
  uint32_t vertex = 0;
  int32_t offset[3] = {0, 0, 0};
};

inline constexpr int kCorrectionGapClasses = 32;
inline constexpr int kCorrectionBuckets = 16;
inline constexpr int kCorrectionClasses = 16;  // |r| <= 2^15
inline constexpr int32_t kMaxCorrectionOffset = 32767;  // what an encoder writes (-32768 is valid too)

// The probabilities of 12.7.2's corrections, all starting at 1024.
struct CorrectionModel {
  uint16_t gap[kCorrectionGapClasses];
  uint16_t gap_mantissa[kCorrectionGapClasses + 1][3];
  uint16_t offset[kCorrectionBuckets][kCorrectionClasses];
  uint16_t sign[3];
  uint16_t offset_mantissa[kCorrectionClasses + 1][3];
  CorrectionModel() {
    std::fill(gap, gap + kCorrectionGapClasses, uint16_t(1024));
    std::fill(&gap_mantissa[0][0], &gap_mantissa[0][0] + sizeof(gap_mantissa) / sizeof(uint16_t), uint16_t(1024));
    std::fill(&offset[0][0], &offset[0][0] + sizeof(offset) / sizeof(uint16_t), uint16_t(1024));
    std::fill(sign, sign + 3, uint16_t(1024));
    std::fill(&offset_mantissa[0][0], &offset_mantissa[0][0] + sizeof(offset_mantissa) / sizeof(uint16_t),
              uint16_t(1024));
  }
};

// 12.7.2: the gap g >= 0 from the previous corrected vertex, 13.5.6's class
// and bits without a sign.
template <class Coder>
uint32_t code_correction_gap(Coder* coder, CorrectionModel* m, uint32_t gap) {
  const int c = code_magnitude_class(coder, m->gap, kCorrectionGapClasses, gap);
  return c == 0 ? 0 : code_magnitude_bits(coder, m->gap_mantissa, c, gap);
}

// 12.7.2: the bucket of offset `axis` from the previous correction's offsets
// (axis 0) or this one's offset before it.
inline int correction_bucket(const int32_t* previous, const int32_t* offset, int axis) {
  const uint32_t t = axis == 0 ? (uint32_t(std::abs(previous[0])) + uint32_t(std::abs(previous[1])) +
                                  uint32_t(std::abs(previous[2]))) / 4
                               : uint32_t(std::abs(offset[axis - 1]));
  int bits = 0;
  for (uint32_t v = t; v != 0; v >>= 1) ++bits;
  return std::min(bits, kCorrectionBuckets - 1);
}

// 12.7.2: one offset (the decoder's value is ignored); the caller applies
// 13.5.6's overflow rule to what a decoder gets.
template <class Coder>
SignedResidual code_correction_offset(Coder* coder, CorrectionModel* m, int bucket, int axis, int32_t value) {
  return code_class_residual(coder, m->offset[bucket], &m->sign[axis], m->offset_mantissa, kCorrectionClasses,
                             SignedResidual{uint32_t(value < 0 ? -int64_t(value) : int64_t(value)), value < 0});
}

}  // namespace qmc
