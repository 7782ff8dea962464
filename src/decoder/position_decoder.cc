// Positions: spec/qmc-format.md section 6 (method 0, seed 001 §2.6, §5.1.2:
// per-axis Huffman-coded deltas between consecutive vertices in file order)
// and section 14 (methods 1 - 14: predicted from the decoded mesh, range
// coded): the payload's header and method 0 here, section 14's decoding of
// the vertices in predicted_grid_decoder.cc.
#include "decoder/position_decoder.h"

#include <cmath>
#include <string>

#include "common/bit_reader.h"
#include "common/byte_io.h"
#include "common/exact_arith.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"
#include "common/position_coding.h"
#include "common/surface_lattice.h"

namespace qmc {
namespace {

Status bad_payload(const std::string& message) { return Status(ErrorCode::kBadChunkPayload, "POSN: " + message); }

// Section 14.1: the byte after vertex_count selects the method.
constexpr uint8_t kPredictedSelector = 0x81, kGradedSelector = 0x83;  // methods 1 and 3 (14.1)
// Methods 4 - 14 (14.1, 14.6 - 14.15), 0x84 .. 0x8E, all with the start
// byte; methods 8 - 14 with the features byte of 14.9 after it, methods 11
// - 14 with their shear and plane bytes after that (14.12 - 14.15), method
// 14 with its lattice byte after those; methods 9 - 14 with a plane end
// with 14.10's plane.
constexpr uint8_t kFirstGeometryOrderSelector = 0x84, kLastGeometryOrderSelector = 0x8E;
constexpr uint8_t kFeaturesSelector = 0x88, kMirrorSelector = 0x89, kNearMirrorSelector = 0x8A;
constexpr uint8_t kShearSelector = 0x8B, kExtrapolationSelector = 0x8C, kAxisClassSelector = 0x8D;
constexpr uint8_t kLatticeSelector = 0x8E;
constexpr uint8_t kLargestShear = 16;

Status read_box(ByteReader* in, QuantizationInfo* info) {
  for (int a = 0; a < 3; ++a)
    if (!in->get_f32le(&info->min[a])) return bad_payload("bounding box cut short");
  for (int a = 0; a < 3; ++a)
    if (!in->get_f32le(&info->max[a])) return bad_payload("bounding box cut short");
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(info->min[a]) || !std::isfinite(info->max[a]) || !(info->min[a] <= info->max[a]))
      return bad_payload("bounding box axis " + std::to_string(a) + " is not finite with min <= max");
  return Status::Ok();
}

// Section 14.1: origin, steps and tops of the grid; every grid point must
// be finite in binary32.
Status read_grid(ByteReader* in, QuantizationInfo* info) {
  uint8_t grid = 0;
  if (!in->get_u8(&grid)) return bad_payload("grid field missing");
  if (grid > 1) return bad_payload("grid " + std::to_string(grid) + " is neither 0 (one step) nor 1 (a step per axis)");
  for (int a = 0; a < 3; ++a)
    if (!in->get_f32le(&info->min[a])) return bad_payload("grid origin cut short");
  for (int a = 0; a < 3; ++a)
    if ((a == 0 || grid == 1) && !in->get_f64le(&info->step[a])) return bad_payload("grid step cut short");
  if (grid == 0) info->step[1] = info->step[2] = info->step[0];
  for (int a = 0; a < 3; ++a) {
    uint64_t top = 0;
    if (!in->get_varint(&top)) return bad_payload("grid top missing or malformed");
    if (top > (uint64_t(1) << 30) - 1) return bad_payload("top " + std::to_string(top) + " above 2^30 - 1");
    info->top[a] = uint32_t(top);
  }
  for (int a = 0; a < 3; ++a) {
    const std::string axis = "axis " + std::to_string(a);
    if (!std::isfinite(info->min[a])) return bad_payload(axis + ": the origin is not finite");
    if (!std::isfinite(info->step[a]) || info->step[a] < 0) return bad_payload(axis + ": the step is not finite and >= 0");
    info->max[a] = float(double(info->min[a]) + mul(double(info->top[a]), info->step[a]));
    if (!std::isfinite(info->max[a])) return bad_payload(axis + ": the grid's last point overflows binary32");
  }
  int bits = 0;
  for (uint32_t t : info->top) bits = std::max(bits, bit_length(t));
  info->bits = bits;
  return Status::Ok();
}

// Sections 14.12 - 14.15: method 11's shear weight (1 .. 16) or methods
// 12's - 14's (0 .. 16, 0 none), and the kind of its plane (0 none, 1
// method 9's, 2 method 10's), before the plane itself.
Status read_shear(ByteReader* in, QuantizationInfo* info, bool* mirrored) {
  const std::string method = "method " + std::to_string(info->method);
  const char* section = info->method == 14   ? " (section 14.15)"
                        : info->method == 13 ? " (section 14.14)"
                        : info->method == 12 ? " (section 14.13)"
                                             : " (section 14.12)";
  const uint8_t least = info->method >= 12 ? 0 : 1;  // methods 12 - 14 may shear nothing
  uint8_t shear = 0, plane = 0;
  if (!in->get_u8(&shear)) return bad_payload(method + "'s shear byte missing" + section);
  if (shear < least || shear > kLargestShear)
    return bad_payload("shear " + std::to_string(shear) + " outside " + std::to_string(least) + "..16" + section);
  if (!in->get_u8(&plane)) return bad_payload(method + "'s plane byte missing" + section);
  if (plane > 2) return bad_payload("plane " + std::to_string(plane) + " is not 0, 1 or 2" + section);
  info->shear = shear;
  info->near_images = plane == 2;
  *mirrored = plane != 0;
  return Status::Ok();
}

// Section 14.15: method 14's lattice factor k, 2 .. 16.
Status read_lattice(ByteReader* in, QuantizationInfo* info) {
  uint8_t k = 0;
  if (!in->get_u8(&k)) return bad_payload("method 14's lattice byte missing (section 14.15)");
  if (k < kLatticeLeastFactor || k > kLatticeLargestFactor)
    return bad_payload("lattice " + std::to_string(k) + " outside 2..16 (section 14.15)");
  info->lattice = k;
  return Status::Ok();
}

// Section 14.10: the plane of methods 9 - 13, its axis byte and sum
// (checked against the grid's top once read_grid has it).
Status read_mirror_plane(ByteReader* in, QuantizationInfo* info) {
  const std::string method = "method " + std::to_string(info->method);
  uint8_t axis = 0;
  uint64_t sum = 0;
  if (!in->get_u8(&axis)) return bad_payload(method + "'s mirror axis missing (section 14.10)");
  if (axis > 2) return bad_payload("mirror axis " + std::to_string(axis) + " is not 0, 1 or 2 (section 14.10)");
  if (!in->get_varint(&sum)) return bad_payload(method + "'s mirror sum missing or malformed (section 14.10)");
  if (sum >= (uint64_t(1) << 31)) return bad_payload("mirror sum " + std::to_string(sum) + " above 2^31 - 1 (section 14.10)");
  info->mirror_axis = axis;
  info->mirror_sum = uint32_t(sum);
  return Status::Ok();
}

Status read_header(ByteReader* in, uint32_t vertex_count, QuantizationInfo* info) {
  uint64_t count = 0;
  uint8_t selector = 0;
  if (!in->get_varint(&count) || !in->get_u8(&selector)) return bad_payload("header cut short or malformed varint");
  if (count != vertex_count)
    return bad_payload("vertex_count " + std::to_string(count) + " differs from CONN's " +
                       std::to_string(vertex_count));
  const bool geometry_order = selector >= kFirstGeometryOrderSelector && selector <= kLastGeometryOrderSelector;
  if (selector == kPredictedSelector || selector == kGradedSelector || geometry_order) {
    info->method = selector - 0x80;
    info->graded_start = selector == kGradedSelector;
    if (geometry_order) {
      uint8_t start = 0;
      if (!in->get_u8(&start))
        return bad_payload("method " + std::to_string(info->method) + "'s start byte missing (section 14.1)");
      if (start > 1) return bad_payload("start " + std::to_string(start) + " is neither 0 nor 1 (section 14.1)");
      info->graded_start = start == 1;
    }
    bool mirrored = selector == kMirrorSelector || selector == kNearMirrorSelector;
    info->near_images = selector == kNearMirrorSelector;
    const bool sheared = selector >= kShearSelector;  // 11 - 14
    info->edge_extrapolation = selector >= kExtrapolationSelector;  // 12 - 14
    info->axis_classes = selector >= kAxisClassSelector;  // 13 and 14
    if (selector == kFeaturesSelector || mirrored || sheared) {
      const std::string method = "method " + std::to_string(info->method);
      uint8_t features = 0;
      if (!in->get_u8(&features)) return bad_payload(method + "'s features byte missing (section 14.9)");
      if (features > 7)
        return bad_payload(method + "'s features " + std::to_string(features) +
                           " has a bit above bit 2 set (section 14.9)");
      info->features = features;
      if (sheared)
        if (Status s = read_shear(in, info, &mirrored); !s.ok()) return s;
      if (selector == kLatticeSelector)
        if (Status s = read_lattice(in, info); !s.ok()) return s;
      if (mirrored)
        if (Status s = read_mirror_plane(in, info); !s.ok()) return s;
    } else {
      info->features = position_features(info->method == 5 || info->method == 7, info->method >= 6, false);
    }
    if (Status s = read_grid(in, info); !s.ok()) return s;
    if (info->mirror_axis >= 0 && info->mirror_sum > 2 * uint64_t(info->top[size_t(info->mirror_axis)]))
      return bad_payload("mirror sum " + std::to_string(info->mirror_sum) + " above 2 top[" +
                         std::to_string(info->mirror_axis) + "] (section 14.10)");
    for (int a = 0; a < 3 && info->lattice > 1; ++a)
      if (info->top[a] >= kLatticeTopBound)
        return bad_payload("top " + std::to_string(info->top[a]) + " of axis " + std::to_string(a) +
                           " not below 2^24, as method 14's lattice needs (section 14.15)");
    return Status::Ok();
  }
  if (selector >= 0x80)
    return Status(ErrorCode::kUnsupportedFeature,
                  "POSN: method " + std::to_string(selector - 0x80) +
                      " is not defined (section 14.1 knows 0, 1 and 3 - 14)");
  if (selector < 1 || selector > 30) return bad_payload("quantization bits " + std::to_string(selector) + " outside 1..30");
  info->method = 0;
  info->bits = selector;
  if (Status s = read_box(in, info); !s.ok()) return s;
  for (int a = 0; a < 3; ++a) {
    info->step[a] = (double(info->max[a]) - double(info->min[a])) / double((uint64_t(1) << info->bits) - 1);
    info->top[a] = uint32_t((uint64_t(1) << info->bits) - 1);
  }
  return Status::Ok();
}

// Section 6.3: Huffman-coded deltas in label order.
Status decode_deltas(BitReader* bits, size_t size, uint32_t vertex_count, const QuantizationInfo& info,
                     std::vector<uint32_t>* quantized) {
  // Each vertex costs at least three code words of one bit.
  if (uint64_t(vertex_count) * 3 > bits->bits_remaining())
    return Status(ErrorCode::kLimitExceeded, "POSN: " + std::to_string(vertex_count) +
                                                 " vertices cannot fit in " + std::to_string(size) + " bytes");
  const uint32_t alphabet = uint32_t(info.bits) + 1;
  HuffmanDecoder codes[3];
  for (HuffmanDecoder& code : codes)
    if (Status s = read_table(bits, alphabet, &code); !s.ok()) return s;
  const int64_t top = (int64_t(1) << info.bits) - 1;
  quantized->resize(size_t(vertex_count) * 3);
  int64_t previous[3] = {0, 0, 0};
  for (size_t i = 0; i < size_t(vertex_count) * 3; ++i) {
    const int axis = int(i % 3);
    const int c = codes[axis].decode(bits);
    if (c < 0) return Status(ErrorCode::kBadSymbol, "POSN: invalid delta code word");
    const int64_t q = previous[axis] + read_signed_extra(bits, c);
    if (bits->overrun()) return Status(ErrorCode::kTruncated, "POSN: bit stream ends before the last vertex");
    const bool flat = info.min[axis] == info.max[axis];
    if (q < 0 || q > top || (flat && q != 0))
      return Status(ErrorCode::kBadSymbol, "POSN: vertex " + std::to_string(i / 3) + " axis " +
                                               std::to_string(axis) + " decodes to " + std::to_string(q) +
                                               ", outside 0.." + std::to_string(flat ? 0 : top));
    previous[axis] = q;
    (*quantized)[i] = uint32_t(q);
  }
  if (!bits->at_clean_end()) return bad_payload("bits left over after the last vertex");
  return Status::Ok();
}

}  // namespace

void dequantization_steps(const QuantizationInfo& info, double lo[3], double step[3]) {
  for (int a = 0; a < 3; ++a) {
    lo[a] = double(info.min[a]);
    step[a] = info.step[a];
  }
}

Status decode_positions(const uint8_t* payload, size_t size, const Mesh& faces, uint32_t vertex_count,
                        QuantizationInfo* info, std::vector<uint32_t>* quantized, std::vector<float>* positions) {
  ByteReader in(payload, size);
  if (Status s = read_header(&in, vertex_count, info); !s.ok()) return s;
  quantized->clear();
  positions->clear();
  if (info->method >= 1) {
    const PredictedGridNames names{"POSN", "vertex", "vertices", "axis"};
    const ClassStart start = info->graded_start ? ClassStart::kGraded : ClassStart::kFlat;
    const PredictionOrder order = info->method >= 4 ? PredictionOrder::kGeometry : PredictionOrder::kLabels;
    const MirrorPlane plane{info->mirror_axis, info->mirror_sum, info->near_images};
    if (Status s = decode_predicted_grid(in.cursor(), in.remaining(), faces, vertex_count, info->top.data(), names,
                                         quantized, start, order, nullptr, info->features & kQuadTwistFeature,
                                         info->features & kMaskContextsFeature, info->features & kTriangleTwistFeature,
                                         info->mirror_axis >= 0 ? &plane : nullptr, nullptr, info->shear,
                                         info->edge_extrapolation, info->axis_classes, info->lattice);
        !s.ok())
      return s;
  } else {
    BitReader bits(in.cursor(), in.remaining());
    if (vertex_count == 0) {
      if (!bits.at_clean_end()) return bad_payload("data after an empty vertex list");
      return Status::Ok();
    }
    if (Status s = decode_deltas(&bits, size, vertex_count, *info, quantized); !s.ok()) return s;
  }
  // Sections 6.4 and 14.1, the step of each axis computed once; mul() keeps
  // the product out of any fused multiply-add.
  double step[3], lo[3];
  dequantization_steps(*info, lo, step);
  positions->resize(quantized->size());
  for (size_t i = 0; i < quantized->size(); i += 3)
    for (int a = 0; a < 3; ++a) {
      const double scaled = mul(double((*quantized)[i + a]), step[a]);
      (*positions)[i + a] = float(lo[a] + scaled);
    }
  return Status::Ok();
}

}  // namespace qmc
