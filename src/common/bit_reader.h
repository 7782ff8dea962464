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
  uint32_t read_bits(int count) {
    const uint32_t value = peek_bits(count);
    skip_bits(count);
    return value;
  }
  bool read_bit() { return read_bits(1) != 0; }
  // The next `count` (0..32) bits without consuming them.
  uint32_t peek_bits(int count) const {
    if (count <= 0) return 0;
    if (pos_ < window_pos_ || pos_ + uint64_t(count) > window_pos_ + 64) refill();
    return uint32_t((window_ << (pos_ - window_pos_)) >> (64 - count));
  }
  void skip_bits(int count) {
    if (count <= 0) return;
    if (pos_ + uint64_t(count) > size_bits_) {
      overrun_ = true;
      pos_ = size_bits_;
      return;
    }
    pos_ += uint64_t(count);
  }
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
  // Loads the 8 bytes from the byte holding pos_ into the window (bytes past
  // the end read as zero), so that peeks are a shift most of the time.
  void refill() const;

  const uint8_t* data_;
  uint64_t size_bits_;
  uint64_t pos_ = 0;
  mutable uint64_t window_ = 0;      // bits window_pos_ .. window_pos_ + 63, first bit in the top
  mutable uint64_t window_pos_ = 1;  // > pos_: nothing loaded yet
  bool overrun_ = false;
  bool invalid_ = false;
};

}  // namespace qmc
