// libFuzzer target: geometry-image files (spec section 13) with valid
// framing, so mutations reach the chunk decoders (GIMG, GMSK, GSEM, GFAC,
// GPLN) and the mesh of 13.9 instead of failing the CRC. Input: sections,
// each a chunk selector byte (0 GIMG, 1 GMSK, 2 GSEM, 3 GFAC, 4 GPLN,
// 5 QEND), a u16le length and the payload; the target adds the signature,
// QHDR 1.4 and, unless given, QEND. What must hold of every file that
// decodes: the mesh's corners name its vertices, faces have 3 or 4 distinct
// corners (modes 0, 1) or 3 (mode 2), every vertex sits on an occupied
// pixel, and the canonical output of 13.10 can be made.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/byte_io.h"
#include "common/crc32.h"
#include "fuzz_limits.h"
#include "qmc/decoder.h"
#include "qmc/format.h"

namespace {

void append_chunk(std::vector<uint8_t>* out, uint32_t type, const uint8_t* payload, size_t length) {
  const size_t start = out->size();
  qmc::put_u32be(out, type);
  qmc::put_u32le(out, uint32_t(length));
  out->insert(out->end(), payload, payload + length);
  qmc::put_u32le(out, qmc::crc32(out->data() + start, out->size() - start));
}

bool mesh_is_sound(const qmc::DecodedFile& file) {
  const qmc::Mesh& m = file.mesh;
  const qmc::GeometryImageData& g = file.gim;
  if (g.vertex_pixels.size() != m.vertex_count()) return false;
  for (uint32_t p : g.vertex_pixels)
    if (p >= g.occupied.size() || g.occupied[p] == 0) return false;
  size_t c = 0;
  for (uint32_t size : m.face_sizes) {
    if (size < 3 || size > (g.face_mode == 0 ? 4u : 3u)) return false;
    for (uint32_t i = 0; i < size; ++i) {
      if (m.corners[c + i] >= m.vertex_count()) return false;
      for (uint32_t j = i + 1; j < size; ++j)
        if (m.corners[c + i] == m.corners[c + j]) return false;
    }
    c += size;
  }
  return c == m.corners.size();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const uint32_t kTypes[] = {qmc::kChunkGeometryImage, qmc::kChunkGimMask, qmc::kChunkGimSeams,
                                    qmc::kChunkGimFaces,      qmc::kChunkGimPlane, qmc::kChunkEnd};
  std::vector<uint8_t> file(qmc::kSignature, qmc::kSignature + 8);
  const uint8_t header[2] = {1, 4};
  append_chunk(&file, qmc::kChunkHeader, header, 2);
  bool ended = false;
  while (size >= 3 && !ended) {
    const uint32_t type = kTypes[data[0] % 6];
    size_t length = data[1] | size_t(data[2]) << 8;
    data += 3, size -= 3;
    if (length > size) length = size;
    append_chunk(&file, type, data, length);
    data += length, size -= length;
    ended = type == qmc::kChunkEnd;
  }
  if (!ended) append_chunk(&file, qmc::kChunkEnd, nullptr, 0);
  qmc::DecodedFile decoded;
  const qmc::Status s = qmc::decode(file.data(), file.size(), &decoded, qmc::fuzz::small_output_limits());
  if (!s.ok()) {
    if (s.message().empty()) __builtin_trap();  // every rejection names its reason
    return 0;
  }
  if (decoded.gim.present && !mesh_is_sound(decoded)) __builtin_trap();
  (void)qmc::canonical_output(decoded);
  return 0;
}
