// Positions of spec/qmc-format.md section 6. The seed (001 §2.6) maps the
// range onto 0..2^n; we use 0..2^n-1 so that every value fits in n bits.
#include "encoder/position_encoder.h"

#include <algorithm>
#include <cmath>

#include "bitio/bit_writer.h"
#include "bitio/byte_io.h"
#include "bitio/huffman.h"
#include "bitio/magnitude_code.h"

namespace qmc {

QuantizedPositions quantize_positions(const std::vector<float>& positions, int bits) {
  QuantizedPositions out;
  out.bits = bits;
  const size_t n = positions.size() / 3;
  for (int a = 0; a < 3; ++a) {
    out.min[a] = n ? positions[a] : 0.f;
    out.max[a] = out.min[a];
  }
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      out.min[a] = std::min(out.min[a], positions[3 * i + a]);
      out.max[a] = std::max(out.max[a], positions[3 * i + a]);
    }
  const double top = double((uint64_t(1) << bits) - 1);
  out.q.resize(positions.size());
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const double range = double(out.max[a]) - double(out.min[a]);
      double v = range > 0 ? std::nearbyint((double(positions[3 * i + a]) - out.min[a]) / range * top) : 0.0;
      out.q[3 * i + a] = uint32_t(std::clamp(v, 0.0, top));
    }
  return out;
}

std::vector<uint8_t> encode_positions(const QuantizedPositions& positions) {
  const size_t n = positions.q.size() / 3;
  std::vector<uint8_t> payload;
  put_varint(&payload, n);
  put_u8(&payload, uint8_t(positions.bits));
  for (int a = 0; a < 3; ++a) put_f32le(&payload, positions.min[a]);
  for (int a = 0; a < 3; ++a) put_f32le(&payload, positions.max[a]);
  if (n == 0) return payload;

  // Deltas from the previous vertex in file order, the first from zero.
  std::vector<int32_t> delta(positions.q.size());
  std::vector<std::vector<uint64_t>> freq(3, std::vector<uint64_t>(positions.bits + 1, 0));
  for (size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const int64_t prev = i ? int64_t(positions.q[3 * (i - 1) + a]) : 0;
      const int32_t d = int32_t(int64_t(positions.q[3 * i + a]) - prev);
      delta[3 * i + a] = d;
      ++freq[a][magnitude_class(uint32_t(d < 0 ? -d : d))];
    }
  BitWriter bits;
  std::vector<HuffmanEncoder> codes;
  for (int a = 0; a < 3; ++a) {
    const std::vector<uint8_t> lengths = huffman_code_lengths(freq[a]);
    write_code_lengths(&bits, lengths);
    codes.emplace_back(lengths);
  }
  for (size_t i = 0; i < 3 * n; ++i) {
    const int32_t d = delta[i];
    const int c = magnitude_class(uint32_t(d < 0 ? -d : d));
    codes[i % 3].write(&bits, uint32_t(c));
    write_signed_extra(&bits, d, c);
  }
  const std::vector<uint8_t> stream = bits.finish();
  payload.insert(payload.end(), stream.begin(), stream.end());
  return payload;
}

}  // namespace qmc
