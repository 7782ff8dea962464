// The attribute part of `qmc compare`: corners of B matched to A's through
// vertex positions and face cycles, then their values compared (see the
// header for the definitions).
#include "attribute_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace qmc::tools {
namespace {

constexpr uint32_t kNoCorner = std::numeric_limits<uint32_t>::max();
constexpr double kPi = 3.14159265358979323846;

qmc::Status invalid(const std::string& what) { return qmc::Status(qmc::ErrorCode::kInvalidArgument, what); }

qmc::Status check_mesh(const char* which, const qmc::Mesh& m) {
  size_t sum = 0;
  for (uint32_t d : m.face_sizes) sum += d;
  if (sum != m.corners.size()) return invalid(std::string(which) + ": face sizes do not add up to the corners");
  for (uint32_t v : m.corners)
    if (v >= m.vertex_count()) return invalid(std::string(which) + ": a corner refers to a missing vertex");
  for (const qmc::MeshAttribute& at : m.attributes) {
    if (at.corner_values.size() != m.corners.size())
      return invalid(std::string(which) + ": attribute \"" + at.name + "\" has no value index per corner");
    for (uint32_t i : at.corner_values)
      if (i >= at.value_count())
        return invalid(std::string(which) + ": attribute \"" + at.name + "\" refers to a missing value");
  }
  return qmc::Status::Ok();
}

std::array<double, 3> position(const qmc::Mesh& m, uint32_t v) {
  return {m.positions[3 * size_t(v)], m.positions[3 * size_t(v) + 1], m.positions[3 * size_t(v) + 2]};
}

// A's vertices sorted into cubic cells of side `cell`, for the vertices
// within one cell's side of a point.
class VertexGrid {
 public:
  VertexGrid(const qmc::Mesh& a, double cell) {
    for (int k = 0; k < 3; ++k) lo_[k] = std::numeric_limits<double>::infinity();
    for (size_t v = 0; v < a.vertex_count(); ++v)
      for (int k = 0; k < 3; ++k) lo_[k] = std::min(lo_[k], double(a.positions[3 * v + k]));
    double extent = 0;
    for (size_t v = 0; v < a.vertex_count(); ++v)
      for (int k = 0; k < 3; ++k) extent = std::max(extent, double(a.positions[3 * v + k]) - lo_[k]);
    cell_ = std::max(cell, extent / double(kCells - 2));  // keeps every cell index below kCells
    entries_.reserve(a.vertex_count());
    for (uint32_t v = 0; v < a.vertex_count(); ++v) entries_.push_back({key(cell_of(position(a, v))), v});
    std::sort(entries_.begin(), entries_.end());
  }

  // Calls visit(v) for every vertex of A in the 27 cells around p.
  template <class Visit>
  void around(const std::array<double, 3>& p, Visit visit) const {
    const std::array<int64_t, 3> c = cell_of(p);
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          const std::array<int64_t, 3> n = {c[0] + dx, c[1] + dy, c[2] + dz};
          if (std::any_of(n.begin(), n.end(), [](int64_t x) { return x < 0 || x >= kCells; })) continue;
          const uint64_t k = key(n);
          auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair<uint64_t, uint32_t>{k, 0});
          for (; it != entries_.end() && it->first == k; ++it) visit(it->second);
        }
  }

 private:
  static constexpr int64_t kCells = int64_t(1) << 20;  // per axis
  std::array<int64_t, 3> cell_of(const std::array<double, 3>& p) const {
    std::array<int64_t, 3> c;
    for (int k = 0; k < 3; ++k) {
      const double x = std::floor((p[k] - lo_[k]) / cell_);
      c[k] = std::isfinite(x) ? int64_t(std::clamp(x, -1.0, double(kCells))) : -1;
    }
    return c;
  }
  static uint64_t key(const std::array<int64_t, 3>& c) {
    return (uint64_t(c[0]) << 40) | (uint64_t(c[1]) << 20) | uint64_t(c[2]);
  }

  double lo_[3];
  double cell_ = 1;
  std::vector<std::pair<uint64_t, uint32_t>> entries_;
};

// Per vertex of B, its candidates among A's vertices, nearest first, as
// ranges of one array. Not the nearest alone: quantization can move two
// nearby vertices of A onto one point, and the faces decide which is which.
struct VertexCandidates {
  std::vector<uint32_t> begin;  // per vertex of B, one more at the end
  std::vector<uint32_t> list;

  bool has(uint32_t vb, uint32_t va) const {
    return std::find(list.begin() + begin[vb], list.begin() + begin[vb + 1], va) != list.begin() + begin[vb + 1];
  }
  bool empty(uint32_t vb) const { return begin[vb] == begin[vb + 1]; }
};

double distance_squared(const std::array<double, 3>& p, const std::array<double, 3>& q) {
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
}

// The candidates of every vertex of B: A's vertices within r of it, where r
// is the largest distance from a vertex of B to its nearest vertex of A
// (at most `tolerance`). A quantized vertex lies within the quantization's
// error bound e of its own vertex, so its nearest is within e too, and r
// comes close to e from below; a smaller radius than the tolerance keeps
// the neighbours of dense regions out.
VertexCandidates vertices_within(const qmc::Mesh& a, const qmc::Mesh& b, double tolerance, double* radius) {
  const VertexGrid grid(a, tolerance);
  std::vector<std::vector<std::pair<double, uint32_t>>> near(b.vertex_count());
  double r2 = 0;
  for (uint32_t vb = 0; vb < b.vertex_count(); ++vb) {
    const std::array<double, 3> p = position(b, vb);
    grid.around(p, [&](uint32_t va) {
      const double d = distance_squared(p, position(a, va));
      if (d <= tolerance * tolerance) near[vb].push_back({d, va});
    });
    std::sort(near[vb].begin(), near[vb].end());
    if (!near[vb].empty()) r2 = std::max(r2, near[vb].front().first);
  }
  *radius = std::sqrt(r2);
  VertexCandidates out;
  out.begin.push_back(0);
  for (uint32_t vb = 0; vb < b.vertex_count(); ++vb) {
    for (const auto& [d, va] : near[vb])
      if (d <= r2) out.list.push_back(va);
    out.begin.push_back(uint32_t(out.list.size()));
  }
  return out;
}

// Per vertex of A, the faces that have it, as ranges of one array.
struct VertexFaces {
  std::vector<uint32_t> begin, faces;
  explicit VertexFaces(const qmc::Mesh& a) : begin(a.vertex_count() + 1, 0) {
    for (uint32_t v : a.corners) ++begin[v + 1];
    for (size_t v = 0; v < a.vertex_count(); ++v) begin[v + 1] += begin[v];
    faces.resize(a.corners.size());
    std::vector<uint32_t> next(begin.begin(), begin.end() - 1);
    for (uint32_t f = 0, c = 0; f < a.face_count(); c += a.face_sizes[f], ++f)
      for (uint32_t k = c; k < c + a.face_sizes[f]; ++k) faces[next[a.corners[k]]++] = f;
  }
};

// One face of B (corners b[0..m-1]) tried against a face of A (corners
// first .. first + k - 1): A's corner of each of B's corners, and the sum of
// their squared distances, the smallest of the ways A's face has them all in
// B's cyclic order (header); none leaves `cost` infinite.
struct FaceMatch {
  double cost = std::numeric_limits<double>::infinity();
  uint32_t corner[3] = {kNoCorner, kNoCorner, kNoCorner};  // m = 3 only
  uint32_t rotation = 0;                                   // m = k
};

class FaceMatcher {
 public:
  FaceMatcher(const qmc::Mesh& a, const qmc::Mesh& b, const VertexCandidates& near) : a_(a), b_(b), near_(near) {}

  FaceMatch same_degree(uint32_t first, uint32_t k, const uint32_t* bf) const {
    FaceMatch best;
    for (uint32_t r = 0; r < k; ++r) {
      double cost = 0;
      for (uint32_t i = 0; i < k && cost < best.cost; ++i) cost += pair_cost(bf[i], first + (r + i) % k);
      if (cost < best.cost) {
        best.cost = cost;
        best.rotation = r;
      }
    }
    return best;
  }

  // B's triangle in a larger face of A, each corner at its nearest match.
  FaceMatch triangle_in(uint32_t first, uint32_t k, const uint32_t* bf) const {
    FaceMatch m;
    double cost = 0;
    uint32_t at[3];
    for (int i = 0; i < 3; ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (uint32_t j = 0; j < k; ++j)
        if (const double c = pair_cost(bf[i], first + j); c < nearest) {
          nearest = c;
          at[i] = j;
        }
      if (!std::isfinite(nearest)) return m;
      cost += nearest;
    }
    const uint32_t d1 = (at[1] + k - at[0]) % k, d2 = (at[2] + k - at[0]) % k;
    if (d1 == 0 || d2 <= d1) return m;
    m.cost = cost;
    for (int i = 0; i < 3; ++i) m.corner[i] = first + at[i];
    return m;
  }

 private:
  // The squared distance of B's vertex and A's corner's vertex if that is a
  // candidate, else infinity.
  double pair_cost(uint32_t vb, uint32_t corner_a) const {
    const uint32_t va = a_.corners[corner_a];
    if (!near_.has(vb, va)) return std::numeric_limits<double>::infinity();
    return distance_squared(position(b_, vb), position(a_, va));
  }

  const qmc::Mesh& a_;
  const qmc::Mesh& b_;
  const VertexCandidates& near_;
};

// Per corner of B, its corner of A, or kNoCorner where its face found none,
// or more than one (the positions cannot tell which face it was: two faces
// of A fit within the tolerance): of A's faces at the candidates of B's
// first corner, the one that fits.
std::vector<uint32_t> match_corners(const qmc::Mesh& a, const qmc::Mesh& b, const VertexCandidates& near,
                                    AttributeComparison* out) {
  std::vector<uint32_t> a_face_start(a.face_count() + 1, 0);
  for (size_t f = 0; f < a.face_count(); ++f) a_face_start[f + 1] = a_face_start[f] + a.face_sizes[f];
  const VertexFaces around(a);
  const FaceMatcher matcher(a, b, near);
  std::vector<uint32_t> corner_in_a(b.corners.size(), kNoCorner);
  out->faces_b = b.face_count();
  for (uint32_t f = 0, c = 0; f < b.face_count(); c += b.face_sizes[f], ++f) {
    const uint32_t* bf = &b.corners[c];
    const uint32_t m = b.face_sizes[f];
    FaceMatch best;
    uint32_t best_face = 0, fits = 0;
    for (uint32_t i = near.begin[bf[0]]; i < near.begin[bf[0] + 1]; ++i)
      for (uint32_t j = around.begin[near.list[i]]; j < around.begin[near.list[i] + 1]; ++j) {
        const uint32_t g = around.faces[j], k = a.face_sizes[g];
        const FaceMatch try_g = m == k ? matcher.same_degree(a_face_start[g], k, bf)
                                : m == 3 ? matcher.triangle_in(a_face_start[g], k, bf)
                                         : FaceMatch{};
        if (!std::isfinite(try_g.cost) || (fits > 0 && g == best_face)) continue;
        ++fits;
        if (try_g.cost < best.cost) {
          best = try_g;
          best_face = g;
        }
      }
    if (fits > 1) ++out->faces_ambiguous;
    if (fits != 1) continue;
    ++out->faces_matched;
    const uint32_t k = a.face_sizes[best_face];
    for (uint32_t i = 0; i < m; ++i)
      corner_in_a[c + i] = m == k ? a_face_start[best_face] + (best.rotation + i) % k : best.corner[i];
  }
  return corner_in_a;
}

const float* value_at(const qmc::MeshAttribute& at, uint32_t corner) {
  return &at.values[size_t(at.corner_values[corner]) * at.components];
}

void add_value_distances(const qmc::MeshAttribute& in_a, const qmc::MeshAttribute& in_b,
                         const std::vector<uint32_t>& corner_in_a, AttributeDistance* d) {
  double sum_squares = 0, angle_sum = 0, angle_squares = 0;
  const bool normals = d->kind == AttributeKind::kNormal && d->components == 3;
  for (uint32_t cb = 0; cb < corner_in_a.size(); ++cb) {
    if (corner_in_a[cb] == kNoCorner) continue;
    const float* x = value_at(in_a, corner_in_a[cb]);
    const float* y = value_at(in_b, cb);
    double squares = 0;
    for (uint32_t k = 0; k < d->components; ++k) squares += (double(x[k]) - y[k]) * (double(x[k]) - y[k]);
    ++d->corners;
    sum_squares += squares;
    d->distance_max = std::max(d->distance_max, std::sqrt(squares));
    if (!normals) continue;
    const double cx = double(x[1]) * y[2] - double(x[2]) * y[1], cy = double(x[2]) * y[0] - double(x[0]) * y[2],
                 cz = double(x[0]) * y[1] - double(x[1]) * y[0];
    const double dot = double(x[0]) * y[0] + double(x[1]) * y[1] + double(x[2]) * y[2];
    const double zero = 0;
    if ((x[0] == zero && x[1] == zero && x[2] == zero) || (y[0] == zero && y[1] == zero && y[2] == zero)) {
      ++d->zero_normals;
      continue;
    }
    const double angle = std::atan2(std::hypot(cx, cy, cz), dot) * (180.0 / kPi);
    ++d->angle_corners;
    angle_sum += angle;
    angle_squares += angle * angle;
    d->angle_max_degrees = std::max(d->angle_max_degrees, angle);
  }
  if (d->corners > 0) d->distance_rms = std::sqrt(sum_squares / double(d->corners));
  if (d->angle_corners > 0) {
    d->angle_mean_degrees = angle_sum / double(d->angle_corners);
    d->angle_rms_degrees = std::sqrt(angle_squares / double(d->angle_corners));
  }
}

// The stretch of one triangle's texture, A's corners (p0, p1, p2) to B's
// (q0, q1, q2) (header): its L2 stretch squared and its largest stretch,
// with A's texture area as the weight.
struct TriangleStretch {
  double weight, l2_squared, largest;
};
bool add_triangle_stretch(const float* p[3], const float* q[3], AttributeDistance* d, TriangleStretch* out) {
  const double p1x = double(p[1][0]) - p[0][0], p1y = double(p[1][1]) - p[0][1];
  const double p2x = double(p[2][0]) - p[0][0], p2y = double(p[2][1]) - p[0][1];
  const double area2 = p1x * p2y - p2x * p1y;  // twice A's signed texture area
  if (area2 == 0) {
    ++d->no_area_in_a;
    return false;
  }
  const double q1x = double(q[1][0]) - q[0][0], q1y = double(q[1][1]) - q[0][1];
  const double q2x = double(q[2][0]) - q[0][0], q2y = double(q[2][1]) - q[0][1];
  const double b_area2 = q1x * q2y - q2x * q1y;
  // J = [q1 q2] [p1 p2]^-1.
  const double j00 = (q1x * p2y - q2x * p1y) / area2, j01 = (q2x * p1x - q1x * p2x) / area2;
  const double j10 = (q1y * p2y - q2y * p1y) / area2, j11 = (q2y * p1x - q1y * p2x) / area2;
  // Singular values of a 2x2 matrix: s = hypot(e, h) +- hypot(f, g).
  const double e = (j00 + j11) / 2, f = (j00 - j11) / 2, g = (j10 + j01) / 2, h = (j10 - j01) / 2;
  const double qq = std::hypot(e, h), rr = std::hypot(f, g);
  const double s1 = qq + rr, s2 = std::fabs(qq - rr);
  ++d->stretch_triangles;
  if ((b_area2 < 0) != (area2 < 0) && b_area2 != 0) ++d->flipped;
  out->weight = std::fabs(area2) / 2;
  out->l2_squared = (s1 * s1 + s2 * s2) / 2;
  if (b_area2 == 0) {
    ++d->collapsed;
    out->largest = std::numeric_limits<double>::infinity();
  } else {
    out->largest = std::max(s1, 1 / s2);
    d->stretch_max = std::max(d->stretch_max, out->largest);
  }
  return true;
}

void add_texture_stretch(const qmc::Mesh& b, const qmc::MeshAttribute& in_a, const qmc::MeshAttribute& in_b,
                         const std::vector<uint32_t>& corner_in_a, AttributeDistance* d) {
  std::vector<TriangleStretch> all;
  for (uint32_t f = 0, c = 0; f < b.face_count(); c += b.face_sizes[f], ++f) {
    if (corner_in_a[c] == kNoCorner) continue;
    for (uint32_t i = 1; i + 1 < b.face_sizes[f]; ++i) {
      const uint32_t fan[3] = {c, c + i, c + i + 1};
      const float* p[3];
      const float* q[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = value_at(in_a, corner_in_a[fan[k]]);
        q[k] = value_at(in_b, fan[k]);
      }
      TriangleStretch t;
      if (add_triangle_stretch(p, q, d, &t)) all.push_back(t);
    }
  }
  double weight = 0, squares = 0;
  for (const TriangleStretch& t : all) {
    weight += t.weight;
    squares += t.weight * t.l2_squared;
  }
  if (weight == 0) return;
  d->stretch_l2 = std::sqrt(squares / weight);
  // The weighted 99th percentile of the largest stretch.
  std::sort(all.begin(), all.end(),
            [](const TriangleStretch& x, const TriangleStretch& y) { return x.largest < y.largest; });
  double below = 0;
  for (const TriangleStretch& t : all) {
    below += t.weight;
    d->stretch_p99 = t.largest;
    if (below >= 0.99 * weight) break;
  }
}

// B's attribute for A's attribute j: the same name, else the first of the
// same kind and components that no attribute of A has by name.
int partner(const qmc::Mesh& a, const qmc::Mesh& b, size_t j, const std::vector<bool>& taken) {
  const qmc::MeshAttribute& x = a.attributes[j];
  for (size_t i = 0; i < b.attributes.size(); ++i)
    if (b.attributes[i].name == x.name) return int(i);
  for (size_t i = 0; i < b.attributes.size(); ++i) {
    const qmc::MeshAttribute& y = b.attributes[i];
    const bool named_in_a = std::any_of(a.attributes.begin(), a.attributes.end(),
                                        [&](const qmc::MeshAttribute& z) { return z.name == y.name; });
    if (!taken[i] && !named_in_a && y.kind == x.kind && y.components == x.components) return int(i);
  }
  return -1;
}

}  // namespace

qmc::Status compare_attributes(const qmc::Mesh& a, const qmc::Mesh& b, double vertex_tolerance,
                               AttributeComparison* out) {
  *out = AttributeComparison{};
  out->vertex_tolerance = vertex_tolerance;
  if (!(vertex_tolerance > 0) || !std::isfinite(vertex_tolerance))
    return invalid("the vertex tolerance must be a positive number");
  if (qmc::Status s = check_mesh("A", a); !s.ok()) return s;
  if (qmc::Status s = check_mesh("B", b); !s.ok()) return s;
  std::vector<bool> taken(b.attributes.size(), false);
  std::vector<std::pair<size_t, size_t>> pairs;
  for (size_t j = 0; j < a.attributes.size(); ++j) {
    const int i = partner(a, b, j, taken);
    if (i < 0 || taken[size_t(i)] || b.attributes[size_t(i)].components != a.attributes[j].components) {
      out->only_in_a.push_back(a.attributes[j].name);
      continue;
    }
    taken[size_t(i)] = true;
    pairs.push_back({j, size_t(i)});
  }
  for (size_t i = 0; i < b.attributes.size(); ++i)
    if (!taken[i]) out->only_in_b.push_back(b.attributes[i].name);
  const VertexCandidates near = vertices_within(a, b, vertex_tolerance, &out->match_radius);
  for (uint32_t v = 0; v < b.vertex_count(); ++v) out->vertices_unmatched += near.empty(v) ? 1 : 0;
  const std::vector<uint32_t> corner_in_a = match_corners(a, b, near, out);
  for (const auto& [j, i] : pairs) {
    const qmc::MeshAttribute& x = a.attributes[j];
    const qmc::MeshAttribute& y = b.attributes[i];
    AttributeDistance d;
    d.name = x.name;
    d.kind = x.kind;
    d.components = x.components;
    d.name_in_b = y.name;
    add_value_distances(x, y, corner_in_a, &d);
    if (x.kind == AttributeKind::kTextureCoordinate && x.components == 2) add_texture_stretch(b, x, y, corner_in_a, &d);
    out->attributes.push_back(d);
  }
  return qmc::Status::Ok();
}

}  // namespace qmc::tools
