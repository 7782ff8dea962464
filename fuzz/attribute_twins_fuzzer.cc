// libFuzzer target: an aTTR payload (spec section 15) against a mesh decoded
// from a CONN payload in the same input, as `attributes` takes them (u16le
// length of the CONN payload, the CONN payload, the aTTR payload), but over
// positions on a small grid, x = v mod 8, y = v / 8 mod 8, z = v / 64 mod 4,
// so that nearly every plane a coding 9 payload states (15.14) gives twins,
// exact or a step away, and its twin candidates, signs and decisions run.
// An accepted attribute must give every corner a value below its table's
// size, and decoding twice must give the same values.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "attribute_checks.h"
#include "conn_prefix.h"
#include "fuzz_limits.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::Mesh mesh;
  uint32_t vertex_count = 0;
  const uint8_t* payload = nullptr;
  size_t length = 0;
  if (!qmc::fuzz::decode_conn_prefix(data, size, &mesh, &vertex_count, &payload, &length)) return 0;
  if (vertex_count > qmc::fuzz::kMaxVerticesWithoutPositions) return 0;
  std::vector<uint32_t> positions(3 * size_t(vertex_count));
  for (uint32_t v = 0; v < vertex_count; ++v) {
    positions[3 * size_t(v)] = v % 8;
    positions[3 * size_t(v) + 1] = v / 8 % 8;
    positions[3 * size_t(v) + 2] = v / 64 % 4;
  }
  qmc::MeshAttribute attribute, again;
  qmc::AttributeCoding coding;
  if (!qmc::fuzz::decode_attribute_payload(payload, length, mesh, vertex_count, positions, &attribute, &coding))
    return 0;
  if (!qmc::fuzz::well_formed(attribute, mesh)) __builtin_trap();
  if (!qmc::fuzz::decode_attribute_payload(payload, length, mesh, vertex_count, positions, &again, &coding) ||
      again.corner_values != attribute.corner_values ||
      std::memcmp(again.values.data(), attribute.values.data(), 4 * attribute.values.size()) != 0)
    __builtin_trap();
  return 0;
}
