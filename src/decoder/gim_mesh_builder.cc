// Rebuilding the mesh of a geometry image: spec/qmc-format.md section 13.9.
// Gu et al.'s geometry images (cited by seeds 000 and 002) are quad meshes by
// construction; seed 002's topology-preserving images carry their triangles.
#include "decoder/gim_mesh_builder.h"

#include <string>

#include "common/exact_arith.h"
#include "common/union_find.h"

namespace qmc {
namespace {

Status payload_error(const std::string& message) { return Status(ErrorCode::kBadChunkPayload, message); }

std::string pixel_name(uint32_t pixel, uint32_t width) {
  return "(" + std::to_string(pixel % width) + ", " + std::to_string(pixel / width) + ")";
}

bool occupied_at(const GimTopologyInput& in, uint32_t pixel) {
  return in.occupied == nullptr || (*in.occupied)[pixel] != 0;
}

// 13.9 steps 1-2: seams join pixels; each class is one vertex, named by its
// smallest pixel, and vertices are numbered in raster order of that pixel.
Status number_vertices(const GimTopologyInput& in, GimTopology* out) {
  const uint32_t pixels = in.width * in.height;
  std::vector<uint32_t> parent(pixels);
  for (uint32_t p = 0; p < pixels; ++p) parent[p] = p;
  if (in.seams != nullptr) {
    for (size_t i = 0; i < in.seams->size(); ++i) {
      const SeamPair s = (*in.seams)[i];
      if (s.a >= pixels || s.b >= pixels || s.a == s.b)
        return payload_error("seam pair " + std::to_string(i) + " is not two distinct pixels of the image");
      if (!occupied_at(in, s.a) || !occupied_at(in, s.b))
        return payload_error("seam pair " + std::to_string(i) + " joins blank pixel " +
                             pixel_name(occupied_at(in, s.a) ? s.b : s.a, in.width));
      union_find_join(parent, s.a, s.b);
    }
  }
  out->vertex_of_pixel.assign(pixels, kNoGimVertex);
  out->pixel_of_vertex.clear();
  for (uint32_t p = 0; p < pixels; ++p) {
    if (!occupied_at(in, p)) continue;
    const uint32_t root = union_find_root(parent, p);
    if (root == p) {
      out->vertex_of_pixel[p] = static_cast<uint32_t>(out->pixel_of_vertex.size());
      out->pixel_of_vertex.push_back(p);
    } else {
      out->vertex_of_pixel[p] = out->vertex_of_pixel[root];  // root < p: already numbered
    }
  }
  return Status::Ok();
}

// 13.9 step 4: drops cyclically repeated corners; a face keeps only if at
// least three distinct corners remain and none repeats.
void emit_face(const uint32_t* corners, int count, GimTopology* out) {
  uint32_t kept[4];
  int n = 0;
  for (int i = 0; i < count; ++i) {
    if (n > 0 && kept[n - 1] == corners[i]) continue;
    kept[n++] = corners[i];
  }
  while (n > 1 && kept[n - 1] == kept[0]) --n;
  if (n < 3) return;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (kept[i] == kept[j]) return;
  out->face_sizes.push_back(static_cast<uint32_t>(n));
  out->corners.insert(out->corners.end(), kept, kept + n);
}

double squared_distance(const double* xyz, uint32_t p, uint32_t q) {
  const double dx = xyz[3 * size_t{p}] - xyz[3 * size_t{q}];
  const double dy = xyz[3 * size_t{p} + 1] - xyz[3 * size_t{q} + 1];
  const double dz = xyz[3 * size_t{p} + 2] - xyz[3 * size_t{q} + 2];
  return mul(dx, dx) + mul(dy, dy) + mul(dz, dz);
}

// 13.9 step 3: one 2 x 2 block. Corner order (x,y) (x+1,y) (x+1,y+1) (x,y+1)
// runs counter-clockwise in the (x, y) plane, the orientation of section 13.9.
void emit_block(const GimTopologyInput& in, uint32_t x, uint32_t y, GimTopology* out) {
  const uint32_t w = in.width;
  const uint32_t pixel[4] = {y * w + x, y * w + x + 1, (y + 1) * w + x + 1, (y + 1) * w + x};
  uint32_t vertex[4];
  int blank = -1, blanks = 0;
  for (int i = 0; i < 4; ++i) {
    vertex[i] = out->vertex_of_pixel[pixel[i]];
    if (vertex[i] == kNoGimVertex) blank = i, ++blanks;
  }
  if (blanks > 1) return;
  if (blanks == 1) {
    uint32_t tri[3];
    for (int i = 1; i <= 3; ++i) tri[i - 1] = vertex[(blank + i) % 4];
    emit_face(tri, 3, out);
    return;
  }
  if (in.mode == GimFaceMode::kGridQuads) {
    emit_face(vertex, 4, out);
    return;
  }
  // Vertex positions, not pixel samples: seam pixels share their vertex's.
  const double* xyz = in.xyz;
  const uint32_t* rep = out->pixel_of_vertex.data();
  const double d02 = squared_distance(xyz, rep[vertex[0]], rep[vertex[2]]);
  const double d13 = squared_distance(xyz, rep[vertex[1]], rep[vertex[3]]);
  if (d13 < d02) {
    const uint32_t a[3] = {vertex[0], vertex[1], vertex[3]}, b[3] = {vertex[1], vertex[2], vertex[3]};
    emit_face(a, 3, out);
    emit_face(b, 3, out);
  } else {
    const uint32_t a[3] = {vertex[0], vertex[1], vertex[2]}, b[3] = {vertex[0], vertex[2], vertex[3]};
    emit_face(a, 3, out);
    emit_face(b, 3, out);
  }
}

Status build_explicit_faces(const GimTopologyInput& in, GimTopology* out) {
  const uint32_t pixels = in.width * in.height;
  const std::vector<uint32_t>& tris = *in.triangles;
  for (size_t t = 0; t < tris.size() / 3; ++t) {
    uint32_t v[3];
    for (int k = 0; k < 3; ++k) {
      const uint32_t p = tris[3 * t + k];
      if (p >= pixels)
        return payload_error("triangle " + std::to_string(t) + " corner " + std::to_string(k) + " is pixel " +
                             std::to_string(p) + ", outside the " + std::to_string(in.width) + " x " +
                             std::to_string(in.height) + " image");
      v[k] = out->vertex_of_pixel[p];
      if (v[k] == kNoGimVertex)
        return payload_error("triangle " + std::to_string(t) + " corner " + std::to_string(k) +
                             " points at blank pixel " + pixel_name(p, in.width));
    }
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
      return payload_error("triangle " + std::to_string(t) + " has two corners on the same vertex");
    out->face_sizes.push_back(3);
    out->corners.insert(out->corners.end(), v, v + 3);
  }
  return Status::Ok();
}

}  // namespace

Status build_gim_topology(const GimTopologyInput& in, GimTopology* out) {
  out->face_sizes.clear();
  out->corners.clear();
  Status status = number_vertices(in, out);
  if (!status.ok()) return status;
  if (in.mode == GimFaceMode::kExplicitTriangles) {
    if (in.triangles == nullptr) return payload_error("a topology-preserving image needs its triangle list");
    return build_explicit_faces(in, out);
  }
  if (in.mode == GimFaceMode::kGridTriangles && in.xyz == nullptr)
    return Status(ErrorCode::kInvalidArgument, "grid triangulation needs the sample positions");
  for (uint32_t y = 0; y + 1 < in.height; ++y)
    for (uint32_t x = 0; x + 1 < in.width; ++x) emit_block(in, x, y, out);
  return Status::Ok();
}

}  // namespace qmc
