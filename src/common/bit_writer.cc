// Bit writer of spec/qmc-format.md section 7.1.
#include "common/bit_writer.h"

#include <utility>

namespace qmc {

void BitWriter::write_bits(uint32_t value, int count) {
  if (overflowed_ || count <= 0) return;
  const uint64_t needed_bytes = (bit_count_ + uint64_t(count) + 7) / 8;
  if (needed_bytes > capacity_) {
    overflowed_ = true;
    return;
  }
  for (int i = count - 1; i >= 0; --i) {
    const size_t byte = size_t(bit_count_ >> 3);
    if (byte == bytes_.size()) bytes_.push_back(0);
    if ((value >> i) & 1u) bytes_[byte] |= uint8_t(0x80u >> (bit_count_ & 7));
    ++bit_count_;
  }
}

void BitWriter::write_exp_golomb(uint32_t value) {
  const uint64_t v = uint64_t(value) + 1;
  int length = 0;
  while ((v >> length) > 1) ++length;
  write_bits(0, length);
  // v has length+1 significant bits; at most 33, so write in two parts.
  write_bits(uint32_t(v >> 16), length + 1 > 16 ? length + 1 - 16 : 0);
  write_bits(uint32_t(v & 0xFFFFu), length + 1 > 16 ? 16 : length + 1);
}

void BitWriter::align_to_byte() {
  const int pad = int((8 - (bit_count_ & 7)) & 7);
  write_bits(0, pad);
}

std::vector<uint8_t> BitWriter::finish() {
  align_to_byte();
  return std::move(bytes_);
}

}  // namespace qmc
