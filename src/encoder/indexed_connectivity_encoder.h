// Indexed connectivity coding, the format's universal fallback
// (spec/qmc-format.md section 5.2).
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/mesh.h"

namespace qmc {

// CONN payload (method 0) for a mesh already in first-reference order
// (encoder/vertex_order.h): every corner's label is at most one above the
// largest label before it.
std::vector<uint8_t> encode_indexed_connectivity(const Mesh& mesh);

}  // namespace qmc
