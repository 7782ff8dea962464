// Bit reader, most-significant bit first (spec/qmc-format.md section 7.1).
#pragma once

#include <cstddef>
#include <cstdint>

namespace qmc {

// Reads bits from a fixed buffer and never touches memory outside it. A read
// past the end returns zero bits and sets the sticky overrun() flag, so a
// decoder can run a bounded loop and check once where it is convenient;
// peek() past the end sees zero bits without setting the flag.
class BitReader {
 public:
  BitReader(const uint8_t* data, size_t size) : data_(data), size_bits_(uint64_t(size) * 8) {}

  // count in 0..32.
  uint32_t read_bits(int count);
  bool read_bit() { return read_bits(1) != 0; }
  // The next `count` (0..32) bits without consuming them.
  uint32_t peek_bits(int count) const;
  void skip_bits(int count);
  // Exp-Golomb order 0 (section 7.2). A prefix of 32 zeros is invalid:
  // sets invalid() and returns 0.
  uint32_t read_exp_golomb();

  uint64_t position() const { return pos_; }
  uint64_t bits_remaining() const { return pos_ >= size_bits_ ? 0 : size_bits_ - pos_; }
  bool overrun() const { return overrun_; }
  bool invalid() const { return invalid_; }
  // Section 7.1: the bits after the last field up to the byte boundary are
  // zero and no whole byte follows.
  bool at_clean_end() const;

 private:
  const uint8_t* data_;
  uint64_t size_bits_;
  uint64_t pos_ = 0;
  bool overrun_ = false;
  bool invalid_ = false;
};

}  // namespace qmc
