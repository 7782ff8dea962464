// Bit writer, most-significant bit first (spec/qmc-format.md section 7.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc {

// Appends bits to a byte vector. A capacity limit may be set; a write that
// would pass it is refused and recorded in overflowed() rather than growing.
class BitWriter {
 public:
  explicit BitWriter(size_t capacity_bytes = SIZE_MAX) : capacity_(capacity_bytes) {}

  // Writes the low `count` bits of `value`, count in 0..32.
  void write_bits(uint32_t value, int count);
  void write_bit(bool bit) { write_bits(bit ? 1u : 0u, 1); }
  // Exp-Golomb order 0 (section 7.2): values 0 .. 2^32 - 2.
  void write_exp_golomb(uint32_t value);
  // Zero bits up to the next byte boundary.
  void align_to_byte();

  uint64_t bit_count() const { return bit_count_; }
  bool overflowed() const { return overflowed_; }
  // Pads to a byte boundary and hands over the bytes.
  std::vector<uint8_t> finish();

 private:
  std::vector<uint8_t> bytes_;
  size_t capacity_;
  uint64_t bit_count_ = 0;
  bool overflowed_ = false;
};

}  // namespace qmc
