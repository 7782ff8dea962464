// The aTTR chunk, spec/qmc-format.md section 15: header and checks (15.1),
// the per-corner mapping (15.3, 15.11), and the values predicted over the
// attribute mesh (15.4, 15.9, 15.10; guided by the positions, 15.12), unit
// normals in an octahedral frame (15.7, 15.13), or stored as binary32 (15.5).
#include "decoder/attribute_decoder.h"

#include <cmath>
#include <cstring>
#include <string>

#include "common/attribute_mapping.h"
#include "common/byte_io.h"
#include "common/exact_arith.h"
#include "common/octahedral_normal.h"
#include "common/predicted_mapping.h"
#include "common/range_coder.h"
#include "decoder/position_decoder.h"

namespace qmc {
namespace {

constexpr uint8_t kMappingPerVertex = 0, kMappingPredicted = 3;  // 1: per corner, 15.3
// 15.1: mapping 2 stays unassigned (the vector valid_attr_unknown_mapping_skipped uses it).
constexpr uint8_t kMappingUnassigned = 2;
// Coding 0 (15.4) has no name here: decode_grid_values reads it like 4 - 7.
constexpr uint8_t kCodingExact = 1, kCodingOctahedral = 3, kCodingGeometryOrder = 4;
constexpr uint8_t kCodingGridGraded = 5, kCodingGeometryOrderGraded = 6;  // 15.10
constexpr uint8_t kCodingGuided = 7;                                       // 15.12
constexpr uint8_t kCodingAngleWeighted = 8;                                // 15.13
constexpr uint8_t kCodingTwins = 9;                                        // 15.14
// 15.12's options: the geometry order, the graded start; other bits are 0.
// 15.14's add the guided rule.
constexpr uint8_t kGuidedGeometryOrder = 1, kGuidedGradedStart = 2, kGuidedOptionBits = 3;
constexpr uint8_t kTwinsGuided = 4, kTwinsOptionBits = 7;
// 15.1: coding 2 stays unassigned (the vector valid_attr_unknown_coding_skipped uses it).
constexpr uint8_t kCodingUnassigned = 2;
constexpr uint32_t kMaxTop = (uint32_t(1) << 30) - 1;

struct Header {
  std::string label = "aTTR";  // "aTTR \"name\"" once the name is read
  uint8_t mapping = 0, coding = 0, components = 0;
  uint64_t value_count = 0;
  const uint8_t* mapping_stream = nullptr;
  size_t mapping_bytes = 0;
};

Status bad(const Header& h, const std::string& message, const char* section = "15.1") {
  return Status(ErrorCode::kBadChunkPayload, h.label + ": " + message + " (section " + section + ")");
}

uint64_t corner_count(const Mesh& faces) { return faces.corners.size(); }

// Checks 1-3 of 15.1.
Status read_identity(ByteReader* in, const Mesh& faces, uint32_t vertex_count,
                     const std::vector<std::string>& earlier, Header* h, MeshAttribute* out) {
  uint64_t v = 0, k = 0;
  if (!in->get_varint(&v) || v != vertex_count)
    return bad(*h, "vertex_count missing, malformed or not CONN's " + std::to_string(vertex_count));
  if (!in->get_varint(&k) || k != corner_count(faces))
    return bad(*h, "corner_count missing, malformed or not CONN's " + std::to_string(corner_count(faces)));
  uint8_t length = 0;
  if (!in->get_u8(&length) || length == 0) return bad(*h, "name_length missing or 0");
  if (in->remaining() < length) return bad(*h, "the name is cut short");
  out->name.assign(reinterpret_cast<const char*>(in->cursor()), length);
  in->skip(length);
  h->label = "aTTR \"" + out->name + "\"";
  for (const std::string& name : earlier)
    if (name == out->name) return bad(*h, "a second attribute of this name (skipped ones count, check 2)");
  uint8_t kind = 0;
  if (!in->get_u8(&kind) || !in->get_u8(&h->components) || !in->get_u8(&h->mapping))
    return bad(*h, "kind, components or mapping missing");
  if (h->components < 1 || h->components > 3)
    return bad(*h, "components " + std::to_string(h->components) + " outside 1..3");
  out->kind = AttributeKind(kind);
  out->components = h->components;
  return Status::Ok();
}

// Checks 5-8 of 15.1 (the caller has skipped an unknown mapping, check 4).
Status read_sizes(ByteReader* in, uint32_t vertex_count, Header* h, bool* skipped) {
  if (!in->get_varint(&h->value_count) || h->value_count > UINT32_MAX)
    return bad(*h, "value_count missing, malformed or above 2^32 - 1");
  if (h->mapping == kMappingPerVertex && h->value_count != vertex_count)
    return bad(*h, "value_count " + std::to_string(h->value_count) + " is not V = " + std::to_string(vertex_count) +
                       " with mapping 0");
  if (!in->get_u8(&h->coding)) return bad(*h, "coding missing");
  if (h->coding > kCodingTwins || h->coding == kCodingUnassigned) {  // 15.1 check 6
    *skipped = true;
    return Status::Ok();
  }
  if ((h->coding == kCodingOctahedral || h->coding == kCodingAngleWeighted) && h->components != 3)
    return bad(*h, "coding " + std::to_string(h->coding) + " (octahedral normals) with " +
                       std::to_string(h->components) + " components, not 3");
  if (h->coding == kCodingGuided && h->components != 2)
    return bad(*h, "coding 7 (guided texture coordinates) with " + std::to_string(h->components) +
                       " components, not 2");
  if (h->mapping != kMappingPerVertex) {
    uint64_t m = 0;
    if (!in->get_varint(&m) || m > in->remaining())
      return bad(*h, "mapping_bytes missing, malformed or beyond the payload");
    h->mapping_stream = in->cursor();
    h->mapping_bytes = size_t(m);
    in->skip(size_t(m));
  }
  const uint64_t rest = in->remaining();
  if (h->coding == kCodingExact && rest != 4 * uint64_t(h->components) * h->value_count)
    return bad(*h, std::to_string(rest) + " bytes of values, not 4 C N = " +
                       std::to_string(4 * uint64_t(h->components) * h->value_count));
  if (h->coding != kCodingExact && !range_stream_justifies(h->value_count, rest))
    return Status(ErrorCode::kLimitExceeded, h->label + ": " + std::to_string(h->value_count) + " values for " +
                                                 std::to_string(rest) + " bytes, above 512 (L + 8) (section 15.1)");
  return Status::Ok();
}

Status mapping_fault(const Header& h, MappingFault fault, uint64_t k, const char* section) {
  const char* what = fault == MappingFault::kOwnIndex     ? "an index past the vertex's own values"
                     : fault == MappingFault::kNothingMet ? "an earlier value before any value was met"
                                                          : "an index past the values met so far";
  return Status(ErrorCode::kBadSymbol,
                h.label + ": corner " + std::to_string(k) + " refers to " + what + " (section " + section + ")");
}

// Sections 15.3 (mapping 1) and 15.11 (mapping 3): m_k for every corner.
Status decode_mapping(const Header& h, const Mesh& faces, uint32_t vertex_count, std::vector<uint32_t>* m) {
  RangeDecoder rc(h.mapping_stream, h.mapping_bytes);
  if (rc.bad_start())
    return Status(ErrorCode::kBadChunkPayload,
                  h.label + ": the mapping stream starts with 0xFFFFFFFF (section 13.5.2)");
  const bool predicted = h.mapping == kMappingPredicted;
  const char* section = predicted ? "15.11" : "15.3";
  AttributeMappingModel model;
  VertexValueLists lists;
  PredictedMappingModel predicted_model;
  PredictedMapping predicted_mapping;
  if (predicted)
    predicted_mapping.reset(vertex_count, faces.face_sizes, faces.corners);
  else
    lists.reset(vertex_count, faces.corners);
  m->resize(faces.corners.size());
  uint32_t met = 0;
  for (size_t k = 0; k < faces.corners.size(); ++k) {
    MappingFault fault = MappingFault::kNone;
    (*m)[k] = predicted ? predicted_mapping.code(&rc, &predicted_model, k, h.value_count, &met, nullptr, nullptr, &fault)
                        : code_corner_value(&rc, &model, &lists, faces.corners[k], h.value_count, &met,
                                            MappingChoice{}, &fault);
    if (fault != MappingFault::kNone) return mapping_fault(h, fault, k, section);
    if (rc.overrun())
      return Status(ErrorCode::kTruncated, h.label + ": the mapping stream ends inside corner " + std::to_string(k) +
                                               " (section " + section + ")");
  }
  if (rc.unread() != 0)
    return Status(ErrorCode::kBadChunkPayload, h.label + ": " + std::to_string(rc.unread()) +
                                                   " bytes after the mapping stream's data (section 13.5.2)");
  return Status::Ok();
}

// Section 15.4's grid: 14.1's fields for C components.
Status read_grid(ByteReader* in, const Header& h, float origin[3], double step[3], uint32_t top[3]) {
  const int c = h.components;
  uint8_t grid = 0;
  if (!in->get_u8(&grid) || grid > 1) return bad(h, "grid missing or above 1");
  for (int a = 0; a < c; ++a)
    if (!in->get_f32le(&origin[a])) return bad(h, "grid origin cut short");
  for (int a = 0; a < (grid == 0 ? 1 : c); ++a)
    if (!in->get_f64le(&step[a])) return bad(h, "grid step cut short");
  for (int a = 1; grid == 0 && a < c; ++a) step[a] = step[0];
  for (int a = 0; a < c; ++a) {
    uint64_t t = 0;
    if (!in->get_varint(&t) || t > kMaxTop) return bad(h, "grid top missing, malformed or above 2^30 - 1");
    top[a] = uint32_t(t);
  }
  for (int a = 0; a < c; ++a) {
    const std::string which = "component " + std::to_string(a);
    if (!std::isfinite(origin[a])) return bad(h, which + ": the origin is not finite");
    if (!std::isfinite(step[a]) || step[a] < 0) return bad(h, which + ": the step is not finite and >= 0");
    if (!std::isfinite(float(double(origin[a]) + mul(double(top[a]), step[a]))))
      return bad(h, which + ": the grid's last point overflows binary32");
  }
  return Status::Ok();
}

// Section 15.14: coding 9's options and mirror plane (before the grid).
Status read_twin_fields(ByteReader* in, const Header& h, uint8_t* options, MirrorPlane* plane) {
  if (!in->get_u8(options) || *options > kTwinsOptionBits)
    return bad(h, "options missing or with a bit of 3..7 set", "15.14");
  if ((*options & kTwinsGuided) && h.components != 2)
    return bad(h, "option bit 2 (the guided rule) with " + std::to_string(h.components) + " components, not 2",
               "15.14");
  uint8_t axis = 0;
  uint64_t sum = 0;
  if (!in->get_u8(&axis) || axis > 2) return bad(h, "mirror axis missing or above 2", "15.14");
  if (!in->get_varint(&sum) || sum > (uint64_t(1) << 31) - 1)
    return bad(h, "mirror sum missing, malformed or above 2^31 - 1", "15.14");
  *plane = MirrorPlane{axis, uint32_t(sum)};
  return Status::Ok();
}

// Sections 15.4, 15.9, 15.10, 15.12 and 15.14: the values predicted over the
// attribute mesh, in label order (codings 0 and 5) or 14.6's geometry order
// (codings 4 and 6), the class probabilities starting at 1024 (0, 4) or as
// 14.4.1 (5, 6); coding 7 says both in its options and is guided by the
// positions (q by CONN label, as 15.7 takes them); coding 9 says all three
// and adds the twin candidate.
Status decode_grid_values(ByteReader* in, const Header& h, const Mesh& faces, const std::vector<uint32_t>& m,
                          const std::vector<uint32_t>& positions, AttributeCoding* coding, std::vector<float>* values) {
  float* origin = coding->origin.data();
  double* step = coding->step.data();
  uint32_t* top = coding->top.data();
  uint8_t options = 0;
  if (h.coding == kCodingGuided && (!in->get_u8(&options) || options > kGuidedOptionBits))
    return bad(h, "options missing or with a bit of 2..7 set", "15.12");
  AttributeTwins twins;
  if (h.coding == kCodingTwins)
    if (Status s = read_twin_fields(in, h, &options, &twins.plane); !s.ok()) return s;
  coding->options = options;
  coding->mirror_axis = h.coding == kCodingTwins ? twins.plane.axis : -1;
  coding->mirror_sum = twins.plane.sum;
  if (Status s = read_grid(in, h, origin, step, top); !s.ok()) return s;
  Mesh attribute_mesh;
  attribute_mesh.face_sizes = faces.face_sizes;
  attribute_mesh.corners = m;
  std::vector<uint32_t> q;
  const PredictedGridNames names{h.label, "value", "values", "component"};
  // Codings 7 and 9 share the options' bits 0 and 1.
  const bool geometry = h.coding == kCodingGeometryOrder || h.coding == kCodingGeometryOrderGraded ||
                        (options & kGuidedGeometryOrder);
  const bool graded = h.coding == kCodingGridGraded || h.coding == kCodingGeometryOrderGraded ||
                      (options & kGuidedGradedStart);
  const bool guided = h.coding == kCodingGuided || (h.coding == kCodingTwins && (options & kTwinsGuided));
  PositionGuide guide;
  guide.vertex_of_corner = faces.corners.data();
  guide.positions = positions.data();
  twins.faces = &faces;
  twins.positions = positions.data();
  twins.vertex_count = uint32_t(positions.size() / 3);  // POSN's integers of CONN's V vertices (4.2: POSN came first)
  if (Status s = decode_predicted_grid(in->cursor(), in->remaining(), attribute_mesh, uint32_t(h.value_count), top,
                                       names, &q, graded ? ClassStart::kGraded : ClassStart::kFlat,
                                       geometry ? PredictionOrder::kGeometry : PredictionOrder::kLabels,
                                       guided ? &guide : nullptr, false, false, false, nullptr,
                                       h.coding == kCodingTwins ? &twins : nullptr);
      !s.ok())
    return s;
  const size_t c = h.components;
  values->resize(c * size_t(h.value_count));
  for (size_t i = 0; i < size_t(h.value_count); ++i)
    for (size_t a = 0; a < c; ++a)
      (*values)[c * i + a] = float(double(origin[a]) + mul(double(q[3 * i + a]), step[a]));
  return Status::Ok();
}

Status truncated_in_value(const Header& h, size_t i) {
  return Status(ErrorCode::kTruncated,
                h.label + ": the range-coded stream ends inside value " + std::to_string(i) + " (section 15.7)");
}

// Sections 15.7 and 15.13: unit normals on the octahedral grid of B bits,
// each in the frame of its prediction from the positions q (coder order),
// the faces weighted by area (coding 3) or by their angle (coding 8).
Status decode_octahedral_values(ByteReader* in, const Header& h, const Mesh& faces, const std::vector<uint32_t>& m,
                                const std::vector<uint32_t>& q, AttributeCoding* coding, std::vector<float>* values) {
  uint8_t bits = 0;
  if (!in->get_u8(&bits) || bits < kOctahedralMinBits || bits > kOctahedralMaxBits)
    return bad(h, "bits missing or outside 2..16", "15.7");
  coding->top = {uint32_t((1u << bits) - 1), uint32_t((1u << bits) - 1), 0};
  const uint32_t steps = coding->top[0];
  RangeDecoder rc(in->cursor(), in->remaining());
  if (rc.bad_start())
    return Status(ErrorCode::kBadChunkPayload, h.label + ": the values' stream starts with 0xFFFFFFFF (section 13.5.2)");
  ValueCorners value_corners;
  value_corners.build(m, size_t(h.value_count));
  CornerCycle cycle;
  cycle.build(faces.face_sizes, faces.corners.size());
  OctahedralModel model;
  values->resize(3 * size_t(h.value_count));
  uint32_t activity = 0;
  for (size_t i = 0; i < size_t(h.value_count); ++i) {
    OctahedralFrame frame;
    uint32_t predicted[2];
    predict_octahedral(value_corners.begin(i), value_corners.end(i), faces.corners, cycle, q.data(), steps, &frame,
                       &predicted[0], &predicted[1], h.coding == kCodingAngleWeighted);
    const int bucket = octahedral_bucket(activity);
    uint32_t grid[2];
    activity = 0;
    for (int e = 0; e < 2; ++e) {
      const SignedResidual r = code_octahedral_residual(&rc, &model, bits, bucket, e, SignedResidual{});
      if (rc.overrun()) return truncated_in_value(h, i);
      const int64_t g = int64_t(predicted[e]) + (r.negative ? -int64_t(r.magnitude) : int64_t(r.magnitude));
      if (g < 0 || g > int64_t(steps))
        return Status(ErrorCode::kBadSymbol, h.label + ": value " + std::to_string(i) + " " + (e ? "v" : "u") +
                                                 " decodes to " + std::to_string(g) + ", outside 0.." +
                                                 std::to_string(steps) + " (section 15.7)");
      grid[e] = uint32_t(g);
      activity += r.magnitude;
    }
    octahedral_output(grid[0], grid[1], steps, frame, &(*values)[3 * i]);
  }
  if (rc.unread() != 0)
    return Status(ErrorCode::kBadChunkPayload, h.label + ": " + std::to_string(rc.unread()) +
                                                   " bytes after the range-coded data (section 13.5.2)");
  return Status::Ok();
}

// Section 15.5: binary32 as stored, NaN payloads included.
void read_exact_values(ByteReader* in, size_t count, std::vector<float>* values) {
  values->resize(count);
  for (size_t i = 0; i < count; ++i) {
    const uint32_t bits = load_u32le(in->cursor() + 4 * i);
    std::memcpy(&(*values)[i], &bits, 4);
  }
}

}  // namespace

Status decode_attribute(const uint8_t* payload, size_t size, const Mesh& faces, uint32_t vertex_count,
                        const std::vector<uint32_t>& quantized, const std::vector<std::string>& earlier,
                        OutputBudget* budget, MeshAttribute* out, AttributeCoding* coding, bool* skipped) {
  *out = MeshAttribute{};
  *coding = AttributeCoding{};
  *skipped = false;
  ByteReader in(payload, size);
  Header h;
  if (Status s = read_identity(&in, faces, vertex_count, earlier, &h, out); !s.ok()) return s;
  if (h.mapping > kMappingPredicted || h.mapping == kMappingUnassigned) {  // check 4: a later revision's mapping
    *skipped = true;
    return Status::Ok();
  }
  if (Status s = read_sizes(&in, vertex_count, &h, skipped); !s.ok() || *skipped) return s;
  if (Status s = check_limit(h.label + ": values", h.value_count, kNoLimit, "max_output_bytes"); !s.ok()) return s;
  if (Status s = budget->charge(attribute_output_bytes(out->name.size(), h.components, h.value_count,
                                                       faces.corners.size()),
                                h.label);
      !s.ok())
    return s;
  coding->mapping = h.mapping;
  coding->coding = h.coding;
  coding->chunk_bytes = 12 + uint64_t(size);
  if (h.mapping == kMappingPerVertex)
    out->corner_values = faces.corners;
  else if (Status s = decode_mapping(h, faces, vertex_count, &out->corner_values); !s.ok())
    return s;
  if (h.coding == kCodingExact) {
    read_exact_values(&in, size_t(h.value_count) * h.components, &out->values);
    return Status::Ok();
  }
  if (h.coding == kCodingOctahedral || h.coding == kCodingAngleWeighted)
    return decode_octahedral_values(&in, h, faces, out->corner_values, quantized, coding, &out->values);
  return decode_grid_values(&in, h, faces, out->corner_values, quantized, coding, &out->values);
}

}  // namespace qmc
