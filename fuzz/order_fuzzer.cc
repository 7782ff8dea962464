// libFuzzer target: an oRDR payload (spec section 4.5) against a mesh decoded
// from a CONN payload in the same input: u16le length of the CONN payload,
// the CONN payload, then the oRDR payload. Accepted maps must be
// permutations of the right sizes with rotations below the degrees, and
// applying them must keep every face's degree and vertex multiset.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "conn_prefix.h"
#include "decoder/order_decoder.h"
#include "fuzz_limits.h"

namespace {

bool is_permutation(const std::vector<uint32_t>& map, size_t n) {
  if (map.size() != n) return false;
  std::vector<uint8_t> seen(n, 0);
  for (uint32_t v : map) {
    if (v >= n || seen[v]) return false;
    seen[v] = 1;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::Mesh mesh;
  uint32_t vertex_count = 0;
  const uint8_t* payload = nullptr;
  size_t length = 0;
  if (!qmc::fuzz::decode_conn_prefix(data, size, &mesh, &vertex_count, &payload, &length)) return 0;
  if (vertex_count > qmc::fuzz::kMaxVerticesWithoutPositions) return 0;
  mesh.positions.assign(3 * size_t(vertex_count), 0.f);
  for (uint32_t v = 0; v < vertex_count; ++v) mesh.positions[3 * size_t(v)] = float(v);
  qmc::OrderMaps maps;
  if (!qmc::decode_order(payload, length, vertex_count, mesh, &maps).ok()) return 0;
  const size_t faces = mesh.face_sizes.size();
  if (!maps.vertex_input.empty() && !is_permutation(maps.vertex_input, vertex_count)) __builtin_trap();
  if (!maps.face_input.empty() && !is_permutation(maps.face_input, faces)) __builtin_trap();
  if (!maps.rotation.empty()) {
    if (maps.rotation.size() != faces) __builtin_trap();
    for (size_t j = 0; j < faces; ++j)
      if (maps.rotation[j] >= mesh.face_sizes[j]) __builtin_trap();
  }
  qmc::Mesh out = mesh;
  std::vector<uint32_t> quantized(mesh.positions.size(), 0);
  qmc::apply_order(maps, &out, &quantized);
  if (out.corners.size() != mesh.corners.size() || out.positions.size() != mesh.positions.size()) __builtin_trap();
  // Every output face is its file face, relabelled and rotated.
  std::vector<size_t> in_offset(faces + 1, 0), out_offset(faces + 1, 0);
  for (size_t j = 0; j < faces; ++j) in_offset[j + 1] = in_offset[j] + mesh.face_sizes[j];
  for (size_t i = 0; i < faces; ++i) out_offset[i + 1] = out_offset[i] + out.face_sizes[i];
  for (size_t j = 0; j < faces; ++j) {
    const size_t i = maps.face_input.empty() ? j : maps.face_input[j];
    const uint32_t d = mesh.face_sizes[j];
    if (out.face_sizes[i] != d) __builtin_trap();
    std::vector<uint32_t> a, b;
    for (uint32_t k = 0; k < d; ++k) {
      const uint32_t label = mesh.corners[in_offset[j] + k];
      a.push_back(maps.vertex_input.empty() ? label : maps.vertex_input[label]);
      b.push_back(out.corners[out_offset[i] + k]);
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b) __builtin_trap();
  }
  // Positions move with their vertices.
  for (uint32_t v = 0; v < vertex_count; ++v) {
    const uint32_t to = maps.vertex_input.empty() ? v : maps.vertex_input[v];
    if (out.positions[3 * size_t(to)] != float(v)) __builtin_trap();
  }
  return 0;
}
