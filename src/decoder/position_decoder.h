// Decoder of the POSN chunk (spec/qmc-format.md section 6).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "qmc/decoder.h"
#include "qmc/status.h"

namespace qmc {

// Decodes a POSN payload; `vertex_count` is the count CONN declared.
// Fills quantized (3 per vertex), positions (section 6.4) and the stored
// quantization parameters.
Status decode_positions(const uint8_t* payload, size_t size, uint32_t vertex_count, QuantizationInfo* info,
                        std::vector<uint32_t>* quantized, std::vector<float>* positions);

// Section 6.4: per axis, the binary64 min and step of x = min + q * step.
void dequantization_steps(const QuantizationInfo& info, double lo[3], double step[3]);

}  // namespace qmc
