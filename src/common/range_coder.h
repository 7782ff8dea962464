// Adaptive binary range coder of the geometry-image planes (spec/qmc-format.md
// section 13.5.2): LZMA-style, a 32-bit range,
// 11-bit probabilities of a 0 bit adapting by a shift of 5, carries resolved
// through a cache byte and a count of pending 0xFF bytes. Unlike LZMA the
// always-zero first byte is not written, and the flush writes only as many
// bytes as it must: the decoder reads missing bytes as zero.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc {

inline constexpr int kRangeProbabilityBits = 11;
inline constexpr uint16_t kRangeProbabilityOne = 1 << kRangeProbabilityBits;  // 2048
inline constexpr uint16_t kRangeProbabilityInit = kRangeProbabilityOne / 2;  // 1024
inline constexpr int kRangeAdaptShift = 5;
inline constexpr uint32_t kRangeTop = 1u << 24;  // renormalize below this range
// Bytes past the end of the data that a decoder may read as zero (the ones
// the encoder's flush leaves out); one more is `truncated`.
inline constexpr uint32_t kRangeMaxInventedBytes = 4;

// Sections 12.7.1 and 14.1: a stream of L bytes justifies at most
// 512 (L + 8) coded items. Every decision costs more than 1/46 bit (the
// probabilities stay within 31 .. 2017 of 2048), so fewer decisions than
// that fit; items that may cost no decision at all are held to the same bound.
inline bool range_stream_justifies(uint64_t items, uint64_t stream_bytes) {
  return items <= 512 * (stream_bytes + 8);
}

// Probability update after coding `bit` with probability *prob of a 0.
inline void range_adapt(uint16_t* prob, int bit) {
  if (bit == 0)
    *prob = uint16_t(*prob + ((kRangeProbabilityOne - *prob) >> kRangeAdaptShift));
  else
    *prob = uint16_t(*prob - (*prob >> kRangeAdaptShift));
}

class RangeEncoder {
 public:
  // Codes `bit` (0/1) with *prob and adapts it; returns the bit.
  int code(int bit, uint16_t* prob) {
    encode(bit, *prob);
    range_adapt(prob, bit);
    return bit;
  }
  // A bit of fixed probability 1/2 (probability 1024, never adapted).
  int code_direct(int bit) {
    encode(bit, kRangeProbabilityInit);
    return bit;
  }
  // A bit of probability `prob` (1 .. 2047) of a 0, which the caller adapts.
  int code_fixed(int bit, uint32_t prob) {
    encode(bit, prob);
    return bit;
  }
  // Adapts *prob to a decision coded with code_fixed (14.14).
  void adapt(uint16_t* prob, int bit) { range_adapt(prob, bit); }
  // The encoder never runs out of stream (the decoder's check, for templates
  // shared by both).
  bool overrun() const { return false; }
  // Ends the stream and returns its bytes; the encoder is spent afterwards.
  std::vector<uint8_t> finish();

 private:
  // Section 13.5.2's encode(p); inline, as it runs once per decision.
  void encode(int bit, uint32_t prob) {
    const uint32_t bound = (range_ >> kRangeProbabilityBits) * prob;
    if (bit == 0) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    while (range_ < kRangeTop) {
      range_ <<= 8;
      shift_low();
    }
  }
  void shift_low();

  uint64_t low_ = 0;  // 33 bits: bit 32 is a carry into bytes not yet written
  uint32_t range_ = 0xFFFFFFFFu;
  uint8_t cache_ = 0;          // the last byte cut from low_, not yet written
  uint64_t pending_ff_ = 0;    // 0xFF bytes after cache_, also not yet written
  bool cache_is_first_ = true; // cache_ holds LZMA's leading zero, never written
  std::vector<uint8_t> out_;
};

class RangeDecoder {
 public:
  RangeDecoder(const uint8_t* data, size_t size);
  int code(int /*encoder's bit, unused*/, uint16_t* prob) {
    const int bit = decode(*prob);
    range_adapt(prob, bit);
    return bit;
  }
  int code_direct(int /*unused*/) { return decode(kRangeProbabilityInit); }
  void adapt(uint16_t* prob, int bit) { range_adapt(prob, bit); }
  int code_fixed(int /*unused*/, uint32_t prob) { return decode(prob); }

  // The first four bytes form 0xFFFFFFFF, a value no encoder writes.
  bool bad_start() const { return bad_start_; }
  // More than kRangeMaxInventedBytes bytes past the end were read.
  bool overrun() const { return invented_ > kRangeMaxInventedBytes; }
  // Bytes of the data never read (non-zero: trailing data). A stream with
  // no decision decoded needs no byte at all (13.5.2: its canonical form is
  // empty), so then every byte of it counts as unread.
  size_t unread() const {
    if (!decided_) return size_;
    return consumed_ >= size_ ? 0 : size_ - consumed_;
  }
  uint64_t invented() const { return invented_; }

 private:
  // Section 13.5.2's decode(p); inline, as it runs once per decision.
  int decode(uint32_t prob) {
    decided_ = true;
    const uint32_t bound = (range_ >> kRangeProbabilityBits) * prob;
    int bit;
    if (code_ < bound) {
      range_ = bound;
      bit = 0;
    } else {
      code_ -= bound;
      range_ -= bound;
      bit = 1;
    }
    while (range_ < kRangeTop) {
      range_ <<= 8;
      code_ = (code_ << 8) | next_byte();
    }
    return bit;
  }
  uint8_t next_byte() {
    if (consumed_ < size_) return data_[consumed_++];
    ++consumed_;
    ++invented_;
    return 0;
  }

  const uint8_t* data_;
  size_t size_;
  size_t consumed_ = 0;
  uint64_t invented_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
  uint32_t code_ = 0;
  bool bad_start_ = false;
  bool decided_ = false;  // some decision was decoded
};

}  // namespace qmc
