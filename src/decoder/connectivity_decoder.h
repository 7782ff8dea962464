// The CONN chunk (spec/qmc-format.md section 5): header, then the method.
#pragma once

#include <cstddef>
#include <cstdint>

#include "decoder/output_budget.h"
#include "qmc/format.h"
#include "qmc/mesh.h"
#include "decoder/polygon_connectivity_decoder.h"
#include "decoder/quad_connectivity_decoder.h"
#include "qmc/status.h"

namespace qmc {

// Section 5.1: the method and the counts, checked in that section's order.
// `method_data` receives the offset of the method data.
Status read_connectivity_header(const uint8_t* payload, size_t size, uint8_t* method, uint64_t* vertex_count,
                                uint64_t* face_count, size_t* method_data);

// Decodes a CONN payload into mesh->face_sizes / mesh->corners. For method
// 1, `quad` (if given) receives the flags and coding; for method 2,
// `polygon` its coding and record counts. `budget` (if given): the output
// charged so far, against which method 2's faces of symbol 18 are checked (8.1).
Status decode_connectivity(const uint8_t* payload, size_t size, uint32_t* vertex_count,
                           ConnectivityMethod* method, Mesh* mesh, QuadConnectivityInfo* quad = nullptr,
                           PolygonConnectivityInfo* polygon = nullptr, const OutputBudget* budget = nullptr);

}  // namespace qmc
