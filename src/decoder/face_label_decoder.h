// Decoder of the fLBL chunk (spec/qmc-format.md section 16): a label per
// face from a table of strings, in coder order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/output_budget.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Decodes an fLBL payload for CONN's face_count faces; `earlier` holds the
// labels decoded before (names must differ). Charges 16.3's output to the
// budget before reserving the labels.
Status decode_face_labels(const uint8_t* payload, size_t size, uint64_t face_count,
                          const std::vector<FaceLabels>& earlier, OutputBudget* budget, FaceLabels* out);

// 16.3's canonical record of one chunk's output.
uint64_t face_label_output_bytes(const FaceLabels& labels);

}  // namespace qmc
