// Chunk framing on the encoder side (spec/qmc-format.md sections 3.1-3.4).
#pragma once

#include <cstdint>
#include <vector>

namespace qmc {

void write_signature(std::vector<uint8_t>* out);
// Appends type, length, payload and the CRC-32 of the three.
void write_chunk(std::vector<uint8_t>* out, uint32_t type, const std::vector<uint8_t>& payload);

}  // namespace qmc
