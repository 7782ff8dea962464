// Bit reader of spec/qmc-format.md section 7.1.
#include "common/bit_reader.h"

namespace qmc {

void BitReader::refill() const {
  window_pos_ = pos_ & ~uint64_t(7);
  const uint64_t first = window_pos_ >> 3, size_bytes = size_bits_ >> 3;
  uint64_t w = 0;
  for (uint64_t b = first; b < first + 8; ++b) w = (w << 8) | (b < size_bytes ? data_[b] : 0u);
  window_ = w;
}

uint32_t BitReader::read_exp_golomb() {
  // Section 7.2: at most 31 leading zeros, so value + 1 < 2^32. The 32nd
  // zero is rejected as soon as it is read.
  int zeros = 0;
  while (!read_bit()) {
    if (overrun_) return 0;
    if (++zeros == 32) {
      invalid_ = true;
      return 0;
    }
  }
  const uint64_t v = (uint64_t(1) << zeros) | read_bits(zeros);
  return uint32_t(v - 1);
}

bool BitReader::at_clean_end() const {
  if (overrun_) return false;
  const uint64_t pad = (8 - (pos_ & 7)) & 7;
  if (pos_ + pad != size_bits_) return false;
  return peek_bits(int(pad)) == 0;
}

}  // namespace qmc
