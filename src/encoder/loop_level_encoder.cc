// LEVL encoder and the progressive file layout, spec/qmc-format.md 12.1,
// 12.7 and 12.10 (seed 003 §3.2.2, §4.2).
#include "encoder/loop_level_encoder.h"

#include <algorithm>
#include <cmath>

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/displacement_coding.h"
#include "common/range_coder.h"
#include "encoder/chunk_writer.h"
#include "encoder/position_encoder.h"

namespace qmc {
namespace {

constexpr int kMaxMagnitude = 127;  // 7-bit magnitude of seed 003 §4.2

int quantize(double r, double step) {
  const double m = std::nearbyint(r / step);
  return int(std::fmax(-kMaxMagnitude, std::fmin(kMaxMagnitude, m)));
}

// Per edge point: r, the displacement in units of N that reaches the
// target's projection on the normal line, and |N|^2, which turns an error in
// those units back into squared length.
struct Projection {
  std::vector<double> r, weight;
};

Projection project(uint32_t coarse_vertices, const LoopMesh& fine, const std::vector<double>& normals,
                   const std::vector<double>& targets) {
  const size_t edges = normals.size() / 3;
  Projection p;
  p.r.resize(edges);
  p.weight.resize(edges);
  for (size_t e = 0; e < edges; ++e) {
    const double* n = &normals[3 * e];
    const double* q = &fine.positions[3 * (coarse_vertices + e)];
    const double* t = &targets[3 * e];
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const double along = (t[0] - q[0]) * n[0] + (t[1] - q[1]) * n[1] + (t[2] - q[2]) * n[2];
    p.weight[e] = nn;
    p.r[e] = nn > 0 && std::isfinite(nn) ? along / nn : 0.0;
  }
  return p;
}

double quantization_error(const Projection& p, double step) {
  double sum = 0;
  for (size_t e = 0; e < p.r.size(); ++e) {
    const double d = p.r[e] - step * quantize(p.r[e], step);
    sum += p.weight[e] * d * d;
  }
  return sum;
}

// 12.10: the step of least squared error among q / 127 * 2^(i/4), i = -8 ..
// 24, q the 99.9th percentile of |r|. A percentile, not the maximum: r is
// a length over |N|^2, and a few edge points with tiny normals would
// otherwise push every step so high that all values round to zero.
double choose_step(const Projection& p) {
  std::vector<double> magnitudes;
  magnitudes.reserve(p.r.size());
  for (double r : p.r)
    if (std::isfinite(r)) magnitudes.push_back(std::fabs(r));
  if (magnitudes.empty()) return 1.0;
  const size_t k = std::min(magnitudes.size() - 1, size_t(0.999 * double(magnitudes.size())));
  std::nth_element(magnitudes.begin(), magnitudes.begin() + std::ptrdiff_t(k), magnitudes.end());
  const double q = magnitudes[k];
  if (!(q > 0)) return 1.0;
  double best_step = 0, best_error = 0;
  for (int i = -8; i <= 24; ++i) {
    const double step = q / kMaxMagnitude * std::exp2(-0.25 * i);
    const double error = quantization_error(p, step);
    if (best_step == 0 || error < best_error) best_step = step, best_error = error;
  }
  return best_step;
}

QuantizationInfo info_of(const QuantizedPositions& q) {
  QuantizationInfo info;
  info.bits = q.bits;
  info.min = q.min;
  info.max = q.max;
  info.step = q.step;
  info.top = q.top;
  return info;
}

}  // namespace

void predict_level(const LoopMesh& coarse, const LoopEdges& coarse_edges, LoopMesh* fine,
                   std::vector<double>* normals) {
  loop_subdivide(coarse, coarse_edges, fine);
  edge_point_normals(*fine, coarse_edges, coarse.vertex_count(), normals);
}

namespace {

// 12.7: the seed's code, a 1-bit zero or a 9-bit sign and magnitude.
std::vector<uint8_t> bit_code_stream(const std::vector<int8_t>& m) {
  BitWriter bits;
  for (int8_t v : m) {
    bits.write_bit(v != 0);
    if (v == 0) continue;
    bits.write_bit(v < 0);
    bits.write_bits(uint32_t(v < 0 ? -v : v), 7);
  }
  return bits.finish();
}

// 12.7.1: the displacements in contexts of the edges' ends, into `rc`
// (codes 2 and 4).
void code_displacements(const std::vector<int8_t>& m, const LoopEdges& edges, uint32_t coarse_vertices,
                        RangeEncoder* rc) {
  std::vector<int8_t> last(coarse_vertices, 0);
  std::vector<DisplacementModel> model(1);
  int previous = 0;
  for (size_t e = 0; e < m.size(); ++e) {
    const uint32_t a = edges.a[e], b = edges.b[e];
    code_displacement(rc, &model[0], DisplacementContext(last[a], last[b], previous), m[e]);
    last[a] = last[b] = m[e];
    previous = m[e];
  }
}

// 12.7.1: code 2's stream.
std::vector<uint8_t> range_code_stream(const std::vector<int8_t>& m, const LoopEdges& edges,
                                       uint32_t coarse_vertices) {
  RangeEncoder rc;
  code_displacements(m, edges, coarse_vertices, &rc);
  return rc.finish();
}

// 12.1: a LEVL payload's level, code, edge_count and step.
std::vector<uint8_t> level_payload_head(uint8_t level, uint8_t code, size_t edges, double step) {
  std::vector<uint8_t> payload;
  put_u8(&payload, level);
  put_u8(&payload, code);
  put_varint(&payload, edges);
  put_f64le(&payload, step);
  return payload;
}

}  // namespace

double level_step_scale(const EncodeOptions& options, int level, int levels) {
  if (level == levels) return options.finest_step_scale;
  if (level == levels - 1) return std::sqrt(options.finest_step_scale);
  return 1.0;
}

std::vector<uint8_t> encode_level(uint8_t level, const LoopEdges& coarse_edges, uint32_t coarse_vertices,
                                  const std::vector<double>& normals, const std::vector<double>& targets,
                                  int code_choice, double step_scale, LoopMesh* fine, LevelCodeStats* stats,
                                  LevelCode* kept) {
  const Projection p = project(coarse_vertices, *fine, normals, targets);
  LevelCode code;
  code.step = choose_step(p) * step_scale;
  code.m.resize(p.r.size());
  *stats = LevelCodeStats{};
  stats->edge_points = uint32_t(p.r.size());
  stats->step = code.step;
  for (size_t e = 0; e < p.r.size(); ++e) {
    const int m = quantize(p.r[e], code.step);
    code.m[e] = int8_t(m);
    stats->zeros += m == 0;
    stats->clamped += std::fabs(p.r[e] / code.step) > kMaxMagnitude + 0.5;
  }
  displace_edge_points(normals, code, coarse_vertices, fine);
  std::vector<uint8_t> stream = bit_code_stream(code.m);
  if (code_choice != 0) {
    std::vector<uint8_t> ranged = range_code_stream(code.m, coarse_edges, coarse_vertices);
    // 12.7.1's bound, which only a level of nearly all zeros could exceed.
    const bool fits = range_stream_justifies(p.r.size(), ranged.size());
    if (fits && (code_choice == 2 || ranged.size() < stream.size())) {
      stream = std::move(ranged);
      stats->code = 2;
    }
  }
  std::vector<uint8_t> payload = level_payload_head(level, stats->code, p.r.size(), code.step);
  payload.insert(payload.end(), stream.begin(), stream.end());
  if (kept) *kept = std::move(code);
  return payload;
}

std::vector<uint8_t> corrected_level_payload(uint8_t level, const LoopEdges& coarse_edges, uint32_t coarse_vertices,
                                             const LevelCode& code) {
  RangeEncoder rc;
  code_displacements(code.m, coarse_edges, coarse_vertices, &rc);
  std::vector<CorrectionModel> corrections(1);
  const int32_t none[3] = {0, 0, 0};
  for (size_t i = 0; i < code.corrections.size(); ++i) {
    const VertexCorrection& c = code.corrections[i];
    code_correction_gap(&rc, &corrections[0], i == 0 ? c.vertex : c.vertex - code.corrections[i - 1].vertex - 1);
    const int32_t* before = i == 0 ? none : code.corrections[i - 1].offset;
    for (int a = 0; a < 3; ++a)
      code_correction_offset(&rc, &corrections[0], correction_bucket(before, c.offset, a), a, c.offset[a]);
  }
  const std::vector<uint8_t> stream = rc.finish();
  std::vector<uint8_t> payload = level_payload_head(level, 4, code.m.size(), code.step);
  put_f64le(&payload, code.correction_step);
  put_varint(&payload, code.corrections.size());
  payload.insert(payload.end(), stream.begin(), stream.end());
  return payload;
}

namespace {

// One level coded towards one set of targets, from the decoder's level below.
struct CodedLevel {
  LoopMesh fine;
  std::vector<uint8_t> payload;
  LevelCode code;
  LevelCodeStats stats;
  double distance = 0;  // to the input, when judged
  uint8_t targets = 0;  // 0: `targets`, else the id of the judge's alternative
};

CodedLevel code_level(int j, int levels, const EncodeOptions& options, const LoopMesh& current,
                      const LoopEdges& edges, const LoopMesh& predicted, const std::vector<double>& normals,
                      const LevelTargets& targets) {
  CodedLevel c;
  c.fine = predicted;
  std::vector<double> level_targets;
  targets(j, c.fine, normals, current.vertex_count(), &level_targets);
  c.payload = encode_level(uint8_t(j), edges, current.vertex_count(), normals, level_targets,
                           options.displacement_code, level_step_scale(options, j, levels), &c.fine, &c.stats,
                           &c.code);
  return c;
}

// 12.10's closed loop: rule 0 unless it leaves the level less than 1 % nearer
// the input than the level below (`previous`); then the first alternative
// that is, or else the nearest of all.
CodedLevel choose_level(int j, int levels, const EncodeOptions& options, const LoopMesh& current,
                        const LoopEdges& edges, const LevelTargets& targets, const LevelJudge* judge,
                        double previous) {
  LoopMesh predicted;
  std::vector<double> normals;
  predict_level(current, edges, &predicted, &normals);
  CodedLevel best = code_level(j, levels, options, current, edges, predicted, normals, targets);
  if (!judge) return best;
  constexpr double kEnough = 0.99;
  best.distance = judge->distance(best.fine);
  for (size_t rule = 0; rule < judge->alternatives.size() && !(best.distance < kEnough * previous); ++rule) {
    const LevelJudge::Alternative& alternative = judge->alternatives[rule];
    CodedLevel other = code_level(j, levels, options, current, edges, predicted, normals, alternative.targets);
    other.distance = judge->distance(other.fine);
    other.targets = alternative.id;
    if (other.distance < best.distance) best = std::move(other);
  }
  return best;
}

// 12.7.2: level j with the corrector's corrections, code 4, unless there
// are none or they leave it no nearer the input than the level below
// (`previous`, with a judge).
Status correct_level(uint8_t j, const LoopEdges& edges, uint32_t coarse_vertices, const LevelCorrector& corrector,
                     const LevelJudge* judge, double previous, CodedLevel* level) {
  LevelCode code = level->code;
  if (Status s = corrector(j, level->fine, &code); !s.ok()) return s;
  if (code.corrections.empty()) return Status::Ok();
  LoopMesh corrected = level->fine;
  correct_vertices(code, &corrected);
  const double distance = judge ? judge->distance(corrected) : 0;
  if (judge && !(distance < previous)) return Status::Ok();
  std::vector<uint8_t> payload = corrected_level_payload(j, edges, coarse_vertices, code);
  if (!range_stream_justifies(code.m.size(), payload.size())) return Status::Ok();
  level->fine = std::move(corrected);
  level->payload = std::move(payload);
  level->distance = distance;
  level->stats.code = 4;
  level->code = std::move(code);
  return Status::Ok();
}

}  // namespace

Status write_loop_file(const FileConnectivity& conn, const std::vector<double>& base_positions, int levels,
                       const EncodeOptions& options, const LevelTargets& targets, const LevelJudge* judge,
                       const LevelCorrector* corrector, std::vector<uint8_t>* out, EncodeStats* st) {
  LoopEncodeStats& ls = st->loop;
  // The base keeps section 6.1's per-axis grid, which both POSN methods
  // carry (method 1 with grid 1 outputs the same positions); the method is
  // the smaller one unless the options name one.
  const QuantizedPositions quantized =
      quantize_positions(std::vector<float>(base_positions.begin(), base_positions.end()), options.position_bits);
  const std::vector<uint8_t> positions_payload =
      encode_positions(quantized, conn.mesh, options.position_method, options.candidate_choice, class_start(options),
                       prediction_order(options), false, false, false, false, false, false,
                       &st->positions);  // a base: no twist, no 14.8, no mirror, no shear
  LoopMesh current;
  current.triangles = conn.mesh.corners;
  loop_base_positions(info_of(quantized), quantized.q, &current);
  LoopEdges edges;
  if (Status s = build_loop_edges(current, &edges); !s.ok())
    return Status(ErrorCode::kInvalidArgument, "the base mesh cannot carry Loop levels: " + s.message());

  ls.levels.clear();
  ls.levels.push_back({current.vertex_count(), current.face_count(), 0, 0, 0, 0,
                       24 + conn.payload.size() + positions_payload.size()});
  std::vector<std::vector<uint8_t>> level_payloads;
  bool format_1_5 = st->positions.method >= 1, format_1_14 = false;
  double previous = judge ? judge->distance(current) : 0;
  for (int j = 1; j <= levels; ++j) {
    CodedLevel level = choose_level(j, levels, options, current, edges, targets, judge, previous);
    if (corrector)
      if (Status s = correct_level(uint8_t(j), edges, current.vertex_count(), *corrector, judge, previous, &level);
          !s.ok())
        return s;
    if (Status s = check_level_range(level.fine, uint8_t(j)); !s.ok())
      return Status(ErrorCode::kInvalidArgument, "level " + std::to_string(j) + " leaves the binary32 range");
    const LevelCodeStats& code_stats = level.stats;
    format_1_5 = format_1_5 || code_stats.code == 2;
    format_1_14 = format_1_14 || code_stats.code == 4;
    level_payloads.push_back(std::move(level.payload));
    ls.levels.push_back({level.fine.vertex_count(), level.fine.face_count(), code_stats.edge_points,
                         code_stats.zeros, code_stats.clamped, code_stats.step, 12 + level_payloads.back().size(),
                         code_stats.code, uint32_t(level.code.corrections.size()), level.targets});
    if (j < levels)
      if (Status s = number_loop_edges(level.fine, &edges); !s.ok())
        return Status(ErrorCode::kInvalidArgument, "internal: level " + std::to_string(j) + ": " + s.message());
    current = std::move(level.fine);
    previous = level.distance;
  }
  // The lowest minor version that defines everything in the file (4.1).
  out->clear();
  write_signature(out);
  const uint8_t minor = std::max<uint8_t>(minor_version_for(conn, st->positions.method),
                                          format_1_14 ? 14 : format_1_5 ? 5 : 3);
  add_chunk(out, st, kChunkHeader, {kFormatMajor, minor});
  for (const std::string& text : options.texts)
    add_chunk(out, st, kChunkText, std::vector<uint8_t>(text.begin(), text.end()));
  add_chunk(out, st, kChunkLoop, {uint8_t(levels), 0});
  add_chunk(out, st, kChunkConnectivity, conn.payload);
  add_chunk(out, st, kChunkPositions, positions_payload);
  for (const std::vector<uint8_t>& payload : level_payloads) add_chunk(out, st, kChunkLevel, payload);
  add_chunk(out, st, kChunkEnd, {});
  st->method = conn.method;
  st->total_bytes = out->size();
  st->file_vertex = conn.file_vertex;
  st->face_source = conn.face_source;
  return Status::Ok();
}

}  // namespace qmc
