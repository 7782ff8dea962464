// What coding decisions and position residuals cost, in bits (spec
// 14.4, 14.5): the information content of each decision under the current
// probabilities, before it adapts them. The encoder compares its candidate
// masks (14.5) by these costs and reports bits per prediction kind.
#pragma once

#include <cmath>
#include <cstdint>

#include "common/position_coding.h"
#include "common/range_coder.h"

namespace qmc {

// A coder for the shared coding templates that codes nothing and adds up
// what each decision would cost.
class CostMeter {
 public:
  int code(int bit, uint16_t* prob) {
    bits += cost(bit, *prob);
    return bit;
  }
  int code_direct(int bit) {
    bits += 1;
    return bit;
  }
  int code_fixed(int bit, uint32_t prob) {
    bits += cost(bit, uint16_t(prob));
    return bit;
  }
  // Prices only: the probabilities stay as they are.
  void adapt(uint16_t*, int) {}
  // The information content of coding `bit` with probability prob of a 0.
  static double cost(int bit, uint16_t prob) { return kCost[bit ? kRangeProbabilityOne - prob : prob]; }
  double bits = 0;

 private:
  struct Table {
    double cost[kRangeProbabilityOne + 1];
    Table() {
      for (int p = 1; p <= kRangeProbabilityOne; ++p) cost[p] = -std::log2(p / double(kRangeProbabilityOne));
      cost[0] = 64;
    }
    double operator[](int p) const { return cost[p]; }
  };
  static inline const Table kCost;
};

// What code_position_residual would cost each residual of one vertex whose
// prediction uses a candidate (14.4's third group), under probabilities that
// do not change while 14.5 compares the vertex's masks: the class decisions
// of a bucket are added up once, on first use and only as far as a class
// asks, so that a residual costs a few lookups instead of one per class
// decision.
class ResidualCosts {
 public:
  explicit ResidualCosts(const PositionResidualModel& model) : m_(model) {}

  // The bits of the residual of `axis` (its magnitude in magnitude[axis],
  // the earlier axes' before it) and sign.
  double axis(const VertexPrediction& p, const uint32_t* magnitude, int axis, bool negative) {
    const int bucket = position_bucket(p.neighbour_activity + p.scale / 8, magnitude, axis);
    const uint32_t value = magnitude[axis];
    const int c = bit_length(value);
    double bits = class_bits(axis, bucket, c, m_.max_class[axis]);
    if (c == 0) return bits;
    bits += CostMeter::cost(negative, m_.sign[axis]);
    if (c >= 2) {
      const int first = int(value >> (c - 2) & 1);
      bits += CostMeter::cost(first, m_.mantissa[c][0]);
      if (c >= 3) bits += CostMeter::cost(int(value >> (c - 3) & 1), m_.mantissa[c][1 + first]) + double(c - 3);
    }
    return bits;
  }

 private:
  static constexpr int kGroup = 2;  // 14.4: a prediction from candidates

  // The bits of the class decisions that code class c <= k (13.5.6's unary
  // "c > i" for i < c, then "c > c" unless c is k, the axis's largest). The
  // decisions "c > i" do not depend on k, so the axes share their sums,
  // unless method 13's probabilities differ per axis (14.14).
  double class_bits(int axis, int bucket, int c, int k) {
    const int a = m_.axis_classes ? axis : 0;
    double* above = above_[a][bucket];  // above[c]: the "c > i" decisions of every i below c
    const uint16_t* cls = m_.cls[kGroup][bucket];
    const uint16_t* own = m_.axis_cls[a][kGroup][bucket];
    const auto p = [&](int i) {
      return m_.axis_classes ? uint16_t(mixed_class_probability(cls[i], own[i])) : cls[i];
    };
    for (int& built = built_[a][bucket]; built <= c; ++built)
      above[built] = built == 0 ? 0 : above[built - 1] + CostMeter::cost(1, p(built - 1));
    return c < k ? above[c] + CostMeter::cost(0, p(c)) : above[c];
  }

  const PositionResidualModel& m_;
  int built_[3][kPositionBuckets] = {};  // entries of above_[axis][bucket] computed (axis 0 but in method 13)
  double above_[3][kPositionBuckets][kPositionMaxClass + 1];
};

}  // namespace qmc
