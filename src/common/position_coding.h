// The residuals of predicted positions (spec/qmc-format.md section 14.4):
// contexts from the prediction's kind, the axis and the residual activity
// around the vertex, and their adaptive probabilities. Shared by the
// encoder and the decoder through one template.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "common/exact_arith.h"  // bit_length64
#include "common/mirror_prediction.h"
#include "common/residual_code.h"
#include "common/vertex_prediction.h"

namespace qmc {

inline constexpr int kPositionBuckets = 16;
// 14.4: the class contexts' groups: previous vertex, neighbours, candidates;
// and 14.10's mirror candidate (POSN methods 9 and 10; aTTR coding 9's twin, 15.14).
inline constexpr int kPositionGroups = 4;
inline constexpr int kPositionMaxClass = 30;  // |r| <= top <= 2^30 - 1

// Where the probabilities of "class > j" start (14.4). POSN method 1 and
// aTTR values start them all at 1024. POSN method 3 starts them graded by
// e = j - b + 1 (b the bucket), clamped to -3 .. 3 (14.4.1): the bucket
// estimates the class, so the coder need not learn that first, which a
// small mesh cannot afford (fish_control_mesh's positions at 14 bits: 574
// -> 514 bytes; 35k-vertex meshes within 0.1 %).
enum class ClassStart : uint8_t { kFlat, kGraded };
inline constexpr uint16_t kGradedClassStart[7] = {150, 300, 700, 1200, 1700, 1900, 1950};  // e = -3 .. 3

inline int bit_length(uint32_t v) { return v == 0 ? 0 : bit_length64(v); }

// 14.9: the bits of method 8's features byte; methods 5 - 7 are method 4
// with the features their selector implies (position_features).
inline constexpr uint8_t kQuadTwistFeature = 1, kMaskContextsFeature = 2, kTriangleTwistFeature = 4;
inline uint8_t position_features(bool quad_twist, bool mask_contexts, bool triangle_twist) {
  return uint8_t((quad_twist ? kQuadTwistFeature : 0) | (mask_contexts ? kMaskContextsFeature : 0) |
                 (triangle_twist ? kTriangleTwistFeature : 0));
}

// 14.8 (POSN methods 6 and 7): the decisions "candidate k is selected" take
// one of these contexts, s = min(bitlen(D), 11).
inline constexpr int kMaskContexts = 12;

// Adaptive probabilities of one POSN payload, all starting at 1024.
struct PositionResidualModel {
  uint16_t cls[kPositionGroups][kPositionBuckets][kPositionMaxClass];  // by group, bucket, i
  // POSN method 13 (14.14): the same per axis, each "class > j" coded with
  // the mean of the shared and the axis's probability and adapting both.
  uint16_t axis_cls[3][kPositionGroups][kPositionBuckets][kPositionMaxClass];
  uint16_t sign[3];
  uint16_t mantissa[kPositionMaxClass + 1][3];
  // 14.4: "candidate k is selected", by 14.8's context (0 but in methods 6
  // and 7), count - 2 and k.
  uint16_t use[kMaskContexts][kMaxCandidates - 1][kMaxCandidates];
  uint16_t mirror[kMirrorContexts];  // 14.10: "the mirror candidate is used", by its context
  // POSN method 14 (14.15): the classes of the residuals a lattice codes in
  // steps of k, in tables of their own (LCLS and, as ACLS, LACLS per axis).
  uint16_t lattice_cls[kPositionBuckets][kPositionMaxClass];
  uint16_t lattice_axis_cls[3][kPositionBuckets][kPositionMaxClass];
  int max_class[3];  // bitlen(top_a): k of 13.5.6 per axis
  bool mask_contexts;  // 14.8: methods 6 and 7
  bool axis_classes;   // 14.14: method 13
  explicit PositionResidualModel(const uint32_t top[3], ClassStart start = ClassStart::kFlat,
                                 bool with_mask_contexts = false, bool with_axis_classes = false);
  // 14.15 (method 14): the lattice's tables, starting as CLS does.
  void start_lattice_classes(ClassStart start);
};

// The class probabilities of one group as `start` has them begin (14.4.1),
// computed at compile time: the encoder starts a model for every payload it
// tries, and on a small mesh filling them one by one cost as much as coding.
struct ClassStartTable {
  uint16_t p[kPositionBuckets][kPositionMaxClass];
};
constexpr ClassStartTable class_start_table(ClassStart start) {
  ClassStartTable t{};
  for (int b = 0; b < kPositionBuckets; ++b)
    for (int j = 0; j < kPositionMaxClass; ++j)
      t.p[b][j] = start == ClassStart::kFlat ? 1024 : kGradedClassStart[std::clamp(j - b + 1, -3, 3) + 3];
  return t;
}
inline constexpr ClassStartTable kFlatClassTable = class_start_table(ClassStart::kFlat);
inline constexpr ClassStartTable kGradedClassTable = class_start_table(ClassStart::kGraded);

inline PositionResidualModel::PositionResidualModel(const uint32_t top[3], ClassStart start, bool with_mask_contexts,
                                                    bool with_axis_classes)
    : mask_contexts(with_mask_contexts), axis_classes(with_axis_classes) {
  for (int a = 0; a < 3; ++a) max_class[a] = bit_length(top[a]);
  std::fill(&use[0][0][0], &use[0][0][0] + sizeof(use) / sizeof(uint16_t), uint16_t(1024));
  const ClassStartTable& table = start == ClassStart::kFlat ? kFlatClassTable : kGradedClassTable;
  static_assert(sizeof cls[0] == sizeof table.p, "a group is one ClassStartTable");
  for (auto& group : cls) std::memcpy(group, table.p, sizeof table.p);
  if (axis_classes)
    for (auto& axis : axis_cls)
      for (auto& group : axis) std::memcpy(group, table.p, sizeof table.p);
  std::fill(sign, sign + 3, uint16_t(1024));
  std::fill(mirror, mirror + kMirrorContexts, uint16_t(1024));
  std::fill(&mantissa[0][0], &mantissa[0][0] + sizeof(mantissa) / sizeof(uint16_t), uint16_t(1024));
}

inline void PositionResidualModel::start_lattice_classes(ClassStart start) {
  const ClassStartTable& table = start == ClassStart::kFlat ? kFlatClassTable : kGradedClassTable;
  static_assert(sizeof lattice_cls == sizeof table.p, "the lattice's classes are one ClassStartTable");
  std::memcpy(lattice_cls, table.p, sizeof table.p);
  for (auto& axis : lattice_axis_cls) std::memcpy(axis, table.p, sizeof table.p);
}

// 14.4: the estimate t of axis a's magnitude from an activity estimate t0
// (a sum over three axes) and the magnitudes of the vertex's earlier axes.
inline uint64_t position_estimate(uint64_t t0, const uint32_t* magnitude, int axis) {
  uint64_t t = t0;
  if (axis > 0) {
    uint64_t own = 0;
    for (int b = 0; b < axis; ++b) own += magnitude[b];
    // 3 own / axis, axis being 1 or 2: no division by a variable, which costs tens of cycles.
    t = (t + (axis == 1 ? 3 * own : 3 * own / 2)) / 2;
  }
  return t;
}
inline int estimate_bucket(uint64_t t) { return t == 0 ? 0 : std::min(bit_length64(t), kPositionBuckets - 1); }
inline int position_bucket(uint64_t t0, const uint32_t* magnitude, int axis) {
  return estimate_bucket(position_estimate(t0, magnitude, axis));
}

// 14.8: the context of a vertex's decisions "candidate k is selected" in
// POSN methods 6 and 7, from D, the largest L1 distance between two of its
// candidates in grid units (their 2^-16 units shifted right by 16):
// candidates that agree leave the choice little to change, far apart it
// matters, and the two are selected differently (face.obj's positions 6 %
// smaller with it at 12 bits, beetle's 5 %). 0 in the other methods.
inline int mask_context(const PositionResidualModel& m, const VertexPrediction& p) {
  if (!m.mask_contexts) return 0;
  int64_t spread = 0;  // below 2^53: the candidates are below 2^50 in magnitude
  for (int i = 0; i < p.candidates; ++i)
    for (int j = i + 1; j < p.candidates; ++j) {
      int64_t distance = 0;
      for (int a = 0; a < 3; ++a) {
        const int64_t d = p.candidate[i][a] - p.candidate[j][a];
        distance += d < 0 ? -d : d;
      }
      spread = std::max(spread, distance);
    }
  const uint64_t grid_units = uint64_t(spread) >> 16;
  return grid_units == 0 ? 0 : std::min(bit_length64(grid_units), kMaskContexts - 1);
}

// 14.4: which of the vertex's count candidates its prediction uses. With
// one candidate it is used; with two or more, a bit per candidate, the last
// one implied when no other is used; `context` is 14.8's.
template <class Coder>
unsigned code_candidate_mask(Coder* coder, PositionResidualModel* m, int count, unsigned mask, int context = 0) {
  if (count < 2) return count == 1 ? 1u : 0u;
  unsigned out = 0;
  for (int i = 0; i < count; ++i) {
    if (i == count - 1 && out == 0) return out | 1u << i;
    if (coder->code(int(mask >> i & 1), &m->use[context][count - 2][i])) out |= 1u << i;
  }
  return out;
}

// 14.14: the probability of "class > j" from the shared and the axis's
// estimate, floor((p + p_a + 1) / 2), within 31 .. 2017 as both are.
inline uint32_t mixed_class_probability(uint16_t shared, uint16_t own) {
  return (uint32_t(shared) + own + 1) >> 1;
}

// 13.5.6's unary class of method 13 (14.14): each decision coded with the
// mixed probability, then both estimates adapt to it (coders that only
// price, the encoder's CostMeter, adapt nothing).
template <class Coder>
int code_mixed_class(Coder* coder, uint16_t* shared, uint16_t* own, int k, uint32_t magnitude) {
  const int value_class = bit_length(magnitude);
  int c = 0;
  while (c < k) {
    const int bit = coder->code_fixed(value_class > c, mixed_class_probability(shared[c], own[c]));
    coder->adapt(&shared[c], bit);
    coder->adapt(&own[c], bit);
    if (!bit) break;
    ++c;
  }
  return c;
}

// Codes the residual of one axis, its class bounded by bitlen(top_a) (14.4);
// magnitude holds the earlier axes' |r| in grid steps. With divisor k > 1
// (14.15, POSN method 14: an axis across the lattice) the value coded is the
// residual in steps of k, its estimate divided by k and its classes LCLS's
// (with LACLS's in 14.14's way) instead of the group's. One function for
// both, so that compilers inline it into the decoder's loop.
template <class Coder>
SignedResidual code_position_residual(Coder* coder, PositionResidualModel* m, const VertexPrediction& p,
                                      const uint32_t* magnitude, int axis, SignedResidual value, int divisor = 1) {
  uint64_t t = position_estimate(p.neighbour_activity + p.scale / 8, magnitude, axis);
  if (divisor > 1) t /= uint64_t(divisor);
  const int bucket = estimate_bucket(t);
  uint16_t* shared;
  uint16_t* own;
  if (divisor > 1) {
    shared = m->lattice_cls[bucket];
    own = m->lattice_axis_cls[axis][bucket];
  } else {
    const int group = p.kind == PredictionKind::kMirror ? 3 : p.kind >= PredictionKind::kSingle ? 2 : int(p.kind);
    shared = m->cls[group][bucket];
    own = m->axis_cls[axis][group][bucket];
  }
  if (!m->axis_classes)
    return code_class_residual(coder, shared, &m->sign[axis], m->mantissa, m->max_class[axis], value);
  const int c = code_mixed_class(coder, shared, own, m->max_class[axis], value.magnitude);
  return code_sign_and_bits(coder, &m->sign[axis], m->mantissa, c, value);
}

}  // namespace qmc
