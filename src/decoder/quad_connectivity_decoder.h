// Decoder of connectivity method 1, the quad coder of seed 001
// (spec/qmc-format.md section 5.3).
#pragma once

#include <cstddef>
#include <cstdint>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

struct QuadConnectivityInfo {
  bool closed = false;
  uint8_t coding = 0;
};

// Decodes the method data that follows the CONN header fields.
Status decode_quad_connectivity(const uint8_t* data, size_t size, uint32_t vertex_count, uint32_t face_count,
                                Mesh* mesh, QuadConnectivityInfo* info);

}  // namespace qmc
