// Lossless plane coding of geometry images (spec/qmc-format.md sections
// 13.5 and 13.6): one plane of W x H
// samples, or the occupancy mask, as a predictor byte and an adaptive binary
// range-coded stream.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "qmc/status.h"

namespace qmc {

enum class GimSampleFormat : uint8_t { kUnorm16 = 0, kFloat32 = 1 };

struct PlaneLayout {
  uint32_t width = 0, height = 0;                 // 1..65535 each, width * height <= 2^26
  const std::vector<uint8_t>* occupied = nullptr;  // width * height bytes (0/1); null: all occupied
  bool blank_stored = true;                        // false: a blank pixel's sample is its prediction
  GimSampleFormat format = GimSampleFormat::kUnorm16;
};

// Samples are u16 values, or binary32 bit patterns, in raster order.
Status decode_plane(const uint8_t* data, size_t size, const PlaneLayout& layout, std::vector<uint32_t>* samples);

// The occupancy mask: width * height bytes of 0 or 1.
Status decode_mask(const uint8_t* data, size_t size, uint32_t width, uint32_t height, std::vector<uint8_t>* occupied);

}  // namespace qmc
