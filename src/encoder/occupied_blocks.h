// The grid points holding a vertex, kept by blocks of 4 x 4 x 4 points
// with a bit per point, for POSN method 10's plane search (spec 14.11,
// encoder only): whether a vertex is within one step of a point on every
// axis, the 27 points around it, looks at the at most 8 blocks those points
// meet (3.4 on average) instead of 27 points.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "common/mirror_prediction.h"  // GridPointTable

namespace qmc {

class OccupiedBlocks {
 public:
  explicit OccupiedBlocks(const std::vector<uint32_t>& q) : blocks_(uint32_t(q.size() / 3)) {
    for (size_t v = 0; v < q.size() / 3; ++v) {
      const uint32_t* point = &q[3 * v];
      const uint32_t block[3] = {point[0] >> 2, point[1] >> 2, point[2] >> 2};
      uint32_t index = blocks_.insert(block, uint32_t(bits_.size()));
      if (index == GridPointTable::kNone) {
        index = uint32_t(bits_.size());
        bits_.push_back(0);
      }
      bits_[index] |= uint64_t(1) << ((point[0] & 3) | (point[1] & 3) << 2 | (point[2] & 3) << 4);
    }
  }

  // Whether a vertex is at a point within one step of `point` on each
  // axis (coordinates below 2^31).
  bool near(const uint32_t point[3]) const {
    int64_t low[3], high[3];  // the points within a step, per axis
    for (int a = 0; a < 3; ++a) {
      low[a] = std::max<int64_t>(0, int64_t(point[a]) - 1);
      high[a] = int64_t(point[a]) + 1;
    }
    for (int64_t bz = low[2] >> 2; bz <= high[2] >> 2; ++bz)
      for (int64_t by = low[1] >> 2; by <= high[1] >> 2; ++by)
        for (int64_t bx = low[0] >> 2; bx <= high[0] >> 2; ++bx) {
          const uint32_t block[3] = {uint32_t(bx), uint32_t(by), uint32_t(bz)};
          const uint32_t index = blocks_.find(block);
          if (index == GridPointTable::kNone) continue;
          if (bits_[index] & points_within(block, low, high)) return true;
        }
    return false;
  }

 private:
  // The bits of a block's points within low .. high on every axis.
  static uint64_t points_within(const uint32_t block[3], const int64_t low[3], const int64_t high[3]) {
    unsigned along[3];  // per axis, a bit per point of the block within range
    for (int a = 0; a < 3; ++a) {
      const int64_t first = std::max<int64_t>(low[a] - 4 * int64_t(block[a]), 0);
      const int64_t last = std::min<int64_t>(high[a] - 4 * int64_t(block[a]), 3);
      along[a] = ((2u << last) - 1) & ~((1u << first) - 1);
    }
    uint64_t mask = 0;
    for (int z = 0; z < 4; ++z)
      for (int y = 0; y < 4; ++y)
        if ((along[2] >> z & 1) && (along[1] >> y & 1)) mask |= uint64_t(along[0]) << (4 * y + 16 * z);
    return mask;
  }

  GridPointTable blocks_;  // block -> its index in bits_
  std::vector<uint64_t> bits_;
};

}  // namespace qmc
