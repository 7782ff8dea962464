// Decoder of connectivity method 2, the polygon coder
// (spec/qmc-format.md section 5.4).
#pragma once

#include <cstddef>
#include <cstdint>

#include "decoder/output_budget.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

struct PolygonConnectivityInfo {
  uint8_t coding = 0;
  uint32_t components = 0, virtual_faces = 0, seams = 0, identifications = 0, loose_faces = 0;
};

// Decodes the method data that follows the CONN header fields; the faces of
// symbol 18 are checked at 4 bytes a corner beyond 3 against `budget`, if
// given (8.1).
Status decode_polygon_connectivity(const uint8_t* data, size_t size, uint32_t vertex_count, uint32_t face_count,
                                   Mesh* mesh, PolygonConnectivityInfo* info, const OutputBudget* budget = nullptr);

}  // namespace qmc
