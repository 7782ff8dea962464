#include "roundtrip_check.h"

#include <cmath>
#include <limits>

#include "encoder/polygon_connectivity_encoder.h"
#include "encoder/quad_traversal_encoder.h"

namespace qmc::tools {

std::vector<uint32_t> spec_vertex_order(const Mesh& mesh) {
  const size_t n = mesh.vertex_count();
  std::vector<bool> seen(n, false);
  std::vector<uint32_t> order;
  order.reserve(n);
  for (uint32_t v : mesh.corners)
    if (v < n && !seen[v]) {
      seen[v] = true;
      order.push_back(v);
    }
  for (uint32_t v = 0; v < n; ++v)
    if (!seen[v]) order.push_back(v);
  return order;
}

bool spec_correspondence(const Mesh& original, ConnectivityMethod method, Correspondence* c, std::string* why) {
  if (method == ConnectivityMethod::kQuad) {
    QuadTraversal traversal;
    *why = encode_quad_traversal(original, &traversal);
    if (!why->empty()) return false;
    c->file_vertex = std::move(traversal.file_vertex);
    c->face_source = std::move(traversal.face_source);
    return true;
  }
  if (method == ConnectivityMethod::kPolygon) {
    // The encoder's correspondence is a witness: check_round_trip still
    // checks every face and coordinate against it.
    PolygonEncoding encoding;
    *why = encode_polygon_connectivity(original, -1, true, &encoding);
    if (!why->empty()) return false;
    c->file_vertex = std::move(encoding.file_vertex);
    c->face_source = std::move(encoding.face_source);
    return true;
  }
  c->file_vertex = spec_vertex_order(original);
  c->face_source.resize(original.face_count());
  for (uint32_t f = 0; f < c->face_source.size(); ++f) c->face_source[f] = f;
  return true;
}

Correspondence identity_correspondence(const Mesh& original) {
  Correspondence c;
  c.file_vertex.resize(original.vertex_count());
  for (uint32_t v = 0; v < c.file_vertex.size(); ++v) c.file_vertex[v] = v;
  c.face_source.resize(original.face_count());
  for (uint32_t f = 0; f < c.face_source.size(); ++f) c.face_source[f] = f;
  c.exact_corners = true;
  return c;
}

namespace {

// Rotation (never reversal) of `source` relabelled that equals `decoded`.
bool same_cycle(const uint32_t* source, const uint32_t* decoded, uint32_t n, const std::vector<uint32_t>& label,
                bool exact) {
  for (uint32_t r = 0; r < (exact ? 1u : n); ++r) {
    uint32_t i = 0;
    while (i < n && label[source[(i + r) % n]] == decoded[i]) ++i;
    if (i == n) return true;
  }
  return false;
}

std::string compare_faces(const Mesh& original, const Mesh& decoded, const Correspondence& c,
                          const std::vector<uint32_t>& label) {
  if (original.face_count() != decoded.face_count() || c.face_source.size() != decoded.face_count())
    return "face count " + std::to_string(decoded.face_count()) + " instead of " +
           std::to_string(original.face_count());
  std::vector<size_t> offset(original.face_count() + 1, 0);
  for (size_t f = 0; f < original.face_count(); ++f) offset[f + 1] = offset[f] + original.face_sizes[f];
  std::vector<bool> used(original.face_count(), false);
  size_t k = 0;
  for (size_t f = 0; f < decoded.face_count(); ++f) {
    const uint32_t src = c.face_source[f];
    if (src >= original.face_count() || used[src]) return "face " + std::to_string(f) + " has no distinct source";
    used[src] = true;
    const uint32_t n = decoded.face_sizes[f];
    if (original.face_sizes[src] != n) return "face " + std::to_string(f) + " degree differs";
    if (!same_cycle(&original.corners[offset[src]], &decoded.corners[k], n, label, c.exact_corners))
      return "face " + std::to_string(f) + " (input face " + std::to_string(src) + ") differs";
    k += n;
  }
  return {};
}

// One unit in the last place of a binary32 of magnitude |x|.
double float_ulp(double x) {
  const float f = float(std::fabs(x));
  return double(std::nextafter(f, std::numeric_limits<float>::infinity())) - double(f);
}

}  // namespace

RoundTripReport check_round_trip(const Mesh& original, const DecodedFile& decoded) {
  if (decoded.order_restored) return check_round_trip(original, decoded, identity_correspondence(original));
  Correspondence c;
  std::string why;
  if (!spec_correspondence(original, decoded.method, &c, &why)) {
    RoundTripReport report;
    report.face_mismatch = "the file's coder cannot take the input: " + why;
    return report;
  }
  return check_round_trip(original, decoded, c);
}

RoundTripReport check_round_trip(const Mesh& original, const DecodedFile& decoded, const Correspondence& c) {
  RoundTripReport report;
  const std::vector<uint32_t>& order = c.file_vertex;
  if (decoded.mesh.vertex_count() != original.vertex_count() || order.size() != original.vertex_count()) {
    report.face_mismatch = "vertex count " + std::to_string(decoded.mesh.vertex_count()) + " instead of " +
                           std::to_string(original.vertex_count());
    return report;
  }
  std::vector<uint32_t> label(order.size(), UINT32_MAX);
  for (uint32_t i = 0; i < order.size(); ++i) {
    if (order[i] >= label.size() || label[order[i]] != UINT32_MAX) {
      report.face_mismatch = "the vertex correspondence is not a permutation";
      return report;
    }
    label[order[i]] = i;
  }
  report.face_mismatch = compare_faces(original, decoded.mesh, c, label);
  report.faces_equal = report.face_mismatch.empty();

  const QuantizationInfo& q = decoded.quantization;
  double allowed[3];
  for (int a = 0; a < 3; ++a) {
    allowed[a] = 0.5 * q.step[a] * (1 + 1e-9) + float_ulp(std::fmax(std::fabs(q.min[a]), std::fabs(q.max[a])));
    report.max_bbox_side = std::fmax(report.max_bbox_side, double(q.max[a]) - double(q.min[a]));
  }
  double sum_sq = 0;
  report.positions_within_bound = true;
  for (uint32_t i = 0; i < order.size(); ++i) {
    double sq = 0;
    for (int a = 0; a < 3; ++a) {
      const double d = double(decoded.mesh.positions[3 * size_t(i) + a]) - original.positions[3 * size_t(order[i]) + a];
      sq += d * d;
      if (std::fabs(d) > allowed[a] && report.positions_within_bound) {
        report.positions_within_bound = false;
        report.position_mismatch = "vertex " + std::to_string(order[i]) + " axis " + std::to_string(a) +
                                   " is off by " + std::to_string(std::fabs(d)) + ", bound " +
                                   std::to_string(allowed[a]);
      }
    }
    sum_sq += sq;
    report.max_error = std::fmax(report.max_error, std::sqrt(sq));
  }
  report.rms_error = order.empty() ? 0 : std::sqrt(sum_sq / double(order.size()));
  return report;
}

}  // namespace qmc::tools
