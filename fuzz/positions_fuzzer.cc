// libFuzzer target: a POSN payload straight into the position decoder (spec
// section 6); the vertex count it must agree with is taken from the
// payload's own first field. Decoded values must respect their bounds.
#include <cstddef>
#include <cstdint>

#include "bitio/byte_io.h"
#include "decoder/position_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::ByteReader peek(data, size);
  uint64_t count = 0;
  if (!peek.get_varint(&count) || count > UINT32_MAX) return 0;
  qmc::QuantizationInfo info;
  std::vector<uint32_t> q;
  std::vector<float> positions;
  if (!qmc::decode_positions(data, size, uint32_t(count), &info, &q, &positions).ok()) return 0;
  if (q.size() != 3 * count || positions.size() != q.size()) __builtin_trap();
  for (uint32_t v : q)
    if (v > (uint64_t(1) << info.bits) - 1) __builtin_trap();
  return 0;
}
