// The canonical serialization of a decoded file (spec/qmc-format.md sections
// 10.2, 12.9 and 13.10), hashed by the conformance manifest.
#include <cstring>

#include "common/byte_io.h"
#include "decoder/no_throw.h"
#include "qmc/decoder.h"

namespace qmc {
namespace {

void append_tag(std::vector<uint8_t>* out, const char (&tag)[9]) {
  for (int i = 0; i < 8; ++i) out->push_back(uint8_t(tag[i]));
}

// Section 10.2.
void append_mesh(std::vector<uint8_t>* out, const Mesh& mesh, const std::vector<uint32_t>& quantized) {
  append_tag(out, "QMCMESH1");
  put_u32le(out, uint32_t(mesh.vertex_count()));
  put_u32le(out, uint32_t(mesh.face_count()));
  for (uint32_t q : quantized) put_u32le(out, q);
  for (float p : mesh.positions) put_f32le(out, p);
  for (uint32_t d : mesh.face_sizes) put_u32le(out, d);
  for (uint32_t v : mesh.corners) put_u32le(out, v);
}

// Section 10.2's record of an attribute (section 15.6).
void append_attribute(std::vector<uint8_t>* out, const MeshAttribute& attribute) {
  append_tag(out, "QMCATTR1");
  put_u32le(out, uint32_t(attribute.name.size()));
  out->insert(out->end(), attribute.name.begin(), attribute.name.end());
  put_u8(out, uint8_t(attribute.kind));
  put_u8(out, uint8_t(attribute.components));
  put_u32le(out, uint32_t(attribute.value_count()));
  for (float x : attribute.values) put_f32le(out, x);
  for (uint32_t m : attribute.corner_values) put_u32le(out, m);
}

void append_string(std::vector<uint8_t>* out, const std::string& s) {
  put_u32le(out, uint32_t(s.size()));
  out->insert(out->end(), s.begin(), s.end());
}

// Section 16.3's record of a chunk's face labels.
void append_face_labels(std::vector<uint8_t>* out, const FaceLabels& labels) {
  append_tag(out, "QMCFLBL1");
  append_string(out, labels.name);
  for (const auto* table : {&labels.references, &labels.values}) {
    put_u32le(out, uint32_t(table->size()));
    for (const std::string& s : *table) append_string(out, s);
  }
  for (uint32_t l : labels.face_values) put_u32le(out, l);
}

// Section 13.10.
void append_geometry_image(std::vector<uint8_t>* out, const DecodedFile& file) {
  const GeometryImageData& g = file.gim;
  append_tag(out, "QMCGIM01");
  put_u32le(out, g.width);
  put_u32le(out, g.height);
  put_u8(out, g.format);
  put_u8(out, g.face_mode);
  put_u8(out, g.flags);
  put_u8(out, g.plane_count);
  for (const GimPlaneData& p : g.planes) {
    put_u8(out, p.kind);
    put_f64le(out, p.offset);
    put_f64le(out, p.step);
  }
  out->insert(out->end(), g.occupied.begin(), g.occupied.end());
  for (const GimPlaneData& p : g.planes)
    for (uint32_t s : p.samples) put_u32le(out, s);
  const Mesh& mesh = file.mesh;
  put_u32le(out, uint32_t(mesh.vertex_count()));
  put_u32le(out, uint32_t(mesh.face_count()));
  for (float x : mesh.positions) put_f32le(out, x);
  for (uint32_t p : g.vertex_pixels) put_u32le(out, p);
  for (uint32_t d : mesh.face_sizes) put_u32le(out, d);
  for (uint32_t v : mesh.corners) put_u32le(out, v);
}

void append_canonical_output(std::vector<uint8_t>* out_bytes, const DecodedFile& file) {
  std::vector<uint8_t>& out = *out_bytes;
  if (file.gim.present) {
    append_geometry_image(&out, file);
    return;
  }
  if (file.loop_level_count == 0 || file.levels.empty()) {
    append_mesh(&out, file.mesh, file.quantized);
    for (const MeshAttribute& attribute : file.mesh.attributes) append_attribute(&out, attribute);
    for (const FaceLabels& labels : file.mesh.face_labels) append_face_labels(&out, labels);
    return;
  }
  // Section 12.9: the base mesh as in 10.2, then every level in binary64.
  append_tag(&out, "QMCLOOP1");
  put_u32le(&out, file.loop_level_count);
  append_mesh(&out, level_mesh(file.levels[0]), file.quantized);
  for (size_t j = 1; j < file.levels.size(); ++j) {
    const LoopLevel& level = file.levels[j];
    put_u32le(&out, level.vertex_count());
    put_u32le(&out, level.face_count());
    for (double x : level.positions) put_f64le(&out, x);
    for (uint32_t v : level.triangles) put_u32le(&out, v);
  }
}

}  // namespace

std::vector<uint8_t> canonical_output(const DecodedFile& file) {
  std::vector<uint8_t> out;
  QMC_TRY { append_canonical_output(&out, file); }
  QMC_CATCH_ALL(out.clear(); out.shrink_to_fit())
  return out;
}

}  // namespace qmc
