// libFuzzer target: the progressive levels of spec section 12 without the
// container. Input: sections, each a u16le length and that many bytes: a
// CONN payload (the base connectivity), a POSN payload, then up to three
// LEVL payloads. What must hold of every level that decodes: V + E vertices
// and 4F faces, the Euler characteristic of the base, a valid level again
// (subdivision keeps section 12.2's rules), coordinates finite in binary32.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/connectivity_decoder.h"
#include "decoder/loop_level_decoder.h"
#include "decoder/position_decoder.h"

namespace {

struct Sections {
  const uint8_t* data;
  size_t size;
  bool next(const uint8_t** payload, size_t* length) {
    if (size < 2) return false;
    *length = data[0] | size_t(data[1]) << 8;
    if (size - 2 < *length) return false;
    *payload = data + 2;
    data += 2 + *length;
    size -= 2 + *length;
    return true;
  }
};

int64_t euler(const qmc::LoopLevel& level, const qmc::LoopEdges& edges) {
  return int64_t(level.vertex_count()) - int64_t(edges.edge_count()) + int64_t(level.face_count());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Sections in{data, size};
  const uint8_t* payload;
  size_t length;
  if (!in.next(&payload, &length)) return 0;
  qmc::Mesh mesh;
  uint32_t vertex_count = 0;
  qmc::ConnectivityMethod method;
  if (!qmc::decode_connectivity(payload, length, &vertex_count, &method, &mesh).ok()) return 0;
  qmc::LoopLevel level;
  qmc::LoopEdges edges;
  if (!qmc::loop_base_connectivity(mesh, vertex_count, &level, &edges).ok()) return 0;
  if (!in.next(&payload, &length)) return 0;
  qmc::QuantizationInfo info;
  std::vector<uint32_t> quantized;
  std::vector<float> positions;
  if (!qmc::decode_positions(payload, length, mesh, vertex_count, &info, &quantized, &positions).ok()) return 0;
  qmc::loop_base_positions(info, quantized, &level);
  const int64_t chi = euler(level, edges);
  for (uint8_t j = 1; j <= 3 && in.next(&payload, &length); ++j) {
    qmc::LoopLevel fine;
    if (!qmc::decode_level(payload, length, j, level, edges, &fine).ok()) return 0;
    if (fine.vertex_count() != level.vertex_count() + edges.edge_count()) __builtin_trap();
    if (fine.face_count() != 4 * level.face_count()) __builtin_trap();
    for (double x : fine.positions)
      if (!(std::fabs(x) < 0x1.ffffff8p+127)) __builtin_trap();
    if (!qmc::build_loop_edges(fine, &edges).ok()) __builtin_trap();
    if (euler(fine, edges) != chi) __builtin_trap();
    level = std::move(fine);
  }
  return 0;
}
