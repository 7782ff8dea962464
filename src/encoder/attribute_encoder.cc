// The aTTR chunk, spec/qmc-format.md section 15, on the encoder side: the
// mapping (one value per vertex, or per corner with the decisions of 15.3 or
// 15.11, whichever is smaller), and
// the values on the uniform grid of their bounding box, predicted over the
// attribute mesh as positions are (15.4), or exact binary32 (15.5).
#include "encoder/attribute_encoder.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/attribute_mapping.h"
#include "common/predicted_mapping.h"
#include "common/byte_io.h"
#include "common/octahedral_normal.h"
#include "common/range_coder.h"
#include "encoder/position_encoder.h"

namespace qmc {
namespace {

constexpr uint8_t kMappingPerVertex = 0, kMappingPerCorner = 1, kMappingPredicted = 3;
constexpr uint8_t kCodingGrid = 0, kCodingExact = 1, kCodingOctahedral = 3, kCodingGeometryOrder = 4;
constexpr uint8_t kCodingGridGraded = 5, kCodingGeometryOrderGraded = 6;  // 15.10
constexpr uint8_t kCodingGuided = 7;                                       // 15.12
constexpr uint8_t kCodingAngleWeighted = 8;                                // 15.13
constexpr uint8_t kCodingTwins = 9;                                        // 15.14
constexpr uint8_t kGuidedGeometryOrder = 1, kGuidedGradedStart = 2;        // 15.12's options
constexpr uint8_t kTwinsGuided = 4;                                        // 15.14's third option
// 15.8: normals within this of unit length take coding 3.
constexpr double kUnitTolerance = 1e-3;
constexpr uint32_t kNone = UINT32_MAX;
// The longest list S_v the encoder searches for a value of the vertex's own
// (15.3); past it, a value is coded as met before, which is as valid.

int bits_for(AttributeKind kind, const EncodeOptions& options) {
  switch (kind) {
    case AttributeKind::kTextureCoordinate: return options.texcoord_bits;
    case AttributeKind::kNormal: return options.normal_bits;
    case AttributeKind::kColour: return options.colour_bits;
    default: return options.generic_bits;
  }
}

// 15.8: mapping 0 when each vertex's corners refer to one value that no
// other vertex refers to, and every vertex has one. A vertex no corner uses
// has the value of its own input number (a value per vertex, as OBJ and PLY
// give them: value v is vertex v's), which mapping 0 keeps tied to it;
// mapping 1 would keep the value but not its vertex. Fills value_of_vertex.
bool one_value_per_vertex(const std::vector<uint32_t>& corner_values, const Mesh& file_mesh,
                          const std::vector<uint32_t>& file_vertex, size_t value_count,
                          std::vector<uint32_t>* value_of_vertex) {
  const size_t vertex_count = file_vertex.size();
  if (value_count != vertex_count) return false;
  value_of_vertex->assign(vertex_count, kNone);
  std::vector<uint32_t> owner(value_count, kNone);
  for (size_t k = 0; k < corner_values.size(); ++k) {
    const uint32_t v = file_mesh.corners[k], x = corner_values[k];
    if ((*value_of_vertex)[v] == kNone) {
      if (owner[x] != kNone) return false;
      (*value_of_vertex)[v] = x;
      owner[x] = v;
    } else if ((*value_of_vertex)[v] != x) {
      return false;
    }
  }
  for (size_t v = 0; v < vertex_count; ++v) {
    if ((*value_of_vertex)[v] != kNone) continue;
    const uint32_t x = file_vertex[v];  // a vertex no corner uses
    if (x >= value_count || owner[x] != kNone) return false;
    (*value_of_vertex)[v] = x;
    owner[x] = uint32_t(v);
  }
  return true;
}

// 15.3: values numbered by first reference over the corners in coder order,
// then the unreferenced ones in input order. Returns the new index of each.
std::vector<uint32_t> first_reference_numbering(const std::vector<uint32_t>& corner_values, size_t value_count) {
  std::vector<uint32_t> number(value_count, kNone);
  uint32_t next = 0;
  for (uint32_t x : corner_values)
    if (number[x] == kNone) number[x] = next++;
  for (uint32_t& n : number)
    if (n == kNone) n = next++;
  return number;
}

// 15.3: the decisions of every corner; m holds m_k.
std::vector<uint8_t> encode_mapping(const std::vector<uint32_t>& m, const Mesh& file_mesh, size_t vertex_count,
                                    size_t value_count) {
  RangeEncoder rc;
  AttributeMappingModel model;
  VertexValueLists lists;
  lists.reset(uint32_t(vertex_count), file_mesh.corners);
  uint32_t met = 0;
  for (size_t k = 0; k < m.size(); ++k) {
    const uint32_t v = file_mesh.corners[k];
    MappingFault fault = MappingFault::kNone;
    code_corner_value(&rc, &model, &lists, v, value_count, &met, fallback_choice(lists, v, m[k], met), &fault);
  }
  return rc.finish();
}

// 15.11: the decisions of every corner, predicted from the faces around it.
std::vector<uint8_t> encode_predicted_mapping(const std::vector<uint32_t>& m, const Mesh& file_mesh,
                                              size_t vertex_count, size_t value_count) {
  const std::vector<uint8_t> single = single_value_vertices(file_mesh.corners, m, vertex_count);
  RangeEncoder rc;
  PredictedMappingModel model;
  PredictedMapping mapping;
  mapping.reset(uint32_t(vertex_count), file_mesh.face_sizes, file_mesh.corners);
  uint32_t met = 0;
  for (size_t k = 0; k < m.size(); ++k) {
    MappingFault fault = MappingFault::kNone;
    mapping.code(&rc, &model, k, value_count, &met, m.data(), &single, &fault);
  }
  return rc.finish();
}

// 15.4: the uniform grid of the values' bounding box (one step, 14.1), the
// grid fields and the range-coded stream; empty if 14.1's bound fails. The
// smallest stream of the label order (coding 0) and, where allowed, 14.6's
// order (coding 4, 15.9), under kGradedStartBelow values 14.4.1's start
// (codings 5 and 6, 15.10; from there on the winner's graded start alone),
// and with a guide the same guided by the positions (coding 7, 15.12, its
// options byte counted), the lowest coding on a tie; with twins, the
// winner's order, start and guide with 15.14's twin candidates too (coding
// 9, its options and plane counted), where smaller; *coding says which.
std::vector<uint8_t> encode_grid_values(const std::vector<float>& table, uint32_t c, int bits, const Mesh& mesh,
                                        bool geometry_order_allowed, bool graded_start_allowed,
                                        const PositionGuide* guide, const AttributeTwins* twins, double* step_out,
                                        uint8_t* coding) {
  const size_t n = table.size() / c;
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (uint32_t a = 0; a < c; ++a) {
    lo[a] = hi[a] = n > 0 ? table[a] : 0.0f;
    for (size_t i = 0; i < n; ++i) {
      lo[a] = std::min(lo[a], table[c * i + a]);
      hi[a] = std::max(hi[a], table[c * i + a]);
    }
  }
  double side = 0;
  for (uint32_t a = 0; a < c; ++a) side = std::max(side, double(hi[a]) - double(lo[a]));
  double step = side / double((uint64_t(1) << bits) - 1);
  if (!(step > 0)) step = 1;  // one point: any step; top 1 below keeps a decision per value
  uint32_t top[3] = {0, 0, 0};
  for (uint32_t a = 0; a < c; ++a) top[a] = uint32_t(std::llround((double(hi[a]) - double(lo[a])) / step));
  if (top[0] == 0 && top[1] == 0 && top[2] == 0) top[0] = 1;
  std::vector<uint32_t> q(3 * n, 0);
  for (size_t i = 0; i < n; ++i)
    for (uint32_t a = 0; a < c; ++a) {
      const long long g = std::llround((double(table[c * i + a]) - double(lo[a])) / step);
      q[3 * i + a] = uint32_t(std::clamp<long long>(g, 0, top[a]));
    }
  std::vector<uint8_t> out;
  put_u8(&out, 0);  // grid 0: one step
  for (uint32_t a = 0; a < c; ++a) put_f32le(&out, lo[a]);
  put_f64le(&out, step);
  for (uint32_t a = 0; a < c; ++a) put_varint(&out, top[a]);
  std::vector<uint8_t> stream = encode_predicted_grid(q, top, mesh, nullptr, CandidateChoice::kFewestBits);
  *coding = kCodingGrid;
  uint8_t options = 0;  // coding 7's and 9's: the order and start of the coding kept
  const auto keep_if_smaller = [&](uint8_t candidate, ClassStart start, PredictionOrder order, const PositionGuide* g) {
    std::vector<uint8_t> other =
        encode_predicted_grid(q, top, mesh, nullptr, CandidateChoice::kFewestBits, start, order, g);
    if (other.size() + (g ? 1 : 0) < stream.size() + (*coding == kCodingGuided ? 1 : 0)) {
      stream = std::move(other);
      *coding = candidate;
      options = uint8_t((order == PredictionOrder::kGeometry ? kGuidedGeometryOrder : 0) |
                        (start == ClassStart::kGraded ? kGuidedGradedStart : 0));
    }
  };
  // The orders and starts allowed, with the coding of each unguided.
  struct Variant {
    uint8_t coding;
    ClassStart start;
    PredictionOrder order;
  };
  std::vector<Variant> variants = {{kCodingGrid, ClassStart::kFlat, PredictionOrder::kLabels}};
  if (geometry_order_allowed) variants.push_back({kCodingGeometryOrder, ClassStart::kFlat, PredictionOrder::kGeometry});
  if (graded_start_allowed && n < kGradedStartBelow) {
    variants.push_back({kCodingGridGraded, ClassStart::kGraded, PredictionOrder::kLabels});
    if (geometry_order_allowed)
      variants.push_back({kCodingGeometryOrderGraded, ClassStart::kGraded, PredictionOrder::kGeometry});
  }
  for (size_t i = 1; i < variants.size(); ++i)
    keep_if_smaller(variants[i].coding, variants[i].start, variants[i].order, nullptr);
  for (size_t i = 0; guide && i < variants.size(); ++i)
    keep_if_smaller(kCodingGuided, variants[i].start, variants[i].order, guide);
  // From kGradedStartBelow values on, the graded start of the winner only
  // (one more pass, not four): it rarely pays there, but when it does a few
  // bytes (spot's texture coordinates: 4,464 -> 4,444).
  if (graded_start_allowed && n >= kGradedStartBelow) {
    if (*coding == kCodingGuided)
      keep_if_smaller(kCodingGuided, ClassStart::kGraded,
                      options & kGuidedGeometryOrder ? PredictionOrder::kGeometry : PredictionOrder::kLabels, guide);
    else if (*coding == kCodingGeometryOrder)
      keep_if_smaller(kCodingGeometryOrderGraded, ClassStart::kGraded, PredictionOrder::kGeometry, nullptr);
    else
      keep_if_smaller(kCodingGridGraded, ClassStart::kGraded, PredictionOrder::kLabels, nullptr);
  }
  if (twins) {  // `options` holds the winner's order and start, whatever its coding
    const bool guided = *coding == kCodingGuided;
    std::vector<uint8_t> twinned = encode_predicted_grid(
        q, top, mesh, nullptr, CandidateChoice::kFewestBits,
        options & kGuidedGradedStart ? ClassStart::kGraded : ClassStart::kFlat,
        options & kGuidedGeometryOrder ? PredictionOrder::kGeometry : PredictionOrder::kLabels,
        guided ? guide : nullptr, false, false, false, twins);
    std::vector<uint8_t> fields = {uint8_t(options | (guided ? kTwinsGuided : 0)), uint8_t(twins->plane.axis)};
    put_varint(&fields, twins->plane.sum);
    if (fields.size() + twinned.size() < stream.size() + (guided ? 1 : 0)) {
      stream = std::move(twinned);
      *coding = kCodingTwins;
      out.insert(out.begin(), fields.begin(), fields.end());
    }
  }
  if (!range_stream_justifies(n, stream.size())) return {};
  if (*coding == kCodingGuided) out.insert(out.begin(), options);
  out.insert(out.end(), stream.begin(), stream.end());
  *step_out = step;
  return out;
}

// 15.8: normals all of unit length (within kUnitTolerance) fit coding 3.
bool unit_normals(const MeshAttribute& a) {
  if (a.kind != AttributeKind::kNormal || a.components != 3) return false;
  for (size_t i = 0; i < a.value_count(); ++i) {
    const double x = a.values[3 * i], y = a.values[3 * i + 1], z = a.values[3 * i + 2];
    if (!(std::fabs(std::sqrt(x * x + y * y + z * z) - 1) <= kUnitTolerance)) return false;
  }
  return true;
}

// 15.8: the grid point, of the four around the octahedral projection of n in
// `frame`, whose output (15.7) is nearest to n in angle.
void nearest_octahedral(const float* n, OctahedralFrame frame, uint32_t steps, uint32_t grid[2]) {
  const double x = n[(frame.t + 1) % 3], y = n[(frame.t + 2) % 3], z = double(frame.sigma) * n[frame.t];
  const double l1 = std::fabs(x) + std::fabs(y) + std::fabs(z);
  double u = x / l1, v = y / l1;
  if (z < 0) {
    const double fu = (u < 0 ? -1.0 : 1.0) * (1 - std::fabs(v)), fv = (v < 0 ? -1.0 : 1.0) * (1 - std::fabs(u));
    u = fu;
    v = fv;
  }
  const double gu = (u + 1) / 2 * steps, gv = (v + 1) / 2 * steps;
  double best = -2;
  for (int du = 0; du < 2; ++du)
    for (int dv = 0; dv < 2; ++dv) {
      const uint32_t cu = uint32_t(std::clamp(std::floor(gu) + du, 0.0, double(steps)));
      const uint32_t cv = uint32_t(std::clamp(std::floor(gv) + dv, 0.0, double(steps)));
      float out[3];
      octahedral_output(cu, cv, steps, frame, out);
      const double dot = double(out[0]) * n[0] + double(out[1]) * n[1] + double(out[2]) * n[2];
      if (dot > best) {
        best = dot;
        grid[0] = cu;
        grid[1] = cv;
      }
    }
}

// 15.7 (15.13 with angle_weighted): bits, then the residuals of every value
// in its predicted frame; m is the value of every corner, q the positions'
// integers in file order.
std::vector<uint8_t> encode_octahedral_values(const std::vector<float>& table, int bits, const Mesh& mesh,
                                              const std::vector<uint32_t>& m, const std::vector<uint32_t>& q,
                                              bool angle_weighted) {
  const size_t n = table.size() / 3;
  const uint32_t steps = (1u << bits) - 1;
  ValueCorners value_corners;
  value_corners.build(m, n);
  CornerCycle cycle;
  cycle.build(mesh.face_sizes, mesh.corners.size());
  OctahedralModel model;
  RangeEncoder rc;
  uint32_t activity = 0;
  for (size_t i = 0; i < n; ++i) {
    OctahedralFrame frame;
    uint32_t predicted[2], grid[2];
    predict_octahedral(value_corners.begin(i), value_corners.end(i), mesh.corners, cycle, q.data(), steps, &frame,
                       &predicted[0], &predicted[1], angle_weighted);
    nearest_octahedral(&table[3 * i], frame, steps, grid);
    const int bucket = octahedral_bucket(activity);
    activity = 0;
    for (int e = 0; e < 2; ++e) {
      const int64_t r = int64_t(grid[e]) - int64_t(predicted[e]);
      const SignedResidual value{uint32_t(r < 0 ? -r : r), r < 0};
      code_octahedral_residual(&rc, &model, bits, bucket, e, value);
      activity += value.magnitude;
    }
  }
  std::vector<uint8_t> out{uint8_t(bits)};
  const std::vector<uint8_t> stream = rc.finish();
  out.insert(out.end(), stream.begin(), stream.end());
  return out;
}

}  // namespace

std::string attribute_problem(const Mesh& mesh, size_t i, bool exact) {
  const MeshAttribute& a = mesh.attributes[i];
  const std::string which = "attribute " + std::to_string(i) + " (\"" + a.name + "\")";
  if (a.name.empty() || a.name.size() > 255) return which + ": a name needs 1 to 255 bytes";
  for (size_t j = 0; j < i; ++j)
    if (mesh.attributes[j].name == a.name) return which + ": a second attribute of this name";
  if (a.components < 1 || a.components > 3) return which + ": components must be 1..3";
  if (a.values.size() % a.components != 0) return which + ": values are not a multiple of the components";
  if (a.value_count() > UINT32_MAX) return which + ": more than 2^32 - 1 values";
  if (a.corner_values.size() != mesh.corners.size())
    return which + ": " + std::to_string(a.corner_values.size()) + " corner indices for " +
           std::to_string(mesh.corners.size()) + " corners";
  for (size_t k = 0; k < a.corner_values.size(); ++k)
    if (a.corner_values[k] >= a.value_count())
      return which + ": corner " + std::to_string(k) + " refers to value " + std::to_string(a.corner_values[k]) +
             " of " + std::to_string(a.value_count());
  if (!exact)
    for (size_t v = 0; v < a.values.size(); ++v)
      if (!std::isfinite(a.values[v]))
        return which + ": value " + std::to_string(v / a.components) +
               " is not finite (exact attributes keep any binary32)";
  return {};
}

Status encode_attribute(const MeshAttribute& attribute, const Mesh& file_mesh, const std::vector<uint32_t>& file_vertex,
                        const std::vector<uint32_t>& quantized, const std::vector<uint64_t>& corner_source,
                        const EncodeOptions& options, std::vector<uint8_t>* payload, AttributeStats* stats,
                        const MirrorPlane* plane) {
  const uint32_t c = attribute.components;
  const size_t value_count = attribute.value_count(), vertex_count = file_vertex.size();
  std::vector<uint32_t> corner_values(corner_source.size());
  for (size_t k = 0; k < corner_source.size(); ++k) corner_values[k] = attribute.corner_values[corner_source[k]];
  // The table in file order: by vertex (mapping 0) or by first reference.
  std::vector<uint32_t> source_value, m;
  const bool per_vertex = one_value_per_vertex(corner_values, file_mesh, file_vertex, value_count, &source_value);
  if (!per_vertex) {
    const std::vector<uint32_t> number = first_reference_numbering(corner_values, value_count);
    source_value.resize(value_count);
    for (size_t x = 0; x < value_count; ++x) source_value[number[x]] = uint32_t(x);
    m.resize(corner_values.size());
    for (size_t k = 0; k < m.size(); ++k) m[k] = number[corner_values[k]];
  }
  std::vector<float> table(value_count * c);
  for (size_t i = 0; i < value_count; ++i)
    for (uint32_t a = 0; a < c; ++a) table[c * i + a] = attribute.values[c * size_t(source_value[i]) + a];

  *stats = AttributeStats{};
  stats->name = attribute.name;
  stats->per_corner = !per_vertex;
  stats->value_count = uint32_t(value_count);
  std::vector<uint8_t> values;
  uint8_t coding = kCodingGrid;
  const bool octahedral = !options.exact_attributes && options.octahedral_normals &&
                          options.normal_bits >= kOctahedralMinBits &&
                          options.normal_bits <= kOctahedralMaxBits && unit_normals(attribute) &&
                          quantized.size() == 3 * vertex_count;
  if (octahedral) {  // 15.7's area weights, or 15.13's angle weights where smaller (15.7 on a tie)
    const std::vector<uint32_t>& corner_values = per_vertex ? file_mesh.corners : m;
    values = encode_octahedral_values(table, options.normal_bits, file_mesh, corner_values, quantized, false);
    coding = kCodingOctahedral;
    if (options.angle_weighted_normals) {
      std::vector<uint8_t> angle = encode_octahedral_values(table, options.normal_bits, file_mesh, corner_values,
                                                            quantized, true);
      if (angle.size() < values.size()) {
        values.swap(angle);
        coding = kCodingAngleWeighted;
      }
    }
    if (!range_stream_justifies(value_count, values.size() - 1)) values.clear();
    if (values.empty()) coding = kCodingGrid;
    stats->step = 2.0 / ((1u << options.normal_bits) - 1);
  }
  if (!options.exact_attributes && values.empty()) {
    Mesh attribute_mesh;
    attribute_mesh.face_sizes = file_mesh.face_sizes;
    attribute_mesh.corners = per_vertex ? file_mesh.corners : m;
    PositionGuide guide;  // 15.12: the CONN vertex of each corner and the positions' integers
    guide.vertex_of_corner = file_mesh.corners.data();
    guide.positions = quantized.data();
    const bool guided = options.attribute_guided && c == 2 && quantized.size() == 3 * vertex_count;
    const bool twinned = plane && quantized.size() == 3 * vertex_count;
    AttributeTwins twins;  // 15.14: over CONN's faces and the positions' integers
    if (twinned) twins = AttributeTwins{*plane, &file_mesh, quantized.data(), uint32_t(vertex_count)};
    values = encode_grid_values(table, c, bits_for(attribute.kind, options), attribute_mesh,
                                options.attribute_geometry_order, options.attribute_graded_start,
                                guided ? &guide : nullptr, twinned ? &twins : nullptr, &stats->step, &coding);
  }
  stats->exact = values.empty();
  if (stats->exact) {
    coding = kCodingExact;
    for (float x : table) put_f32le(&values, x);
  }
  stats->octahedral = coding == kCodingOctahedral || coding == kCodingAngleWeighted;
  stats->angle_weighted = coding == kCodingAngleWeighted;
  const uint8_t guided_options = coding == kCodingGuided || coding == kCodingTwins ? values[0] : 0;
  stats->guided = coding == kCodingGuided || (coding == kCodingTwins && (guided_options & kTwinsGuided) != 0);
  stats->twins = coding == kCodingTwins;
  stats->geometry_order = coding == kCodingGeometryOrder || coding == kCodingGeometryOrderGraded ||
                          (guided_options & kGuidedGeometryOrder);
  stats->graded_start = coding == kCodingGridGraded || coding == kCodingGeometryOrderGraded ||
                        (guided_options & kGuidedGradedStart);

  payload->clear();
  put_varint(payload, vertex_count);
  put_varint(payload, file_mesh.corners.size());
  put_u8(payload, uint8_t(attribute.name.size()));
  payload->insert(payload->end(), attribute.name.begin(), attribute.name.end());
  put_u8(payload, uint8_t(attribute.kind));
  put_u8(payload, uint8_t(c));
  std::vector<uint8_t> mapping;
  uint8_t mapping_kind = kMappingPerVertex;
  if (!per_vertex) {  // 15.3 or 15.11, the smaller (15.3 on a tie)
    mapping = encode_mapping(m, file_mesh, vertex_count, value_count);
    mapping_kind = kMappingPerCorner;
    if (options.attribute_predicted_mapping) {
      std::vector<uint8_t> predicted = encode_predicted_mapping(m, file_mesh, vertex_count, value_count);
      if (predicted.size() < mapping.size()) {
        mapping.swap(predicted);
        mapping_kind = kMappingPredicted;
      }
    }
  }
  stats->predicted_mapping = mapping_kind == kMappingPredicted;
  put_u8(payload, mapping_kind);
  put_varint(payload, value_count);
  put_u8(payload, coding);
  if (!per_vertex) {
    put_varint(payload, mapping.size());
    payload->insert(payload->end(), mapping.begin(), mapping.end());
    stats->mapping_bytes = mapping.size();
  }
  payload->insert(payload->end(), values.begin(), values.end());
  stats->value_bytes = values.size();
  stats->chunk_bytes = 12 + payload->size();
  return Status::Ok();
}

}  // namespace qmc
