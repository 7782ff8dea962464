// libFuzzer target: a geometry-image plane payload (spec 13.5)
// with an optional occupancy mask payload. Input: width - 1 (6 bits),
// height - 1 (6 bits), flags (bit 0 float32, bit 1 blank pixels stored,
// bit 2 mask present); with a mask, its length as u16le and its bytes; the
// rest is the plane payload. A plane that decodes must survive re-encoding.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/plane_decoder.h"
#include "encoder/plane_encoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  qmc::PlaneLayout layout;
  layout.width = (data[0] & 63u) + 1;
  layout.height = (data[1] & 63u) + 1;
  layout.format = (data[2] & 1) ? qmc::GimSampleFormat::kFloat32 : qmc::GimSampleFormat::kUnorm16;
  layout.blank_stored = (data[2] & 2) != 0;
  size_t pos = 3;
  std::vector<uint8_t> mask;
  if (data[2] & 4) {
    if (size < pos + 2) return 0;
    const size_t length = data[pos] | size_t(data[pos + 1]) << 8;
    pos += 2;
    if (length > size - pos) return 0;
    if (!qmc::decode_mask(data + pos, length, layout.width, layout.height, &mask).ok()) return 0;
    if (mask.size() != size_t(layout.width) * layout.height) __builtin_trap();
    for (uint8_t o : mask)
      if (o > 1) __builtin_trap();
    const std::vector<uint8_t> again = qmc::encode_mask(mask, layout.width, layout.height);
    std::vector<uint8_t> back;
    if (!qmc::decode_mask(again.data(), again.size(), layout.width, layout.height, &back).ok() || back != mask)
      __builtin_trap();
    layout.occupied = &mask;
    pos += length;
  }
  std::vector<uint32_t> samples;
  if (!qmc::decode_plane(data + pos, size - pos, layout, &samples).ok()) return 0;
  if (samples.size() != size_t(layout.width) * layout.height) __builtin_trap();
  const std::vector<uint8_t> again = qmc::encode_plane_with(samples, layout, data[pos]);
  std::vector<uint32_t> back;
  if (!qmc::decode_plane(again.data(), again.size(), layout, &back).ok() || back != samples) __builtin_trap();
  return 0;
}
