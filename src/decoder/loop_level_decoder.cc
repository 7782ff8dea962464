// Progressive levels, spec/qmc-format.md section 12: the LOOP header, the
// base mesh checks, and each LEVL chunk's displacements (seed 003 §4.2's
// 1-bit/9-bit code, or range coded) applied along the limit normals of
// section 12.6, then code 4's vertex corrections.
#include "decoder/loop_level_decoder.h"

#include <cmath>
#include <string>

#include "common/bit_reader.h"
#include "common/byte_io.h"
#include "common/displacement_coding.h"
#include "common/exact_arith.h"
#include "common/range_coder.h"
#include "decoder/no_throw.h"
#include "decoder/position_decoder.h"

namespace qmc {
namespace {

Status bad_payload(const char* chunk, const std::string& message) {
  return Status(ErrorCode::kBadChunkPayload, std::string(chunk) + ": " + message);
}

}  // namespace

Status decode_loop_header(const uint8_t* payload, size_t size, uint8_t* level_count) {
  if (size != 2) return bad_payload("LOOP", "payload is " + std::to_string(size) + " bytes, not 2");
  if (payload[0] < 1 || payload[0] > kMaxLoopLevels)
    return bad_payload("LOOP", "level_count " + std::to_string(payload[0]) + " outside 1.." +
                                   std::to_string(kMaxLoopLevels));
  if (payload[1] != 0)
    return Status(ErrorCode::kUnsupportedFeature, "LOOP: subdivision scheme " + std::to_string(payload[1]) +
                                                      " is not defined (section 12.1 knows 0)");
  *level_count = payload[0];
  return Status::Ok();
}

Status loop_base_connectivity(const Mesh& mesh, uint32_t vertex_count, LoopMesh* base, LoopEdges* edges) {
  base->positions.clear();
  base->triangles.clear();
  for (size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_sizes[f] != 3)
      return bad_payload("CONN", "progressive base mesh face " + std::to_string(f) + " has " +
                                     std::to_string(mesh.face_sizes[f]) + " corners, not 3 (section 12.2)");
  // 12.2: more vertices than corners breaks rule 4 whatever else holds;
  // said before anything of size V is reserved (V is not tied to the bits).
  if (vertex_count > mesh.corners.size())
    return bad_payload("CONN", "progressive base mesh: " + std::to_string(vertex_count) + " vertices but " +
                                   std::to_string(mesh.corners.size()) + " corners, so a vertex is in no face " +
                                   "(section 12.2 rule 4)");
  base->positions.assign(3 * size_t(vertex_count), 0.0);
  base->triangles = mesh.corners;
  if (Status s = build_loop_edges(*base, edges); !s.ok())
    return bad_payload("CONN", "progressive base mesh: " + s.message() + " (section 12.2)");
  return Status::Ok();
}

void loop_base_positions(const QuantizationInfo& info, const std::vector<uint32_t>& quantized, LoopMesh* base) {
  double lo[3], step[3];
  dequantization_steps(info, lo, step);
  base->positions.resize(quantized.size());
  for (size_t i = 0; i < quantized.size(); ++i) base->positions[i] = lo[i % 3] + mul(double(quantized[i]), step[i % 3]);
}

namespace {

// 12.7: the seed's 1-bit / 9-bit code.
Status decode_bit_code(ByteReader* in, uint32_t edge_count, LevelCode* code) {
  BitReader bits(in->cursor(), in->remaining());
  if (edge_count > bits.bits_remaining())
    return Status(ErrorCode::kLimitExceeded, "LEVL: " + std::to_string(edge_count) +
                                                 " displacement codes cannot fit in " +
                                                 std::to_string(in->remaining()) + " bytes");
  code->m.assign(edge_count, 0);
  for (uint32_t e = 0; e < edge_count; ++e) {
    if (!bits.read_bit()) continue;
    const bool negative = bits.read_bit();
    const int magnitude = int(bits.read_bits(7));
    if (bits.overrun()) break;
    if (magnitude == 0)
      return Status(ErrorCode::kBadSymbol, "LEVL: edge " + std::to_string(e) + " has a 9-bit code of magnitude 0");
    code->m[e] = int8_t(negative ? -magnitude : magnitude);
  }
  if (bits.overrun()) return Status(ErrorCode::kTruncated, "LEVL: bit stream ends before the last displacement");
  if (!bits.at_clean_end()) return bad_payload("LEVL", "bits left over after the last displacement");
  return Status::Ok();
}

// 12.7.2: code 4's corrections after the displacements, C of them, for the
// V + E vertices of the fine level.
Status decode_corrections(RangeDecoder* rc, uint64_t count, uint64_t fine_vertices, LevelCode* code) {
  std::vector<CorrectionModel> model(1);
  const int32_t none[3] = {0, 0, 0};
  uint64_t vertex = 0;
  for (uint64_t i = 0; i < count; ++i) {
    const uint32_t gap = code_correction_gap(rc, &model[0], 0);
    if (rc->overrun())
      return Status(ErrorCode::kTruncated, "LEVL: the range-coded stream ends at correction " + std::to_string(i));
    vertex = i == 0 ? gap : vertex + 1 + gap;
    if (vertex >= fine_vertices)
      return Status(ErrorCode::kBadSymbol, "LEVL: correction " + std::to_string(i) + " names vertex " +
                                               std::to_string(vertex) + " of a level of " +
                                               std::to_string(fine_vertices) + " (section 12.7.2)");
    VertexCorrection c;
    c.vertex = uint32_t(vertex);
    const int32_t* previous = code->corrections.empty() ? none : code->corrections.back().offset;
    for (int a = 0; a < 3; ++a) {
      const SignedResidual r =
          code_correction_offset(rc, &model[0], correction_bucket(previous, c.offset, a), a, 0);
      if (rc->overrun())
        return Status(ErrorCode::kTruncated, "LEVL: the range-coded stream ends at correction " + std::to_string(i));
      if (r.magnitude > 32768 || (r.magnitude == 32768 && !r.negative))
        return Status(ErrorCode::kBadSymbol, "LEVL: correction " + std::to_string(i) + " has an offset of " +
                                                 (r.negative ? "-" : "") + std::to_string(r.magnitude) +
                                                 ", outside -32768 .. 32767 (sections 12.7.2, 13.5.6)");
      c.offset[a] = r.negative ? -int32_t(r.magnitude) : int32_t(r.magnitude);
    }
    code->corrections.push_back(c);
  }
  return Status::Ok();
}

// 12.7.1: code 2, range coded in contexts of the edges' ends; 12.7.2: code
// 4, the same followed by `corrections` vertex corrections.
Status decode_range_code(ByteReader* in, const LoopEdges& edges, uint32_t coarse_vertices, uint64_t corrections,
                         LevelCode* code) {
  const uint32_t edge_count = edges.edge_count();
  if (!range_stream_justifies(edge_count, in->remaining()))
    return Status(ErrorCode::kLimitExceeded, "LEVL: " + std::to_string(edge_count) + " edges for " +
                                                 std::to_string(in->remaining()) +
                                                 " stream bytes, above 512 (L + 8) (section 12.7.1)");
  code->m.assign(edge_count, 0);
  std::vector<int8_t> last(coarse_vertices, 0);
  std::vector<DisplacementModel> model(1);
  RangeDecoder rc(in->cursor(), in->remaining());
  if (rc.bad_start()) return bad_payload("LEVL", "the range coder's first four bytes are 0xFFFFFFFF (section 13.5.2)");
  int previous = 0;
  for (uint32_t e = 0; e < edge_count; ++e) {
    const uint32_t a = edges.a[e], b = edges.b[e];
    const int m = code_displacement(&rc, &model[0], DisplacementContext(last[a], last[b], previous), 0);
    if (rc.overrun())
      return Status(ErrorCode::kTruncated, "LEVL: the range-coded stream ends at edge " + std::to_string(e));
    code->m[e] = int8_t(m);
    last[a] = last[b] = int8_t(m);
    previous = m;
  }
  if (corrections > 0)
    if (Status s = decode_corrections(&rc, corrections, uint64_t(coarse_vertices) + edge_count, code); !s.ok())
      return s;
  if (rc.unread() != 0)
    return bad_payload("LEVL", std::to_string(rc.unread()) + " bytes after the range-coded data (section 13.5.2)");
  return Status::Ok();
}

}  // namespace

Status decode_level_code(const uint8_t* payload, size_t size, uint8_t expected_level, const LoopEdges& edges,
                         uint32_t coarse_vertices, LevelCode* code) {
  const uint32_t edge_count = edges.edge_count();
  ByteReader in(payload, size);
  uint8_t level = 0, method = 0;
  if (!in.get_u8(&level) || level != expected_level)
    return bad_payload("LEVL", "level field " + (size ? std::to_string(level) : std::string("missing")) +
                                   ", expected " + std::to_string(expected_level));
  if (!in.get_u8(&method)) return bad_payload("LEVL", "code field missing");
  if (method != 0 && method != 2 && method != 4)
    return Status(ErrorCode::kUnsupportedFeature, "LEVL: displacement code " + std::to_string(method) +
                                                      " is not defined (section 12.1 knows 0, 2 and 4)");
  uint64_t declared = 0;
  if (!in.get_varint(&declared)) return bad_payload("LEVL", "edge_count missing or malformed");
  if (declared != edge_count)
    return bad_payload("LEVL", "edge_count " + std::to_string(declared) + " but level " +
                                   std::to_string(expected_level - 1) + " has " + std::to_string(edge_count) +
                                   " edges");
  if (!in.get_f64le(&code->step)) return bad_payload("LEVL", "step missing");
  if (!std::isfinite(code->step) || !(code->step > 0))
    return bad_payload("LEVL", "step is not a finite number greater than zero");
  if (method == 0) return decode_bit_code(&in, edge_count, code);
  uint64_t corrections = 0;
  if (method == 4) {
    if (!in.get_f64le(&code->correction_step)) return bad_payload("LEVL", "correction_step missing");
    if (!std::isfinite(code->correction_step) || !(code->correction_step > 0))
      return bad_payload("LEVL", "correction_step is not a finite number greater than zero");
    if (!in.get_varint(&corrections)) return bad_payload("LEVL", "correction_count missing or malformed");
    const uint64_t fine_vertices = uint64_t(coarse_vertices) + edge_count;
    if (corrections > fine_vertices)
      return bad_payload("LEVL", "correction_count " + std::to_string(corrections) + " but level " +
                                     std::to_string(expected_level) + " has " + std::to_string(fine_vertices) +
                                     " vertices (section 12.1)");
  }
  return decode_range_code(&in, edges, coarse_vertices, corrections, code);
}

void displace_edge_points(const std::vector<double>& normals, const LevelCode& code, uint32_t coarse_vertices,
                          LoopMesh* fine) {
  for (size_t e = 0; e < code.m.size(); ++e) {
    if (code.m[e] == 0) continue;  // 12.7: unchanged, even where w * N would not be finite
    const double w = mul(double(code.m[e]), code.step);
    double* x = &fine->positions[3 * (size_t(coarse_vertices) + e)];
    for (int k = 0; k < 3; ++k) x[k] = x[k] + mul(w, normals[3 * e + k]);
  }
}

void correct_vertices(const LevelCode& code, LoopMesh* fine) {
  for (const VertexCorrection& c : code.corrections) {
    double* x = &fine->positions[3 * size_t(c.vertex)];
    for (int k = 0; k < 3; ++k)
      if (c.offset[k] != 0) x[k] = x[k] + mul(double(c.offset[k]), code.correction_step);  // 12.7.2: only if r != 0
  }
}

Status check_level_range(const LoopMesh& level, uint8_t level_index) {
  // Binary32 rounding overflows from 2^128 - 2^103 up; NaN fails the test too.
  constexpr double kBinary32Overflow = 0x1.ffffff8p+127;
  for (size_t i = 0; i < level.positions.size(); ++i)
    if (!(std::fabs(level.positions[i]) < kBinary32Overflow))
      return bad_payload("LEVL", "level " + std::to_string(level_index) + " vertex " + std::to_string(i / 3) +
                                     " has a coordinate that is not finite in binary32 (section 12.8)");
  return Status::Ok();
}

Status decode_level(const uint8_t* payload, size_t size, uint8_t expected_level, const LoopMesh& coarse,
                    const LoopEdges& coarse_edges, LoopMesh* fine) {
  LevelCode code;
  if (Status s = decode_level_code(payload, size, expected_level, coarse_edges, coarse.vertex_count(), &code);
      !s.ok())
    return s;
  loop_subdivide(coarse, coarse_edges, fine);
  std::vector<double> normals;
  edge_point_normals(*fine, coarse_edges, coarse.vertex_count(), &normals);
  displace_edge_points(normals, code, coarse.vertex_count(), fine);
  correct_vertices(code, fine);
  if (Status s = check_level_range(*fine, expected_level); !s.ok()) return s;
  fine->step = code.step;
  fine->edge_points = coarse_edges.edge_count();
  fine->zero_displacements = 0;
  for (int8_t m : code.m) fine->zero_displacements += m == 0;
  fine->corrected_vertices = uint32_t(code.corrections.size());
  return Status::Ok();
}

// Empty if memory runs out (no exception leaves the API: decoder.h).
Mesh level_mesh(const LoopLevel& level) {
  Mesh mesh;
  QMC_TRY {
    mesh.positions.resize(level.positions.size());
    for (size_t i = 0; i < level.positions.size(); ++i) mesh.positions[i] = float(level.positions[i]);
    mesh.face_sizes.assign(level.face_count(), 3);
    mesh.corners = level.triangles;
  }
  QMC_CATCH_ALL(mesh = Mesh())
  return mesh;
}

}  // namespace qmc
