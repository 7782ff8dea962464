// Adaptive binary range coder (spec/qmc-format.md section 13.5.2).
#include "common/range_coder.h"

#include <utility>

namespace qmc {

// Moves the top byte of the 32-bit low_ out. A byte of 0xFF may still receive
// a carry, so it waits (with the byte before it in cache_) until a byte below
// 0xFF or a carry settles them.
void RangeEncoder::shift_low() {
  if (low_ < 0xFF000000u || low_ > 0xFFFFFFFFu) {
    const uint8_t carry = uint8_t(low_ >> 32);
    if (!cache_is_first_) out_.push_back(uint8_t(cache_ + carry));
    for (; pending_ff_ > 0; --pending_ff_) out_.push_back(uint8_t(0xFF + carry));
    cache_ = uint8_t(low_ >> 24);
    cache_is_first_ = false;
  } else {
    ++pending_ff_;
  }
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

std::vector<uint8_t> RangeEncoder::finish() {
  // Any value in [low, low + range) identifies the stream; take the one with
  // the most trailing zero bytes, which the decoder need not be given.
  const uint64_t end = low_ + range_;
  const uint64_t whole = (low_ + 0xFFFFFFFFu) & ~uint64_t(0xFFFFFFFFu);
  low_ = whole < end ? whole : (low_ + 0xFFFFFFu) & ~uint64_t(0xFFFFFFu);
  for (int i = 0; i < 5; ++i) shift_low();
  for (uint32_t i = 0; i < kRangeMaxInventedBytes && !out_.empty() && out_.back() == 0; ++i) out_.pop_back();
  return std::move(out_);
}

RangeDecoder::RangeDecoder(const uint8_t* data, size_t size) : data_(data), size_(size) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next_byte();
  bad_start_ = code_ == 0xFFFFFFFFu;
}

}  // namespace qmc
