// libFuzzer target: a polygon soup built from the input goes through the
// encoder and back; the decoded faces must match exactly (spec 5.2.1) and
// the encoder must accept every valid soup.
#include <cstddef>
#include <cstdint>

#include "qmc/decoder.h"
#include "qmc/encoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  const uint32_t vertices = uint32_t(data[0]) + 1;
  const int bits = 1 + data[1] % 30;
  qmc::Mesh mesh;
  for (uint32_t v = 0; v < vertices; ++v)
    for (int a = 0; a < 3; ++a) mesh.positions.push_back(float(int(v * 7 + a * 13) % 101) - 50.f);
  for (size_t pos = 2; pos < size;) {
    const uint32_t degree = 3 + data[pos++] % 6;
    if (pos + degree > size) break;
    mesh.face_sizes.push_back(degree);
    for (uint32_t i = 0; i < degree; ++i) mesh.corners.push_back(data[pos++] % vertices);
  }
  qmc::EncodeOptions options;
  options.position_bits = bits;
  std::vector<uint8_t> bytes;
  qmc::EncodeStats stats;
  if (!qmc::encode(mesh, options, &bytes, &stats).ok()) __builtin_trap();
  qmc::DecodedFile file;
  if (!qmc::decode(bytes.data(), bytes.size(), &file).ok()) __builtin_trap();
  if (file.mesh.face_sizes != mesh.face_sizes) __builtin_trap();
  for (size_t k = 0; k < mesh.corners.size(); ++k)
    if (stats.file_vertex[file.mesh.corners[k]] != mesh.corners[k]) __builtin_trap();
  return 0;
}
