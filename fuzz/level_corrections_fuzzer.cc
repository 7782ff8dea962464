// libFuzzer target: LEVL code 4 (spec section 12.7.2), the displacements and
// vertex corrections of one level over a fixed base, an octahedron (6
// vertices, 12 edges: level 1 has 18 vertices). Input: one byte choosing the
// correction count C (0 .. 19, so one past the level's vertices too), then
// the range-coded stream. What must hold of every payload that decodes: C
// corrections of increasing vertices below 18, offsets within -32768 ..
// 32767, each vertex moved by exactly its offsets times the step from where
// the same displacements without corrections put it, and coordinates finite
// in binary32.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/byte_io.h"
#include "decoder/loop_level_decoder.h"

namespace {

constexpr double kStep = 0x1p-6, kCorrectionStep = 0x1p-10;

qmc::LoopLevel octahedron() {
  qmc::LoopLevel base;
  base.positions = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  base.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return base;
}

std::vector<uint8_t> payload(uint64_t corrections, const uint8_t* stream, size_t size) {
  std::vector<uint8_t> p{1, 4};
  qmc::put_varint(&p, 12);
  qmc::put_f64le(&p, kStep);
  qmc::put_f64le(&p, kCorrectionStep);
  qmc::put_varint(&p, corrections);
  p.insert(p.end(), stream, stream + size);
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const qmc::LoopLevel base = octahedron();
  static qmc::LoopEdges edges;
  static const bool built = qmc::build_loop_edges(base, &edges).ok();
  if (!built) __builtin_trap();
  const uint64_t count = data[0] % 20;
  const std::vector<uint8_t> p = payload(count, data + 1, size - 1);
  qmc::LevelCode code;
  if (!qmc::decode_level_code(p.data(), p.size(), 1, edges, base.vertex_count(), &code).ok()) return 0;
  if (code.corrections.size() != count) __builtin_trap();
  for (size_t i = 0; i < code.corrections.size(); ++i) {
    const qmc::VertexCorrection& c = code.corrections[i];
    if (c.vertex >= 18 || (i > 0 && c.vertex <= code.corrections[i - 1].vertex)) __builtin_trap();
    for (int32_t r : c.offset)
      if (r < -32768 || r > 32767) __builtin_trap();
  }
  qmc::LoopLevel fine;
  if (!qmc::decode_level(p.data(), p.size(), 1, base, edges, &fine).ok()) __builtin_trap();  // the code decoded
  if (fine.vertex_count() != 18 || fine.corrected_vertices != count) __builtin_trap();
  // The same displacements without the corrections.
  qmc::LevelCode plain = code;
  plain.corrections.clear();
  qmc::LoopLevel displaced;
  qmc::loop_subdivide(base, edges, &displaced);
  std::vector<double> normals;
  qmc::edge_point_normals(displaced, edges, base.vertex_count(), &normals);
  qmc::displace_edge_points(normals, plain, base.vertex_count(), &displaced);
  std::vector<double> expected = displaced.positions;
  for (const qmc::VertexCorrection& c : code.corrections)
    for (int a = 0; a < 3; ++a)
      if (c.offset[a] != 0) expected[3 * c.vertex + a] += double(c.offset[a]) * kCorrectionStep;  // exact here
  if (expected != fine.positions) __builtin_trap();
  for (double x : fine.positions)
    if (!(std::fabs(x) < 0x1.ffffff8p+127)) __builtin_trap();
  return 0;
}
