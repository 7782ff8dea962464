// Spirale Reversi decoding of quad connectivity: seed 001 §3.3 (Program 2),
// after Isenburg and Snoeyink. Interaction types are replayed last to first,
// growing the decoded part outward (spec/qmc-format.md section 5.3.6).
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Rebuilds the quads of `types` (compression order, values 1..13). Fills
// mesh->face_sizes and mesh->corners with file labels (section 5.3.4);
// `vertex_count` bounds the labels.
Status spirale_reversi_decode(const std::vector<uint8_t>& types, bool closed, uint32_t vertex_count, Mesh* mesh);

}  // namespace qmc
