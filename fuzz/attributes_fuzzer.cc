// libFuzzer target: an aTTR payload (spec section 15) against a mesh decoded
// from a CONN payload in the same input: u16le length of the CONN payload,
// the CONN payload, then the aTTR payload. An accepted attribute must give
// every corner a value index below its table's size; coded again by the
// encoder (exact binary32) and decoded, every corner must keep its value
// bit for bit.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "attribute_checks.h"
#include "conn_prefix.h"
#include "decoder/attribute_decoder.h"
#include "encoder/attribute_encoder.h"
#include "fuzz_limits.h"

namespace {

bool same_corner_values(const qmc::MeshAttribute& a, const qmc::MeshAttribute& b) {
  if (a.corner_values.size() != b.corner_values.size() || a.components != b.components) return false;
  for (size_t k = 0; k < a.corner_values.size(); ++k)
    if (std::memcmp(&a.values[a.components * size_t(a.corner_values[k])],
                    &b.values[b.components * size_t(b.corner_values[k])], 4 * a.components) != 0)
      return false;
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
  // Positions for coding 3's predictions (15.7): a fixed scatter of integers.
  std::vector<uint32_t> quantized(3 * size_t(vertex_count));
  for (size_t i = 0; i < quantized.size(); ++i) quantized[i] = uint32_t((i * 2654435761u) >> 7) & 0xFFFFF;
  qmc::MeshAttribute attribute;
  qmc::AttributeCoding coding;
  if (!qmc::fuzz::decode_attribute_payload(payload, length, mesh, vertex_count, quantized, &attribute, &coding))
    return 0;
  if (!qmc::fuzz::well_formed(attribute, mesh)) __builtin_trap();
  if (coding.mapping == 0 && attribute.corner_values != mesh.corners) __builtin_trap();

  // Coded again, exactly, over the same faces.
  mesh.positions.assign(3 * size_t(vertex_count), 0.f);
  std::vector<uint64_t> source(mesh.corners.size());
  for (size_t k = 0; k < source.size(); ++k) source[k] = k;
  qmc::EncodeOptions options;
  options.exact_attributes = true;
  std::vector<uint8_t> again;
  qmc::AttributeStats stats;
  std::vector<uint32_t> file_vertex(vertex_count);  // the decoded mesh is its own input
  for (uint32_t v = 0; v < vertex_count; ++v) file_vertex[v] = v;
  if (!qmc::encode_attribute(attribute, mesh, file_vertex, {}, source, options, &again, &stats).ok()) __builtin_trap();
  qmc::MeshAttribute round_trip;
  if (!qmc::fuzz::decode_attribute_payload(again.data(), again.size(), mesh, vertex_count, quantized, &round_trip,
                                          &coding) ||
      !same_corner_values(attribute, round_trip))
    __builtin_trap();
  return 0;
}
