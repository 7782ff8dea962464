#include "roundtrip_check.h"

#include <cmath>
#include <limits>

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

namespace {

std::string compare_faces(const Mesh& original, const Mesh& decoded, const std::vector<uint32_t>& label) {
  if (original.face_sizes.size() != decoded.face_sizes.size())
    return "face count " + std::to_string(decoded.face_sizes.size()) + " instead of " +
           std::to_string(original.face_sizes.size());
  if (original.corners.size() != decoded.corners.size()) return "corner count differs";
  size_t k = 0;
  for (size_t f = 0; f < original.face_sizes.size(); ++f) {
    if (original.face_sizes[f] != decoded.face_sizes[f]) return "face " + std::to_string(f) + " degree differs";
    for (uint32_t i = 0; i < original.face_sizes[f]; ++i, ++k)
      if (label[original.corners[k]] != decoded.corners[k])
        return "face " + std::to_string(f) + " corner " + std::to_string(i) + " differs";
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
  RoundTripReport report;
  const std::vector<uint32_t> order = spec_vertex_order(original);
  if (decoded.mesh.vertex_count() != original.vertex_count()) {
    report.face_mismatch = "vertex count " + std::to_string(decoded.mesh.vertex_count()) + " instead of " +
                           std::to_string(original.vertex_count());
    return report;
  }
  std::vector<uint32_t> label(order.size());
  for (uint32_t i = 0; i < order.size(); ++i) label[order[i]] = i;
  report.face_mismatch = compare_faces(original, decoded.mesh, label);
  report.faces_equal = report.face_mismatch.empty();

  const QuantizationInfo& q = decoded.quantization;
  double allowed[3];
  for (int a = 0; a < 3; ++a) {
    const double step = (double(q.max[a]) - double(q.min[a])) / double((uint64_t(1) << q.bits) - 1);
    allowed[a] = 0.5 * step * (1 + 1e-9) + float_ulp(std::fmax(std::fabs(q.min[a]), std::fabs(q.max[a])));
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
