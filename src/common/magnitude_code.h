// Magnitude classes (spec/qmc-format.md section 7.4): an integer is sent as a
// Huffman-coded class, its bit length, followed by the bits below its
// leading one sent raw. Small values cost a short code; any 32-bit value
// stays codable with an alphabet of 33 symbols.
#pragma once

#include <cstdint>

#include "common/bit_reader.h"
#include "common/bit_writer.h"

namespace qmc {

inline constexpr uint32_t kMagnitudeClasses = 33;  // classes 0..32

// 0 for v = 0, else the position of the leading one plus one.
inline int magnitude_class(uint32_t v) {
  int c = 0;
  while (v != 0) {
    ++c;
    v >>= 1;
  }
  return c;
}

// The c - 1 bits below the leading one (nothing for classes 0 and 1).
inline void write_magnitude_extra(BitWriter* writer, uint32_t v, int c) {
  if (c >= 2) writer->write_bits(v & ((c - 1 == 32) ? 0xFFFFFFFFu : ((1u << (c - 1)) - 1)), c - 1);
}

inline uint32_t read_magnitude_extra(BitReader* reader, int c) {
  if (c == 0) return 0;
  if (c == 1) return 1;
  return (uint32_t(1) << (c - 1)) | reader->read_bits(c - 1);
}

// Signed values: class of |d|, then (class > 0) a sign bit, 1 = negative,
// then the extra bits. |d| must be below 2^31.
inline void write_signed_extra(BitWriter* writer, int32_t d, int c) {
  if (c == 0) return;
  writer->write_bit(d < 0);
  write_magnitude_extra(writer, uint32_t(d < 0 ? -d : d), c);
}

inline int32_t read_signed_extra(BitReader* reader, int c) {
  if (c == 0) return 0;
  const bool negative = reader->read_bit();
  const int32_t magnitude = int32_t(read_magnitude_extra(reader, c));
  return negative ? -magnitude : magnitude;
}

}  // namespace qmc
