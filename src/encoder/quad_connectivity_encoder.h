// Connectivity method 1: the interaction types of the traversal coded with
// the cheapest of the codings of seed 001 chapter 4 (spec 5.3.2, 5.3.5).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "encoder/quad_traversal_encoder.h"

namespace qmc {

struct QuadCodingChoice {
  uint8_t coding = 0;
  std::array<int64_t, 5> stream_bits{};  // per coding, -1 where it cannot code the sequence
};

// CONN payload (method 1) for a traversal of a mesh with `vertex_count`
// vertices; reports the size under every coding and the one chosen: the
// smallest, or `forced` (0..4) if it is not -1. Returns an empty payload if
// the forced coding cannot express the sequence.
std::vector<uint8_t> encode_quad_connectivity(const QuadTraversal& traversal, uint32_t vertex_count, int forced,
                                              QuadCodingChoice* choice);

}  // namespace qmc
