// libFuzzer target: quad connectivity (spec/qmc-format.md 5.3) without the
// container. Input: face_count as u16 (little-endian), then method-1 data
// (flags, coding, stream). Whatever decodes must be a single oriented
// manifold genus-0 quad mesh (5.3.1), and encoding that mesh again must give
// back exactly the decoded interaction types (5.3.3 inverts 5.3.6).
#include <cstddef>
#include <cstdint>

#include "common/bit_reader.h"
#include "common/quad_codings.h"
#include "decoder/spirale_reversi_decoder.h"
#include "encoder/opposite_edge_table.h"
#include "encoder/quad_traversal_encoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 4) return 0;
  const uint32_t faces = uint32_t(data[0]) | (uint32_t(data[1]) << 8);
  const uint8_t flags = data[2], coding = data[3];
  if (flags > 1 || coding >= qmc::kQuadCodingCount) return 0;
  const bool closed = flags & 1;
  if (faces < 1u + closed) return 0;
  qmc::BitReader bits(data + 4, size - 4);
  std::vector<uint8_t> types;
  if (!qmc::read_quad_stream(qmc::QuadCoding(coding), faces - closed, &bits, &types).ok()) return 0;
  qmc::Mesh mesh;
  if (!qmc::spirale_reversi_decode(types, closed, UINT32_MAX, &mesh).ok()) return 0;
  uint32_t vertices = 0;
  for (uint32_t v : mesh.corners) vertices = v + 1 > vertices ? v + 1 : vertices;
  mesh.positions.assign(3 * size_t(vertices), 0.f);
  qmc::OppositeEdgeTable table;
  if (!qmc::build_opposite_edge_table(mesh, &table).empty()) __builtin_trap();
  if (table.components != 1 || table.boundary_loops != (closed ? 0u : 1u)) __builtin_trap();
  if (table.euler_characteristic != 2 - int64_t(table.boundary_loops)) __builtin_trap();
  qmc::QuadTraversal again;
  if (!qmc::encode_quad_traversal(mesh, &again).empty() || again.types != types) __builtin_trap();
  return 0;
}
