// LEVL displacement code 2 (spec/qmc-format.md section 12.7.1): each edge
// point's displacement m in -127..127 coded by 13.5.6's binarisation over the
// adaptive range coder, in contexts from the displacements already coded at
// the edge's two ends and from the edge before it. Shared by the encoder and
// the decoder through one template.
#pragma once

#include <algorithm>
#include <cstdint>

#include "bitio/residual_code.h"

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

}  // namespace qmc
