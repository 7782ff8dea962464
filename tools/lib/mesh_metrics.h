// qmc tools: geometric error between an original mesh and what a codec gave
// back, reported in absolute units together with the original's bounding box
// so that callers can normalise (e.g. error / bbox_diagonal).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "qmc/mesh.h"

namespace qmc::tools {

struct ErrorMetrics {
  double max_error = 0, rms_error = 0;
  double max_bbox_side = 0;  // longest side of the original's bounding box
  double bbox_diagonal = 0;  // diagonal of the original's bounding box
  size_t compared = 0;       // number of distances that went into the errors
};

// Decoded vertex i corresponds to original vertex decoded_to_original[i];
// errors are Euclidean distances between corresponding vertices. A mapping of
// the wrong length or with an index out of range cannot be measured, so it
// yields infinite max and rms errors instead of a plausible-looking number.
ErrorMetrics correspondence_error(const qmc::Mesh& original, const qmc::Mesh& decoded,
                                  const std::vector<uint32_t>& decoded_to_original);

// For codecs that reorder, split or drop vertices without saying how (Draco):
// for every original vertex, referenced or not, the distance to the nearest
// decoded vertex. Exact nearest neighbour over a uniform grid, O(n) expected.
// Original vertices with no decoded vertex at all to compare against get an
// infinite error.
ErrorMetrics nearest_vertex_error(const qmc::Mesh& original, const qmc::Mesh& decoded);

}  // namespace qmc::tools
