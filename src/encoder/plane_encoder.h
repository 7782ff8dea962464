// Encoder of the geometry-image plane and mask payloads (spec/qmc-format.md
// sections 13.5 and 13.6). It codes the plane with every predictor and keeps
// the shortest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/plane_decoder.h"

namespace qmc {

struct PlaneEncodeStats {
  int predictor = 0;                  // the one kept
  size_t bytes = 0;                   // payload size
  std::vector<size_t> bytes_per_predictor;  // payload size with each predictor id
};

// `samples`: width * height u16 values (format kUnorm16, each <= 65535) or
// binary32 bit patterns (kFloat32). With blank_stored false the samples of
// blank pixels are ignored: the decoder sets them to their predictions.
std::vector<uint8_t> encode_plane(const std::vector<uint32_t>& samples, const PlaneLayout& layout,
                                  PlaneEncodeStats* stats = nullptr);

// The plane payload with a given predictor id (0..4).
std::vector<uint8_t> encode_plane_with(const std::vector<uint32_t>& samples, const PlaneLayout& layout,
                                       int predictor);

// `occupied`: width * height bytes, 0 blank, anything else occupied.
std::vector<uint8_t> encode_mask(const std::vector<uint8_t>& occupied, uint32_t width, uint32_t height);

}  // namespace qmc
