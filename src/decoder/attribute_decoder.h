// Decoder of the aTTR chunk (spec/qmc-format.md section 15): one attribute
// of the mesh's corners, in coder order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/output_budget.h"
#include "qmc/decoder.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Decodes an aTTR payload against `faces` (CONN's faces in coder order,
// vertex_count vertices). `earlier` holds the names of the aTTR chunks
// before, skipped ones included (15.1 check 2: names must differ); out->name
// is set even when the chunk is skipped. Sets *skipped, and leaves *out empty, for a mapping
// or coding this revision does not define (15.1); charges the output to
// the budget before reserving it.
// *coding says how it was coded (mapping 0's values move with the vertices
// when oRDR is applied).
// `quantized` holds POSN's integers in coder order (3 per vertex), from
// which coding 3 predicts normals (15.7).
Status decode_attribute(const uint8_t* payload, size_t size, const Mesh& faces, uint32_t vertex_count,
                        const std::vector<uint32_t>& quantized, const std::vector<std::string>& earlier,
                        OutputBudget* budget, MeshAttribute* out, AttributeCoding* coding, bool* skipped);

}  // namespace qmc
