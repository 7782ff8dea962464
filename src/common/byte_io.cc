// Byte-level fields of spec/qmc-format.md section 2.2.
#include "common/byte_io.h"

#include <cstring>

namespace qmc {

void put_u8(std::vector<uint8_t>* out, uint8_t v) { out->push_back(v); }

void put_u32le(std::vector<uint8_t>* out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out->push_back(uint8_t(v >> (8 * i)));
}

void put_u32be(std::vector<uint8_t>* out, uint32_t v) {
  for (int i = 3; i >= 0; --i) out->push_back(uint8_t(v >> (8 * i)));
}

void put_f32le(std::vector<uint8_t>* out, float v) {
  uint32_t bits;
  std::memcpy(&bits, &v, 4);
  put_u32le(out, bits);
}

void put_f64le(std::vector<uint8_t>* out, double v) {
  uint64_t bits;
  std::memcpy(&bits, &v, 8);
  for (int i = 0; i < 8; ++i) out->push_back(uint8_t(bits >> (8 * i)));
}

void put_varint(std::vector<uint8_t>* out, uint64_t v) {
  while (v >= 0x80) {
    out->push_back(uint8_t(v | 0x80));
    v >>= 7;
  }
  out->push_back(uint8_t(v));
}

uint32_t load_u32le(const uint8_t* p) {
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}

uint32_t load_u32be(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

bool ByteReader::get_u8(uint8_t* v) {
  if (remaining() < 1) return false;
  *v = data_[pos_++];
  return true;
}

bool ByteReader::get_u32le(uint32_t* v) {
  if (remaining() < 4) return false;
  *v = load_u32le(data_ + pos_);
  pos_ += 4;
  return true;
}

bool ByteReader::get_f32le(float* v) {
  uint32_t bits;
  if (!get_u32le(&bits)) return false;
  std::memcpy(v, &bits, 4);
  return true;
}

bool ByteReader::get_f64le(double* v) {
  if (remaining() < 8) return false;
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= uint64_t(data_[pos_ + i]) << (8 * i);
  pos_ += 8;
  std::memcpy(v, &bits, 8);
  return true;
}

bool ByteReader::get_varint(uint64_t* v) {
  uint64_t value = 0;
  for (size_t i = 0; i < 10; ++i) {
    if (pos_ + i >= size_) return false;
    const uint8_t byte = data_[pos_ + i];
    const uint64_t payload = byte & 0x7F;
    // The 10th byte may only contribute the top bit of a 64-bit value.
    if (i == 9 && payload > 1) return false;
    value |= payload << (7 * i);
    if ((byte & 0x80) == 0) {
      if (i > 0 && byte == 0) return false;  // not the shortest form
      *v = value;
      pos_ += i + 1;
      return true;
    }
  }
  return false;
}

}  // namespace qmc
