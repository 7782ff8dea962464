// Unit normals on an octahedral grid, predicted from the decoded positions
// (spec/qmc-format.md section 15.7): the prediction's frame, its grid point,
// the output of a grid point, and the decisions of one value. Shared by the
// encoder and the decoder so the two cannot drift apart.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/exact_arith.h"
#include "common/position_coding.h"
#include "common/residual_code.h"

namespace qmc {

inline constexpr int kOctahedralMinBits = 2, kOctahedralMaxBits = 16;
inline constexpr uint32_t kOctahedralCorners = 16;  // corners of a value that predict it
inline constexpr int kOctahedralBuckets = 8;

// 15.7's frame: axis t goes up, with sign sigma.
struct OctahedralFrame {
  int t = 2;
  int sigma = 1;
};


// The corners of every value, in corner order (m: the value of each corner).
class ValueCorners {
 public:
  void build(const std::vector<uint32_t>& m, size_t value_count) {
    first_.assign(value_count + 1, 0);
    for (uint32_t v : m) ++first_[size_t(v) + 1];
    for (size_t i = 0; i < value_count; ++i) first_[i + 1] += first_[i];
    corners_.resize(m.size());
    std::vector<uint32_t> next(first_.begin(), first_.end() - 1);
    for (size_t k = 0; k < m.size(); ++k) corners_[next[m[k]]++] = uint32_t(k);
  }
  const uint32_t* begin(size_t i) const { return corners_.data() + first_[i]; }
  const uint32_t* end(size_t i) const { return corners_.data() + first_[i + 1]; }

 private:
  std::vector<uint32_t> first_, corners_;
};

// Per corner, the corners after and before it in its face (along +1, -1).
struct CornerCycle {
  std::vector<uint32_t> next, previous;
  void build(const std::vector<uint32_t>& face_sizes, size_t corner_count) {
    next.resize(corner_count);
    previous.resize(corner_count);
    uint64_t start = 0;
    for (uint32_t d : face_sizes) {
      for (uint32_t i = 0; i < d; ++i) {
        next[start + i] = uint32_t(start + (i + 1 == d ? 0 : i + 1));
        previous[start + i] = uint32_t(start + (i == 0 ? d - 1 : i - 1));
      }
      start += d;
    }
  }
};

// 15.7: the sum S of the cross products a x b of the value's corners
// [first, last) (at most 16), a = q[n] - q[c] and b = q[p] - q[c], all shifted
// by the one s that brings every component into 21 bits.
inline void area_weighted_sum(const uint32_t* first, const uint32_t* last, const std::vector<uint32_t>& corners,
                              const CornerCycle& cycle, const uint32_t* q, int64_t sum[3]) {
  int64_t edge[kOctahedralCorners][2][3];  // per corner, a = q[n] - q[c] and b = q[p] - q[c]
  int64_t largest = 0;  // of x >= 0 and -x - 1 < 0: floor(x / 2^s) fits in 21 bits iff largest >> s does
  for (const uint32_t* k = first; k != last; ++k) {
    const uint32_t c = corners[*k], ends[2] = {corners[cycle.next[*k]], corners[cycle.previous[*k]]};
    for (int side = 0; side < 2; ++side)
      for (int a = 0; a < 3; ++a) {
        const int64_t x = int64_t(q[3 * size_t(ends[side]) + a]) - int64_t(q[3 * size_t(c) + a]);
        edge[k - first][side][a] = x;
        largest = std::max(largest, x < 0 ? -x - 1 : x);
      }
  }
  // floor(x / 2^s) in -2^20 .. 2^20 - 1 for the smallest such s
  const int s = largest < (int64_t(1) << 20) ? 0 : bit_length64(uint64_t(largest)) - 20;
  sum[0] = sum[1] = sum[2] = 0;
  for (ptrdiff_t j = 0; j < last - first; ++j) {
    int64_t a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = floor_shift(edge[j][0][i], s);
      b[i] = floor_shift(edge[j][1][i], s);
    }
    sum[0] += a[1] * b[2] - a[2] * b[1];
    sum[1] += a[2] * b[0] - a[0] * b[2];
    sum[2] += a[0] * b[1] - a[1] * b[0];
  }
}

// 15.13: atan(2^-i) in units of pi / 2^16, rounded, i = 0 .. 15.
inline constexpr int64_t kCordicAngle[16] = {16384, 9672, 5110, 2594, 1302, 652, 326, 163,
                                             81,    41,   20,   10,   5,    3,    1,   1};

// 15.13: the angle atan2(y, x) of a vector with y > 0, in units of pi / 2^16
// (0 .. 2^16), by 16 steps of CORDIC in integers; of `count` <= 16 vectors
// at once (x[j], y[j] -> angle[j]), whose independent steps the processor
// can overlap. The vectors are dot products and cross-product lengths of
// two vectors of 15-bit components, x^2 + y^2 <= (3 2^28)^2 (15.13), so
// the steps, which grow a vector by at most 1.65 and their floors by less
// than 40, keep every x and y below 2^31 in magnitude: they run in 32 bits,
// four vectors at a time, which a compiler turns in one 128-bit register.
inline void integer_angles(int count, const int64_t* x_in, const int64_t* y_in, int64_t* angle) {
  static_assert((int32_t(-5) >> 1) == -3, "needs an arithmetic right shift");
  int32_t x[kOctahedralCorners], y[kOctahedralCorners], z[kOctahedralCorners];
  for (int j = 0; j < count; ++j) {
    int64_t xj = x_in[j], yj = y_in[j];
    z[j] = 0;
    if (xj < 0) {  // turn by -pi/2: (x, y) -> (y, -x), both then >= 0
      xj = y_in[j];
      yj = -x_in[j];
      z[j] = int32_t(1) << 15;
    }
    // Doubled until the larger reaches 2^24: by 25 - bitlen at once.
    const int doublings = std::max(0, 25 - bit_length64(uint64_t(std::max(xj, yj))));
    x[j] = int32_t(xj * (int64_t(1) << doublings));
    y[j] = int32_t(yj * (int64_t(1) << doublings));
  }
  // Groups of four, the last one filled with idle vectors (1, 1).
  const int padded = (count + 3) / 4 * 4;
  for (int j = count; j < padded; ++j) x[j] = y[j] = 1, z[j] = 0;
  for (int group = 0; group < padded; group += 4)
    for (int i = 0; i < 16; ++i)
      for (int j = group; j < group + 4; ++j) {
        // Turn towards y = 0: add (dx, -dy, angle) for y > 0, subtract them
        // otherwise; (v ^ flip) - flip is v, or -v when flip is all ones.
        const int32_t dx = y[j] >> i, dy = x[j] >> i;  // floor(y / 2^i), floor(x / 2^i)
        const int32_t flip = -int32_t(y[j] <= 0);
        x[j] += (dx ^ flip) - flip;
        y[j] -= (dy ^ flip) - flip;
        z[j] += (int32_t(kCordicAngle[i]) ^ flip) - flip;
      }
  for (int j = 0; j < count; ++j) angle[j] = z[j];
}

// The same of one vector.
inline int64_t integer_angle(int64_t x, int64_t y) {
  int64_t angle;
  integer_angles(1, &x, &y, &angle);
  return angle;
}

// 15.13: the sum S over the value's corners [first, last) (at most 16) of
// each corner's unit face normal (2^20 long) times its angle: the normal
// that weights every face by its angle at the vertex, as many tools compute
// vertex normals. Each corner's a and b are shifted into 15 bits on their own.
inline void angle_weighted_sum(const uint32_t* first, const uint32_t* last, const std::vector<uint32_t>& corners,
                               const CornerCycle& cycle, const uint32_t* q, int64_t sum[3]) {
  int64_t g[kOctahedralCorners][3], length[kOctahedralCorners], dot[kOctahedralCorners], angle[kOctahedralCorners];
  int count = 0;  // the corners that are not degenerate
  for (const uint32_t* k = first; k != last; ++k) {
    const uint32_t c = corners[*k], n = corners[cycle.next[*k]], p = corners[cycle.previous[*k]];
    int64_t a[3], b[3];
    for (int i = 0; i < 3; ++i) {
      a[i] = int64_t(q[3 * size_t(n) + i]) - int64_t(q[3 * size_t(c) + i]);
      b[i] = int64_t(q[3 * size_t(p) + i]) - int64_t(q[3 * size_t(c) + i]);
    }
    shift_into_15_bits(a, b);
    int64_t* cross = g[count];
    cross[0] = a[1] * b[2] - a[2] * b[1];
    cross[1] = a[2] * b[0] - a[0] * b[2];
    cross[2] = a[0] * b[1] - a[1] * b[0];
    length[count] = integer_sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    if (length[count] == 0) continue;  // a degenerate corner adds nothing
    dot[count++] = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  integer_angles(count, dot, length, angle);
  sum[0] = sum[1] = sum[2] = 0;
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < 3; ++i) sum[i] += floor_div(g[j][i] * (int64_t(1) << 20), length[j]) * angle[j];
}

// 15.7's prediction of a value from the positions q (3 per vertex) at its
// corners [first, last): the frame and the grid point (pu, pv) of M, from
// the sum S of 15.7 (area weights) or, with angle_weighted, of 15.13.
inline void predict_octahedral(const uint32_t* first, const uint32_t* last, const std::vector<uint32_t>& corners,
                               const CornerCycle& cycle, const uint32_t* q, uint32_t m_steps, OctahedralFrame* frame,
                               uint32_t* pu, uint32_t* pv, bool angle_weighted = false) {
  last = first + std::min<ptrdiff_t>(last - first, kOctahedralCorners);
  int64_t sum[3];
  if (angle_weighted)
    angle_weighted_sum(first, last, corners, cycle, q, sum);
  else
    area_weighted_sum(first, last, corners, cycle, q, sum);
  const auto l1 = [&] { return std::abs(sum[0]) + std::abs(sum[1]) + std::abs(sum[2]); };
  while (l1() >= (int64_t(1) << 40))
    for (int64_t& x : sum) x = floor_shift(x, 1);
  const int64_t l = l1();
  *frame = OctahedralFrame{};
  if (l == 0) {
    *pu = *pv = m_steps / 2;
    return;
  }
  int t = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(sum[a]) > std::abs(sum[t])) t = a;
  frame->t = t;
  frame->sigma = sum[t] < 0 ? -1 : 1;
  const int64_t x = sum[(t + 1) % 3], y = sum[(t + 2) % 3], m = m_steps;
  *pu = uint32_t(((x + l) * m + l) / (2 * l));
  *pv = uint32_t(((y + l) * m + l) / (2 * l));
}

// 15.7's output of grid point (gu, gv) of M in `frame`.
inline void octahedral_output(uint32_t gu, uint32_t gv, uint32_t m_steps, OctahedralFrame frame, float out[3]) {
  const double m = double(m_steps);
  const double u = (2.0 * double(gu) - m) / m, v = (2.0 * double(gv) - m) / m;
  const double w = 1.0 - std::fabs(u) - std::fabs(v);
  double x = u, y = v;
  if (w < 0) {
    x = (u < 0 ? -1.0 : 1.0) * (1.0 - std::fabs(v));
    y = (v < 0 ? -1.0 : 1.0) * (1.0 - std::fabs(u));
  }
  const double length = std::sqrt(rounded(rounded(mul(x, x) + mul(y, y)) + mul(w, w)));
  out[(frame.t + 1) % 3] = float(x / length);
  out[(frame.t + 2) % 3] = float(y / length);
  out[frame.t] = float(double(frame.sigma) * w / length);
}

// 15.7's probabilities of one payload, all starting at 1024.
struct OctahedralModel {
  uint16_t cls[2][kOctahedralBuckets][kOctahedralMaxBits];
  uint16_t sign[2];
  uint16_t mantissa[kOctahedralMaxBits + 1][3];
  OctahedralModel() {
    std::fill(&cls[0][0][0], &cls[0][0][0] + sizeof(cls) / sizeof(uint16_t), uint16_t(1024));
    std::fill(sign, sign + 2, uint16_t(1024));
    std::fill(&mantissa[0][0], &mantissa[0][0] + sizeof(mantissa) / sizeof(uint16_t), uint16_t(1024));
  }
};

// 15.7's bucket of a value: the activity |r_u| + |r_v| of the value before.
inline int octahedral_bucket(uint32_t activity) { return std::min(bit_length(activity), kOctahedralBuckets - 1); }

// 15.7's residual of component e (0: u, 1: v) of one value: decoded, or
// `value` coded.
template <class Coder>
SignedResidual code_octahedral_residual(Coder* coder, OctahedralModel* model, int bits, int bucket, int e,
                                        SignedResidual value) {
  return code_class_residual(coder, model->cls[e][bucket], &model->sign[e], model->mantissa, bits, value);
}

}  // namespace qmc
