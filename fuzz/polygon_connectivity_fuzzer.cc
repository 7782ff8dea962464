// libFuzzer target: polygon connectivity (spec/qmc-format.md 5.4) without
// the container. Input: vertex_count and face_count as u16 (little-endian),
// then method-2 data (flags, coding, stream). Whatever decodes must name
// only vertices below vertex_count, and the polygon encoder must take the
// decoded faces and give them back exactly (up to its relabelling and
// reordering, checked face by face against its own correspondence).
#include <cstddef>
#include <cstdint>

#include "decoder/connectivity_decoder.h"
#include "decoder/polygon_connectivity_decoder.h"
#include "encoder/polygon_connectivity_encoder.h"

namespace {

bool same_cycle(const uint32_t* source, const uint32_t* decoded, uint32_t n, const std::vector<uint32_t>& label) {
  for (uint32_t r = 0; r < n; ++r) {
    uint32_t i = 0;
    while (i < n && label[source[(i + r) % n]] == decoded[i]) ++i;
    if (i == n) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 4) return 0;
  const uint32_t vertices = uint32_t(data[0]) | (uint32_t(data[1]) << 8);
  const uint32_t faces = uint32_t(data[2]) | (uint32_t(data[3]) << 8);
  qmc::Mesh mesh;
  qmc::PolygonConnectivityInfo info;
  if (!qmc::decode_polygon_connectivity(data + 4, size - 4, vertices, faces, &mesh, &info).ok()) return 0;
  if (mesh.face_count() != faces) __builtin_trap();
  for (uint32_t v : mesh.corners)
    if (v >= vertices) __builtin_trap();
  mesh.positions.assign(3 * size_t(vertices), 0.f);
  qmc::PolygonEncoding again;
  if (!qmc::encode_polygon_connectivity(mesh, -1, true, true, true, &again).empty()) __builtin_trap();
  // The re-encoded payload decodes to the encoder's file mesh ...
  qmc::Mesh decoded;
  uint32_t count = 0;
  qmc::ConnectivityMethod method;
  if (!qmc::decode_connectivity(again.payload.data(), again.payload.size(), &count, &method, &decoded).ok())
    __builtin_trap();
  if (count != vertices || decoded.corners != again.file_mesh.corners || decoded.face_sizes != again.file_mesh.face_sizes)
    __builtin_trap();
  // ... which is the fuzzed mesh, face by face.
  std::vector<uint32_t> label(vertices);
  if (again.file_vertex.size() != vertices || again.face_source.size() != faces) __builtin_trap();
  for (uint32_t i = 0; i < vertices; ++i) label[again.file_vertex[i]] = i;
  std::vector<size_t> begin(faces + 1, 0);
  for (uint32_t f = 0; f < faces; ++f) begin[f + 1] = begin[f] + mesh.face_sizes[f];
  size_t k = 0;
  for (uint32_t f = 0; f < faces; ++f) {
    const uint32_t src = again.face_source[f], n = decoded.face_sizes[f];
    if (src >= faces || mesh.face_sizes[src] != n) __builtin_trap();
    if (!same_cycle(&mesh.corners[begin[src]], &decoded.corners[k], n, label)) __builtin_trap();
    k += n;
  }
  return 0;
}
