// Decoder limits of spec/qmc-format.md section 8.1: the counts an embedder
// caps, and the size of the canonical output (10.2, 12.9, 13.10) charged as
// each chunk is decoded, before memory is reserved for it.
#pragma once

#include <cstdint>
#include <string>

#include "qmc/decoder.h"
#include "qmc/status.h"

namespace qmc {

// kLimitExceeded naming the count and the DecoderLimits field, or kOk.
// Counts whose arrays (up to 64 bytes per element) a size_t can address:
// in 32-bit builds (WebAssembly) a larger count could make an index or a
// size wrap, even under DecoderLimits::unlimited(); in 64-bit builds no
// 32-bit count of the format comes near it.
inline constexpr uint64_t kAddressableCount = uint64_t(SIZE_MAX) / 64;

// limit_exceeded when `count` is above the caller's `limit` (field names it)
// or above kAddressableCount.
Status check_limit(const std::string& what, uint64_t count, uint64_t limit, const char* field);

// 10.2: "QMCMESH1", V, F, q and x per vertex, a degree per face, the corners.
inline uint64_t mesh_output_bytes(uint64_t vertices, uint64_t faces, uint64_t corners) {
  return 16 + 24 * vertices + 4 * faces + 4 * corners;
}
// 12.9: "QMCLOOP1" and K before the base mesh.
inline constexpr uint64_t kLoopOutputHeaderBytes = 12;
// 12.9: one level j >= 1: V_j, F_j, binary64 positions, three corners a face.
inline uint64_t level_output_bytes(uint64_t vertices, uint64_t faces) { return 8 + 24 * vertices + 12 * faces; }
// 13.10 up to the mesh: header, plane headers, occupancy, every plane's samples.
inline uint64_t gim_image_output_bytes(uint64_t pixels, uint64_t planes) {
  return 20 + 17 * planes + pixels + 4 * pixels * planes;
}
// 13.10 from V on: V and F, then per vertex x and its pixel, degrees, corners.
inline uint64_t gim_mesh_output_bytes(uint64_t vertices, uint64_t faces, uint64_t corners) {
  return 8 + 16 * vertices + 4 * faces + 4 * corners;
}
// 10.2's record of one attribute (section 15): tag, name, kind, C, N, the
// values and a value index per corner.
inline uint64_t attribute_output_bytes(uint64_t name_length, uint64_t components, uint64_t values,
                                       uint64_t corners) {
  return 8 + 4 + name_length + 2 + 4 + 4 * values * components + 4 * corners;
}

class OutputBudget {
 public:
  explicit OutputBudget(uint64_t limit) : limit_(limit) {}
  // Adds `bytes` (what `what` will output); kLimitExceeded past the limit.
  Status charge(uint64_t bytes, const std::string& what);
  // Whether `bytes` more would still fit, charging nothing.
  Status check(uint64_t bytes, const std::string& what) const;
  uint64_t used() const { return used_; }
  uint64_t left() const { return limit_ - used_; }

 private:
  uint64_t limit_;
  uint64_t used_ = 0;
};

// 8.1: the corners beyond 3 of the polygon coder's symbol-18 faces (5.4.3,
// 5.4.10), virtual ones included, checked at 4 bytes each against what is
// left of max_output_bytes as soon as each degree is read. Spirale Reversi
// reserves memory for every corner of a face, and CONN's corners are charged
// only once all of them are decoded.
// Without a budget (a component decoded on its own) nothing is checked.
class OtherFaceCorners {
 public:
  explicit OtherFaceCorners(const OutputBudget* budget) : budget_(budget) {}
  // kLimitExceeded when the corners of a face of `degree` (>= 3), with those
  // taken before, are more than is left.
  Status take(uint64_t degree);

 private:
  const OutputBudget* budget_;
  uint64_t corners_ = 0;
};

}  // namespace qmc
