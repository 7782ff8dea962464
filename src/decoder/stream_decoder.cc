// The container of spec/qmc-format.md sections 3 and 4: signature, chunk
// framing, CRC, the required chunk order, and dispatch to the chunk
// decoders. decode() is the streaming decoder fed all bytes at once.
#include <cstring>
#include <new>
#include <string>

#include "common/byte_io.h"
#include "decoder/attribute_decoder.h"
#include "decoder/chunk_frame.h"
#include "decoder/connectivity_decoder.h"
#include "decoder/face_label_decoder.h"
#include "decoder/gim_decoder.h"
#include "decoder/loop_level_decoder.h"
#include "decoder/no_throw.h"
#include "decoder/order_decoder.h"
#include "decoder/output_budget.h"
#include "decoder/position_decoder.h"
#include "qmc/decoder.h"

namespace qmc {

struct StreamDecoder::State {
  explicit State(const DecoderLimits& l) : limits(l), budget(l.max_output_bytes) {}
  DecoderLimits limits;
  OutputBudget budget;      // section 8.1
  std::vector<uint8_t> pending;  // bytes of a unit (signature or chunk) not yet complete
  uint64_t offset = 0;           // file offset of the first byte not yet consumed
  bool signature_seen = false, header_seen = false, connectivity_seen = false, positions_seen = false;
  bool complete = false;
  bool order_seen = false;  // oRDR (section 4.5)
  std::vector<std::string> attribute_names;  // of every aTTR so far, skipped ones included (15.1)
  uint32_t vertex_count = 0;
  uint64_t base_bytes = 0;  // CONN and POSN chunks of a progressive file
  LoopEdges level_edges;    // section 12.3: edges of the finest level so far
  DecodedFile file;
  GimChunkDecoder gim{&file, &limits, &budget};  // section 13
  Status error;

  Status consume(const uint8_t* data, size_t size, size_t* used);
  Status consume_signature(const uint8_t* data, size_t size, size_t* used);
  Status handle_chunk(uint32_t type, const uint8_t* payload, uint32_t length);
  Status handle_header(const uint8_t* payload, uint32_t length);
  Status handle_connectivity(const uint8_t* payload, uint32_t length);
  Status check_connectivity_counts(const uint8_t* payload, uint32_t length);
  Status check_level_counts(uint8_t level);
  Status check_next_level_fits(uint8_t level);
  Status check_level_limits(const std::string& what, uint64_t level, uint64_t vertices, uint64_t faces, bool charge);
  Status handle_positions(const uint8_t* payload, uint32_t length);
  Status handle_order(const uint8_t* payload, uint32_t length);
  Status handle_attribute(const uint8_t* payload, uint32_t length, bool* skipped);
  Status handle_face_labels(const uint8_t* payload, uint32_t length);
  Status check_mesh_extension(const char* type, const char* section) const;
  Status handle_loop(const uint8_t* payload, uint32_t length);
  Status handle_level(const uint8_t* payload, uint32_t length);
  Status handle_end(uint32_t length);
};

namespace {

Status order_error(const std::string& message) { return Status(ErrorCode::kChunkOrder, message); }

}  // namespace

std::string chunk_type_name(uint32_t type) {
  std::string name;
  for (int shift = 24; shift >= 0; shift -= 8) {
    const uint8_t c = uint8_t(type >> shift);
    if (c >= 0x20 && c < 0x7F) {
      name += char(c);
    } else {
      static const char kHex[] = "0123456789ABCDEF";
      name += "\\x";
      name += kHex[c >> 4];
      name += kHex[c & 15];
    }
  }
  return name;
}

const char* connectivity_method_name(ConnectivityMethod method) {
  switch (method) {
    case ConnectivityMethod::kIndexed: return "indexed";
    case ConnectivityMethod::kQuad: return "quad";
    case ConnectivityMethod::kPolygon: return "polygon";
  }
  return "unknown";
}

Status StreamDecoder::State::consume_signature(const uint8_t* data, size_t size, size_t* used) {
  const size_t n = size < sizeof(kSignature) ? size : sizeof(kSignature);
  if (n == 0) return Status::Ok();  // nothing to compare (and data may be null)
  if (std::memcmp(data, kSignature, n) != 0)
    return Status(ErrorCode::kBadSignature, "the file does not start with the qmc signature (section 3.1)");
  if (n == sizeof(kSignature)) {
    signature_seen = true;
    *used = n;
  }
  return Status::Ok();
}

Status StreamDecoder::State::consume(const uint8_t* data, size_t size, size_t* used) {
  size_t pos = 0;
  *used = 0;
  if (!signature_seen) {
    if (Status s = consume_signature(data, size, &pos); !s.ok() || !signature_seen) return s;
    offset += pos;
  }
  while (pos < size) {
    if (complete)
      return Status(ErrorCode::kTrailingData, "at byte " + std::to_string(offset) + ": data after QEND");
    ChunkFrame frame;
    if (Status s = read_chunk_frame(data + pos, size - pos, offset, limits.max_chunk_length, &frame); !s.ok())
      return s;
    if (!frame.complete) break;
    const uint32_t type = frame.type, length = frame.length;
    const uint8_t* chunk = data + pos;
    if (Status s = handle_chunk(type, chunk + 8, length); !s.ok())
      return Status(s.code(), "at byte " + std::to_string(offset) + ": " + s.message());
    pos += 12 + size_t(length);
    offset += 12 + uint64_t(length);
    *used = pos;
  }
  *used = pos;
  return Status::Ok();
}

Status StreamDecoder::State::handle_chunk(uint32_t type, const uint8_t* payload, uint32_t length) {
  ChunkInfo info;
  info.type = type;
  info.offset = offset;
  info.length = length;
  info.critical = chunk_is_critical(type);
  info.known = true;
  if (!header_seen && type != kChunkHeader)
    return order_error("the first chunk must be QHDR, found " + chunk_type_name(type));
  if (gim.active() && (type == kChunkConnectivity || type == kChunkPositions || type == kChunkLoop ||
                       type == kChunkLevel || type == kChunkOrder || type == kChunkAttribute ||
                       type == kChunkFaceLabels))
    return order_error(chunk_type_name(type) + " in a geometry-image file (section 13.1)");
  Status s;
  switch (type) {
    case kChunkHeader: s = handle_header(payload, length); break;
    case kChunkConnectivity: s = handle_connectivity(payload, length); break;
    case kChunkPositions: s = handle_positions(payload, length); break;
    case kChunkEnd: s = handle_end(length); break;
    case kChunkText: file.texts.emplace_back(reinterpret_cast<const char*>(payload), length); break;
    case kChunkOrder: s = handle_order(payload, length); break;
    case kChunkFaceLabels: s = handle_face_labels(payload, length); break;
    case kChunkAttribute: {
      bool skipped = false;
      s = handle_attribute(payload, length, &skipped);
      info.known = !skipped;  // 15.1: a mapping or coding of a later revision
      break;
    }
    case kChunkLoop: s = handle_loop(payload, length); break;
    case kChunkLevel: s = handle_level(payload, length); break;
    case kChunkGeometryImage:
      s = gim.header(payload, length, connectivity_seen || positions_seen || file.loop_level_count > 0);
      break;
    case kChunkGimMask: s = gim.mask(payload, length); break;
    case kChunkGimSeams: s = gim.seams(payload, length); break;
    case kChunkGimFaces: s = gim.faces(payload, length); break;
    case kChunkGimPlane: s = gim.plane(payload, length); break;
    default:
      if (info.critical)
        return Status(ErrorCode::kUnknownCriticalChunk, "unknown critical chunk " + chunk_type_name(type));
      info.known = false;  // section 3.3: unknown ancillary chunks are skipped
  }
  if (s.ok()) file.chunks.push_back(info);
  return s;
}

Status StreamDecoder::State::handle_header(const uint8_t* payload, uint32_t length) {
  if (header_seen) return order_error("a second QHDR");
  if (Status s = read_version(payload, length, &file.version_major, &file.version_minor); !s.ok()) return s;
  header_seen = true;
  return Status::Ok();
}

// Section 8.1: CONN's counts against the embedder's limits before any memory
// is reserved for them; the output is charged at its smallest (3 corners a
// face), the corners beyond that once decoded.
Status StreamDecoder::State::check_connectivity_counts(const uint8_t* payload, uint32_t length) {
  uint8_t method = 0;
  uint64_t vertices = 0, faces = 0;
  size_t start = 0;
  if (Status s = read_connectivity_header(payload, length, &method, &vertices, &faces, &start); !s.ok()) return s;
  if (Status s = check_limit("CONN: vertices", vertices, limits.max_vertices, "max_vertices"); !s.ok()) return s;
  if (Status s = check_limit("CONN: faces", faces, limits.max_faces, "max_faces"); !s.ok()) return s;
  const uint64_t header = file.loop_level_count > 0 ? kLoopOutputHeaderBytes : 0;
  return budget.charge(header + mesh_output_bytes(vertices, faces, 3 * faces), "CONN");
}

Status StreamDecoder::State::handle_connectivity(const uint8_t* payload, uint32_t length) {
  if (connectivity_seen) return order_error("a second CONN");
  if (Status s = check_connectivity_counts(payload, length); !s.ok()) return s;
  QuadConnectivityInfo quad;
  PolygonConnectivityInfo polygon;
  if (Status s = decode_connectivity(payload, length, &vertex_count, &file.method, &file.mesh, &quad, &polygon,
                                     &budget);
      !s.ok())
    return s;
  const uint64_t extra_corners = file.mesh.corners.size() - 3 * uint64_t(file.mesh.face_count());
  if (Status s = budget.charge(4 * extra_corners, "CONN"); !s.ok()) return s;
  if (file.method == ConnectivityMethod::kPolygon) {
    file.polygon_coding = polygon.coding;
    file.polygon_components = polygon.components;
    file.polygon_virtual_faces = polygon.virtual_faces;
    file.polygon_seams = polygon.seams;
    file.polygon_identifications = polygon.identifications;
    file.polygon_loose_faces = polygon.loose_faces;
  }
  if (file.method == ConnectivityMethod::kQuad) {
    file.quad_coding = quad.coding;
    file.quad_closed = quad.closed;
  }
  if (file.loop_level_count > 0) {  // section 12.2
    file.levels.resize(1);
    if (Status s = loop_base_connectivity(file.mesh, vertex_count, &file.levels[0], &level_edges); !s.ok()) return s;
    base_bytes = 12 + uint64_t(length);
  }
  connectivity_seen = true;
  return Status::Ok();
}

Status StreamDecoder::State::handle_positions(const uint8_t* payload, uint32_t length) {
  if (!connectivity_seen) return order_error("POSN before CONN");
  if (positions_seen) return order_error("a second POSN");
  Status s = decode_positions(payload, length, file.mesh, vertex_count, &file.quantization, &file.quantized,
                              &file.mesh.positions);
  if (!s.ok()) return s;
  if (file.loop_level_count > 0) {
    loop_base_positions(file.quantization, file.quantized, &file.levels[0]);
    file.levels[0].chunk_bytes = base_bytes + 12 + uint64_t(length);
  }
  positions_seen = true;
  return Status::Ok();
}

// Section 4.5: applied as soon as it arrives; until then file() is in coder order.
Status StreamDecoder::State::handle_order(const uint8_t* payload, uint32_t length) {
  if (!positions_seen) return order_error("oRDR before POSN");
  if (file.loop_level_count > 0) return order_error("oRDR in a progressive file (section 12.1)");
  if (order_seen) return order_error("a second oRDR");
  OrderMaps maps;
  if (Status s = decode_order(payload, length, vertex_count, file.mesh, &maps); !s.ok()) return s;
  std::vector<uint8_t> per_vertex;  // 15.6: mapping 0's values move with their vertices
  for (const AttributeCoding& c : file.attribute_codings) per_vertex.push_back(c.mapping == 0 ? 1 : 0);
  apply_order(maps, &file.mesh, &file.quantized, per_vertex);
  file.order_restored = true;
  file.order_flags = maps.flags;
  order_seen = true;
  return Status::Ok();
}

// Sections 15.1 and 16.1: after POSN, before oRDR, not in a progressive file.
Status StreamDecoder::State::check_mesh_extension(const char* type, const char* section) const {
  if (!positions_seen) return order_error(std::string(type) + " before POSN");
  if (file.loop_level_count > 0)
    return order_error(std::string(type) + " in a progressive file (section " + section + ")");
  if (order_seen) return order_error(std::string(type) + " after oRDR (section " + section + ")");
  return Status::Ok();
}

// Section 16.
Status StreamDecoder::State::handle_face_labels(const uint8_t* payload, uint32_t length) {
  if (Status s = check_mesh_extension("fLBL", "16.1"); !s.ok()) return s;
  FaceLabels labels;
  if (Status s = decode_face_labels(payload, length, file.mesh.face_count(), file.mesh.face_labels, &budget, &labels);
      !s.ok())
    return s;
  file.mesh.face_labels.push_back(std::move(labels));
  return Status::Ok();
}

// Section 15.
Status StreamDecoder::State::handle_attribute(const uint8_t* payload, uint32_t length, bool* skipped) {
  if (Status s = check_mesh_extension("aTTR", "15.1"); !s.ok()) return s;
  MeshAttribute attribute;
  AttributeCoding coding;
  if (Status s = decode_attribute(payload, length, file.mesh, vertex_count, file.quantized, attribute_names, &budget,
                                  &attribute, &coding, skipped);
      !s.ok())
    return s;
  attribute_names.push_back(attribute.name);
  if (*skipped) return Status::Ok();
  file.mesh.attributes.push_back(std::move(attribute));
  file.attribute_codings.push_back(coding);
  return Status::Ok();
}

// Section 12.1: LOOP before CONN, once.
Status StreamDecoder::State::handle_loop(const uint8_t* payload, uint32_t length) {
  if (file.loop_level_count > 0) return order_error("a second LOOP");
  if (connectivity_seen) return order_error("LOOP after CONN");
  if (order_seen) return order_error("LOOP in a file with oRDR (section 12.1)");
  return decode_loop_header(payload, length, &file.loop_level_count);
}

// Section 12.5-12.8: each LEVL refines the finest level the moment it lands.
Status StreamDecoder::State::handle_level(const uint8_t* payload, uint32_t length) {
  if (file.loop_level_count == 0) return order_error("LEVL without LOOP");
  if (!positions_seen) return order_error("LEVL before POSN: a level before its base mesh");
  if (file.levels.size() > file.loop_level_count)
    return order_error("LEVL beyond the " + std::to_string(file.loop_level_count) + " levels LOOP declared");
  const uint8_t j = uint8_t(file.levels.size());
  if (Status s = check_level_counts(j); !s.ok()) return s;
  LoopLevel fine;
  if (Status s = decode_level(payload, length, j, file.levels.back(), level_edges, &fine); !s.ok()) return s;
  fine.chunk_bytes = 12 + uint64_t(length);
  file.levels.push_back(std::move(fine));
  file.mesh = level_mesh(file.levels.back());
  if (j == file.loop_level_count) return Status::Ok();
  // The edges of level j, needed by level j + 1 only, cost more memory than
  // level j's output: level j + 1 must fit before they are numbered (8.1).
  if (Status s = check_next_level_fits(j); !s.ok()) return s;
  if (Status s = number_loop_edges(file.levels.back(), &level_edges); !s.ok())
    return Status(ErrorCode::kBadChunkPayload, "LEVL: level " + std::to_string(j) + ": " + s.message());
  return Status::Ok();
}

// Section 8.1: what level j tells of level j + 1 before its edges are
// numbered: 4 F_j faces and at least V_j + 3 F_j / 2 vertices.
Status StreamDecoder::State::check_next_level_fits(uint8_t level) {
  const LoopLevel& current = file.levels.back();
  const uint64_t vertices = current.vertex_count() + (3 * uint64_t(current.face_count()) + 1) / 2;
  return check_level_limits("LEVL: level " + std::to_string(level) + ": the next level", level + 1u, vertices,
                            4 * uint64_t(current.face_count()), false);
}

// Section 8.1: level j has V + E vertices and 4 F faces of level j - 1.
Status StreamDecoder::State::check_level_counts(uint8_t level) {
  const LoopLevel& coarse = file.levels.back();
  return check_level_limits("LEVL: level " + std::to_string(level), level,
                            uint64_t(coarse.vertex_count()) + level_edges.edge_count(),
                            4 * uint64_t(coarse.face_count()), true);
}

// Level `level` with these counts against every limit of 8.1; its output is
// charged when its chunk has arrived, only checked when foretold.
Status StreamDecoder::State::check_level_limits(const std::string& what, uint64_t level, uint64_t vertices,
                                                uint64_t faces, bool charge) {
  if (Status s = check_limit(what + ": levels", level, limits.max_levels, "max_levels"); !s.ok()) return s;
  if (Status s = check_limit(what + ": vertices", vertices, limits.max_vertices, "max_vertices"); !s.ok()) return s;
  if (Status s = check_limit(what + ": faces", faces, limits.max_faces, "max_faces"); !s.ok()) return s;
  const uint64_t bytes = level_output_bytes(vertices, faces);
  return charge ? budget.charge(bytes, what) : budget.check(bytes, what);
}

Status StreamDecoder::State::handle_end(uint32_t length) {
  // Section 3.6: order rules before payload checks.
  if (gim.active()) {
    if (Status s = gim.check_end(); !s.ok()) return s;
    if (length != 0) return Status(ErrorCode::kBadChunkPayload, "QEND payload must be empty");
    complete = true;
    return Status::Ok();
  }
  if (!connectivity_seen || !positions_seen)
    return order_error(std::string("QEND before ") + (connectivity_seen ? "POSN" : "CONN"));
  if (file.loop_level_count > 0 && file.levels.size() <= file.loop_level_count)
    return order_error("QEND after " + std::to_string(file.levels.size() - 1) + " of " +
                       std::to_string(file.loop_level_count) + " levels");
  if (length != 0) return Status(ErrorCode::kBadChunkPayload, "QEND payload must be empty");
  complete = true;
  return Status::Ok();
}

namespace {

Status out_of_memory(uint64_t offset) {
  return Status(ErrorCode::kLimitExceeded,
                "at byte " + std::to_string(offset) + ": out of memory (section 8.1: lower DecoderLimits)");
}

}  // namespace

StreamDecoder::StreamDecoder(const DecoderLimits& limits) : state_(new (std::nothrow) State(limits)) {}
StreamDecoder::~StreamDecoder() = default;

Status StreamDecoder::feed(const uint8_t* data, size_t size) {
  if (!state_) return out_of_memory(0);
  State& st = *state_;
  if (!st.error.ok()) return st.error;
  size_t used = 0;
  QMC_TRY {
    if (st.pending.empty()) {
      st.error = st.consume(data, size, &used);
      if (st.error.ok() && used < size) st.pending.assign(data + used, data + size);
    } else {
      if (size > 0) st.pending.insert(st.pending.end(), data, data + size);
      st.error = st.consume(st.pending.data(), st.pending.size(), &used);
      if (st.error.ok()) st.pending.erase(st.pending.begin(), st.pending.begin() + std::ptrdiff_t(used));
    }
  }
  QMC_CATCH_ALL(st.error = out_of_memory(st.offset))
  return st.error;
}

Status StreamDecoder::finish() {
  if (!state_) return out_of_memory(0);
  State& st = *state_;
  if (!st.error.ok()) return st.error;
  if (st.complete) return Status::Ok();
  if (!st.signature_seen)
    st.error = Status(ErrorCode::kTruncated, "the input ends inside the signature");
  else if (!st.pending.empty())
    st.error = Status(ErrorCode::kTruncated, "the input ends inside the chunk at byte " + std::to_string(st.offset));
  else
    st.error = Status(ErrorCode::kTruncated, "the input ends before QEND");
  return st.error;
}

namespace {
const DecodedFile kNoFile;
}  // namespace

bool StreamDecoder::complete() const { return state_ && state_->complete; }
bool StreamDecoder::has_connectivity() const {
  return state_ && (state_->connectivity_seen || state_->gim.mesh_ready());
}
bool StreamDecoder::has_positions() const { return state_ && (state_->positions_seen || state_->gim.mesh_ready()); }
int StreamDecoder::complete_level() const {
  if (!state_) return -1;
  const DecodedFile& f = state_->file;
  return f.loop_level_count > 0 && state_->positions_seen ? int(f.levels.size()) - 1 : -1;
}
int StreamDecoder::level_count() const { return state_ ? state_->file.loop_level_count : 0; }
const DecodedFile& StreamDecoder::file() const { return state_ ? state_->file : kNoFile; }
DecodedFile StreamDecoder::take_file() { return state_ ? std::move(state_->file) : DecodedFile(); }

Status decode(const uint8_t* data, size_t size, DecodedFile* out, const DecoderLimits& limits) {
  StreamDecoder decoder(limits);
  if (Status s = decoder.feed(data, size); !s.ok()) return s;
  if (Status s = decoder.finish(); !s.ok()) return s;
  *out = decoder.take_file();
  return Status::Ok();
}

}  // namespace qmc
