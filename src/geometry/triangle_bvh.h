// A bounding volume hierarchy over a fixed set of triangles, in binary64:
// the geometric queries of the Loop remesher (seed 003 §3.1.2: the
// displacement of each vertex of the subdivided mesh along its limit normal
// onto the original surface, and the closest point as the fallback; the same
// for each limit position in seed 003 step III, the adjustment of Suzuki et
// al.), and of the Metro-style distances of tools/lib/mesh_distance.h (seed
// 003 §4.1).
//
// The tree: split by the surface area heuristic over 16 bins of the
// centroids along their longest axis, at most four triangles per leaf, nodes
// in depth-first order (an inner node's first child follows it, the second is
// named). From depth 48 on the split is at the median centroid instead, which
// halves the triangles, so the depth, and with it the fixed traversal stack,
// stays under 48 + log2(triangles) + 1 even for clustered or repeated
// triangles. Building and both searches are iterative.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc {

struct Vec3d {
  double x = 0, y = 0, z = 0;
};

inline Vec3d operator+(const Vec3d& u, const Vec3d& v) { return {u.x + v.x, u.y + v.y, u.z + v.z}; }
inline Vec3d operator-(const Vec3d& u, const Vec3d& v) { return {u.x - v.x, u.y - v.y, u.z - v.z}; }
inline Vec3d operator*(const Vec3d& u, double s) { return {u.x * s, u.y * s, u.z * s}; }
inline double dot(const Vec3d& u, const Vec3d& v) { return u.x * v.x + u.y * v.y + u.z * v.z; }
inline Vec3d cross(const Vec3d& u, const Vec3d& v) {
  return {u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
}
inline double component(const Vec3d& v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
// Vertex v of a flat array of positions, three per vertex (LoopMesh::positions).
inline Vec3d position_of(const std::vector<double>& positions, uint32_t v) {
  return {positions[3 * size_t(v)], positions[3 * size_t(v) + 1], positions[3 * size_t(v) + 2]};
}

struct Triangle3d {
  Vec3d a, b, c;
};

inline constexpr uint32_t kNoTriangle = UINT32_MAX;

// The barycentric lattice of order s >= 1 over a triangle: the (s + 1)(s + 2)
// / 2 weights ((s - i - j) / s, i / s, j / s), i outer, j inner.
std::vector<std::array<double, 3>> lattice_points(uint32_t s);

// Squared Euclidean distance from p to the closed triangle abc; the closest
// point goes to *closest if it is not null. Decides which Voronoi region of
// the triangle (a vertex, an edge or the interior) p projects into, so the
// answer is exact up to rounding whatever the region.
double point_triangle_distance_squared(const Vec3d& p, const Triangle3d& t, Vec3d* closest = nullptr);

// The nearest point of the surface to a query point.
struct SurfacePoint {
  double distance_squared;  // +infinity when there are no triangles
  Vec3d point;
  uint32_t triangle;  // index given to the constructor, kNoTriangle if none
};

// Where the line origin + t * direction meets the surface.
struct LineHit {
  double t;         // the line parameter: point = origin + t * direction (t < 0: behind the origin)
  double distance;  // t * |direction|: signed Euclidean distance from the origin
  Vec3d point;
  uint32_t triangle;
};

class TriangleBvh {
 public:
  TriangleBvh() = default;
  explicit TriangleBvh(const std::vector<Triangle3d>& triangles);

  size_t size() const { return triangles_.size(); }
  // The triangle given to the constructor at `index`.
  const Triangle3d& triangle(uint32_t index) const { return triangles_[position_[index]]; }
  // Diagonal of the box around all triangles (0 when empty).
  double bbox_diagonal() const;
  // Nodes on the longest path from the root to a leaf (0 when empty).
  int depth() const { return depth_; }

  // Squared distance from p to the nearest triangle (+infinity if there are
  // none). *nearest, if not null, receives that triangle's index in the
  // vector given to the constructor. `hint`, a triangle index, seeds the
  // search with that triangle's distance: passing the previous answer makes a
  // run of nearby queries cheap. The search stops at the first triangle
  // within squared distance `enough`, for callers to whom all distances that
  // small are alike.
  double distance_squared(const Vec3d& p, uint32_t hint = kNoTriangle, uint32_t* nearest = nullptr,
                          double enough = 0) const;

  // The nearest point of the surface to p, with its triangle.
  SurfacePoint closest_point(const Vec3d& p, uint32_t hint = kNoTriangle) const;

  // The intersection of the whole line origin + t * direction (t of either
  // sign; direction need not be unit) with the triangles that is nearest to
  // the origin, among those with |t| * |direction| <= max_distance. Returns
  // false, leaving *hit alone, when there is none or direction is zero.
  // Möller-Trumbore per triangle, with a relative tolerance of 1e-9 on the
  // barycentric coordinates so that a line through a shared edge or vertex
  // is not lost between two triangles to rounding; triangles edge-on to the
  // line are ignored. With `same_facing`, so are triangles whose normal
  // (b - a) x (c - a) points against `direction`: seen along a surface normal,
  // those are the far side of a thin part, not the surface itself.
  bool nearest_line_hit(const Vec3d& origin, const Vec3d& direction, double max_distance, LineHit* hit,
                        bool same_facing = false) const;

 private:
  struct Node {
    double lo[3], hi[3];
    uint32_t first;  // leaf: first triangle; inner: index of the second child (the first is next)
    uint32_t count;  // triangles in a leaf, 0 for an inner node
    double pad;      // the margin of the box's slab test in nearest_line_hit
  };
  void build(const std::vector<Triangle3d>& triangles);

  std::vector<Node> nodes_;
  std::vector<Triangle3d> triangles_;  // in leaf order
  std::vector<double> planes_;         // leaf order: unit normal and offset, 4 values per triangle
  std::vector<uint32_t> original_;     // leaf order -> constructor order
  std::vector<uint32_t> position_;     // constructor order -> leaf order
  int depth_ = 0;
};

}  // namespace qmc
