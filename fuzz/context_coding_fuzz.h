// The body of the polygon_coding7 and polygon_coding8 libFuzzer targets
// (spec/qmc-format.md 5.4.10), which differ in the coding byte alone.
// Input: vertex_count and face_count as u16 (little-endian), then method-2
// data after the coding byte (groups, symbol_bytes, symbols, stream); flags
// 0 and the coding are put in front, so every input reaches that coding.
// Whatever decodes must name only vertices below vertex_count and must come
// back, face for face in the encoder's order, from the encoder's same coding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/byte_io.h"
#include "decoder/polygon_connectivity_decoder.h"
#include "encoder/polygon_connectivity_encoder.h"
#include "qmc/format.h"

inline int fuzz_context_coding(const uint8_t* data, size_t size, int coding) {
  if (size < 4) return 0;
  const uint32_t vertices = uint32_t(data[0]) | (uint32_t(data[1]) << 8);
  const uint32_t faces = uint32_t(data[2]) | (uint32_t(data[3]) << 8);
  std::vector<uint8_t> payload{0, uint8_t(coding)};
  payload.insert(payload.end(), data + 4, data + size);
  qmc::Mesh mesh;
  qmc::PolygonConnectivityInfo info;
  if (!qmc::decode_polygon_connectivity(payload.data(), payload.size(), vertices, faces, &mesh, &info).ok()) return 0;
  if (mesh.face_count() != faces) __builtin_trap();
  for (uint32_t v : mesh.corners)
    if (v >= vertices) __builtin_trap();
  mesh.positions.assign(3 * size_t(vertices), 0.f);
  qmc::PolygonEncoding again;
  const bool quad_contexts = coding == qmc::kPolygonQuadContextCoded;
  if (!qmc::encode_polygon_connectivity(mesh, coding, true, quad_contexts, true, &again).empty()) __builtin_trap();
  // The encoder's payload: method, vertex_count, face_count, then the data.
  qmc::ByteReader header(again.payload.data(), again.payload.size());
  uint8_t method = 0;
  uint64_t count = 0;
  if (!header.get_u8(&method) || !header.get_varint(&count) || !header.get_varint(&count)) __builtin_trap();
  qmc::Mesh decoded;
  if (!qmc::decode_polygon_connectivity(header.cursor(), header.remaining(), vertices, faces, &decoded, &info).ok())
    __builtin_trap();
  if (decoded.face_sizes != again.file_mesh.face_sizes || decoded.corners != again.file_mesh.corners) __builtin_trap();
  return 0;
}
