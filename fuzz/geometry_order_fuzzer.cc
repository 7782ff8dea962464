// libFuzzer target: the geometry order of POSN method 4 (spec section 14.6)
// over the faces of a CONN payload (u16le length, the payload; the rest of
// the input is ignored, so the predicted_positions seeds serve). The order
// must be a permutation, and on meshes of at most 300 vertices the one
// 14.6's text gives, computed literally (every face scanned per step).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/geometry_order.h"
#include "conn_prefix.h"
#include "geometry_order_rule.h"
#include "fuzz_limits.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::Mesh mesh;
  uint32_t vertex_count = 0;
  const uint8_t* rest = nullptr;
  size_t rest_size = 0;
  if (!qmc::fuzz::decode_conn_prefix(data, size, &mesh, &vertex_count, &rest, &rest_size)) return 0;
  if (vertex_count > qmc::fuzz::kMaxVertices) return 0;
  const std::vector<uint32_t> order = qmc::geometry_order(vertex_count, mesh.face_sizes, mesh.corners);
  if (order.size() != vertex_count) __builtin_trap();
  std::vector<uint8_t> seen(vertex_count, 0);
  for (uint32_t v : order) {
    if (v >= vertex_count || seen[v]) __builtin_trap();
    seen[v] = 1;
  }
  if (vertex_count <= 300 && mesh.corners.size() <= 3000 && order != qmc::fuzz::geometry_order_by_the_rule(vertex_count, mesh))
    __builtin_trap();
  return 0;
}
