// The encoder entry point: validates the input, relabels vertices, and
// writes the chunks in the order spec/qmc-format.md section 4 requires.
#include "qmc/encoder.h"

#include <cmath>
#include <string>

#include "common/byte_io.h"
#include "encoder/attribute_encoder.h"
#include "encoder/chunk_writer.h"
#include "encoder/gim_encoder.h"
#include "encoder/encoder_internal.h"
#include "encoder/face_label_encoder.h"
#include "encoder/indexed_connectivity_encoder.h"
#include "encoder/loop_encoder.h"
#include "encoder/order_encoder.h"
#include "decoder/connectivity_decoder.h"
#include "decoder/position_decoder.h"
#include "encoder/polygon_connectivity_encoder.h"
#include "encoder/position_encoder.h"
#include "encoder/quad_connectivity_encoder.h"
#include "encoder/quad_traversal_encoder.h"
#include "encoder/vertex_order.h"

namespace qmc {
namespace {

Status invalid(const std::string& message) { return Status(ErrorCode::kInvalidArgument, message); }

// Sections 15 and 16: what aTTR and fLBL can carry, and only in a plain file.
Status validate_attributes(const Mesh& mesh, const EncodeOptions& options) {
  for (int bits : {options.texcoord_bits, options.normal_bits, options.colour_bits, options.generic_bits})
    if (bits < 1 || bits > 30) return invalid("attribute bits must be in 1..30, got " + std::to_string(bits));
  if (mesh.attributes.empty() && mesh.face_labels.empty()) return Status::Ok();
  if (options.progressive_levels > 0 || options.gim.size > 0)
    return invalid(std::string("a ") + (options.progressive_levels > 0 ? "progressive file" : "geometry image") +
                   " cannot carry attributes or face labels (sections 15.1, 16.1): drop them first");
  for (size_t i = 0; i < mesh.attributes.size(); ++i)
    if (std::string why = attribute_problem(mesh, i, options.exact_attributes); !why.empty()) return invalid(why);
  for (size_t i = 0; i < mesh.face_labels.size(); ++i)
    if (std::string why = face_label_problem(mesh, i); !why.empty()) return invalid(why);
  return Status::Ok();
}

}  // namespace

Status validate_options(const EncodeOptions& options) {
  if (options.position_bits < kMinPositionBits || options.position_bits > kMaxPositionBits)
    return invalid("position bits must be in " + std::to_string(kMinPositionBits) + ".." +
                   std::to_string(kMaxPositionBits) + ", got " + std::to_string(options.position_bits));
  for (const std::string& text : options.texts)
    if (text.size() > kMaxChunkLength) return invalid("text too long for one chunk");
  if (options.polygon_coding < -1 || options.polygon_coding >= kPolygonCodingCount)
    return invalid("polygon coding must be -1 (smallest) or 0.." + std::to_string(kPolygonCodingCount - 1));
  if (options.displacement_code != -1 && options.displacement_code != 0 && options.displacement_code != 2)
    return invalid("the displacement code must be -1 (smaller), 0 (section 12.7) or 2 (12.7.1), got " +
                   std::to_string(options.displacement_code));
  if (options.progressive_levels < 0 || options.progressive_levels > 8)
    return invalid("progressive levels must be 0 (not progressive) or 1..8, got " +
                   std::to_string(options.progressive_levels));
  if (options.progressive_levels > 0 && options.keep_order)
    return invalid("a progressive file has no input order to keep (section 12.1): drop keep_order");
  if (!(options.position_step >= 0) || !std::isfinite(options.position_step))
    return invalid("the position step must be a finite number > 0 (or 0: from the bits)");
  if (!(options.max_position_error >= 0) || !std::isfinite(options.max_position_error))
    return invalid("the max position error must be a finite number > 0 (or 0: from the bits)");
  if (options.position_step > 0 && options.max_position_error > 0)
    return invalid("give a position step or a max position error, not both");
  if (options.position_method == PositionMethod::kDeltas && options.progressive_levels == 0 &&
      (options.position_grid != PositionGrid::kPerAxis || options.position_step > 0 || options.max_position_error > 0))
    return invalid("position method 0 (deltas, section 6) carries only the per-axis grid of section 6.1");
  if (options.progressive_levels > 0 && (options.position_step > 0 || options.max_position_error > 0))
    return invalid("a progressive file's base takes section 6.1's grid of position_bits: no step or max error");
  if (options.quad_coding < -1 || options.quad_coding >= kQuadCodingCount)
    return invalid("quad coding must be -1 (smallest) or 0.." + std::to_string(kQuadCodingCount - 1));
  if (!(options.finest_step_scale >= 1 && options.finest_step_scale <= 64))
    return invalid("the finest level's step scale must be in 1..64 (12.10)");
  if (!(options.max_deviation >= 0 && options.max_deviation < 1))
    return invalid("the max deviation must be 0 (none) or a fraction of the diagonal below 1 (12.7.2)");
  if (options.max_deviation > 0 && options.progressive_levels == 0)
    return invalid("a max deviation corrects progressive levels (12.7.2): give progressive levels too");
  if (options.start_faces < 1 || options.start_faces > kMaxStartFaces)
    return invalid("start faces must be in 1.." + std::to_string(kMaxStartFaces) + ", got " +
                   std::to_string(options.start_faces));
  if (options.start_faces > 1 && (options.progressive_levels > 0 || options.gim.size > 0))
    return invalid("start faces choose a single-rate file's first faces (5.4.2): not with progressive levels or "
                   "a geometry image");
  return Status::Ok();
}

Status validate_input(const Mesh& mesh, const EncodeOptions& options) {
  if (Status s = validate_options(options); !s.ok()) return s;
  if (mesh.positions.size() % 3 != 0) return invalid("positions are not a multiple of 3 floats");
  if (mesh.vertex_count() > UINT32_MAX || mesh.face_count() > UINT32_MAX)
    return invalid("more than 2^32 - 1 vertices or faces");
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i]))
      return invalid("vertex " + std::to_string(i / 3) + " has a non-finite coordinate");
  uint64_t total = 0;
  for (size_t f = 0; f < mesh.face_sizes.size(); ++f) {
    if (mesh.face_sizes[f] < 3)
      return invalid("face " + std::to_string(f) + " has " + std::to_string(mesh.face_sizes[f]) +
                     " corners; a face needs at least 3");
    total += mesh.face_sizes[f];
  }
  if (total != mesh.corners.size())
    return invalid("face sizes add up to " + std::to_string(total) + " corners but " +
                   std::to_string(mesh.corners.size()) + " are given");
  for (size_t k = 0; k < mesh.corners.size(); ++k)
    if (mesh.corners[k] >= mesh.vertex_count())
      return invalid("corner " + std::to_string(k) + " names vertex " + std::to_string(mesh.corners[k]) +
                     " of " + std::to_string(mesh.vertex_count()));
  return validate_attributes(mesh, options);
}

namespace {

std::vector<float> permuted_positions(const Mesh& mesh, const std::vector<uint32_t>& file_vertex) {
  std::vector<float> out;
  out.reserve(mesh.positions.size());
  for (uint32_t v : file_vertex)
    for (int a = 0; a < 3; ++a) out.push_back(mesh.positions[3 * size_t(v) + a]);
  return out;
}

FileConnectivity indexed_connectivity(const Mesh& mesh) {
  FileConnectivity c;
  const VertexOrder order = first_reference_order(mesh);
  c.mesh = relabel(mesh, order);
  c.payload = encode_indexed_connectivity(c.mesh);
  c.file_vertex = order.file_vertex;
  c.face_source.resize(mesh.face_count());
  for (uint32_t f = 0; f < c.face_source.size(); ++f) c.face_source[f] = f;
  return c;
}

// Decodes the coder's own CONN payload; "" if it gives back the file mesh.
std::string self_check(const FileConnectivity& c, size_t vertex_count, const char* coder) {
  Mesh check;
  uint32_t vertices = 0;
  ConnectivityMethod method;
  const Status decoded = decode_connectivity(c.payload.data(), c.payload.size(), &vertices, &method, &check);
  if (decoded.ok() && check.corners == c.mesh.corners && check.face_sizes == c.mesh.face_sizes &&
      vertices == vertex_count)
    return {};
  return std::string("internal: the ") + coder + "'s output did not decode to the input (" + decoded.to_string() + ")";
}

// The quad coder (section 5.3), checked by decoding its own output: a mesh
// it would get wrong goes to the polygon coder instead, with the reason.
std::string quad_connectivity(const Mesh& mesh, int forced_coding, FileConnectivity* c, QuadCoderStats* stats) {
  QuadTraversal traversal;
  if (std::string why = encode_quad_traversal(mesh, &traversal); !why.empty()) return why;
  QuadCodingChoice choice;
  c->method = ConnectivityMethod::kQuad;
  c->payload = encode_quad_connectivity(traversal, uint32_t(mesh.vertex_count()), forced_coding, &choice);
  if (c->payload.empty())
    return std::string(quad_coding_name(QuadCoding(forced_coding))) + " cannot code this mesh's interaction types";
  c->mesh.face_sizes.assign(traversal.faces.size() / 4, 4);
  c->mesh.corners = traversal.faces;
  c->mesh.positions = permuted_positions(mesh, traversal.file_vertex);
  c->file_vertex = std::move(traversal.file_vertex);
  c->face_source = std::move(traversal.face_source);
  if (std::string why = self_check(*c, mesh.vertex_count(), "quad coder"); !why.empty()) return why;
  stats->closed = traversal.closed;
  stats->coding = choice.coding;
  stats->coding_bits = choice.stream_bits;
  stats->claim_violations = traversal.claim_violations;
  for (uint8_t t : traversal.types) ++stats->type_counts[t];
  return {};
}

// The polygon coder (section 5.4), also checked by decoding its own output.
std::string polygon_connectivity(const Mesh& mesh, const EncodeOptions& options, TraversalStart start,
                                 FileConnectivity* c, PolygonCoderStats* stats) {
  PolygonEncoding enc;
  if (std::string why = encode_polygon_connectivity(mesh, options.polygon_coding, options.polygon_context_coding,
                                                    options.polygon_quad_contexts,
                                                    options.unused_vertices_along_curve, &enc, start);
      !why.empty())
    return why;
  c->method = ConnectivityMethod::kPolygon;
  c->polygon_coding = enc.coding;
  c->payload = std::move(enc.payload);
  c->mesh = std::move(enc.file_mesh);
  c->mesh.positions = permuted_positions(mesh, enc.file_vertex);
  c->file_vertex = std::move(enc.file_vertex);
  c->face_source = std::move(enc.face_source);
  if (std::string why = self_check(*c, mesh.vertex_count(), "polygon coder"); !why.empty()) return why;
  stats->coding = enc.coding;
  stats->coding_bits = enc.coding_bits;
  stats->components = enc.components;
  stats->holes = enc.holes;
  stats->handles = enc.handles;
  stats->identifications = enc.identifications;
  stats->loose_faces = enc.loose_faces;
  stats->non_quad_faces = enc.non_quad_faces;
  stats->record_bits = enc.record_bits;
  return {};
}

}  // namespace

void add_chunk(std::vector<uint8_t>* out, EncodeStats* stats, uint32_t type, const std::vector<uint8_t>& payload) {
  write_chunk(out, type, payload);
  stats->chunks.push_back({type, 12 + uint64_t(payload.size())});
}

Status choose_connectivity(const Mesh& mesh, const EncodeOptions& options, FileConnectivity* conn, EncodeStats* st,
                           TraversalStart start) {
  bool structured = false;
  if (options.connectivity == ConnectivityChoice::kAuto || options.connectivity == ConnectivityChoice::kQuad) {
    const std::string why = quad_connectivity(mesh, options.quad_coding, conn, &st->quad);
    structured = why.empty();
    if (!structured && options.connectivity == ConnectivityChoice::kQuad)
      return invalid("the quad coder cannot take this mesh: " + why);
    st->fallback_reason = why;
  }
  // Codings 7 and 8 of the polygon coder often beat the quad coder on
  // all-quad meshes too (5.4.10): keep the smaller CONN.
  if (structured && options.connectivity == ConnectivityChoice::kAuto && options.polygon_context_coding) {
    FileConnectivity polygon;
    PolygonCoderStats polygon_stats;
    if (polygon_connectivity(mesh, options, start, &polygon, &polygon_stats).empty() &&
        polygon.payload.size() < conn->payload.size()) {
      st->fallback_reason = "the polygon coder's CONN is smaller (" + std::to_string(polygon.payload.size()) +
                            " bytes against " + std::to_string(conn->payload.size()) + ")";
      *conn = std::move(polygon);
      st->polygon = polygon_stats;
    }
  }
  if (!structured && options.connectivity != ConnectivityChoice::kIndexed) {
    *conn = FileConnectivity{};
    const std::string why = polygon_connectivity(mesh, options, start, conn, &st->polygon);
    structured = why.empty();
    if (!structured && options.connectivity == ConnectivityChoice::kPolygon)
      return invalid("the polygon coder cannot take this mesh: " + why);
    st->polygon_fallback_reason = why;
  }
  if (!structured) *conn = indexed_connectivity(mesh);
  st->method = conn->method;
  return Status::Ok();
}

uint8_t minor_version_for(const FileConnectivity& conn, int position_method) {
  if (position_method == 14) return 19;
  if (conn.polygon_coding == kPolygonQuadContextCoded) return 18;
  if (position_method >= 13) return 17;
  if (position_method == 12) return 16;
  if (position_method == 11) return 15;
  if (position_method == 10) return 13;
  if (position_method == 9) return 12;
  if (position_method == 8) return 11;
  if (position_method >= 6) return 10;
  if (position_method == 5) return 9;
  if (position_method == 4) return 8;
  if (position_method == 3) return 7;
  if (conn.polygon_coding == kPolygonContextCoded) return 6;
  if (position_method == 1) return 5;
  const ConnectivityMethod method = conn.method;
  return method == ConnectivityMethod::kPolygon ? 2 : method == ConnectivityMethod::kQuad ? 1 : 0;
}

// Section 15.8: the input corner of every file corner.
Status corner_sources(const Mesh& mesh, const FileConnectivity& conn, std::vector<uint64_t>* source) {
  std::vector<uint32_t> rotation;
  if (Status s = face_rotations(mesh, conn.mesh, conn.file_vertex, conn.face_source, &rotation); !s.ok()) return s;
  std::vector<uint64_t> input_offset(mesh.face_count() + 1, 0);
  for (size_t f = 0; f < mesh.face_count(); ++f) input_offset[f + 1] = input_offset[f] + mesh.face_sizes[f];
  source->resize(conn.mesh.corners.size());
  uint64_t k0 = 0;
  for (size_t j = 0; j < conn.mesh.face_sizes.size(); ++j) {
    const uint32_t d = conn.mesh.face_sizes[j];
    for (uint32_t i = 0; i < d; ++i) (*source)[k0 + i] = input_offset[conn.face_source[j]] + (i + d - rotation[j]) % d;
    k0 += d;
  }
  return Status::Ok();
}

// 15.14's plane for twin candidates: POSN method 9's, else one
// find_mirror_plane finds on the positions' integers.
bool twin_plane(const QuantizationInfo& info, const std::vector<uint32_t>& quantized, MirrorPlane* plane) {
  if (info.mirror_axis >= 0) {
    *plane = MirrorPlane{info.mirror_axis, info.mirror_sum};
    return true;
  }
  QuantizedPositions grid;
  grid.top = info.top;
  grid.q = quantized;
  return find_mirror_plane(grid, plane, false);
}

// Section 15: an aTTR chunk per attribute, right after POSN. Normals are
// predicted from the integers the decoder gets from `positions` (15.7),
// decoded here: the POSN payload may hold another grid than the one asked
// for (method 0 when every vertex is on one point).
Status add_attributes(const Mesh& mesh, const EncodeOptions& options, const FileConnectivity& conn,
                      const std::vector<uint8_t>& positions, std::vector<uint8_t>* out, EncodeStats* st) {
  if (mesh.attributes.empty()) return Status::Ok();
  std::vector<uint64_t> source;
  if (Status s = corner_sources(mesh, conn, &source); !s.ok()) return s;
  QuantizationInfo info;
  std::vector<uint32_t> quantized;
  std::vector<float> decoded;
  // Normals (15.7, 15.13), two-component values (15.12), twins (15.14).
  bool predicted_from_positions = options.attribute_twins;
  for (const MeshAttribute& a : mesh.attributes)
    predicted_from_positions = predicted_from_positions || a.kind == AttributeKind::kNormal ||
                               (options.attribute_guided && a.components == 2);
  if (Status s = predicted_from_positions ? decode_positions(positions.data(), positions.size(), conn.mesh,
                                                              uint32_t(mesh.vertex_count()), &info, &quantized,
                                                              &decoded)
                                          : Status::Ok();
      !s.ok())
    return Status(ErrorCode::kInvalidArgument, "internal: the encoder's POSN does not decode: " + s.to_string());
  MirrorPlane plane;
  const bool mirrored = options.attribute_twins && twin_plane(info, quantized, &plane);
  for (const MeshAttribute& attribute : mesh.attributes) {
    std::vector<uint8_t> payload;
    AttributeStats stats;
    if (Status s = encode_attribute(attribute, conn.mesh, conn.file_vertex, quantized, source, options, &payload,
                                    &stats, mirrored ? &plane : nullptr);
        !s.ok())
      return s;
    add_chunk(out, st, kChunkAttribute, payload);
    st->attributes.push_back(stats);
  }
  return Status::Ok();
}

namespace {

// A single-rate file (sections 5, 6, 14 - 16) with the polygon coder's
// components started as `start` says.
Status encode_single_rate(const Mesh& mesh, const EncodeOptions& options, TraversalStart start,
                          std::vector<uint8_t>* out, EncodeStats* stats) {
  EncodeStats& st = *stats;
  st = EncodeStats{};
  FileConnectivity conn;
  if (Status s = choose_connectivity(mesh, options, &conn, &st, start); !s.ok()) return s;
  QuantizedPositions quantized;
  if (Status s = quantize_positions(conn.mesh.positions, options, &quantized); !s.ok()) return s;
  const auto positions_of = [&](const QuantizedPositions& grid, PositionStats* stats) {
    return encode_positions(grid, conn.mesh, options.position_method, options.candidate_choice, class_start(options),
                            prediction_order(options), options.quad_twist, options.mask_contexts,
                            options.triangle_twist, options.mirror_symmetry, options.near_mirror, options.shear,
                            stats, options.edge_extrapolation, options.axis_class_probabilities);
  };
  std::vector<uint8_t> positions = positions_of(quantized, &st.positions);
  if (options.surface_lattice > 1) {
    // 14.15: the lattice where its POSN is smaller than the grid's. On regular or
    // mirrored meshes, or where vertices are few steps apart, it is not (the
    // corpus's torus, face and cow at 12 bits): the grid's file is then kept,
    // nearer the input too, and the report says so.
    QuantizedPositions lattice = quantized;
    if (Status s = set_surface_lattice(conn.mesh, options.surface_lattice, &lattice); !s.ok()) return s;
    PositionStats lattice_stats;
    std::vector<uint8_t> on_lattice = positions_of(lattice, &lattice_stats);
    st.positions.lattice_payload_bytes = on_lattice.size();
    if (on_lattice.size() < positions.size()) {
      lattice_stats.lattice_payload_bytes = on_lattice.size();
      lattice_stats.grid_payload_bytes = positions.size();
      st.positions = lattice_stats;
      positions = std::move(on_lattice);
    } else {
      st.positions.grid_payload_bytes = positions.size();
    }
  }

  out->clear();
  write_signature(out);
  // The lowest minor version that defines everything in the file (4.1).
  add_chunk(out, &st, kChunkHeader, {kFormatMajor, minor_version_for(conn, st.positions.method)});
  for (const std::string& text : options.texts)
    add_chunk(out, &st, kChunkText, std::vector<uint8_t>(text.begin(), text.end()));
  add_chunk(out, &st, kChunkConnectivity, conn.payload);
  add_chunk(out, &st, kChunkPositions, positions);
  if (Status s = add_attributes(mesh, options, conn, positions, out, &st); !s.ok()) return s;
  for (const FaceLabels& labels : mesh.face_labels)  // section 16
    add_chunk(out, &st, kChunkFaceLabels, encode_face_labels(labels, conn.face_source));
  if (options.keep_order) {  // section 4.5: right after POSN, only if the coder order differs
    std::vector<uint8_t> order;
    if (Status s = encode_order(mesh, conn.mesh, conn.file_vertex, conn.face_source, &order); !s.ok()) return s;
    if (!order.empty()) add_chunk(out, &st, kChunkOrder, order);
  }
  add_chunk(out, &st, kChunkEnd, {});
  st.total_bytes = out->size();
  st.file_vertex = std::move(conn.file_vertex);
  st.face_source = std::move(conn.face_source);
  return Status::Ok();
}

// EncodeOptions::start_faces: the whole file from each start, the smallest
// kept (ties: the earlier start). Only the polygon coder has a start to
// choose; with any other connectivity the first file is the file.
Status encode_from_starts(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out,
                          EncodeStats* st) {
  if (Status s = encode_single_rate(mesh, options, {}, out, st); !s.ok()) return s;
  if (st->method != ConnectivityMethod::kPolygon) return Status::Ok();
  const uint64_t usual = out->size();
  uint32_t kept = 0;
  std::vector<uint8_t> trial_bytes;
  EncodeStats trial_stats;
  for (uint32_t t = 1; t < options.start_faces; ++t) {
    if (options.progress) options.progress("start faces", double(t) / options.start_faces);
    if (Status s = encode_single_rate(mesh, options, {t}, &trial_bytes, &trial_stats); !s.ok())
      return s;
    if (trial_bytes.size() >= out->size()) continue;
    std::swap(*out, trial_bytes);
    std::swap(*st, trial_stats);
    kept = t;
  }
  st->polygon.start_trials = options.start_faces;
  st->polygon.start_kept = kept;
  st->polygon.usual_start_bytes = usual;
  return Status::Ok();
}

}  // namespace

Status encode(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out, EncodeStats* stats) {
  if (Status s = validate_input(mesh, options); !s.ok()) return s;
  EncodeStats local;
  EncodeStats& st = stats ? *stats : local;
  st = EncodeStats{};
  if (options.progressive_levels > 0 && options.gim.size > 0)
    return invalid("a file is either progressive (section 12) or a geometry image (section 13), not both");
  if (options.progressive_levels > 0) return encode_loop_levels(mesh, options, out, &st);
  if (options.gim.size > 0) return encode_geometry_image(mesh, options, out, &st);
  if (options.start_faces > 1) return encode_from_starts(mesh, options, out, &st);
  return encode_single_rate(mesh, options, {}, out, &st);
}

}  // namespace qmc
