// CRC-32 as in ISO-HDLC / PNG / zlib: reflected polynomial 0xEDB88320,
// initial value and final XOR 0xFFFFFFFF (spec/qmc-format.md section 3.4).
#pragma once

#include <cstddef>
#include <cstdint>

namespace qmc {

// Continues a running CRC; start with crc = 0.
uint32_t crc32_update(uint32_t crc, const uint8_t* data, size_t size);
inline uint32_t crc32(const uint8_t* data, size_t size) { return crc32_update(0, data, size); }

}  // namespace qmc
