// The canonical serialization of a decoded mesh (spec/qmc-format.md section
// 10.2), hashed by the conformance manifest.
#include <cstring>

#include "bitio/byte_io.h"
#include "qmc/decoder.h"

namespace qmc {

std::vector<uint8_t> canonical_output(const DecodedFile& file) {
  const Mesh& mesh = file.mesh;
  static const uint8_t kTag[8] = {'Q', 'M', 'C', 'M', 'E', 'S', 'H', '1'};
  std::vector<uint8_t> out(kTag, kTag + 8);
  out.reserve(16 + 4 * (file.quantized.size() + mesh.positions.size() + mesh.face_sizes.size() +
                        mesh.corners.size()));
  put_u32le(&out, uint32_t(mesh.vertex_count()));
  put_u32le(&out, uint32_t(mesh.face_count()));
  for (uint32_t q : file.quantized) put_u32le(&out, q);
  for (float p : mesh.positions) put_f32le(&out, p);
  for (uint32_t d : mesh.face_sizes) put_u32le(&out, d);
  for (uint32_t v : mesh.corners) put_u32le(&out, v);
  return out;
}

}  // namespace qmc
