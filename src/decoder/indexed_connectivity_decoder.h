// Decoder of the indexed connectivity coding (spec/qmc-format.md section 5.2).
#pragma once

#include <cstddef>
#include <cstdint>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Decodes the bit stream that follows the CONN header fields into
// mesh->face_sizes and mesh->corners.
Status decode_indexed_connectivity(const uint8_t* data, size_t size, uint32_t vertex_count,
                                   uint32_t face_count, Mesh* mesh);

}  // namespace qmc
