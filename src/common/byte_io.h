// Byte-level fields: little-endian integers, IEEE binary32/64 and LEB128
// varints (spec/qmc-format.md section 2.2).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc {

void put_u8(std::vector<uint8_t>* out, uint8_t v);
void put_u32le(std::vector<uint8_t>* out, uint32_t v);
void put_u32be(std::vector<uint8_t>* out, uint32_t v);
void put_f32le(std::vector<uint8_t>* out, float v);
void put_f64le(std::vector<uint8_t>* out, double v);
// Unsigned LEB128, shortest form.
void put_varint(std::vector<uint8_t>* out, uint64_t v);

uint32_t load_u32le(const uint8_t* p);
uint32_t load_u32be(const uint8_t* p);

// Reads fields from a fixed buffer. Every getter returns false (and leaves
// the cursor unchanged) when the field does not fit or is malformed.
class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  bool get_u8(uint8_t* v);
  bool get_u32le(uint32_t* v);
  bool get_f32le(float* v);
  bool get_f64le(double* v);
  // LEB128 of at most 10 bytes; rejects values above 2^64 - 1 and
  // non-shortest encodings (a final byte of 0x00 after the first).
  bool get_varint(uint64_t* v);

  // Moves past n bytes; false if fewer remain.
  bool skip(size_t n) {
    if (n > remaining()) return false;
    pos_ += n;
    return true;
  }

  size_t position() const { return pos_; }
  size_t remaining() const { return size_ - pos_; }
  const uint8_t* cursor() const { return data_ + pos_; }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

}  // namespace qmc
