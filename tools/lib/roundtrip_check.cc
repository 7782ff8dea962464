#include "roundtrip_check.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "encoder/polygon_connectivity_encoder.h"
#include "encoder/polygon_surface.h"
#include "qmc/encoder.h"
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

namespace {

// The polygon coder's correspondence as its encoder makes it, a witness:
// check_round_trip still checks every face and coordinate against it.
bool polygon_witness(const Mesh& original, bool unused_along_curve, Correspondence* c, std::string* why,
                     TraversalStart start = {}) {
  PolygonEncoding encoding;
  *why = encode_polygon_connectivity(original, -1, true, true, unused_along_curve, &encoding, start);
  if (!why->empty()) return false;
  c->file_vertex = std::move(encoding.file_vertex);
  c->face_source = std::move(encoding.face_source);
  return true;
}

}  // namespace

bool spec_correspondence(const Mesh& original, ConnectivityMethod method, Correspondence* c, std::string* why) {
  if (method == ConnectivityMethod::kQuad) {
    QuadTraversal traversal;
    *why = encode_quad_traversal(original, &traversal);
    if (!why->empty()) return false;
    c->file_vertex = std::move(traversal.file_vertex);
    c->face_source = std::move(traversal.face_source);
    return true;
  }
  if (method == ConnectivityMethod::kPolygon) return polygon_witness(original, true, c, why);
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

// One unit in the last place of a binary32 of magnitude |x|.
double float_ulp(double x) {
  const float f = float(std::fabs(x));
  return double(std::nextafter(f, std::numeric_limits<float>::infinity())) - double(f);
}

// Section 15: each attribute's allowed difference per component: half its
// grid's step plus binary32 rounding, or 0 (bit for bit) for exact values.
std::vector<std::array<double, 3>> attribute_tolerances(const DecodedFile& decoded) {
  std::vector<std::array<double, 3>> out;
  for (const AttributeCoding& c : decoded.attribute_codings) {
    std::array<double, 3> t{};
    // Codings 3 and 8 (15.7, 15.13): the grid point is one of the four around the input's
    // octahedral projection, |du|, |dv| <= 2 / M; the map back to the unit
    // sphere stretches that by less than 3 per component.
    if (c.octahedral()) t.fill(12.0 / double(c.top[0]));
    for (int a = 0; a < 3 && c.on_grid(); ++a) {
      const double last = double(c.origin[a]) + double(c.top[a]) * c.step[a];
      t[a] = 0.5 * c.step[a] * (1 + 1e-9) + float_ulp(std::fmax(std::fabs(c.origin[a]), std::fabs(last)));
    }
    out.push_back(t);
  }
  return out;
}

bool same_value(float input, float decoded, double tolerance) {
  if (tolerance == 0) return std::memcmp(&input, &decoded, sizeof(float)) == 0;
  return std::fabs(double(input) - double(decoded)) <= tolerance;
}

// Whether decoded corner k + i carries source corner s + (i + r) mod n's
// value of every attribute.
bool same_attributes(const Mesh& original, const DecodedFile& decoded, size_t s, size_t k, uint32_t n, uint32_t r,
                     const std::vector<std::array<double, 3>>& tolerance) {
  for (size_t j = 0; j < original.attributes.size(); ++j) {
    const MeshAttribute& in = original.attributes[j];
    const MeshAttribute& out = decoded.mesh.attributes[j];
    for (uint32_t i = 0; i < n; ++i) {
      const size_t x = in.corner_values[s + (i + r) % n], y = out.corner_values[k + i];
      for (uint32_t a = 0; a < in.components; ++a)
        if (!same_value(in.values[in.components * x + a], out.values[out.components * y + a], tolerance[j][a]))
          return false;
    }
  }
  return true;
}

// Rotation (never reversal) of `source` relabelled that equals `decoded`,
// with the same attributes at every corner.
bool same_cycle(const Mesh& original, const DecodedFile& decoded, size_t s, size_t k, uint32_t n,
                const std::vector<uint32_t>& label, bool exact, const std::vector<std::array<double, 3>>& tolerance) {
  const uint32_t* source = &original.corners[s];
  const uint32_t* corners = &decoded.mesh.corners[k];
  for (uint32_t r = 0; r < (exact ? 1u : n); ++r) {
    uint32_t i = 0;
    while (i < n && label[source[(i + r) % n]] == corners[i]) ++i;
    if (i == n && same_attributes(original, decoded, s, k, n, r, tolerance)) return true;
  }
  return false;
}

// Names, kinds and components of the attributes, in order.
std::string compare_attribute_tables(const Mesh& original, const DecodedFile& decoded) {
  const auto& in = original.attributes;
  const auto& out = decoded.mesh.attributes;
  if (in.size() != out.size() || decoded.attribute_codings.size() != out.size())
    return std::to_string(out.size()) + " attributes instead of " + std::to_string(in.size());
  for (size_t j = 0; j < in.size(); ++j)
    if (in[j].name != out[j].name || in[j].kind != out[j].kind || in[j].components != out[j].components ||
        out[j].corner_values.size() != decoded.mesh.corners.size())
      return "attribute " + std::to_string(j) + " (\"" + in[j].name + "\") differs in name, kind or components";
  return {};
}

// Section 16: the same labels, in order, with the same references.
std::string compare_label_tables(const Mesh& original, const Mesh& decoded) {
  const auto& in = original.face_labels;
  const auto& out = decoded.face_labels;
  if (in.size() != out.size()) return std::to_string(out.size()) + " face labels instead of " + std::to_string(in.size());
  for (size_t j = 0; j < in.size(); ++j)
    if (in[j].name != out[j].name || in[j].references != out[j].references ||
        out[j].face_values.size() != decoded.face_count())
      return "face labels " + std::to_string(j) + " (\"" + in[j].name + "\") differ in name or references";
  return {};
}

// Whether decoded face f has the labels of input face src (compared as strings).
bool same_labels(const Mesh& original, const Mesh& decoded, size_t f, size_t src) {
  for (size_t j = 0; j < original.face_labels.size(); ++j) {
    const FaceLabels& in = original.face_labels[j];
    const FaceLabels& out = decoded.face_labels[j];
    const uint32_t a = in.face_values[src], b = out.face_values[f];
    if ((a == in.none()) != (b == out.none())) return false;
    if (a != in.none() && in.values[a] != out.values[b]) return false;
  }
  return true;
}

// A vertex no face uses keeps its value of an attribute with a value a
// vertex, numbered as the vertices (what OBJ and PLY readers give): that
// value is checked here, as no corner carries it.
std::string compare_values_of_faceless_vertices(const Mesh& original, const Mesh& decoded,
                                                const std::vector<uint32_t>& label,
                                                const std::vector<std::array<double, 3>>& tolerance) {
  const size_t n = original.vertex_count();
  std::vector<uint8_t> in_a_face(n, 0);
  for (uint32_t v : original.corners) in_a_face[v] = 1;
  for (size_t j = 0; j < original.attributes.size(); ++j) {
    const MeshAttribute& in = original.attributes[j];
    const MeshAttribute& out = decoded.attributes[j];
    bool by_vertex = in.value_count() == n;
    for (size_t k = 0; by_vertex && k < original.corners.size(); ++k) by_vertex = in.corner_values[k] == original.corners[k];
    if (!by_vertex) continue;
    for (size_t v = 0; v < n; ++v) {
      if (in_a_face[v]) continue;
      const size_t y = label[v];
      if (out.value_count() != n) return "attribute \"" + in.name + "\": vertex " + std::to_string(v) + ", in no face, lost its value";
      for (uint32_t a = 0; a < in.components; ++a)
        if (!same_value(in.values[in.components * v + a], out.values[out.components * y + a], tolerance[j][a]))
          return "attribute \"" + in.name + "\": vertex " + std::to_string(v) + ", in no face, has another value";
    }
  }
  return {};
}

std::string compare_faces(const Mesh& original, const DecodedFile& file, const Correspondence& c,
                          const std::vector<uint32_t>& label) {
  const Mesh& decoded = file.mesh;
  if (std::string why = compare_attribute_tables(original, file); !why.empty()) return why;
  if (std::string why = compare_label_tables(original, decoded); !why.empty()) return why;
  const std::vector<std::array<double, 3>> tolerance = attribute_tolerances(file);
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
    if (!same_cycle(original, file, offset[src], k, n, label, c.exact_corners, tolerance))
      return "face " + std::to_string(f) + " (input face " + std::to_string(src) + ") differs" +
             (original.attributes.empty() ? "" : " (its corners or their attributes)");
    if (!same_labels(original, decoded, f, src))
      return "face " + std::to_string(f) + " (input face " + std::to_string(src) + ") has other labels";
    k += n;
  }
  return compare_values_of_faceless_vertices(original, decoded, label, tolerance);
}


// Per axis, how far a decoded coordinate may be from its input: half a step
// (6.4, 14.1), or on 14.15's lattice the k steps its encoder keeps to, plus
// binary32 rounding.
std::array<double, 3> position_allowance(const QuantizationInfo& q) {
  std::array<double, 3> allowed{};
  for (int a = 0; a < 3; ++a) {
    const double within = q.lattice > 1 ? double(q.lattice) : 0.5;
    allowed[a] = within * q.step[a] * (1 + 1e-9) + float_ulp(std::fmax(std::fabs(q.min[a]), std::fabs(q.max[a])));
  }
  return allowed;
}

bool near_input(const Mesh& original, uint32_t v, const DecodedFile& decoded, uint32_t i,
                const std::array<double, 3>& allowed) {
  if (v >= original.vertex_count() || i >= decoded.mesh.vertex_count()) return false;
  for (int a = 0; a < 3; ++a)
    if (std::fabs(double(decoded.mesh.positions[3 * size_t(i) + a]) - original.positions[3 * size_t(v) + a]) >
        allowed[a])
      return false;
  return true;
}

// EncodeOptions::start_faces: the polygon coder's file from another first
// face. The decoder's vertices 0 and 1 are c1 and c0 of the first face
// (first_labels), so only the starts whose c1 and c0 lie there are tried.
bool other_start_matches(const Mesh& original, const DecodedFile& decoded, RoundTripReport* report) {
  PolygonSurfaceModel surface;
  if (!build_polygon_surface(original, &surface).empty()) return false;
  const std::array<double, 3> allowed = position_allowance(decoded.quantization);
  const std::vector<std::array<uint32_t, 2>> labels = first_labels(surface, kMaxStartFaces);
  for (uint32_t t = 1; t < labels.size(); ++t) {
    const std::array<uint32_t, 2>& c = labels[t];
    if (!near_input(original, surface.original[c[0]], decoded, 0, allowed) ||
        !near_input(original, surface.original[c[1]], decoded, 1, allowed))
      continue;
    Correspondence witness;
    std::string why;
    if (!polygon_witness(original, true, &witness, &why, {t})) continue;
    if (RoundTripReport r = check_round_trip(original, decoded, witness); r.ok()) {
      *report = r;
      return true;
    }
  }
  return false;
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
  RoundTripReport report = check_round_trip(original, decoded, c);
  // The encoder lists the vertices no face uses along a curve, or in input
  // order when asked (5.4.9): either witness will do.
  if (!report.ok() && decoded.method == ConnectivityMethod::kPolygon && polygon_witness(original, false, &c, &why))
    if (RoundTripReport r = check_round_trip(original, decoded, c); r.ok()) return r;
  if (!report.ok() && decoded.method == ConnectivityMethod::kPolygon) other_start_matches(original, decoded, &report);
  return report;
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
  report.face_mismatch = compare_faces(original, decoded, c, label);
  report.faces_equal = report.face_mismatch.empty();

  const QuantizationInfo& q = decoded.quantization;
  const std::array<double, 3> allowed = position_allowance(q);
  for (int a = 0; a < 3; ++a)
    report.max_bbox_side = std::fmax(report.max_bbox_side, double(q.max[a]) - double(q.min[a]));
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
