// Decoder of the oRDR chunk (spec/qmc-format.md section 4.5): three maps coded
// as Huffman-coded magnitude classes (7.3, 7.4) of differences from "one more
// than the previous value", validated to be permutations before use.
#include "decoder/order_decoder.h"

#include <string>

#include "common/bit_reader.h"
#include "common/byte_io.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"

namespace qmc {
namespace {

Status bad_payload(const std::string& message) { return Status(ErrorCode::kBadChunkPayload, "oRDR: " + message); }
Status bad_symbol(const std::string& message) { return Status(ErrorCode::kBadSymbol, "oRDR: " + message); }
Status truncated(const char* part) {
  return Status(ErrorCode::kTruncated, std::string("oRDR: the bit stream ends inside the ") + part);
}

// Section 7.4, signed: the class c of |e| (0..32), a sign bit, c - 1 extra bits.
int64_t read_signed_value(BitReader* bits, int c) {
  if (c == 0) return 0;
  const bool negative = bits->read_bit();
  const int64_t magnitude = int64_t(read_magnitude_extra(bits, c));
  return negative ? -magnitude : magnitude;
}

// One permutation of 0..n-1 as differences e from previous + 1 (section 4.5).
// out[k] = k-th value; `taken` detects repeats.
Status read_permutation(BitReader* bits, uint32_t n, const char* part, std::vector<uint32_t>* out) {
  HuffmanDecoder code;
  if (Status s = read_table(bits, kMagnitudeClasses, &code); !s.ok())
    return Status(s.code(), std::string("oRDR ") + part + ": " + s.message());
  out->assign(n, 0);
  std::vector<uint8_t> taken(n, 0);
  int64_t previous = -1;
  for (uint32_t k = 0; k < n; ++k) {
    const int c = code.decode(bits);
    if (c < 0) return bad_symbol(std::string("invalid code word in the ") + part);
    const int64_t value = previous + 1 + read_signed_value(bits, c);
    if (bits->overrun()) return truncated(part);
    if (value < 0 || value >= int64_t(n))
      return bad_symbol(std::string(part) + " entry " + std::to_string(k) + " is " + std::to_string(value) +
                        ", outside 0.." + std::to_string(int64_t(n) - 1));
    if (taken[size_t(value)])
      return bad_symbol(std::string(part) + " entry " + std::to_string(k) + " repeats " + std::to_string(value) +
                        ": not a permutation");
    taken[size_t(value)] = 1;
    (*out)[k] = uint32_t(value);
    previous = value;
  }
  return Status::Ok();
}

}  // namespace

Status decode_order(const uint8_t* payload, size_t size, uint32_t vertex_count, const Mesh& mesh, OrderMaps* maps) {
  *maps = OrderMaps{};
  const uint64_t face_count = mesh.face_sizes.size();
  ByteReader in(payload, size);
  uint64_t v = 0, f = 0;
  uint8_t flags = 0;
  // Check 1.
  if (!in.get_varint(&v)) return bad_payload("vertex_count missing or malformed");
  if (v != vertex_count)
    return bad_payload("vertex_count " + std::to_string(v) + " differs from CONN's " + std::to_string(vertex_count));
  if (!in.get_varint(&f)) return bad_payload("face_count missing or malformed");
  if (f != face_count)
    return bad_payload("face_count " + std::to_string(f) + " differs from CONN's " + std::to_string(face_count));
  // Check 2.
  if (!in.get_u8(&flags)) return bad_payload("flags missing");
  if (flags & ~(kOrderFaces | kOrderVertices | kOrderRotations))
    return bad_payload("reserved flag bits set (flags " + std::to_string(flags) + ")");
  if (((flags & (kOrderFaces | kOrderRotations)) && face_count == 0) || ((flags & kOrderVertices) && vertex_count == 0))
    return bad_payload("a map is flagged for zero elements");
  maps->flags = flags;
  BitReader bits(in.cursor(), in.remaining());
  // Check 3.
  if (flags == 0) {
    if (!bits.at_clean_end()) return bad_payload("data after flags 0");
    return Status::Ok();
  }
  // Check 4: every value takes at least one bit.
  const uint64_t needed = ((flags & kOrderFaces) ? face_count : 0) + ((flags & kOrderVertices) ? vertex_count : 0) +
                          ((flags & kOrderRotations) ? face_count : 0);
  if (needed > bits.bits_remaining())
    return Status(ErrorCode::kLimitExceeded, "oRDR: " + std::to_string(needed) + " values cannot fit in " +
                                                 std::to_string(in.remaining()) + " bytes");
  // Check 5: faces, vertices, rotations.
  if (flags & kOrderFaces)
    if (Status s = read_permutation(&bits, uint32_t(face_count), "face order", &maps->face_input); !s.ok()) return s;
  std::vector<uint64_t> offset(face_count + 1, 0);
  for (size_t j = 0; j < face_count; ++j) offset[j + 1] = offset[j] + mesh.face_sizes[j];
  if (flags & kOrderVertices) {
    // The walk w: vertices by first reference of the faces in output order,
    // corners in file order, then the unreferenced ones in increasing order.
    std::vector<uint32_t> file_face(face_count);
    for (uint32_t j = 0; j < face_count; ++j) file_face[maps->face_input.empty() ? j : maps->face_input[j]] = j;
    std::vector<uint32_t> walk;
    walk.reserve(vertex_count);
    std::vector<uint8_t> seen(vertex_count, 0);
    for (uint32_t j : file_face)
      for (uint64_t k = offset[j]; k < offset[j + 1]; ++k) {
        const uint32_t label = mesh.corners[k];
        if (!seen[label]) {
          seen[label] = 1;
          walk.push_back(label);
        }
      }
    for (uint32_t label = 0; label < vertex_count; ++label)
      if (!seen[label]) walk.push_back(label);
    std::vector<uint32_t> u;
    if (Status s = read_permutation(&bits, vertex_count, "vertex order", &u); !s.ok()) return s;
    maps->vertex_input.assign(vertex_count, 0);
    for (uint32_t k = 0; k < vertex_count; ++k) maps->vertex_input[walk[k]] = u[k];
  }
  if (flags & kOrderRotations) {
    HuffmanDecoder code;
    if (Status s = read_table(&bits, kMagnitudeClasses, &code); !s.ok())
      return Status(s.code(), "oRDR rotations: " + s.message());
    maps->rotation.assign(face_count, 0);
    const std::vector<uint32_t>& vi = maps->vertex_input;
    auto input_index = [&vi](uint32_t label) { return vi.empty() ? label : vi[label]; };
    for (uint32_t j = 0; j < face_count; ++j) {
      const int c = code.decode(&bits);
      if (c < 0) return bad_symbol("invalid code word in the rotations");
      const uint32_t s = read_magnitude_extra(&bits, c);
      if (bits.overrun()) return truncated("rotations");
      const uint32_t degree = mesh.face_sizes[j];
      if (s >= degree)
        return bad_symbol("face " + std::to_string(j) + " rotation offset " + std::to_string(s) +
                          " is not below its degree " + std::to_string(degree));
      // m_j: the first corner of lowest input index.
      uint32_t m = 0;
      for (uint32_t i = 1; i < degree; ++i)
        if (input_index(mesh.corners[offset[j] + i]) < input_index(mesh.corners[offset[j] + m])) m = i;
      maps->rotation[j] = uint32_t((uint64_t(m) + s) % degree);
    }
  }
  // Check 6.
  if (!bits.at_clean_end()) return bad_payload("bits after the last value are not zero padding");
  return Status::Ok();
}

namespace {

// Section 15.6: a per-vertex attribute's values move with their vertices.
void permute_vertex_values(const std::vector<uint32_t>& vertex_input, MeshAttribute* attribute) {
  const size_t c = attribute->components;
  std::vector<float> values(attribute->values.size());
  for (size_t l = 0; l < vertex_input.size(); ++l)
    for (size_t a = 0; a < c; ++a) values[c * vertex_input[l] + a] = attribute->values[c * l + a];
  attribute->values = std::move(values);
  for (uint32_t& m : attribute->corner_values) m = vertex_input[m];
}

}  // namespace

void apply_order(const OrderMaps& maps, Mesh* mesh, std::vector<uint32_t>* quantized,
                 const std::vector<uint8_t>& attribute_per_vertex) {
  const size_t vertices = mesh->vertex_count(), faces = mesh->face_sizes.size();
  auto vertex = [&maps](uint32_t label) { return maps.vertex_input.empty() ? label : maps.vertex_input[label]; };
  auto face = [&maps](size_t j) { return maps.face_input.empty() ? j : size_t(maps.face_input[j]); };
  if (!maps.vertex_input.empty()) {
    std::vector<float> positions(mesh->positions.size());
    for (size_t l = 0; l < vertices; ++l)
      for (int a = 0; a < 3; ++a) positions[3 * size_t(vertex(uint32_t(l))) + a] = mesh->positions[3 * l + a];
    mesh->positions = std::move(positions);
    if (quantized && quantized->size() == 3 * vertices) {
      std::vector<uint32_t> q(quantized->size());
      for (size_t l = 0; l < vertices; ++l)
        for (int a = 0; a < 3; ++a) q[3 * size_t(vertex(uint32_t(l))) + a] = (*quantized)[3 * l + a];
      *quantized = std::move(q);
    }
    for (size_t i = 0; i < mesh->attributes.size(); ++i)
      if (i < attribute_per_vertex.size() && attribute_per_vertex[i])
        permute_vertex_values(maps.vertex_input, &mesh->attributes[i]);
  }
  std::vector<uint32_t> sizes(faces);
  for (size_t j = 0; j < faces; ++j) sizes[face(j)] = mesh->face_sizes[j];
  std::vector<uint64_t> out_offset(faces + 1, 0);
  for (size_t i = 0; i < faces; ++i) out_offset[i + 1] = out_offset[i] + sizes[i];
  // Section 4.5 (and 15.6 for the attributes): output corner k of face
  // face_input[j] is file corner (k + rotation[j]) mod d_j.
  std::vector<uint64_t> source(mesh->corners.size());
  uint64_t k0 = 0;
  for (size_t j = 0; j < faces; ++j) {
    const uint32_t degree = mesh->face_sizes[j];
    const uint32_t r = maps.rotation.empty() ? 0 : maps.rotation[j];
    const uint64_t out = out_offset[face(j)];
    for (uint32_t k = 0; k < degree; ++k) source[out + k] = k0 + (uint64_t(k) + r) % degree;
    k0 += degree;
  }
  std::vector<uint32_t> corners(mesh->corners.size());
  for (size_t k = 0; k < corners.size(); ++k) corners[k] = vertex(mesh->corners[source[k]]);
  for (MeshAttribute& attribute : mesh->attributes) {
    std::vector<uint32_t> values(attribute.corner_values.size());
    for (size_t k = 0; k < values.size(); ++k) values[k] = attribute.corner_values[source[k]];
    attribute.corner_values = std::move(values);
  }
  for (FaceLabels& labels : mesh->face_labels) {  // 16.3
    std::vector<uint32_t> values(labels.face_values.size());
    for (size_t j = 0; j < values.size(); ++j) values[face(j)] = labels.face_values[j];
    labels.face_values = std::move(values);
  }
  mesh->face_sizes = std::move(sizes);
  mesh->corners = std::move(corners);
}

}  // namespace qmc
