// Geometry-image chunks, spec/qmc-format.md section 13 (seeds 000 and 002).
#include "decoder/gim_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "common/byte_io.h"
#include "common/exact_arith.h"
#include "common/gim_face_code.h"
#include "common/range_coder.h"
#include "common/union_find.h"
#include "decoder/gim_mesh_builder.h"
#include "decoder/plane_decoder.h"

namespace qmc {
namespace {

inline constexpr uint64_t kMaxGimPixels = uint64_t(1) << 24;  // 13.2
inline constexpr int kMinPlanes = 3, kMaxPlanes = 16;
inline constexpr uint8_t kMaxPlaneKind = 8;

Status payload_error(const std::string& message) { return Status(ErrorCode::kBadChunkPayload, message); }
Status order_error(const std::string& message) { return Status(ErrorCode::kChunkOrder, message); }

int64_t zigzag_decode(uint64_t v) { return (v & 1) ? -int64_t(v >> 1) - 1 : int64_t(v >> 1); }

bool finite_positive(double v) { return std::isfinite(v) && v > 0; }

Status read_plane_header(ByteReader* in, int index, uint8_t format, GimPlaneData* plane) {
  const std::string name = "GIMG: plane " + std::to_string(index);
  if (!in->get_u8(&plane->kind)) return payload_error(name + ": kind missing");
  const uint8_t expected = uint8_t(index);
  if (index < 3 ? plane->kind != expected : (plane->kind < 3 || plane->kind > kMaxPlaneKind))
    return payload_error(name + ": kind " + std::to_string(plane->kind) +
                         (index < 3 ? " (planes 0, 1, 2 are X, Y, Z: kinds 0, 1, 2)" : " (attribute kinds are 3..8)"));
  if (format != 0) return Status::Ok();
  if (!in->get_f64le(&plane->offset) || !std::isfinite(plane->offset))
    return payload_error(name + ": offset missing or not finite");
  if (!in->get_f64le(&plane->step) || !finite_positive(plane->step))
    return payload_error(name + ": step missing, not finite or not > 0");
  return Status::Ok();
}

std::vector<SeamPair> seam_list(const GeometryImageData& g) {
  std::vector<SeamPair> seams(g.seam_pairs.size() / 2);
  for (size_t i = 0; i < seams.size(); ++i) seams[i] = {g.seam_pairs[2 * i], g.seam_pairs[2 * i + 1]};
  return seams;
}

// 13.8, the last check: once the seams (all known: GSEM comes before GFAC)
// join pixels, no triangle may have two corners on one vertex. Only pixels
// named by a seam or a triangle matter, so the union-find runs over those:
// memory follows the two chunks, not W H, which no chunk may have justified
// yet (13.3).
Status check_joined_triangles(const GeometryImageData& g) {
  std::vector<uint32_t> named(g.seam_pairs);
  named.insert(named.end(), g.triangles.begin(), g.triangles.end());
  std::sort(named.begin(), named.end());
  named.erase(std::unique(named.begin(), named.end()), named.end());
  const auto id = [&named](uint32_t pixel) {
    return uint32_t(std::lower_bound(named.begin(), named.end(), pixel) - named.begin());
  };
  UnionFind classes(named.size());
  for (size_t i = 0; i + 1 < g.seam_pairs.size(); i += 2) classes.unite(id(g.seam_pairs[i]), id(g.seam_pairs[i + 1]));
  for (size_t t = 0; t < g.triangles.size() / 3; ++t) {
    uint32_t v[3];
    for (int k = 0; k < 3; ++k) v[k] = classes.find(id(g.triangles[3 * t + size_t(k)]));
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
      return payload_error("GFAC: triangle " + std::to_string(t) + " has two corners on the same vertex");
  }
  return Status::Ok();
}

}  // namespace

double GeometryImageData::value(int plane, uint32_t pixel) const {
  const GimPlaneData& p = planes[size_t(plane)];
  const uint32_t s = p.samples[pixel];
  if (format == 0) return p.offset + mul(double(s), p.step);
  float f;
  std::memcpy(&f, &s, sizeof f);
  return double(f);
}

Status GimChunkDecoder::header(const uint8_t* payload, uint32_t length, bool other_mesh_chunks_seen) {
  GeometryImageData& g = file_->gim;
  if (g.present) return order_error("a second GIMG");
  if (other_mesh_chunks_seen) return order_error("GIMG in a file with CONN, POSN or LOOP (section 13.1)");
  ByteReader in(payload, length);
  uint64_t w = 0, h = 0;
  if (!in.get_varint(&w) || w < 1 || w > 65535) return payload_error("GIMG: width missing or outside 1..65535");
  if (!in.get_varint(&h) || h < 1 || h > 65535) return payload_error("GIMG: height missing or outside 1..65535");
  if (w * h > kMaxGimPixels)
    return Status(ErrorCode::kLimitExceeded,
                  "GIMG: " + std::to_string(w) + " x " + std::to_string(h) + " pixels exceed 2^24");
  if (!in.get_u8(&g.format)) return payload_error("GIMG: format missing");
  if (g.format > 1)
    return Status(ErrorCode::kUnsupportedFeature, "GIMG: sample format " + std::to_string(g.format));
  if (!in.get_u8(&g.face_mode)) return payload_error("GIMG: face_mode missing");
  if (g.face_mode > 2)
    return Status(ErrorCode::kUnsupportedFeature, "GIMG: face mode " + std::to_string(g.face_mode));
  if (!in.get_u8(&g.flags) || (g.flags & 0xFC) != 0) return payload_error("GIMG: flags missing or reserved bits set");
  if (!in.get_u8(&g.plane_count) || g.plane_count < kMinPlanes || g.plane_count > kMaxPlanes)
    return payload_error("GIMG: plane count missing or outside 3..16");
  g.planes.assign(g.plane_count, GimPlaneData{});
  for (int i = 0; i < g.plane_count; ++i)
    if (Status s = read_plane_header(&in, i, g.format, &g.planes[size_t(i)]); !s.ok()) return s;
  if (in.remaining() != 0) return payload_error("GIMG: " + std::to_string(in.remaining()) + " bytes after the planes");
  if (Status s = check_limit("GIMG: pixels", w * h, limits_->max_pixels, "max_pixels"); !s.ok()) return s;
  if (Status s = budget_->charge(gim_image_output_bytes(w * h, g.plane_count), "GIMG"); !s.ok()) return s;
  g.width = uint32_t(w);
  g.height = uint32_t(h);
  g.present = true;
  return Status::Ok();
}

Status GimChunkDecoder::require_image(const char* chunk) const {
  if (!file_->gim.present) return order_error(std::string(chunk) + " without GIMG");
  if (file_->gim.planes_decoded() > 0) return order_error(std::string(chunk) + " after the first GPLN");
  return Status::Ok();
}

// 13.3: the first chunk that needs W x H memory must justify it, by the
// rule of its own payload (13.5.1, 13.6: W H <= 512 (L + 1), L the bytes
// after the predictor byte of a plane, all of a mask), before anything is
// reserved.
Status GimChunkDecoder::justify_size(const char* chunk, uint32_t length) {
  if (size_justified_) return Status::Ok();
  const uint64_t pixels = uint64_t(file_->gim.width) * file_->gim.height;
  const uint64_t stream = std::string(chunk) == "GPLN" && length > 0 ? length - 1 : length;
  if (pixels > 512 * (stream + 1))
    return Status(ErrorCode::kLimitExceeded, std::string(chunk) + ": " + std::to_string(length) +
                                                 " bytes cannot code " + std::to_string(pixels) +
                                                 " pixels (sections 13.3, 13.5.1, 13.6)");
  size_justified_ = true;
  return Status::Ok();
}

Status GimChunkDecoder::mask(const uint8_t* payload, uint32_t length) {
  if (Status s = require_image("GMSK"); !s.ok()) return s;
  GeometryImageData& g = file_->gim;
  if (mask_seen_) return order_error("a second GMSK");
  if ((g.flags & 1) == 0) return order_error("GMSK in an image whose GIMG flags say it has no mask");
  if (Status s = justify_size("GMSK", length); !s.ok()) return s;
  if (Status s = decode_mask(payload, length, g.width, g.height, &g.occupied); !s.ok())
    return Status(s.code(), "GMSK: " + s.message());
  g.mask_bytes = 12 + uint64_t(length);
  mask_seen_ = true;
  return Status::Ok();
}

Status GimChunkDecoder::seams(const uint8_t* payload, uint32_t length) {
  if (Status s = require_image("GSEM"); !s.ok()) return s;
  GeometryImageData& g = file_->gim;
  if (seams_seen_) return order_error("a second GSEM");
  if (faces_seen_) return order_error("GSEM after GFAC");
  if ((g.flags & 1) != 0 && !mask_seen_) return order_error("GSEM before GMSK");
  ByteReader in(payload, length);
  uint64_t runs = 0;
  if (!in.get_varint(&runs)) return payload_error("GSEM: run count missing or malformed");
  if (runs > length) return Status(ErrorCode::kLimitExceeded, "GSEM: " + std::to_string(runs) + " runs in " +
                                                                  std::to_string(length) + " bytes");
  const int64_t pixels = int64_t(g.width) * g.height;
  // 13.7: without a mask nothing has justified W H memory (13.3); a run
  // along a row or column has at most max(W, H) pairs and takes 5 bytes.
  const uint64_t max_unmasked_pairs = uint64_t(std::max(g.width, g.height)) * length;
  uint64_t total = 0;
  g.seam_pairs.clear();
  for (uint64_t r = 0; r < runs; ++r) {
    const std::string name = "GSEM: run " + std::to_string(r);
    uint64_t a = 0, b = 0, count = 0, za = 0, zb = 0;
    if (!in.get_varint(&a) || !in.get_varint(&b) || !in.get_varint(&count) || count == 0)
      return payload_error(name + ": a field is missing or malformed, or count is 0");
    // Compared before the sum so that a count near 2^64 cannot wrap it.
    if (count > uint64_t(pixels) - total)
      return Status(ErrorCode::kLimitExceeded, name + ": more seam pairs than pixels");
    total += count;
    if (g.occupied.empty() && total > max_unmasked_pairs)
      return Status(ErrorCode::kLimitExceeded, name + ": " + std::to_string(total) + " seam pairs in " +
                                                   std::to_string(length) +
                                                   " bytes of an image without a mask (13.7: max(W, H) per byte)");
    if (!in.get_varint(&za) || !in.get_varint(&zb)) return payload_error(name + ": a step is missing or malformed");
    const int64_t sa = zigzag_decode(za), sb = zigzag_decode(zb);
    if (a >= uint64_t(pixels) || b >= uint64_t(pixels)) return payload_error(name + ": a pixel outside the image");
    // A step longer than the image leaves it at the second pair; checking
    // that first keeps k * step within int64 (k < 2^24, |step| <= 2^24).
    if (count > 1 && (sa > pixels || sa < -pixels || sb > pixels || sb < -pixels))
      return payload_error(name + ": pair 1 leaves the image");
    for (uint64_t k = 0; k < count; ++k) {
      const int64_t pa = int64_t(a) + int64_t(k) * sa, pb = int64_t(b) + int64_t(k) * sb;
      if (pa < 0 || pb < 0 || pa >= pixels || pb >= pixels)
        return payload_error(name + ": pair " + std::to_string(k) + " leaves the image");
      const uint32_t ua = uint32_t(pa), ub = uint32_t(pb);
      const bool occupied_a = g.occupied.empty() || g.occupied[ua] != 0;
      const bool occupied_b = g.occupied.empty() || g.occupied[ub] != 0;
      if (ua == ub || !occupied_a || !occupied_b)
        return payload_error(name + ": pair " + std::to_string(k) + " (" + std::to_string(ua) + ", " +
                             std::to_string(ub) + ") " + (ua == ub ? "joins a pixel to itself" : "has a blank pixel"));
      g.seam_pairs.push_back(ua);
      g.seam_pairs.push_back(ub);
    }
  }
  if (in.remaining() != 0) return payload_error("GSEM: " + std::to_string(in.remaining()) + " bytes after the runs");
  g.seam_bytes = 12 + uint64_t(length);
  seams_seen_ = true;
  return Status::Ok();
}

Status GimChunkDecoder::faces(const uint8_t* payload, uint32_t length) {
  if (Status s = require_image("GFAC"); !s.ok()) return s;
  GeometryImageData& g = file_->gim;
  if (faces_seen_) return order_error("a second GFAC");
  if (g.face_mode != 2) return order_error("GFAC in an image whose face mode is not 2");
  if ((g.flags & 1) != 0 && !mask_seen_) return order_error("GFAC before GMSK");
  ByteReader in(payload, length);
  uint64_t count = 0;
  if (!in.get_varint(&count)) return payload_error("GFAC: triangle count missing or malformed");
  uint64_t occupied = uint64_t(g.width) * g.height;
  if (!g.occupied.empty()) {
    occupied = 0;
    for (uint8_t o : g.occupied) occupied += o;
  }
  if (count > 2 * occupied)
    return Status(ErrorCode::kLimitExceeded, "GFAC: " + std::to_string(count) + " triangles over " +
                                                 std::to_string(occupied) + " occupied pixels");
  // 13.8: six coded values a triangle, at most 512 decisions a byte (13.5.1).
  if (6 * count > 512 * (uint64_t(in.remaining()) + 1))
    return Status(ErrorCode::kLimitExceeded, "GFAC: " + std::to_string(count) + " triangles cannot fit in " +
                                                 std::to_string(in.remaining()) + " stream bytes");
  if (Status s = check_limit("GFAC: faces", count, limits_->max_faces, "max_faces"); !s.ok()) return s;
  RangeDecoder rc(in.cursor(), in.remaining());
  if (rc.bad_start()) return payload_error("GFAC: the stream starts with four 0xFF bytes");
  GimSignedContexts contexts[kGimFaceContextSets];
  g.triangles.assign(size_t(count) * 3, 0);
  int64_t x0 = 0, y0 = 0;
  for (uint64_t t = 0; t < count; ++t) {
    int32_t d[6];
    for (int k = 0; k < 6; ++k)
      if (!decode_gim_signed(&rc, &contexts[k], &d[k]))
        return Status(ErrorCode::kBadSymbol, "GFAC: triangle " + std::to_string(t) + ": a value of 18 or more bits");
    if (rc.overrun()) return Status(ErrorCode::kTruncated, "GFAC: the stream ends inside triangle " + std::to_string(t));
    x0 += d[0];
    y0 += d[1];
    const int64_t xs[3] = {x0, x0 + d[2], x0 + d[4]}, ys[3] = {y0, y0 + d[3], y0 + d[5]};
    for (int k = 0; k < 3; ++k) {
      if (xs[k] < 0 || ys[k] < 0 || xs[k] >= g.width || ys[k] >= g.height)
        return Status(ErrorCode::kBadSymbol, "GFAC: triangle " + std::to_string(t) + " corner " +
                                                 std::to_string(k) + " at (" + std::to_string(xs[k]) + ", " +
                                                 std::to_string(ys[k]) + ") is outside the image");
      const uint32_t p = uint32_t(ys[k]) * g.width + uint32_t(xs[k]);
      if (!g.occupied.empty() && g.occupied[p] == 0)
        return payload_error("GFAC: triangle " + std::to_string(t) + " corner " + std::to_string(k) +
                             " points at blank pixel (" + std::to_string(xs[k]) + ", " + std::to_string(ys[k]) + ")");
      g.triangles[size_t(3 * t) + size_t(k)] = p;
    }
  }
  if (rc.overrun()) return Status(ErrorCode::kTruncated, "GFAC: the stream ends early");
  if (rc.unread() != 0) return payload_error("GFAC: " + std::to_string(rc.unread()) + " bytes after the last triangle");
  if (Status s = check_joined_triangles(g); !s.ok()) return s;
  g.face_bytes = 12 + uint64_t(length);
  faces_seen_ = true;
  return Status::Ok();
}

Status GimChunkDecoder::plane(const uint8_t* payload, uint32_t length) {
  GeometryImageData& g = file_->gim;
  if (!g.present) return order_error("GPLN without GIMG");
  const int index = g.planes_decoded();
  if (index >= g.plane_count) return order_error("GPLN beyond the " + std::to_string(g.plane_count) + " planes of GIMG");
  if ((g.flags & 1) != 0 && !mask_seen_) return order_error("GPLN before GMSK");
  if (g.face_mode == 2 && !faces_seen_) return order_error("GPLN before GFAC");
  if (Status s = justify_size("GPLN", length); !s.ok()) return s;
  if (g.occupied.empty()) g.occupied.assign(size_t(g.width) * g.height, 1);
  PlaneLayout layout;
  layout.width = g.width;
  layout.height = g.height;
  layout.occupied = &g.occupied;
  layout.blank_stored = (g.flags & 2) != 0;
  layout.format = g.format == 0 ? GimSampleFormat::kUnorm16 : GimSampleFormat::kFloat32;
  GimPlaneData& plane = g.planes[size_t(index)];
  if (Status s = decode_plane(payload, length, layout, &plane.samples); !s.ok())
    return Status(s.code(), "GPLN " + std::to_string(index) + ": " + s.message());
  plane.chunk_bytes = 12 + uint64_t(length);
  if (index == 2) return build_mesh();
  return Status::Ok();
}

// 13.9: after plane 2, vertices, positions and faces.
Status GimChunkDecoder::build_mesh() {
  GeometryImageData& g = file_->gim;
  const size_t pixels = size_t(g.width) * g.height;
  const std::vector<SeamPair> seams = seam_list(g);
  GimTopologyInput in;
  in.width = g.width;
  in.height = g.height;
  in.occupied = &g.occupied;
  in.seams = &seams;
  in.mode = GimFaceMode(g.face_mode);
  in.triangles = &g.triangles;
  // Positions per pixel (binary32 as output, held in binary64), for 13.9
  // steps 2 and 3; blank pixels are never read.
  std::vector<double> xyz(pixels * 3, 0.0);
  GimTopology topology;
  // Vertex numbering first (no faces: an empty triangle list), so positions
  // are checked in vertex order before the faces need them.
  {
    const std::vector<uint32_t> no_triangles;
    GimTopologyInput numbering = in;
    numbering.mode = GimFaceMode::kExplicitTriangles;
    numbering.triangles = &no_triangles;
    if (Status s = build_gim_topology(numbering, &topology); !s.ok()) return Status(s.code(), "GSEM: " + s.message());
  }
  const uint64_t vertices = topology.pixel_of_vertex.size();
  if (Status s = check_limit("GPLN 2: mesh vertices", vertices, limits_->max_vertices, "max_vertices"); !s.ok())
    return s;
  if (Status s = budget_->charge(gim_mesh_output_bytes(vertices, 0, 0), "GPLN 2: mesh"); !s.ok()) return s;
  Mesh& mesh = file_->mesh;
  mesh.positions.assign(topology.pixel_of_vertex.size() * 3, 0.0f);
  for (size_t v = 0; v < topology.pixel_of_vertex.size(); ++v) {
    const uint32_t p = topology.pixel_of_vertex[v];
    for (int a = 0; a < 3; ++a) {
      const float f = float(g.value(a, p));
      if (!std::isfinite(f))
        return payload_error("vertex " + std::to_string(v) + " (pixel " + std::to_string(p) + ") has a coordinate " +
                             "that is not finite in binary32");
      mesh.positions[3 * v + size_t(a)] = f;
      xyz[3 * size_t(p) + size_t(a)] = double(f);
    }
  }
  in.xyz = xyz.data();
  if (Status s = build_gim_topology(in, &topology); !s.ok()) return Status(s.code(), "GFAC: " + s.message());
  const uint64_t faces = topology.face_sizes.size();
  if (Status s = check_limit("GPLN 2: mesh faces", faces, limits_->max_faces, "max_faces"); !s.ok()) return s;
  if (Status s = budget_->charge(4 * (faces + topology.corners.size()), "GPLN 2: mesh faces"); !s.ok()) return s;
  mesh.face_sizes = std::move(topology.face_sizes);
  mesh.corners = std::move(topology.corners);
  g.vertex_pixels = std::move(topology.pixel_of_vertex);
  mesh_built_ = true;
  return Status::Ok();
}

Status GimChunkDecoder::check_end() const {
  const GeometryImageData& g = file_->gim;
  if (g.planes_decoded() < g.plane_count)
    return order_error("QEND after " + std::to_string(g.planes_decoded()) + " of " + std::to_string(g.plane_count) +
                       " planes");
  return Status::Ok();
}

}  // namespace qmc
