// Geometry-image chunks, spec/qmc-format.md section 13.
#include "encoder/gim_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/byte_io.h"
#include "common/gim_face_code.h"
#include "common/range_coder.h"
#include "encoder/chunk_writer.h"
#include "encoder/encoder_internal.h"
#include "encoder/plane_encoder.h"
#include "qmc/decoder.h"

namespace qmc {
namespace {

inline constexpr uint8_t kGimMinorVersion = 4;  // section 11

Status invalid(const std::string& message) { return Status(ErrorCode::kInvalidArgument, message); }

uint64_t zigzag(int64_t v) { return v < 0 ? (uint64_t(-(v + 1)) << 1) | 1 : uint64_t(v) << 1; }

struct PlaneScale {
  double offset = 0, step = 1;
};

// 13.2 format 0: each axis from its minimum, one step for X, Y and Z (the
// largest extent over 65535), so the grid is quantized isotropically, as
// POSN does (6.1).
void geometry_scales(const std::vector<double>& xyz, PlaneScale out[3]) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t p = 0; p < xyz.size() / 3; ++p)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], xyz[3 * p + size_t(a)]);
      hi[a] = std::max(hi[a], xyz[3 * p + size_t(a)]);
    }
  const double step = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / 65535.0;
  for (int a = 0; a < 3; ++a) out[a] = {lo[a], step > 0 ? step : 1.0};
}

uint32_t quantize16(double value, const PlaneScale& scale) {
  const double q = std::nearbyint((value - scale.offset) / scale.step);
  return uint32_t(std::clamp(q, 0.0, 65535.0));
}

uint32_t float_bits(double value) {
  const float f = float(value);
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

std::vector<uint8_t> gimg_payload(const GimRawImage& g, uint8_t flags) {
  std::vector<uint8_t> p;
  put_varint(&p, g.width);
  put_varint(&p, g.height);
  put_u8(&p, g.format);
  put_u8(&p, g.face_mode);
  put_u8(&p, flags);
  put_u8(&p, uint8_t(g.kinds.size()));
  for (size_t i = 0; i < g.kinds.size(); ++i) {
    put_u8(&p, g.kinds[i]);
    if (g.format == 0) {
      put_f64le(&p, g.offsets[i]);
      put_f64le(&p, g.steps[i]);
    }
  }
  return p;
}

}  // namespace

// 13.8: corner 0 relative to the previous triangle's, corners 1 and 2
// relative to corner 0.
std::vector<uint8_t> encode_gim_triangles(const std::vector<uint32_t>& triangles, uint32_t width) {
  std::vector<uint8_t> p;
  put_varint(&p, triangles.size() / 3);
  RangeEncoder rc;
  GimSignedContexts contexts[kGimFaceContextSets];
  int64_t px = 0, py = 0;
  for (size_t t = 0; t < triangles.size() / 3; ++t) {
    int64_t x[3], y[3];
    for (int k = 0; k < 3; ++k) x[k] = triangles[3 * t + size_t(k)] % width, y[k] = triangles[3 * t + size_t(k)] / width;
    const int64_t d[6] = {x[0] - px, y[0] - py, x[1] - x[0], y[1] - y[0], x[2] - x[0], y[2] - y[0]};
    for (int k = 0; k < 6; ++k) encode_gim_signed(&rc, &contexts[k], int32_t(d[k]));
    px = x[0];
    py = y[0];
  }
  const std::vector<uint8_t> stream = rc.finish();
  p.insert(p.end(), stream.begin(), stream.end());
  return p;
}

namespace {

// The file must decode to exactly the samples, mask, seams and triangles
// written; anything else is a bug of this encoder, never the user's input.
Status check_round_trip(const std::vector<uint8_t>& file, const GimRawImage& s, bool blank_stored) {
  const std::vector<std::vector<uint32_t>>& planes = s.planes;
  DecodedFile decoded;  // our own output: no embedder's limits apply (spec 8.1)
  if (Status st = decode(file.data(), file.size(), &decoded, DecoderLimits::unlimited()); !st.ok())
    return Status(ErrorCode::kInvalidArgument, "internal error: the geometry image does not decode: " + st.to_string());
  const GeometryImageData& g = decoded.gim;
  for (size_t i = 0; i < planes.size(); ++i)
    for (size_t p = 0; p < planes[i].size(); ++p) {
      const bool occupied = s.occupied.empty() || s.occupied[p] != 0;
      if ((occupied || blank_stored) && g.planes[i].samples[p] != planes[i][p])
        return invalid("internal error: plane " + std::to_string(i) + " pixel " + std::to_string(p) + " differs");
    }
  if (g.triangles != s.triangles) return invalid("internal error: GFAC does not round-trip");
  return Status::Ok();
}

}  // namespace

std::vector<uint8_t> encode_seam_runs(const std::vector<SeamPair>& pairs) {
  struct Run {
    uint32_t a, b, count;
    int64_t sa, sb;
  };
  std::vector<Run> runs;
  for (const SeamPair& pair : pairs) {
    if (!runs.empty()) {
      Run& r = runs.back();
      const int64_t da = int64_t(pair.a) - r.a, db = int64_t(pair.b) - r.b;
      if (r.count == 1 && da != 0) {
        r.sa = da, r.sb = db, r.count = 2;
        continue;
      }
      if (r.count > 1 && da == r.sa * r.count && db == r.sb * r.count) {
        ++r.count;
        continue;
      }
    }
    runs.push_back({pair.a, pair.b, 1, 0, 0});
  }
  std::vector<uint8_t> p;
  put_varint(&p, runs.size());
  for (const Run& r : runs) {
    put_varint(&p, r.a);
    put_varint(&p, r.b);
    put_varint(&p, r.count);
    put_varint(&p, zigzag(r.sa));
    put_varint(&p, zigzag(r.sb));
  }
  return p;
}

Status write_raw_geometry_image(const GimRawImage& g, const std::vector<std::string>& texts,
                                std::vector<uint8_t>* out, EncodeStats* st) {
  const size_t pixels = size_t(g.width) * g.height;
  if (g.width < 1 || g.height < 1 || g.width > 65535 || g.height > 65535 || pixels > (size_t(1) << 24))
    return invalid("geometry image of " + std::to_string(g.width) + " x " + std::to_string(g.height) +
                   " pixels: the format takes 1..65535 per side and 2^24 pixels");
  if (g.kinds.size() < 3 || g.kinds.size() > 16 || g.planes.size() != g.kinds.size() || g.format > 1 ||
      g.face_mode > 2 || (g.format == 0 && (g.offsets.size() != g.kinds.size() || g.steps.size() != g.kinds.size())))
    return invalid("geometry image: 3..16 planes with a kind (and for 16-bit samples an offset and step) each");
  for (size_t i = 0; i < g.kinds.size(); ++i) {
    if (i < 3 ? g.kinds[i] != i : (g.kinds[i] < 3 || g.kinds[i] > 8))
      return invalid("plane " + std::to_string(i) + " has kind " + std::to_string(g.kinds[i]) +
                     " (planes 0-2 are X, Y, Z; attributes take kinds 3..8)");
    if (g.planes[i].size() != pixels) return invalid("plane " + std::to_string(i) + " has the wrong sample count");
    if (g.format == 0 && !(std::isfinite(g.offsets[i]) && std::isfinite(g.steps[i]) && g.steps[i] > 0))
      return invalid("plane " + std::to_string(i) + ": offset and step must be finite, step > 0");
    if (g.format == 0)
      for (uint32_t v : g.planes[i])
        if (v > 65535) return invalid("plane " + std::to_string(i) + " has a sample above 65535");
  }
  if (!g.occupied.empty() && g.occupied.size() != pixels) return invalid("the mask has the wrong size");
  if (g.face_mode != 2 && !g.triangles.empty())
    return invalid("triangles are listed only in face mode 2");
  const bool has_mask = !g.occupied.empty() && std::count(g.occupied.begin(), g.occupied.end(), 0) > 0;
  const uint8_t flags = uint8_t((has_mask ? 1 : 0) | (has_mask && g.store_blank ? 2 : 0));

  EncodeStats local;
  EncodeStats& stats = st ? *st : local;
  out->clear();
  write_signature(out);
  add_chunk(out, &stats, kChunkHeader, {kFormatMajor, kGimMinorVersion});
  for (const std::string& text : texts) add_chunk(out, &stats, kChunkText, std::vector<uint8_t>(text.begin(), text.end()));
  add_chunk(out, &stats, kChunkGeometryImage, gimg_payload(g, flags));
  GimEncodeStats& gs = stats.gim;
  gs.width = g.width;
  gs.height = g.height;
  gs.seam_pairs = uint32_t(g.seams.size());
  gs.occupied = has_mask ? uint32_t(std::count_if(g.occupied.begin(), g.occupied.end(), [](uint8_t o) { return o != 0; }))
                         : uint32_t(pixels);
  if (has_mask) {
    add_chunk(out, &stats, kChunkGimMask, encode_mask(g.occupied, g.width, g.height));
    gs.mask_bytes = stats.chunks.back().bytes;
  }
  if (!g.seams.empty()) {
    add_chunk(out, &stats, kChunkGimSeams, encode_seam_runs(g.seams));
    gs.seam_bytes = stats.chunks.back().bytes;
  }
  if (g.face_mode == 2) {
    add_chunk(out, &stats, kChunkGimFaces, encode_gim_triangles(g.triangles, g.width));
    gs.face_bytes = stats.chunks.back().bytes;
  }
  PlaneLayout layout;
  layout.width = g.width;
  layout.height = g.height;
  layout.occupied = has_mask ? &g.occupied : nullptr;
  layout.blank_stored = (flags & 2) != 0;
  layout.format = g.format == 0 ? GimSampleFormat::kUnorm16 : GimSampleFormat::kFloat32;
  gs.plane_predictors.clear();
  gs.plane_bytes.clear();
  for (const std::vector<uint32_t>& plane : g.planes) {
    PlaneEncodeStats ps;
    add_chunk(out, &stats, kChunkGimPlane, encode_plane(plane, layout, &ps));
    gs.plane_predictors.push_back(ps.predictor);
    gs.plane_bytes.push_back(stats.chunks.back().bytes);
  }
  add_chunk(out, &stats, kChunkEnd, {});
  stats.total_bytes = out->size();
  return check_round_trip(*out, g, layout.blank_stored);
}

Status write_geometry_image(const GimSamples& s, const std::vector<GimExtraPlane>& extra,
                            const GeometryImageOptions& options, const std::vector<std::string>& texts,
                            std::vector<uint8_t>* out, EncodeStats* st) {
  const size_t pixels = size_t(s.width) * s.height;
  if (s.xyz.size() != 3 * pixels || (!s.occupied.empty() && s.occupied.size() != pixels))
    return invalid("internal error: sample arrays do not match the image size");
  if (3 + extra.size() > 16) return invalid("at most 13 attribute planes");
  for (double v : s.xyz)
    if (!std::isfinite(v)) return invalid("a geometry-image sample is not finite");
  GimRawImage g;
  g.width = s.width;
  g.height = s.height;
  g.format = options.float_samples ? 1 : 0;
  g.face_mode = !s.triangles.empty() ? 2 : options.quads ? 0 : 1;
  g.store_blank = options.store_blank_pixels;
  g.occupied = s.occupied;
  g.seams = s.seams;
  g.triangles = s.triangles;
  std::vector<std::vector<double>> values(3, std::vector<double>(pixels));
  for (size_t p = 0; p < pixels; ++p)
    for (int a = 0; a < 3; ++a) values[size_t(a)][p] = s.xyz[3 * p + size_t(a)];
  g.kinds = {0, 1, 2};
  for (const GimExtraPlane& e : extra) {
    if (e.values.size() != pixels || e.kind < 3 || e.kind > 8) return invalid("attribute plane of the wrong size or kind");
    values.push_back(e.values);
    g.kinds.push_back(e.kind);
  }
  std::vector<PlaneScale> scales(values.size());
  if (g.format == 0) {
    geometry_scales(s.xyz, scales.data());
    for (size_t i = 3; i < values.size(); ++i) {
      const auto [lo, hi] = std::minmax_element(values[i].begin(), values[i].end());
      scales[i] = {*lo, *hi > *lo ? (*hi - *lo) / 65535.0 : 1.0};
    }
    for (const PlaneScale& sc : scales) {
      g.offsets.push_back(sc.offset);
      g.steps.push_back(sc.step);
    }
  }
  g.planes.assign(values.size(), std::vector<uint32_t>(pixels));
  for (size_t i = 0; i < values.size(); ++i)
    for (size_t p = 0; p < pixels; ++p)
      g.planes[i][p] = g.format == 0 ? quantize16(values[i][p], scales[i]) : float_bits(values[i][p]);
  return write_raw_geometry_image(g, texts, out, st);
}

}  // namespace qmc
