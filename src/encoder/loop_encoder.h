// The progressive encoder (spec/qmc-format.md section 12.10; seed 003
// fig. 1, steps I-VII): simplify, fit, subdivide, displace, inverse Loop,
// then code the base mesh and each level in a closed loop.
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/encoder.h"

namespace qmc {

// Called by encode() when options.progressive_levels > 0, after the common
// input checks. The mesh must be a triangle mesh with a face of some area
// (anything else is an error naming the problem); where it is not manifold
// or not consistently oriented it is cut first (geometry/manifold_cut.h).
Status encode_loop_levels(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out,
                          EncodeStats* stats);

}  // namespace qmc
