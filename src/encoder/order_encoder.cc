// oRDR payload of spec/qmc-format.md section 4.5: the face order, the vertex
// order along the walk, and each face's rotation relative to its corner of
// lowest input index, each as Huffman-coded magnitude classes (7.3, 7.4).
#include "encoder/order_encoder.h"

#include <string>

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"
#include "decoder/order_decoder.h"

namespace qmc {
namespace {

Status internal(const std::string& message) {
  return Status(ErrorCode::kInvalidArgument, "internal: oRDR: " + message);
}

uint32_t magnitude(int64_t v) { return uint32_t(v < 0 ? -v : v); }

// Differences from previous + 1 (section 4.5), signed magnitude classes.
void write_permutation(BitWriter* bits, const std::vector<uint32_t>& values) {
  std::vector<uint64_t> freq(kMagnitudeClasses, 0);
  int64_t previous = -1;
  for (uint32_t v : values) {
    ++freq[magnitude_class(magnitude(int64_t(v) - previous - 1))];
    previous = v;
  }
  const std::vector<uint8_t> lengths = huffman_code_lengths(freq);
  write_code_lengths(bits, lengths);
  const HuffmanEncoder code(lengths);
  previous = -1;
  for (uint32_t v : values) {
    const int64_t e = int64_t(v) - previous - 1;
    const int c = magnitude_class(magnitude(e));
    code.write(bits, uint32_t(c));
    if (c > 0) bits->write_bit(e < 0);
    write_magnitude_extra(bits, magnitude(e), c);
    previous = v;
  }
}

bool is_identity(const std::vector<uint32_t>& map) {
  for (uint32_t i = 0; i < map.size(); ++i)
    if (map[i] != i) return false;
  return true;
}

bool is_permutation(const std::vector<uint32_t>& map) {
  std::vector<uint8_t> seen(map.size(), 0);
  for (uint32_t v : map) {
    if (v >= map.size() || seen[v]) return false;
    seen[v] = 1;
  }
  return true;
}

constexpr uint32_t kNoRotation = UINT32_MAX;

// The smallest s such that input face `in` reads like the file face started
// at its corner (m + s) mod d, or kNoRotation (section 4.5 rotations).
// Knuth-Morris-Pratt over the file face read twice around: linear in d even
// for a face that repeats a vertex, where trying each rotation in turn costs
// up to d^2 comparisons. `border` is scratch space, kept between faces.
uint32_t rotation_after_min(const uint32_t* in, const uint32_t* file, const std::vector<uint32_t>& file_vertex,
                            uint32_t d, uint32_t m, std::vector<uint32_t>* border) {
  // border[i]: length of the longest proper prefix of in[0..i] that is also its suffix.
  border->assign(d, 0);
  for (uint32_t i = 1, k = 0; i < d; ++i) {
    while (k > 0 && in[i] != in[k]) k = (*border)[k - 1];
    if (in[i] == in[k]) ++k;
    (*border)[i] = k;
  }
  uint32_t matched = 0, corner = m;
  for (uint32_t j = 0; j + 1 < 2 * d; ++j) {
    const uint32_t v = file_vertex[file[corner]];
    corner = corner + 1 == d ? 0 : corner + 1;
    while (matched > 0 && v != in[matched]) matched = (*border)[matched - 1];
    if (v == in[matched]) ++matched;
    if (matched == d) return j + 1 - d;
  }
  return kNoRotation;
}

}  // namespace

Status face_rotations(const Mesh& input, const Mesh& file_mesh, const std::vector<uint32_t>& file_vertex,
                      const std::vector<uint32_t>& face_source, std::vector<uint32_t>* rotation) {
  const size_t vertices = input.vertex_count(), faces = input.face_count();
  if (file_vertex.size() != vertices || !is_permutation(file_vertex))
    return internal("the file's vertex order is not a permutation of the input's vertices");
  if (face_source.size() != faces || file_mesh.face_count() != faces || !is_permutation(face_source))
    return internal("the file's face order is not a permutation of the input's faces");
  std::vector<uint64_t> input_offset(faces + 1, 0);
  for (size_t f = 0; f < faces; ++f) input_offset[f + 1] = input_offset[f] + input.face_sizes[f];
  rotation->assign(faces, 0);
  uint64_t k0 = 0;
  std::vector<uint32_t> border;
  for (size_t j = 0; j < faces; ++j) {
    const uint32_t degree = file_mesh.face_sizes[j];
    const uint32_t* file = &file_mesh.corners[k0];
    k0 += degree;
    const uint32_t src = face_source[j];
    if (input.face_sizes[src] != degree)
      return internal("file face " + std::to_string(j) + " has degree " + std::to_string(degree) + ", input face " +
                      std::to_string(src) + " " + std::to_string(input.face_sizes[src]));
    const uint32_t* in = &input.corners[input_offset[src]];
    uint32_t m = 0;
    for (uint32_t i = 1; i < degree; ++i)
      if (file_vertex[file[i]] < file_vertex[file[m]]) m = i;
    const uint32_t s = rotation_after_min(in, file, file_vertex, degree, m, &border);
    if (s == kNoRotation)
      return internal("file face " + std::to_string(j) + " is no rotation of input face " + std::to_string(src));
    (*rotation)[j] = uint32_t((uint64_t(m) + s) % degree);
  }
  return Status::Ok();
}

Status encode_order(const Mesh& input, const Mesh& file_mesh, const std::vector<uint32_t>& file_vertex,
                    const std::vector<uint32_t>& face_source, std::vector<uint8_t>* payload) {
  payload->clear();
  const size_t vertices = input.vertex_count(), faces = input.face_count();
  std::vector<uint32_t> rotation;
  if (Status s = face_rotations(input, file_mesh, file_vertex, face_source, &rotation); !s.ok()) return s;
  // Rotations: the smallest s such that the input face starts at file corner (m + s) mod d.
  std::vector<uint32_t> offset_from_min(faces, 0);
  bool rotated = false;
  uint64_t k0 = 0;
  for (size_t j = 0; j < faces; ++j) {
    const uint32_t degree = file_mesh.face_sizes[j];
    const uint32_t* file = &file_mesh.corners[k0];
    k0 += degree;
    uint32_t m = 0;
    for (uint32_t i = 1; i < degree; ++i)
      if (file_vertex[file[i]] < file_vertex[file[m]]) m = i;
    offset_from_min[j] = (rotation[j] + degree - m) % degree;
    rotated = rotated || rotation[j] != 0;
  }

  const bool reorder_faces = !is_identity(face_source), relabel = !is_identity(file_vertex);
  const uint8_t flags = uint8_t((reorder_faces ? kOrderFaces : 0) | (relabel ? kOrderVertices : 0) |
                                (rotated ? kOrderRotations : 0));
  if (flags == 0) return Status::Ok();  // the coder order is the input's order
  put_varint(payload, vertices);
  put_varint(payload, faces);
  put_u8(payload, flags);
  BitWriter bits;
  if (reorder_faces) write_permutation(&bits, face_source);
  if (relabel) {
    // The walk: file vertices by first reference of the faces in input
    // order, corners in file order, then the unreferenced ones.
    std::vector<uint64_t> file_offset(faces + 1, 0);
    for (size_t j = 0; j < faces; ++j) file_offset[j + 1] = file_offset[j] + file_mesh.face_sizes[j];
    std::vector<uint32_t> file_face(faces);
    for (uint32_t j = 0; j < faces; ++j) file_face[face_source[j]] = j;
    std::vector<uint8_t> seen(vertices, 0);
    std::vector<uint32_t> u;
    u.reserve(vertices);
    for (uint32_t j : file_face)
      for (uint64_t k = file_offset[j]; k < file_offset[j + 1]; ++k) {
        const uint32_t label = file_mesh.corners[k];
        if (!seen[label]) {
          seen[label] = 1;
          u.push_back(file_vertex[label]);
        }
      }
    for (uint32_t label = 0; label < vertices; ++label)
      if (!seen[label]) u.push_back(file_vertex[label]);
    write_permutation(&bits, u);
  }
  if (rotated) {
    std::vector<uint64_t> freq(kMagnitudeClasses, 0);
    for (uint32_t s : offset_from_min) ++freq[magnitude_class(s)];
    const std::vector<uint8_t> lengths = huffman_code_lengths(freq);
    write_code_lengths(&bits, lengths);
    const HuffmanEncoder code(lengths);
    for (uint32_t s : offset_from_min) {
      const int c = magnitude_class(s);
      code.write(&bits, uint32_t(c));
      write_magnitude_extra(&bits, s, c);
    }
  }
  const std::vector<uint8_t> stream = bits.finish();
  payload->insert(payload->end(), stream.begin(), stream.end());
  return Status::Ok();
}

}  // namespace qmc
