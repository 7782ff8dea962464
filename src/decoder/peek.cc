// peek() of decoder.h: what a file will cost (spec 8.1), from the chunks
// before its first CONN or GIMG and that chunk's header, without decoding.
#include <cstring>
#include <string>

#include "decoder/chunk_frame.h"
#include "decoder/connectivity_decoder.h"
#include "decoder/gim_decoder.h"
#include "decoder/loop_level_decoder.h"
#include "decoder/output_budget.h"
#include "qmc/decoder.h"

namespace qmc {
namespace {

// 12.9: the finest level has 4^K F faces; every level j has at least
// V_j-1 + 3 F_j-1 / 2 vertices (an edge is in at most two faces).
void add_level_bounds(FileSummary* s) {
  uint64_t vertices = s->vertex_count, faces = s->face_count;
  for (int j = 1; j <= s->loop_level_count; ++j) {
    vertices += (3 * faces + 1) / 2;
    faces *= 4;
    s->min_output_bytes += level_output_bytes(vertices, faces);
  }
  s->finest_face_count = faces;
}

Status peek_connectivity(const uint8_t* payload, uint32_t length, FileSummary* s) {
  uint8_t method = 0;
  size_t start = 0;
  if (Status st = read_connectivity_header(payload, length, &method, &s->vertex_count, &s->face_count, &start);
      !st.ok())
    return st;
  s->has_connectivity = true;
  s->method = ConnectivityMethod(method);
  s->min_output_bytes = mesh_output_bytes(s->vertex_count, s->face_count, 3 * s->face_count);
  if (s->loop_level_count > 0) {
    s->min_output_bytes += kLoopOutputHeaderBytes;
    add_level_bounds(s);
  }
  return Status::Ok();
}

Status peek_geometry_image(const uint8_t* payload, uint32_t length, FileSummary* s) {
  DecodedFile scratch;
  const DecoderLimits limits = DecoderLimits::unlimited();
  OutputBudget budget(limits.max_output_bytes);
  GimChunkDecoder gim(&scratch, &limits, &budget);
  if (Status st = gim.header(payload, length, false); !st.ok()) return st;
  s->has_geometry_image = true;
  s->gim_width = scratch.gim.width;
  s->gim_height = scratch.gim.height;
  s->gim_plane_count = scratch.gim.plane_count;
  s->min_output_bytes = gim_image_output_bytes(uint64_t(s->gim_width) * s->gim_height, s->gim_plane_count);
  return Status::Ok();
}

Status peek_chunk(uint32_t type, const uint8_t* payload, uint32_t length, FileSummary* s, bool* done) {
  switch (type) {
    case kChunkHeader: return read_version(payload, length, &s->version_major, &s->version_minor);
    case kChunkLoop: return decode_loop_header(payload, length, &s->loop_level_count);
    case kChunkConnectivity: *done = true; return peek_connectivity(payload, length, s);
    case kChunkGeometryImage: *done = true; return peek_geometry_image(payload, length, s);
    default: return Status::Ok();
  }
}

}  // namespace

DecoderLimits DecoderLimits::unlimited() {
  DecoderLimits l;
  l.max_vertices = l.max_faces = l.max_pixels = l.max_output_bytes = kNoLimit;
  l.max_levels = UINT32_MAX;
  return l;
}

Status peek(const uint8_t* data, size_t size, FileSummary* out) {
  *out = FileSummary{};
  if (size > 0 && std::memcmp(data, kSignature, size < sizeof(kSignature) ? size : sizeof(kSignature)) != 0)
    return Status(ErrorCode::kBadSignature, "the file does not start with the qmc signature (section 3.1)");
  size_t pos = sizeof(kSignature);
  while (size >= pos) {
    ChunkFrame frame;
    if (Status s = read_chunk_frame(data + pos, size - pos, pos, kMaxChunkLength, &frame); !s.ok()) return s;
    if (!frame.complete) break;
    bool done = false;
    if (Status s = peek_chunk(frame.type, data + pos + 8, frame.length, out, &done); !s.ok())
      return Status(s.code(), "at byte " + std::to_string(pos) + ": " + s.message());
    if (done) return Status::Ok();
    if (frame.type == kChunkEnd) return Status(ErrorCode::kChunkOrder, "QEND before CONN or GIMG");
    pos += 12 + size_t(frame.length);
  }
  return Status(ErrorCode::kTruncated, "peek: no CONN or GIMG header in the " + std::to_string(size) + " bytes given");
}

}  // namespace qmc
