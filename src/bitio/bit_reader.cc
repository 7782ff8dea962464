// Bit reader of spec/qmc-format.md section 7.1.
#include "bitio/bit_reader.h"

namespace qmc {

uint32_t BitReader::peek_bits(int count) const {
  if (count <= 0) return 0;
  // Gather the (at most 5) bytes covering the request; bytes past the end read as zero.
  const uint64_t first = pos_ >> 3;
  const uint64_t last = (pos_ + uint64_t(count) - 1) >> 3;
  const uint64_t size_bytes = size_bits_ >> 3;
  uint64_t acc = 0;
  for (uint64_t b = first; b <= last; ++b) acc = (acc << 8) | (b < size_bytes ? data_[b] : 0u);
  const int drop = int(((last + 1) * 8) - (pos_ + uint64_t(count)));
  const uint64_t mask = (count == 32) ? 0xFFFFFFFFull : ((1ull << count) - 1);
  return uint32_t((acc >> drop) & mask);
}

uint32_t BitReader::read_bits(int count) {
  if (count <= 0) return 0;
  const uint32_t value = peek_bits(count);
  if (pos_ + uint64_t(count) <= size_bits_) {
    pos_ += uint64_t(count);
  } else {
    overrun_ = true;
    pos_ = size_bits_;
  }
  return value;
}

void BitReader::skip_bits(int count) {
  if (count <= 0) return;
  if (pos_ + uint64_t(count) > size_bits_) {
    overrun_ = true;
    pos_ = size_bits_;
    return;
  }
  pos_ += uint64_t(count);
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
