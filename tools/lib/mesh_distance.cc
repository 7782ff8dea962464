// Metro-style surface distance (Cignoni, Rocchini, Scopigno 1998); the
// definitions are in mesh_distance.h.
#include "mesh_distance.h"

#include "splitmix64.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <string>

namespace qmc::tools {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Vec3d operator-(const Vec3d& u, const Vec3d& v) { return {u.x - v.x, u.y - v.y, u.z - v.z}; }
Vec3d operator+(const Vec3d& u, const Vec3d& v) { return {u.x + v.x, u.y + v.y, u.z + v.z}; }
Vec3d operator*(const Vec3d& u, double s) { return {u.x * s, u.y * s, u.z * s}; }
double dot(const Vec3d& u, const Vec3d& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
Vec3d cross(const Vec3d& u, const Vec3d& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
double component(const Vec3d& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

Vec3d position(const qmc::Mesh& mesh, uint32_t v) {
  return {mesh.positions[3 * size_t(v)], mesh.positions[3 * size_t(v) + 1], mesh.positions[3 * size_t(v) + 2]};
}

double box_distance_squared(const double lo[3], const double hi[3], const Vec3d& p) {
  double sum = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double c = component(p, axis);
    const double d = c < lo[axis] ? lo[axis] - c : c > hi[axis] ? c - hi[axis] : 0.0;
    sum += d * d;
  }
  return sum;
}

// Sample points and closest points carry rounding errors of a few units in
// the last place of double coordinates, so a point on a shared surface comes
// out at 1e-17 instead of 0. Distances up to 2^-40 times the largest
// coordinate magnitude are such noise: they are 2^16 times finer than float
// input coordinates can resolve, and counting them as 0 makes coincident
// surfaces measure exactly 0 (and PSNR infinite).
double rounding_noise(const qmc::Mesh& a, const qmc::Mesh& b) {
  double largest = 0;
  for (const qmc::Mesh* m : {&a, &b})
    for (float v : m->positions) largest = std::max(largest, std::fabs(double(v)));
  return std::ldexp(largest, -40);
}

double bbox_diagonal(const qmc::Mesh& mesh) {
  if (mesh.vertex_count() == 0) return 0;
  double lo[3], hi[3];
  for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = mesh.positions[size_t(axis)];
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const int axis = int(i % 3);
    lo[axis] = std::min(lo[axis], double(mesh.positions[i]));
    hi[axis] = std::max(hi[axis], double(mesh.positions[i]));
  }
  double sum = 0;
  for (int axis = 0; axis < 3; ++axis) sum += (hi[axis] - lo[axis]) * (hi[axis] - lo[axis]);
  return std::sqrt(sum);
}

// Everything needed to measure distances from and to one mesh.
struct Surface {
  std::vector<Triangle> triangles;
  std::vector<uint32_t> vertices;
  SurfaceInfo info;
};

qmc::Status prepare(const qmc::Mesh& mesh, const char* name, Surface* s) {
  qmc::Status status = fan_triangulate(mesh, &s->triangles, &s->info.degenerate, &s->vertices);
  if (!status.ok()) return qmc::Status(status.code(), std::string("mesh ") + name + ": " + status.message());
  if (s->triangles.empty())
    return qmc::Status(qmc::ErrorCode::kInvalidArgument,
                       std::string("mesh ") + name + " has no face of non-zero area to measure distances to");
  s->info.triangles = s->triangles.size();
  s->info.referenced_vertices = s->vertices.size();
  for (const Triangle& t : s->triangles) s->info.area += triangle_area(t);
  return qmc::Status::Ok();
}

// Distances from the samples and vertices of `from` to the triangles in `to`.
class OneSidedMeasure {
 public:
  OneSidedMeasure(const TriangleBvh& to, double noise, const MeshDistanceOptions& options, size_t* done, size_t total)
      : to_(to), noise_squared_(noise * noise), options_(options), done_(done), total_(total) {}

  OneSidedDistance run(const std::vector<SurfaceSample>& samples, const qmc::Mesh& from_mesh,
                       const std::vector<uint32_t>& vertices) {
    OneSidedDistance r;
    double sum = 0, sum_squares = 0;
    for (const SurfaceSample& s : samples) {
      const double d2 = query(s.point);
      sum += std::sqrt(d2);
      sum_squares += d2;
    }
    for (uint32_t v : vertices) query(position(from_mesh, v));
    r.area_samples = samples.size();
    r.vertex_samples = vertices.size();
    if (!samples.empty()) {
      r.mean = sum / double(samples.size());
      r.rms = std::sqrt(sum_squares / double(samples.size()));
    }
    r.max = std::sqrt(max_squared_);
    return r;
  }

 private:
  double query(const Vec3d& p) {
    // Consecutive samples lie on the same or neighbouring triangles, so the
    // previous answer is usually the new one or close to it.
    double d2 = to_.distance_squared(p, hint_, &hint_, noise_squared_);
    if (d2 <= noise_squared_) d2 = 0;
    max_squared_ = std::max(max_squared_, d2);
    if ((++*done_ & 0x3fff) == 0 && options_.progress) options_.progress(*done_, total_);
    return d2;
  }

  const TriangleBvh& to_;
  double noise_squared_;
  const MeshDistanceOptions& options_;
  size_t* done_;
  size_t total_;
  uint32_t hint_ = UINT32_MAX;
  double max_squared_ = 0;
};

}  // namespace

double point_triangle_distance_squared(const Vec3d& p, const Triangle& t, Vec3d* closest) {
  // Regions are told apart by the signs of dot products of p - vertex with
  // the edge vectors; each test rules out what the earlier ones covered.
  const Vec3d ab = t.b - t.a, ac = t.c - t.a;
  const Vec3d ap = p - t.a;
  const double a_ab = dot(ab, ap), a_ac = dot(ac, ap);
  Vec3d q;
  if (a_ab <= 0 && a_ac <= 0) {
    q = t.a;  // behind a along both edges that leave a
  } else {
    const Vec3d bp = p - t.b;
    const double b_ab = dot(ab, bp), b_ac = dot(ac, bp);
    const Vec3d cp = p - t.c;
    const double c_ab = dot(ab, cp), c_ac = dot(ac, cp);
    // Unnormalised barycentric weights of the projection of p: each is
    // proportional to the signed area of the sub-triangle opposite that
    // vertex, negative when p lies beyond the edge opposite it.
    const double weight_c = a_ab * b_ac - b_ab * a_ac;
    const double weight_b = c_ab * a_ac - a_ab * c_ac;
    const double weight_a = b_ab * c_ac - c_ab * b_ac;
    if (b_ab >= 0 && b_ac <= b_ab) {
      q = t.b;
    } else if (weight_c <= 0 && a_ab >= 0 && b_ab <= 0) {
      q = t.a + ab * (a_ab / (a_ab - b_ab));  // edge ab
    } else if (c_ac >= 0 && c_ab <= c_ac) {
      q = t.c;
    } else if (weight_b <= 0 && a_ac >= 0 && c_ac <= 0) {
      q = t.a + ac * (a_ac / (a_ac - c_ac));  // edge ac
    } else if (weight_a <= 0 && b_ac - b_ab >= 0 && c_ab - c_ac >= 0) {
      const double s = (b_ac - b_ab) / ((b_ac - b_ab) + (c_ab - c_ac));
      q = t.b + (t.c - t.b) * s;  // edge bc
    } else {
      const double sum = weight_a + weight_b + weight_c;
      if (sum > 0) {
        q = t.a + ab * (weight_b / sum) + ac * (weight_c / sum);
      } else {
        // Only a sliver so thin that rounding swallowed its area gets here:
        // it is as good as its longest edge, so take the nearest edge point.
        double best = kInfinity;
        const Vec3d ends[3][2] = {{t.a, t.b}, {t.b, t.c}, {t.c, t.a}};
        for (const auto& e : ends) {
          const Vec3d dir = e[1] - e[0];
          const double len2 = dot(dir, dir);
          const double s = len2 > 0 ? std::clamp(dot(p - e[0], dir) / len2, 0.0, 1.0) : 0.0;
          const Vec3d r = e[0] + dir * s;
          const double d2 = dot(p - r, p - r);
          if (d2 < best) best = d2, q = r;
        }
      }
    }
  }
  if (closest) *closest = q;
  const Vec3d d = p - q;
  return dot(d, d);
}

double triangle_area(const Triangle& t) {
  const Vec3d n = cross(t.b - t.a, t.c - t.a);
  return 0.5 * std::sqrt(dot(n, n));
}

qmc::Status fan_triangulate(const qmc::Mesh& mesh, std::vector<Triangle>* triangles, size_t* degenerate,
                            std::vector<uint32_t>* vertices) {
  size_t total_corners = 0;
  for (uint32_t size : mesh.face_sizes) total_corners += size;
  if (total_corners != mesh.corners.size() || mesh.positions.size() % 3 != 0)
    return qmc::Status(qmc::ErrorCode::kInvalidArgument,
                       "face sizes add up to " + std::to_string(total_corners) + " corners, but there are " +
                           std::to_string(mesh.corners.size()));
  const size_t n = mesh.vertex_count();
  for (size_t i = 0; i < mesh.corners.size(); ++i)
    if (mesh.corners[i] >= n)
      return qmc::Status(qmc::ErrorCode::kInvalidArgument, "corner " + std::to_string(i) + " names vertex " +
                                                               std::to_string(mesh.corners[i]) + " of " +
                                                               std::to_string(n));
  std::vector<Triangle> out;
  size_t skipped = 0;
  size_t c = 0;
  for (uint32_t size : mesh.face_sizes) {
    for (uint32_t i = 1; i + 1 < size; ++i) {
      const Triangle t{position(mesh, mesh.corners[c]), position(mesh, mesh.corners[c + i]),
                       position(mesh, mesh.corners[c + i + 1])};
      if (triangle_area(t) > 0)
        out.push_back(t);
      else
        ++skipped;
    }
    c += size;
  }
  if (vertices) {
    std::vector<char> used(n, 0);
    for (uint32_t v : mesh.corners) used[v] = 1;
    vertices->clear();
    for (size_t v = 0; v < n; ++v)
      if (used[v]) vertices->push_back(uint32_t(v));
  }
  if (triangles) *triangles = std::move(out);
  if (degenerate) *degenerate = skipped;
  return qmc::Status::Ok();
}

std::vector<SurfaceSample> sample_surface(const std::vector<Triangle>& triangles, size_t count, uint64_t seed) {
  std::vector<double> area(triangles.size());
  double total = 0;
  size_t last_positive = 0;
  for (size_t i = 0; i < triangles.size(); ++i) {
    area[i] = triangle_area(triangles[i]);
    total += area[i];
    if (area[i] > 0) last_positive = i;
  }
  std::vector<SurfaceSample> out;
  if (count == 0 || !(total > 0)) return out;
  out.reserve(count);
  SplitMix64 rng(seed);
  // Systematic sampling: sample k sits at cumulative area (k + offset) * step.
  // Every point of the surface is equally likely to be picked, as with
  // independent draws, but each triangle gets its expected share rounded up
  // or down instead of a binomial count, so estimates vary less.
  const double step = total / double(count);
  const double offset = rng.unit();
  double cumulative = 0;
  for (size_t i = 0; i < triangles.size() && out.size() < count; ++i) {
    cumulative += area[i];
    size_t end = count;  // rounding must not lose samples past the last triangle
    if (i < last_positive) {
      const double k = std::ceil(cumulative / step - offset);
      end = k <= 0 ? 0 : std::min(count, size_t(k));
    }
    const Triangle& t = triangles[i];
    while (out.size() < end) {
      // sqrt makes the distance from a uniform in area, not in length.
      const double s = std::sqrt(rng.unit()), r = rng.unit();
      const double wa = 1 - s, wb = s * (1 - r), wc = s * r;
      out.push_back({{wa * t.a.x + wb * t.b.x + wc * t.c.x, wa * t.a.y + wb * t.b.y + wc * t.c.y,
                      wa * t.a.z + wb * t.b.z + wc * t.c.z},
                     uint32_t(i)});
    }
  }
  return out;
}

TriangleBvh::TriangleBvh(const std::vector<Triangle>& triangles) {
  if (triangles.empty()) return;
  original_.resize(triangles.size());
  std::iota(original_.begin(), original_.end(), 0u);
  std::vector<Vec3d> centroids(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i)
    centroids[i] = (triangles[i].a + triangles[i].b + triangles[i].c) * (1.0 / 3.0);
  nodes_.reserve(2 * (triangles.size() / 2 + 1));
  build(triangles, centroids, 0, uint32_t(triangles.size()));
  triangles_.resize(triangles.size());
  position_.resize(triangles.size());
  planes_.assign(4 * triangles.size(), 0.0);
  for (size_t i = 0; i < original_.size(); ++i) {
    const Triangle& t = triangles_[i] = triangles[original_[i]];
    position_[original_[i]] = uint32_t(i);
    const Vec3d n = cross(t.b - t.a, t.c - t.a);
    const double length = std::sqrt(dot(n, n));
    if (length > 0) {  // a zero-area triangle keeps the useless bound 0
      const Vec3d u = n * (1 / length);
      planes_[4 * i] = u.x, planes_[4 * i + 1] = u.y, planes_[4 * i + 2] = u.z;
      planes_[4 * i + 3] = dot(u, t.a);
    }
  }
}

uint32_t TriangleBvh::build(const std::vector<Triangle>& triangles, const std::vector<Vec3d>& centroids,
                            uint32_t begin, uint32_t end) {
  Node node;
  for (int axis = 0; axis < 3; ++axis) node.lo[axis] = kInfinity, node.hi[axis] = -kInfinity;
  double clo[3] = {kInfinity, kInfinity, kInfinity}, chi[3] = {-kInfinity, -kInfinity, -kInfinity};
  for (uint32_t k = begin; k < end; ++k) {
    const Triangle& t = triangles[original_[k]];
    for (int axis = 0; axis < 3; ++axis) {
      for (const Vec3d* v : {&t.a, &t.b, &t.c}) {
        node.lo[axis] = std::min(node.lo[axis], component(*v, axis));
        node.hi[axis] = std::max(node.hi[axis], component(*v, axis));
      }
      const double c = component(centroids[original_[k]], axis);
      clo[axis] = std::min(clo[axis], c);
      chi[axis] = std::max(chi[axis], c);
    }
  }
  const uint32_t index = uint32_t(nodes_.size());
  nodes_.push_back(node);
  if (end - begin <= 4) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (chi[a] - clo[a] > chi[axis] - clo[axis]) axis = a;
  // A median split keeps the tree balanced, so its depth, and with it the
  // search stack, stays logarithmic even for clustered or repeated triangles.
  const uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(original_.begin() + begin, original_.begin() + mid, original_.begin() + end,
                   [&](uint32_t x, uint32_t y) {
                     const double cx = component(centroids[x], axis), cy = component(centroids[y], axis);
                     return cx < cy || (cx == cy && x < y);
                   });
  nodes_[index].count = 0;
  build(triangles, centroids, begin, mid);
  const uint32_t second = build(triangles, centroids, mid, end);
  nodes_[index].first = second;
  return index;
}

double TriangleBvh::distance_squared(const Vec3d& p, uint32_t hint, uint32_t* nearest, double enough) const {
  double best = kInfinity;
  uint32_t best_index = UINT32_MAX;
  if (hint < triangles_.size()) {
    best_index = position_[hint];
    best = point_triangle_distance_squared(p, triangles_[best_index]);
  }
  if (!nodes_.empty() && best > enough) {
    struct Entry {
      uint32_t node;
      double distance_squared;
    };
    Entry stack[96];  // the tree is balanced: depth <= log2(triangles) + 1
    int top = 0;
    stack[top++] = {0, box_distance_squared(nodes_[0].lo, nodes_[0].hi, p)};
    while (top > 0) {
      const Entry e = stack[--top];
      if (e.distance_squared >= best) continue;
      const Node& n = nodes_[e.node];
      if (n.count > 0) {
        for (uint32_t k = n.first; k < n.first + n.count; ++k) {
          // The distance to the triangle's plane is a lower bound that costs
          // one dot product. Boxes of tilted triangles are loose, so far from
          // a curved surface many leaves survive the box test and fail this
          // one. The margin keeps rounding in the bound from skipping a
          // triangle that is nearer by an ulp.
          const double* plane = &planes_[4 * size_t(k)];
          const double h = plane[0] * p.x + plane[1] * p.y + plane[2] * p.z - plane[3];
          if (h * h > best * (1 + 1e-9)) continue;
          const double d2 = point_triangle_distance_squared(p, triangles_[k]);
          if (d2 < best) best = d2, best_index = k;
        }
        // Boxes that contain p cannot be pruned however small `best` is, so
        // without this a point on many overlapping triangles visits them all.
        if (best <= enough) break;
        continue;
      }
      uint32_t near = e.node + 1, far = n.first;
      double near_d2 = box_distance_squared(nodes_[near].lo, nodes_[near].hi, p);
      double far_d2 = box_distance_squared(nodes_[far].lo, nodes_[far].hi, p);
      if (far_d2 < near_d2) std::swap(near, far), std::swap(near_d2, far_d2);
      // The nearer box goes on top, so it is searched first and tightens
      // `best` before the farther one is looked at.
      if (far_d2 < best) stack[top++] = {far, far_d2};
      if (near_d2 < best) stack[top++] = {near, near_d2};
    }
  }
  if (nearest) *nearest = best_index == UINT32_MAX ? UINT32_MAX : original_[best_index];
  return best;
}

qmc::Status measure_mesh_distance(const qmc::Mesh& a, const qmc::Mesh& b, const MeshDistanceOptions& options,
                                  MeshDistance* out) {
  Surface sa, sb;
  if (qmc::Status s = prepare(a, "A", &sa); !s.ok()) return s;
  if (qmc::Status s = prepare(b, "B", &sb); !s.ok()) return s;
  // Different streams for the two surfaces, so identical meshes are not
  // sampled at identical points (which would hide nothing, but would make the
  // identical-mesh result a special case rather than an ordinary one).
  const std::vector<SurfaceSample> samples_a = sample_surface(sa.triangles, options.samples, options.seed);
  const std::vector<SurfaceSample> samples_b =
      sample_surface(sb.triangles, options.samples, options.seed ^ 0xD1B54A32D192ED03ull);
  const TriangleBvh bvh_a(sa.triangles), bvh_b(sb.triangles);
  const size_t total = samples_a.size() + sa.vertices.size() + samples_b.size() + sb.vertices.size();
  size_t done = 0;
  MeshDistance r;
  r.a = sa.info;
  r.b = sb.info;
  const double noise = rounding_noise(a, b);
  r.a_to_b = OneSidedMeasure(bvh_b, noise, options, &done, total).run(samples_a, a, sa.vertices);
  r.b_to_a = OneSidedMeasure(bvh_a, noise, options, &done, total).run(samples_b, b, sb.vertices);
  if (options.progress) options.progress(total, total);
  r.hausdorff = std::max(r.a_to_b.max, r.b_to_a.max);
  r.l2 = std::max(r.a_to_b.rms, r.b_to_a.rms);
  r.mean = std::max(r.a_to_b.mean, r.b_to_a.mean);
  r.bbox_diagonal = bbox_diagonal(a);
  r.psnr_db = r.l2 > 0 ? 20 * std::log10(r.bbox_diagonal / r.l2) : kInfinity;
  *out = r;
  return qmc::Status::Ok();
}

}  // namespace qmc::tools
