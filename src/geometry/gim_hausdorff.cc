// Seed 000 §3.2-3.3: Hausdorff-error-driven adjustment of geometry image
// samples (see gim_hausdorff.h for the choices made where the seed is silent).
#include "geometry/gim_hausdorff.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace qmc {

// ---- Distance types and gradients ---------------------------------------------

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3d corner_of(const Triangle3d& t, int k) { return k == 0 ? t.a : k == 1 ? t.b : t.c; }

// Squared distance from p to segment [q1, q2] and the clamped parameter.
double segment_distance_squared(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, double* t_out) {
  const Vec3d e = q2 - q1;
  const double len2 = dot(e, e);
  double t = len2 > 0 ? dot(p - q1, e) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  *t_out = t;
  const Vec3d r = p - (q1 + e * t);
  return dot(r, r);
}

// The nearest point of segment (corner i, corner j) as a feature.
GimFeature segment_feature(int i, int j, double t) {
  GimFeature f;
  if (t <= 0) {
    f.type = GimDistanceType::kPointPoint, f.corner[0] = uint8_t(i);
  } else if (t >= 1) {
    f.type = GimDistanceType::kPointPoint, f.corner[0] = uint8_t(j);
  } else {
    f.type = GimDistanceType::kPointEdge, f.corner[0] = uint8_t(i), f.corner[1] = uint8_t(j);
  }
  return f;
}

// The nearest feature among the edges opposite the corners listed in `edges`.
GimFeature nearest_segment(const Vec3d& p, const Triangle3d& t, const int* opposite, int count) {
  double best = kInf;
  GimFeature out;
  for (int e = 0; e < count; ++e) {
    const int i = (opposite[e] + 1) % 3, j = (opposite[e] + 2) % 3;
    double s;
    const double d2 = segment_distance_squared(p, corner_of(t, i), corner_of(t, j), &s);
    if (d2 < best) best = d2, out = segment_feature(i, j, s);
  }
  return out;
}

}  // namespace

GimFeature classify_distance(const Vec3d& p, const Triangle3d& t) {
  static const int kAllEdges[3] = {0, 1, 2};
  const Vec3d n = cross(t.b - t.a, t.c - t.a);
  const double nn = dot(n, n);
  const double longest = std::max({dot(t.b - t.a, t.b - t.a), dot(t.c - t.b, t.c - t.b), dot(t.a - t.c, t.a - t.c)});
  if (!(nn > 1e-24 * longest * longest)) return nearest_segment(p, t, kAllEdges, 3);
  // Eq. (4): lambda_k = l(corner k) * l(projection of p), l the line of the
  // edge opposite corner k, evaluated in the triangle's plane.
  const Vec3d pbar = p - n * (dot(p - t.a, n) / nn);
  int outside[3], count = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3d qi = corner_of(t, (k + 1) % 3), qj = corner_of(t, (k + 2) % 3);
    const double at_corner = dot(cross(qj - qi, corner_of(t, k) - qi), n);
    const double at_p = dot(cross(qj - qi, pbar - qi), n);
    if (at_corner * at_p <= 0) outside[count++] = k;
  }
  if (count == 0) return GimFeature{};  // point-face
  // Eq. (5)'s edge region (count 1) or corner region (count 2), refined to
  // the nearest feature on the edges bounding that region.
  return nearest_segment(p, t, outside, count == 3 ? 3 : count);
}

double squared_distance_pp(const Vec3d& p, const Vec3d& q) {
  return (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) + (q.z - p.z) * (q.z - p.z);
}

double squared_distance_pe(const Vec3d& p, const Vec3d& q1, const Vec3d& q2) {
  const double x12 = q1.x - q2.x, y12 = q1.y - q2.y, z12 = q1.z - q2.z;
  const double dx = p.x - q1.x, dy = p.y - q1.y, dz = p.z - q1.z;
  const double c1 = dy * z12 - dz * y12, c2 = dz * x12 - dx * z12, c3 = dx * y12 - dy * x12;
  const double len2 = x12 * x12 + y12 * y12 + z12 * z12;
  return len2 > 0 ? (c1 * c1 + c2 * c2 + c3 * c3) / len2 : dx * dx + dy * dy + dz * dz;
}

double squared_distance_pf(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, const Vec3d& q3) {
  const double x23 = q2.x - q3.x, x31 = q3.x - q1.x, x12 = q1.x - q2.x;
  const double y23 = q2.y - q3.y, y31 = q3.y - q1.y, y12 = q1.y - q2.y;
  const double z23 = q2.z - q3.z, z31 = q3.z - q1.z, z12 = q1.z - q2.z;
  const double a = q1.y * z23 + q2.y * z31 + q3.y * z12;
  const double b = q1.z * x23 + q2.z * x31 + q3.z * x12;
  const double c = q1.x * y23 + q2.x * y31 + q3.x * y12;
  const double g = q1.x * (q3.y * q2.z - q2.y * q3.z) + q2.x * (q1.y * q3.z - q3.y * q1.z) +
                   q3.x * (q2.y * q1.z - q1.y * q2.z);
  const double s = a * p.x + b * p.y + c * p.z + g, nn = a * a + b * b + c * c;
  return nn > 0 ? s * s / nn : squared_distance_pe(p, q1, q2);
}

// Every case below is d^2 = |p - c|^2 with c = sum_i b_i q_i the foot of p on
// the feature's affine span (b = 1; (1 - t, t); the in-plane barycentric
// coordinates). c minimizes |p - c|^2 over that span, so by the envelope
// theorem d(d^2)/dq_i = -2 b_i (p - c) and d(d^2)/dp = 2 (p - c); with p =
// alpha p1 + beta p2 + gamma p3, d(d^2)/dp_j = 2 bary_j (p - c). Written out
// in coordinates these are the seed's eqs. (9)-(17).

Vec3d gradient_pp_feature(const Vec3d& p, const Vec3d& q) { return (q - p) * 2; }  // eq. (9)

void gradient_pe_feature(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, Vec3d out[2]) {  // eq. (16)
  const Vec3d e = q2 - q1;
  const double len2 = dot(e, e);
  if (!(len2 > 0)) {
    out[0] = out[1] = q1 - p;  // both ends on one point: half of eq. (9) each
    return;
  }
  const double t = dot(p - q1, e) / len2;
  const Vec3d r = p - (q1 + e * t);
  out[0] = r * (-2 * (1 - t));
  out[1] = r * (-2 * t);
}

namespace {

// Foot of p on the plane of q1 q2 q3 and its barycentric coordinates there;
// false for a degenerate triangle.
bool plane_foot(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, const Vec3d& q3, Vec3d* r, double b[3]) {
  const Vec3d n = cross(q2 - q1, q3 - q1);
  const double nn = dot(n, n);
  if (!(nn > 0)) return false;
  *r = n * (dot(p - q1, n) / nn);  // p - foot
  const Vec3d c = p - *r;
  b[0] = dot(cross(q2 - c, q3 - c), n) / nn;
  b[1] = dot(cross(q3 - c, q1 - c), n) / nn;
  b[2] = 1 - b[0] - b[1];
  return true;
}

}  // namespace

void gradient_pf_feature(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, const Vec3d& q3, Vec3d out[3]) {  // (17)
  Vec3d r;
  double b[3];
  if (!plane_foot(p, q1, q2, q3, &r, b)) {
    gradient_pe_feature(p, q1, q2, out);
    out[2] = Vec3d{};
    return;
  }
  for (int i = 0; i < 3; ++i) out[i] = r * (-2 * b[i]);
}

void gradient_pp_point(const Vec3d p[3], const double bary[3], const Vec3d& q, Vec3d out[3]) {  // eq. (10)
  const Vec3d ps = p[0] * bary[0] + p[1] * bary[1] + p[2] * bary[2];
  for (int j = 0; j < 3; ++j) out[j] = (ps - q) * (2 * bary[j]);
}

void gradient_pe_point(const Vec3d p[3], const double bary[3], const Vec3d& q1, const Vec3d& q2,
                       Vec3d out[3]) {  // eq. (12)
  const Vec3d ps = p[0] * bary[0] + p[1] * bary[1] + p[2] * bary[2];
  const Vec3d e = q2 - q1;
  const double len2 = dot(e, e);
  const Vec3d r = len2 > 0 ? ps - (q1 + e * (dot(ps - q1, e) / len2)) : ps - q1;
  for (int j = 0; j < 3; ++j) out[j] = r * (2 * bary[j]);
}

void gradient_pf_point(const Vec3d p[3], const double bary[3], const Vec3d& q1, const Vec3d& q2, const Vec3d& q3,
                       Vec3d out[3]) {  // eq. (15)
  const Vec3d ps = p[0] * bary[0] + p[1] * bary[1] + p[2] * bary[2];
  Vec3d r;
  double b[3];
  if (!plane_foot(ps, q1, q2, q3, &r, b)) return gradient_pe_point(p, bary, q1, q2, out);
  for (int j = 0; j < 3; ++j) out[j] = r * (2 * bary[j]);
}

// ---- Parameter-domain triangles -------------------------------------------------

namespace {

// Do the closed 2-D triangles a and b share a point? Separating axes: the
// coordinate axes and the six edge normals.
bool triangles_meet(const double au[3], const double av[3], const double bu[3], const double bv[3]) {
  double scale = 0;
  for (int k = 0; k < 3; ++k)
    scale = std::max({scale, std::fabs(au[k]), std::fabs(av[k]), std::fabs(bu[k]), std::fabs(bv[k])});
  auto separated = [&](double nx, double ny) {
    double alo = kInf, ahi = -kInf, blo = kInf, bhi = -kInf;
    for (int k = 0; k < 3; ++k) {
      const double a = nx * au[k] + ny * av[k], b = nx * bu[k] + ny * bv[k];
      alo = std::min(alo, a), ahi = std::max(ahi, a), blo = std::min(blo, b), bhi = std::max(bhi, b);
    }
    const double tol = 1e-12 * (1 + scale) * (std::fabs(nx) + std::fabs(ny));
    return ahi < blo - tol || bhi < alo - tol;
  };
  if (separated(1, 0) || separated(0, 1)) return false;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (separated(av[k] - av[j], au[j] - au[k]) || separated(bv[k] - bv[j], bu[j] - bu[k])) return false;
  }
  return true;
}

constexpr size_t kMaxCells = size_t(1) << 22;

}  // namespace

void ParamTriangleIndex::build(const std::vector<double>& uv, const std::vector<uint32_t>& triangles) {
  uv_ = &uv, triangles_ = &triangles;
  const size_t n = triangles.size() / 3;
  double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
  for (uint32_t v : triangles)
    for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], uv[2 * size_t(v) + a]), hi[a] = std::max(hi[a], uv[2 * size_t(v) + a]);
  if (n == 0) lo[0] = lo[1] = 0, hi[0] = hi[1] = 1;
  const double w = std::max(hi[0] - lo[0], 1e-300), h = std::max(hi[1] - lo[1], 1e-300);
  // About one triangle per cell.
  const double cells = double(std::min(std::max<size_t>(n, 1), kMaxCells));
  cell_ = std::max(std::sqrt(w * h / cells), std::max(w, h) / 4096);
  lo_[0] = lo[0], lo_[1] = lo[1];
  nu_ = int(std::min(4096.0, std::floor(w / cell_) + 1)), nv_ = int(std::min(4096.0, std::floor(h / cell_) + 1));
  cell_start_.assign(size_t(nu_) * nv_ + 1, 0);
  // Two passes: count, then fill.
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<uint32_t> fill;
    if (pass == 1) {
      std::partial_sum(cell_start_.begin(), cell_start_.end(), cell_start_.begin());
      cell_items_.resize(cell_start_.back());
      fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    }
    for (size_t t = 0; t < n; ++t) {
      double l[2] = {kInf, kInf}, hh[2] = {-kInf, -kInf};
      for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 2; ++a) {
          const double c = uv[2 * size_t(triangles[3 * t + k]) + a];
          l[a] = std::min(l[a], c), hh[a] = std::max(hh[a], c);
        }
      int r[4];
      cell_range(l[0], l[1], hh[0], hh[1], r);
      for (int y = r[1]; y <= r[3]; ++y)
        for (int x = r[0]; x <= r[2]; ++x) {
          const size_t cell = size_t(y) * nu_ + x;
          if (pass == 0) ++cell_start_[cell + 1];
          else cell_items_[fill[cell]++] = uint32_t(t);
        }
    }
  }
  stamp_.assign(n, 0);
  epoch_ = 0;
}

void ParamTriangleIndex::cell_range(double lo_u, double lo_v, double hi_u, double hi_v, int range[4]) const {
  auto cell = [&](double c, int axis, int count) {
    const double f = std::floor((c - lo_[axis]) / cell_);
    return int(std::clamp(f, 0.0, double(count - 1)));
  };
  range[0] = cell(lo_u, 0, nu_), range[1] = cell(lo_v, 1, nv_);
  range[2] = cell(hi_u, 0, nu_), range[3] = cell(hi_v, 1, nv_);
}

void ParamTriangleIndex::overlapping(const double u[3], const double v[3], std::vector<uint32_t>* out) const {
  out->clear();
  if (!triangles_ || triangles_->empty()) return;
  if (++epoch_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), epoch_ = 1;
  int r[4];
  cell_range(std::min({u[0], u[1], u[2]}), std::min({v[0], v[1], v[2]}), std::max({u[0], u[1], u[2]}),
             std::max({v[0], v[1], v[2]}), r);
  const std::vector<double>& uv = *uv_;
  const std::vector<uint32_t>& tri = *triangles_;
  for (int y = r[1]; y <= r[3]; ++y)
    for (int x = r[0]; x <= r[2]; ++x) {
      const size_t cell = size_t(y) * nu_ + x;
      for (uint32_t i = cell_start_[cell]; i < cell_start_[cell + 1]; ++i) {
        const uint32_t t = cell_items_[i];
        if (stamp_[t] == epoch_) continue;
        stamp_[t] = epoch_;
        double tu[3], tv[3];
        for (int k = 0; k < 3; ++k) tu[k] = uv[2 * size_t(tri[3 * t + k])], tv[k] = uv[2 * size_t(tri[3 * t + k]) + 1];
        if (triangles_meet(u, v, tu, tv)) out->push_back(t);
      }
    }
}

bool ParamTriangleIndex::locate(double u, double v, uint32_t* triangle, double bary[3]) const {
  if (!triangles_ || triangles_->empty()) return false;
  int r[4];
  cell_range(u, v, u, v, r);
  const std::vector<double>& uv = *uv_;
  const std::vector<uint32_t>& tri = *triangles_;
  double best = -kInf;
  const size_t cell = size_t(r[1]) * nu_ + r[0];
  for (uint32_t i = cell_start_[cell]; i < cell_start_[cell + 1]; ++i) {
    const uint32_t t = cell_items_[i];
    double tu[3], tv[3];
    for (int k = 0; k < 3; ++k) tu[k] = uv[2 * size_t(tri[3 * t + k])], tv[k] = uv[2 * size_t(tri[3 * t + k]) + 1];
    const double area = (tu[1] - tu[0]) * (tv[2] - tv[0]) - (tu[2] - tu[0]) * (tv[1] - tv[0]);
    if (area == 0) continue;
    double b[3];
    for (int k = 0; k < 3; ++k) {
      const int i1 = (k + 1) % 3, i2 = (k + 2) % 3;
      b[k] = ((tu[i1] - u) * (tv[i2] - v) - (tu[i2] - u) * (tv[i1] - v)) / area;
    }
    const double worst = std::min({b[0], b[1], b[2]});
    if (worst > best) best = worst, *triangle = t, bary[0] = b[0], bary[1] = b[1], bary[2] = b[2];
  }
  return best >= -1e-9;
}

// ---- GIM grid triangles ----------------------------------------------------------

void grid_triangles_over_pixels(uint32_t width, uint32_t height, const std::vector<uint8_t>* occupied,
                                const double* xyz, std::vector<uint32_t>* triangles) {
  triangles->clear();
  auto dist2 = [&](uint32_t a, uint32_t b) {
    double s = 0;
    for (int k = 0; k < 3; ++k) s += (xyz[3 * size_t(a) + k] - xyz[3 * size_t(b) + k]) * (xyz[3 * size_t(a) + k] - xyz[3 * size_t(b) + k]);
    return s;
  };
  for (uint32_t y = 0; y + 1 < height; ++y)
    for (uint32_t x = 0; x + 1 < width; ++x) {
      const uint32_t p00 = y * width + x, p10 = p00 + 1, p01 = p00 + width, p11 = p01 + 1;
      if (occupied && !occupied->empty() &&
          !((*occupied)[p00] && (*occupied)[p10] && (*occupied)[p01] && (*occupied)[p11]))
        continue;
      if (xyz && dist2(p10, p01) < dist2(p00, p11))
        triangles->insert(triangles->end(), {p00, p10, p01, p10, p11, p01});
      else
        triangles->insert(triangles->end(), {p00, p10, p11, p00, p11, p01});
    }
}

// ---- The adjustment ------------------------------------------------------------------

namespace {

// Compressed lists: items of list i are items[start[i] .. start[i + 1]).
struct Csr {
  std::vector<uint32_t> start{0}, items;
  void close_list() { start.push_back(uint32_t(items.size())); }
  size_t size() const { return start.size() - 1; }
};

// Max over a fixed number of values with point updates.
class MaxTree {
 public:
  void reset(size_t n) {
    size_ = 1;
    while (size_ < n) size_ *= 2;
    v_.assign(2 * size_, -kInf);
  }
  void set(size_t i, double value) {
    i += size_;
    v_[i] = value;
    for (i /= 2; i >= 1; i /= 2) v_[i] = std::max(v_[2 * i], v_[2 * i + 1]);
  }
  double max() const { return v_[1]; }
  size_t argmax() const {
    size_t i = 1;
    while (i < size_) i = v_[2 * i] >= v_[2 * i + 1] ? 2 * i : 2 * i + 1;
    return i - size_;
  }

 private:
  size_t size_ = 1;
  std::vector<double> v_{-kInf, -kInf};
};

struct FaceRecord {
  double d2 = -kInf;  // squared directed distance; -inf: not evaluated (masked out)
  uint32_t point = 0;  // lattice point giving it
  uint32_t nearest = kNoTriangle;
};

class Adjuster {
 public:
  Adjuster(const HausdorffAdjustInput& in, GimSamples* s) : in_(in), s_(s) {}
  Status validate();
  void load_geometry();  // M's positions, pixel uv, lattice
  void set_up();
  Status run(HausdorffAdjustStats* stats, const std::function<void(double)>& progress);

  // Exact per-face distances (gim_face_distances_exact).
  void exact(std::vector<double>* d1, std::vector<double>* d2);

 private:
  Triangle3d m_triangle(uint32_t f) const {
    const uint32_t* t = &in_.cut->triangles[3 * size_t(f)];
    return {m_pos_[t[0]], m_pos_[t[1]], m_pos_[t[2]]};
  }
  Vec3d pixel(uint32_t p) const { return {s_->xyz[3 * size_t(p)], s_->xyz[3 * size_t(p) + 1], s_->xyz[3 * size_t(p) + 2]}; }
  void set_pixel(uint32_t p, const Vec3d& v) {
    s_->xyz[3 * size_t(p)] = v.x, s_->xyz[3 * size_t(p) + 1] = v.y, s_->xyz[3 * size_t(p) + 2] = v.z;
  }
  Triangle3d g_triangle(uint32_t g) const {
    const uint32_t* t = &(*g_tris_)[3 * size_t(g)];
    return {pixel(t[0]), pixel(t[1]), pixel(t[2])};
  }
  static Vec3d at(const Triangle3d& t, const std::array<double, 3>& b) { return t.a * b[0] + t.b * b[1] + t.c * b[2]; }
  bool in_mask(uint32_t g) const { return !in_.gim_face_mask || (*in_.gim_face_mask)[g]; }

  void build_candidates(const std::vector<double>& from_uv, const std::vector<uint32_t>& from_tris,
                        const std::vector<Triangle3d>& from_3d, const ParamTriangleIndex& to_index,
                        const std::vector<Triangle3d>& to_3d, bool masked_from, Csr* out);
  FaceRecord evaluate_m(uint32_t f);
  FaceRecord evaluate_g(uint32_t g);
  void gradients(bool drive_d1, std::vector<uint32_t>* pixels, std::vector<Vec3d>* grads, GimDistanceType* type);
  bool try_steps(bool drive_d1, const std::vector<uint32_t>& pixels, const std::vector<Vec3d>& grads,
                 HausdorffAdjustStats* stats, bool* out_of_budget);
  double m1() const { return symmetric_ ? tree1_.max() : -kInf; }
  double m2() const { return tree2_.max(); }

  const HausdorffAdjustInput& in_;
  GimSamples* s_;
  const std::vector<uint32_t>* g_tris_ = nullptr;
  bool symmetric_ = true;
  size_t pixels_ = 0;
  std::vector<Vec3d> m_pos_;
  std::vector<double> g_uv_;
  std::vector<std::array<double, 3>> lattice_;
  std::vector<uint32_t> group_of_;
  Csr group_members_, pixel_faces_, cand1_, rev1_, cand2_;
  std::vector<FaceRecord> rec1_, rec2_;
  MaxTree tree1_, tree2_;
  uint64_t evaluations_ = 0;
  uint32_t fallback_faces_ = 0;
  std::vector<uint32_t> stamp_g_, stamp_m_;
  uint32_t epoch_ = 0;
};

Status invalid(const std::string& what) { return Status(ErrorCode::kInvalidArgument, "hausdorff_adjust: " + what); }

Status Adjuster::validate() {
  if (!in_.original || !in_.cut || !in_.param) return invalid("original mesh, disk cut and parametrization are required");
  const HausdorffAdjustOptions& o = in_.options;
  if (!(o.rho > 0 && o.rho < 1)) return invalid("rho must lie in (0, 1)");
  if (o.lattice_order < 1 || o.lattice_order > 32) return invalid("lattice_order must be 1..32");
  if (!(o.footprint_scale >= 1 && o.footprint_scale <= 64)) return invalid("footprint_scale must be 1..64");
  if (o.step_count > 1000) return invalid("step_count above 1000");
  const size_t disk_vertices = in_.cut->original_vertex.size();
  if (in_.param->uv.size() != 2 * disk_vertices) return invalid("parametrization has " + std::to_string(in_.param->uv.size() / 2) + " positions for " + std::to_string(disk_vertices) + " disk vertices");
  for (uint32_t v : in_.cut->original_vertex)
    if (v >= in_.original->vertex_count()) return invalid("disk vertex maps to input vertex " + std::to_string(v) + " out of range");
  if (in_.cut->triangles.size() % 3 || in_.cut->triangles.empty()) return invalid("the disk has no triangles");
  for (uint32_t v : in_.cut->triangles)
    if (v >= disk_vertices) return invalid("disk triangle corner " + std::to_string(v) + " out of range");
  const uint32_t w = s_->width, h = s_->height;
  pixels_ = size_t(w) * h;
  if (w < 2 || h < 2 || s_->xyz.size() != 3 * pixels_) return invalid("samples are not a W x H image of at least 2 x 2");
  if (in_.pixel_uv) {
    if (in_.pixel_uv->size() != 2 * pixels_) return invalid("pixel_uv needs 2 values per pixel");
  } else if (!in_.column_u || !in_.row_v || in_.column_u->size() != w || in_.row_v->size() != h) {
    return invalid("column_u / row_v must have W / H entries (or give pixel_uv)");
  }
  g_tris_ = in_.gim_triangles ? in_.gim_triangles : &s_->triangles;
  if (g_tris_->empty() || g_tris_->size() % 3) return invalid("no GIM triangles");
  for (uint32_t p : *g_tris_)
    if (p >= pixels_) return invalid("GIM triangle corner " + std::to_string(p) + " is not a pixel");
  if (in_.gim_face_mask && in_.gim_face_mask->size() != g_tris_->size() / 3) return invalid("gim_face_mask needs one byte per GIM triangle");
  for (const SeamPair& sp : s_->seams)
    if (sp.a >= pixels_ || sp.b >= pixels_) return invalid("seam pair outside the image");
  symmetric_ = in_.gim_face_mask == nullptr;
  return Status::Ok();
}

void Adjuster::load_geometry() {
  const uint32_t w = s_->width;
  m_pos_.resize(in_.cut->original_vertex.size());
  for (size_t v = 0; v < m_pos_.size(); ++v) {
    const size_t o = in_.cut->original_vertex[v];
    m_pos_[v] = {in_.original->positions[3 * o], in_.original->positions[3 * o + 1], in_.original->positions[3 * o + 2]};
  }
  if (in_.pixel_uv) {
    g_uv_ = *in_.pixel_uv;
  } else {
    g_uv_.resize(2 * pixels_);
    for (size_t p = 0; p < pixels_; ++p) g_uv_[2 * p] = (*in_.column_u)[p % w], g_uv_[2 * p + 1] = (*in_.row_v)[p / w];
  }
  lattice_ = lattice_points(in_.options.lattice_order);
}

void Adjuster::set_up() {
  load_geometry();
  // Seam groups by union-find with path halving (bounded by the pixel count).
  std::vector<uint32_t> parent(pixels_);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const SeamPair& sp : s_->seams) {
    const uint32_t a = find(sp.a), b = find(sp.b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  group_of_.resize(pixels_);
  std::vector<std::vector<uint32_t>> members;  // only groups of several pixels matter, but keep it simple
  std::vector<uint32_t> id(pixels_, UINT32_MAX);
  for (uint32_t p = 0; p < pixels_; ++p) {
    const uint32_t r = find(p);
    if (id[r] == UINT32_MAX) id[r] = uint32_t(members.size()), members.emplace_back();
    group_of_[p] = id[r];
    members[id[r]].push_back(p);
  }
  for (const auto& m : members) group_members_.items.insert(group_members_.items.end(), m.begin(), m.end()), group_members_.close_list();

  const size_t g_count = g_tris_->size() / 3;
  std::vector<std::vector<uint32_t>> faces_of(pixels_);
  for (size_t g = 0; g < g_count; ++g)
    for (int k = 0; k < 3; ++k) faces_of[(*g_tris_)[3 * g + k]].push_back(uint32_t(g));
  for (const auto& f : faces_of) pixel_faces_.items.insert(pixel_faces_.items.end(), f.begin(), f.end()), pixel_faces_.close_list();

  // Candidate lists from the parameter footprints.
  std::vector<Triangle3d> m3(in_.cut->triangles.size() / 3), g3(g_count);
  for (size_t f = 0; f < m3.size(); ++f) m3[f] = m_triangle(uint32_t(f));
  for (size_t g = 0; g < g_count; ++g) g3[g] = g_triangle(uint32_t(g));
  ParamTriangleIndex m_index, g_index;
  m_index.build(in_.param->uv, in_.cut->triangles);
  g_index.build(g_uv_, *g_tris_);
  if (symmetric_) build_candidates(in_.param->uv, in_.cut->triangles, m3, g_index, g3, false, &cand1_);
  build_candidates(g_uv_, *g_tris_, g3, m_index, m3, true, &cand2_);

  // Reverse lists: which M faces look at GIM face g.
  std::vector<uint32_t> count(g_count + 1, 0);
  for (size_t f = 0; f < cand1_.size(); ++f)
    for (uint32_t i = cand1_.start[f]; i < cand1_.start[f + 1]; ++i) ++count[cand1_.items[i] + 1];
  std::partial_sum(count.begin(), count.end(), count.begin());
  rev1_.start = count;
  rev1_.items.resize(count.back());
  for (size_t f = 0; f < cand1_.size(); ++f)
    for (uint32_t i = cand1_.start[f]; i < cand1_.start[f + 1]; ++i) rev1_.items[count[cand1_.items[i]]++] = uint32_t(f);
  if (!symmetric_) rev1_.start.assign(g_count + 1, 0);

  stamp_g_.assign(g_count, 0);
  stamp_m_.assign(m3.size(), 0);
  rec1_.assign(symmetric_ ? m3.size() : 0, FaceRecord{});
  rec2_.assign(g_count, FaceRecord{});
  tree1_.reset(rec1_.size());
  tree2_.reset(rec2_.size());
  for (uint32_t f = 0; f < rec1_.size(); ++f) rec1_[f] = evaluate_m(f), tree1_.set(f, rec1_[f].d2);
  for (uint32_t g = 0; g < rec2_.size(); ++g)
    if (in_mask(g)) rec2_[g] = evaluate_g(g), tree2_.set(g, rec2_[g].d2);
}

void Adjuster::build_candidates(const std::vector<double>& from_uv, const std::vector<uint32_t>& from_tris,
                                const std::vector<Triangle3d>& from_3d, const ParamTriangleIndex& to_index,
                                const std::vector<Triangle3d>& to_3d, bool masked_from, Csr* out) {
  const double scale = in_.options.footprint_scale;
  std::vector<uint32_t> found;
  TriangleBvh bvh;  // built on first need only
  for (size_t f = 0; f < from_tris.size() / 3; ++f) {
    if (masked_from && !in_mask(uint32_t(f))) {
      out->close_list();
      continue;
    }
    double u[3], v[3], cu = 0, cv = 0;
    for (int k = 0; k < 3; ++k) {
      u[k] = from_uv[2 * size_t(from_tris[3 * f + k])], v[k] = from_uv[2 * size_t(from_tris[3 * f + k]) + 1];
      cu += u[k] / 3, cv += v[k] / 3;
    }
    for (int k = 0; k < 3; ++k) u[k] = cu + scale * (u[k] - cu), v[k] = cv + scale * (v[k] - cv);
    to_index.overlapping(u, v, &found);
    if (found.empty()) {
      if (bvh.size() == 0) bvh = TriangleBvh(to_3d);
      for (const auto& b : lattice_) {
        uint32_t nearest = kNoTriangle;
        bvh.distance_squared(at(from_3d[f], b), kNoTriangle, &nearest);
        if (nearest != kNoTriangle && std::find(found.begin(), found.end(), nearest) == found.end()) found.push_back(nearest);
      }
      ++fallback_faces_;
    }
    out->items.insert(out->items.end(), found.begin(), found.end());
    out->close_list();
  }
}

// The worst lattice point of triangle t and its nearest candidate face, the
// directed distance of section 3.2 over the face neighbourhood `list` of the
// other mesh, whose triangles `other` returns.
template <class OtherTriangle>
FaceRecord worst_point(const Triangle3d& t, const std::vector<std::array<double, 3>>& lattice, const Csr& list,
                       uint32_t face, OtherTriangle other, uint64_t* evaluations) {
  FaceRecord r;
  const uint32_t b = list.start[face], e = list.start[face + 1];
  for (uint32_t k = 0; k < lattice.size(); ++k) {
    const Vec3d p = t.a * lattice[k][0] + t.b * lattice[k][1] + t.c * lattice[k][2];
    double best = kInf;
    uint32_t nearest = kNoTriangle;
    for (uint32_t i = b; i < e; ++i) {
      const double d2 = point_triangle_distance_squared(p, other(list.items[i]));
      if (d2 < best) best = d2, nearest = list.items[i];
    }
    *evaluations += e - b;
    if (best > r.d2) r.d2 = best, r.point = k, r.nearest = nearest;
  }
  return r;
}

FaceRecord Adjuster::evaluate_m(uint32_t f) {
  return worst_point(m_triangle(f), lattice_, cand1_, f, [this](uint32_t g) { return g_triangle(g); }, &evaluations_);
}

FaceRecord Adjuster::evaluate_g(uint32_t g) {
  return worst_point(g_triangle(g), lattice_, cand2_, g, [this](uint32_t f) { return m_triangle(f); }, &evaluations_);
}

// Algorithm 1 lines 4-6 and 9-11: the target point, face and distance type,
// and the gradient of d^2 for the pixels that Algorithm 2 or 3 moves.
void Adjuster::gradients(bool drive_d1, std::vector<uint32_t>* pixels, std::vector<Vec3d>* grads,
                         GimDistanceType* type) {
  pixels->clear(), grads->clear();
  if (drive_d1) {
    const uint32_t f = uint32_t(tree1_.argmax());
    const FaceRecord& r = rec1_[f];
    const Vec3d p = at(m_triangle(f), lattice_[r.point]);
    const uint32_t* corners = &(*g_tris_)[3 * size_t(r.nearest)];
    const Triangle3d t = g_triangle(r.nearest);
    const GimFeature feature = classify_distance(p, t);
    *type = feature.type;
    const Vec3d q[3] = {t.a, t.b, t.c};
    Vec3d g[3];
    if (feature.type == GimDistanceType::kPointPoint) {
      pixels->push_back(corners[feature.corner[0]]);
      grads->push_back(gradient_pp_feature(p, q[feature.corner[0]]));
    } else if (feature.type == GimDistanceType::kPointEdge) {
      gradient_pe_feature(p, q[feature.corner[0]], q[feature.corner[1]], g);
      for (int k = 0; k < 2; ++k) pixels->push_back(corners[feature.corner[k]]), grads->push_back(g[k]);
    } else {
      gradient_pf_feature(p, q[0], q[1], q[2], g);
      for (int k = 0; k < 3; ++k) pixels->push_back(corners[k]), grads->push_back(g[k]);
    }
    return;
  }
  const uint32_t gface = uint32_t(tree2_.argmax());
  const FaceRecord& r = rec2_[gface];
  const Triangle3d own = g_triangle(gface);
  const Vec3d ps[3] = {own.a, own.b, own.c};
  const double* bary = lattice_[r.point].data();
  const Vec3d p = at(own, lattice_[r.point]);
  const Triangle3d t = m_triangle(r.nearest);
  const Vec3d q[3] = {t.a, t.b, t.c};
  const GimFeature feature = classify_distance(p, t);
  *type = feature.type;
  Vec3d g[3];
  if (feature.type == GimDistanceType::kPointPoint) gradient_pp_point(ps, bary, q[feature.corner[0]], g);
  else if (feature.type == GimDistanceType::kPointEdge) gradient_pe_point(ps, bary, q[feature.corner[0]], q[feature.corner[1]], g);
  else gradient_pf_point(ps, bary, q[0], q[1], q[2], g);
  for (int k = 0; k < 3; ++k) pixels->push_back((*g_tris_)[3 * size_t(gface) + k]), grads->push_back(g[k]);
}

// Algorithms 2 and 3, lines "for k = 0..K": true when a step was taken.
bool Adjuster::try_steps(bool drive_d1, const std::vector<uint32_t>& pixels, const std::vector<Vec3d>& grads,
                         HausdorffAdjustStats* stats, bool* out_of_budget) {
  // One displacement per seam group: the gradient with respect to the group's
  // shared position is the sum over its pixels.
  std::vector<std::pair<uint32_t, Vec3d>> groups;
  for (size_t i = 0; i < pixels.size(); ++i) {
    const uint32_t g = group_of_[pixels[i]];
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == g; });
    if (it == groups.end()) groups.push_back({g, grads[i]});
    else it->second = it->second + grads[i];
  }
  std::vector<std::pair<uint32_t, Vec3d>> moved;  // pixel, old position
  for (const auto& [g, grad] : groups)
    for (uint32_t i = group_members_.start[g]; i < group_members_.start[g + 1]; ++i)
      moved.push_back({group_members_.items[i], pixel(group_members_.items[i])});
  if (++epoch_ == 0) std::fill(stamp_g_.begin(), stamp_g_.end(), 0), std::fill(stamp_m_.begin(), stamp_m_.end(), 0), epoch_ = 1;
  std::vector<uint32_t> g_faces, m_faces;
  for (const auto& [p, old] : moved)
    for (uint32_t i = pixel_faces_.start[p]; i < pixel_faces_.start[p + 1]; ++i) {
      const uint32_t g = pixel_faces_.items[i];
      if (stamp_g_[g] == epoch_) continue;
      stamp_g_[g] = epoch_;
      if (in_mask(g)) g_faces.push_back(g);
      for (uint32_t j = rev1_.start[g]; j < rev1_.start[g + 1]; ++j)
        if (stamp_m_[rev1_.items[j]] != epoch_) stamp_m_[rev1_.items[j]] = epoch_, m_faces.push_back(rev1_.items[j]);
    }
  // The worst face is among those recomputed; trying it first rejects most
  // steps after one face.
  const uint32_t worst = uint32_t(drive_d1 ? tree1_.argmax() : tree2_.argmax());
  std::vector<uint32_t>& driving = drive_d1 ? m_faces : g_faces;
  auto w = std::find(driving.begin(), driving.end(), worst);
  const bool worst_first = w != driving.end();
  if (worst_first) std::iter_swap(driving.begin(), w);

  std::vector<FaceRecord> old1(m_faces.size()), old2(g_faces.size());
  for (size_t i = 0; i < m_faces.size(); ++i) old1[i] = rec1_[m_faces[i]];
  for (size_t i = 0; i < g_faces.size(); ++i) old2[i] = rec2_[g_faces[i]];
  const double old_m1 = m1(), old_m2 = m2(), old_h = std::max(old_m1, old_m2);
  const double old_target = drive_d1 ? old_m1 : old_m2;
  bool accepted = false;
  double step = 1;
  for (uint32_t k = 0; k <= in_.options.step_count && !accepted; ++k, step *= in_.options.rho) {
    if (evaluations_ >= in_.options.work_budget) {
      *out_of_budget = true;
      break;
    }
    ++stats->step_trials;
    size_t next = 0;
    for (const auto& [g, grad] : groups)
      for (uint32_t i = group_members_.start[g]; i < group_members_.start[g + 1]; ++i, ++next)
        set_pixel(moved[next].first, moved[next].second - grad * step);
    // A rejected trial leaves records and trees as they were, so the next
    // one starts from the old state.
    FaceRecord first;
    if (worst_first) {
      first = drive_d1 ? evaluate_m(driving[0]) : evaluate_g(driving[0]);
      if (first.d2 >= old_target) continue;
    }
    for (size_t i = 0; i < m_faces.size(); ++i) {
      rec1_[m_faces[i]] = drive_d1 && worst_first && i == 0 ? first : evaluate_m(m_faces[i]);
      tree1_.set(m_faces[i], rec1_[m_faces[i]].d2);
    }
    for (size_t i = 0; i < g_faces.size(); ++i) {
      rec2_[g_faces[i]] = !drive_d1 && worst_first && i == 0 ? first : evaluate_g(g_faces[i]);
      tree2_.set(g_faces[i], rec2_[g_faces[i]].d2);
    }
    const double new_target = drive_d1 ? m1() : m2(), new_other = drive_d1 ? m2() : m1();
    accepted = new_target < old_target && new_other <= old_h;
    if (!accepted) {
      for (size_t i = 0; i < m_faces.size(); ++i) rec1_[m_faces[i]] = old1[i], tree1_.set(m_faces[i], old1[i].d2);
      for (size_t i = 0; i < g_faces.size(); ++i) rec2_[g_faces[i]] = old2[i], tree2_.set(g_faces[i], old2[i].d2);
    }
  }
  if (!accepted)
    for (const auto& [p, old] : moved) set_pixel(p, old);
  return accepted;
}

Status Adjuster::run(HausdorffAdjustStats* stats, const std::function<void(double)>& progress) {
  HausdorffAdjustStats st;
  st.fallback_faces = fallback_faces_;
  st.d1_before = symmetric_ ? std::sqrt(std::max(0.0, m1())) : 0;
  st.d2_before = std::sqrt(std::max(0.0, m2()));
  st.hausdorff_before = std::max(st.d1_before, st.d2_before);
  std::vector<uint32_t> pixels;
  std::vector<Vec3d> grads;
  st.stop = HausdorffStop::kMaxIterations;
  for (uint32_t iteration = 0; iteration < in_.options.max_iterations; ++iteration) {
    if (progress && iteration % 32 == 0) progress(double(iteration) / in_.options.max_iterations);
    if (std::max(m1(), m2()) <= 0) {
      st.stop = HausdorffStop::kZeroDistance;
      break;
    }
    const bool drive_d1 = symmetric_ && m1() > m2();
    GimDistanceType type;
    gradients(drive_d1, &pixels, &grads, &type);
    bool out_of_budget = false;
    if (!try_steps(drive_d1, pixels, grads, &st, &out_of_budget)) {
      st.stop = out_of_budget ? HausdorffStop::kWorkBudget : HausdorffStop::kNoStep;
      break;
    }
    ++st.iterations;
    ++(drive_d1 ? st.algorithm2_steps : st.algorithm3_steps);
    ++st.type_steps[int(type)];
  }
  if (progress) progress(1.0);
  st.d1_after = symmetric_ ? std::sqrt(std::max(0.0, m1())) : 0;
  st.d2_after = std::sqrt(std::max(0.0, m2()));
  st.hausdorff_after = std::max(st.d1_after, st.d2_after);
  st.distance_evaluations = evaluations_;
  if (stats) *stats = st;
  return Status::Ok();
}

void Adjuster::exact(std::vector<double>* d1, std::vector<double>* d2) {
  load_geometry();
  const size_t g_count = g_tris_->size() / 3, m_count = in_.cut->triangles.size() / 3;
  std::vector<Triangle3d> m3(m_count), g3(g_count);
  for (size_t f = 0; f < m_count; ++f) m3[f] = m_triangle(uint32_t(f));
  for (size_t g = 0; g < g_count; ++g) g3[g] = g_triangle(uint32_t(g));
  const TriangleBvh m_bvh(m3), g_bvh(g3);
  auto directed = [&](const std::vector<Triangle3d>& from, const TriangleBvh& to, std::vector<double>* out) {
    out->assign(from.size(), 0);
    uint32_t hint = kNoTriangle;
    for (size_t f = 0; f < from.size(); ++f) {
      double worst = 0;
      for (const auto& b : lattice_) worst = std::max(worst, to.distance_squared(at(from[f], b), hint, &hint));
      (*out)[f] = std::sqrt(worst);
    }
  };
  directed(m3, g_bvh, d1);
  directed(g3, m_bvh, d2);
}

}  // namespace

Status hausdorff_adjust(const HausdorffAdjustInput& input, GimSamples* samples, HausdorffAdjustStats* stats,
                        const std::function<void(double)>& progress) {
  if (!samples) return invalid("no samples");
  Adjuster a(input, samples);
  if (Status s = a.validate(); !s.ok()) return s;
  a.set_up();
  return a.run(stats, progress);
}

Status gim_face_distances_exact(const HausdorffAdjustInput& input, const GimSamples& samples,
                                std::vector<double>* d1, std::vector<double>* d2) {
  GimSamples copy = samples;  // the adjuster's accessors take a mutable image
  Adjuster a(input, &copy);
  if (Status s = a.validate(); !s.ok()) return s;
  a.exact(d1, d2);
  return Status::Ok();
}

}  // namespace qmc
