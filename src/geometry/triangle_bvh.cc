// Triangle BVH: closest point and nearest line hit (seed 003 §3.1.2 and step
// III; the definitions are in triangle_bvh.h).
#include "geometry/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numeric>

namespace qmc {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Barycentric slack of a line hit: a line through a shared edge must hit one
// of the two triangles even when rounding puts it a hair outside both.
constexpr double kBarycentricSlack = 1e-9;
// Both searches keep a fixed stack: the tree is balanced, so its depth is at
// most log2(triangles) + 1, and each step pushes at most two nodes.
constexpr int kStackSize = 96;

double box_distance_squared(const double lo[3], const double hi[3], const Vec3d& p) {
  double sum = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double c = component(p, axis);
    const double d = c < lo[axis] ? lo[axis] - c : c > hi[axis] ? c - hi[axis] : 0.0;
    sum += d * d;
  }
  return sum;
}

// The padding of a box for line_box_entry: a relative 1e-9, so that
// rounding in the slab test never drops a triangle that touches the box's
// face. Worked out once per node, when the tree is built.
double line_pad(const double lo[3], const double hi[3]) {
  return 1e-9 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) + 1e-300;
}

// The part of the line parameter range [-limit, limit] inside the box padded
// by `pad`, as the smallest |t| in it. False when the line misses the box
// within the range.
bool line_box_entry(const double lo[3], const double hi[3], double pad, const Vec3d& origin, const Vec3d& direction,
                    const double inverse[3], double limit, double* nearest_abs_t) {
  double t_min = -limit, t_max = limit;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = component(origin, axis), low = lo[axis] - pad, high = hi[axis] + pad;
    if (component(direction, axis) == 0) {
      if (o < low || o > high) return false;
      continue;
    }
    double t1 = (low - o) * inverse[axis], t2 = (high - o) * inverse[axis];
    if (t1 > t2) std::swap(t1, t2);
    t_min = std::max(t_min, t1);
    t_max = std::min(t_max, t2);
    if (t_min > t_max) return false;
  }
  *nearest_abs_t = t_min > 0 ? t_min : t_max < 0 ? -t_max : 0.0;
  return true;
}

// A box grown point by point or box by box.
struct Box {
  double lo[3] = {kInfinity, kInfinity, kInfinity}, hi[3] = {-kInfinity, -kInfinity, -kInfinity};
  void add(const Vec3d& p) {
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::min(lo[axis], component(p, axis));
      hi[axis] = std::max(hi[axis], component(p, axis));
    }
  }
  void add(const Box& b) {
    for (int axis = 0; axis < 3; ++axis) lo[axis] = std::min(lo[axis], b.lo[axis]), hi[axis] = std::max(hi[axis], b.hi[axis]);
  }
  int longest_axis() const {
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    return axis;
  }
  double half_area() const {
    const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return x < 0 ? 0 : x * y + y * z + z * x;
  }
};

constexpr uint32_t kLeafTriangles = 4;
constexpr int kSplitBins = 16;

// The surface area heuristic (MacDonald and Booth 1990; binned, Wald 2007)
// gives boxes of less overlap than a median split, so that a point or line
// near the surface meets fewer of them: the progressive encoder on
// stanford-bunny at K = 4, 14.7 -> 13.1 G instructions (line searches 4.9 ->
// 3.8 G, closest points 2.5 -> 2.2 G, building 0.6 -> 0.8 G). Binning the
// longest axis alone, not all three, halved the cost of building for the same
// searches. Below this depth the median split takes over, so that however
// the triangles cluster the tree's depth, and with it the searches' fixed
// stack, stays under 48 + log2(triangles) + 1.
constexpr int kSurfaceAreaDepth = 48;

// Splits [begin, end) of `order` at the cheapest of the kSplitBins - 1
// planes between the centroids' bins along the longest axis of their box;
// the first index of the second half, or 0 where no plane leaves triangles
// on both sides.
uint32_t surface_area_split(const std::vector<Vec3d>& centroids, const std::vector<Box>& boxes, const Box& centroid_box,
                            uint32_t begin, uint32_t end, std::vector<uint32_t>* order) {
  const int axis = centroid_box.longest_axis();
  const double lo = centroid_box.lo[axis], extent = centroid_box.hi[axis] - lo;
  if (!(extent > 0)) return 0;
  const double scale = kSplitBins / extent;
  auto bin_of = [&](uint32_t t) { return std::min(kSplitBins - 1, int((component(centroids[t], axis) - lo) * scale)); };
  Box bin_box[kSplitBins];
  uint32_t bin_count[kSplitBins] = {};
  for (uint32_t k = begin; k < end; ++k) {
    const uint32_t t = (*order)[k];
    bin_box[bin_of(t)].add(boxes[t]);
    ++bin_count[bin_of(t)];
  }
  // Plane p sends bins < p to the first half: cost = area x count per side.
  double right_area[kSplitBins];
  uint32_t right_count[kSplitBins];
  Box side;
  uint32_t count = 0;
  for (int b = kSplitBins - 1; b > 0; --b) {
    side.add(bin_box[b]);
    count += bin_count[b];
    right_area[b] = side.half_area(), right_count[b] = count;
  }
  side = Box{};
  count = 0;
  double best_cost = kInfinity;
  int best_plane = 0;
  for (int plane = 1; plane < kSplitBins; ++plane) {
    side.add(bin_box[plane - 1]);
    count += bin_count[plane - 1];
    if (count == 0 || right_count[plane] == 0) continue;
    const double cost = side.half_area() * count + right_area[plane] * right_count[plane];
    if (cost < best_cost) best_cost = cost, best_plane = plane;
  }
  if (best_plane == 0) return 0;
  const auto middle = std::partition(order->begin() + begin, order->begin() + end,
                                     [&](uint32_t t) { return bin_of(t) < best_plane; });
  return uint32_t(middle - order->begin());
}

// Splits [begin, end) of `order` at the median centroid on the longest axis
// of the centroids' box; returns the first index of the second half.
uint32_t median_split(const std::vector<Vec3d>& centroids, const Box& centroid_box, uint32_t begin, uint32_t end,
                      std::vector<uint32_t>* order) {
  const int axis = centroid_box.longest_axis();
  const uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order->begin() + begin, order->begin() + mid, order->begin() + end, [&](uint32_t x, uint32_t y) {
    const double cx = component(centroids[x], axis), cy = component(centroids[y], axis);
    return cx < cy || (cx == cy && x < y);
  });
  return mid;
}

}  // namespace

double point_triangle_distance_squared(const Vec3d& p, const Triangle3d& t, Vec3d* closest) {
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

TriangleBvh::TriangleBvh(const std::vector<Triangle3d>& triangles) {
  if (triangles.empty()) return;
  build(triangles);
  triangles_.resize(triangles.size());
  position_.resize(triangles.size());
  planes_.assign(4 * triangles.size(), 0.0);
  for (size_t i = 0; i < original_.size(); ++i) {
    const Triangle3d& t = triangles_[i] = triangles[original_[i]];
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

void TriangleBvh::build(const std::vector<Triangle3d>& triangles) {
  original_.resize(triangles.size());
  std::iota(original_.begin(), original_.end(), 0u);
  std::vector<Vec3d> centroids(triangles.size());
  std::vector<Box> boxes(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    centroids[i] = (triangles[i].a + triangles[i].b + triangles[i].c) * (1.0 / 3.0);
    for (const Vec3d* v : {&triangles[i].a, &triangles[i].b, &triangles[i].c}) boxes[i].add(*v);
  }
  nodes_.reserve(2 * (triangles.size() / 2 + 1));
  // Depth-first with an explicit stack: the first child is pushed last, so it
  // is built right after its parent and lands at the parent's index + 1.
  struct Task {
    uint32_t begin, end, parent;  // parent: the inner node whose second child this is, or none
    int depth;
  };
  std::vector<Task> tasks = {{0, uint32_t(triangles.size()), UINT32_MAX, 0}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    Box box, centroid_box;
    for (uint32_t k = task.begin; k < task.end; ++k) {
      box.add(boxes[original_[k]]);
      centroid_box.add(centroids[original_[k]]);
    }
    Node node;
    std::copy_n(box.lo, 3, node.lo);
    std::copy_n(box.hi, 3, node.hi);
    node.pad = line_pad(node.lo, node.hi);
    const uint32_t index = uint32_t(nodes_.size());
    depth_ = std::max(depth_, task.depth + 1);
    if (task.parent != UINT32_MAX) nodes_[task.parent].first = index;
    node.first = task.begin;
    node.count = task.end - task.begin;
    nodes_.push_back(node);
    if (task.end - task.begin <= kLeafTriangles) continue;
    uint32_t mid = task.depth < kSurfaceAreaDepth
                       ? surface_area_split(centroids, boxes, centroid_box, task.begin, task.end, &original_)
                       : 0;
    if (mid == 0) mid = median_split(centroids, centroid_box, task.begin, task.end, &original_);
    nodes_[index].count = 0;
    tasks.push_back({mid, task.end, index, task.depth + 1});
    tasks.push_back({task.begin, mid, UINT32_MAX, task.depth + 1});
  }
}

std::vector<std::array<double, 3>> lattice_points(uint32_t s) {
  std::vector<std::array<double, 3>> out;
  for (uint32_t i = 0; i <= s; ++i)
    for (uint32_t j = 0; i + j <= s; ++j) out.push_back({double(s - i - j) / s, double(i) / s, double(j) / s});
  return out;
}

double TriangleBvh::bbox_diagonal() const {
  if (nodes_.empty()) return 0;
  double sum = 0;
  for (int axis = 0; axis < 3; ++axis) sum += (nodes_[0].hi[axis] - nodes_[0].lo[axis]) * (nodes_[0].hi[axis] - nodes_[0].lo[axis]);
  return std::sqrt(sum);
}

double TriangleBvh::distance_squared(const Vec3d& p, uint32_t hint, uint32_t* nearest, double enough) const {
  double best = kInfinity;
  uint32_t best_index = kNoTriangle;
  if (hint < triangles_.size()) {
    best_index = position_[hint];
    best = point_triangle_distance_squared(p, triangles_[best_index]);
  }
  if (!nodes_.empty() && best > enough) {
    struct Entry {
      uint32_t node;
      double distance_squared;
    };
    Entry stack[kStackSize];
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
  if (nearest) *nearest = best_index == kNoTriangle ? kNoTriangle : original_[best_index];
  return best;
}

SurfacePoint TriangleBvh::closest_point(const Vec3d& p, uint32_t hint) const {
  SurfacePoint r{kInfinity, p, kNoTriangle};
  distance_squared(p, hint, &r.triangle);
  if (r.triangle != kNoTriangle) r.distance_squared = point_triangle_distance_squared(p, triangle(r.triangle), &r.point);
  return r;
}

bool TriangleBvh::nearest_line_hit(const Vec3d& origin, const Vec3d& direction, double max_distance, LineHit* hit,
                                   bool same_facing) const {
  const double length = std::sqrt(dot(direction, direction));
  if (nodes_.empty() || !(length > 0) || !(max_distance >= 0)) return false;
  const double limit = max_distance / length;  // on |t|
  const Vec3d unit = direction * (1 / length);
  double inverse[3];
  for (int axis = 0; axis < 3; ++axis) inverse[axis] = 1 / component(direction, axis);
  double best_abs = kInfinity, best_t = 0;
  uint32_t best_index = kNoTriangle;
  struct Entry {
    uint32_t node;
    double nearest_abs_t;
  };
  Entry stack[kStackSize];
  int top = 0;
  double root_t;
  if (line_box_entry(nodes_[0].lo, nodes_[0].hi, nodes_[0].pad, origin, direction, inverse, limit, &root_t))
    stack[top++] = {0, root_t};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.nearest_abs_t > best_abs) continue;
    const Node& n = nodes_[e.node];
    if (n.count > 0) {
      for (uint32_t k = n.first; k < n.first + n.count; ++k) {
        // Edge-on and zero-area triangles (whose stored normal is 0) cannot
        // give a stable crossing.
        const double* plane = &planes_[4 * size_t(k)];
        const double facing = plane[0] * unit.x + plane[1] * unit.y + plane[2] * unit.z;
        if (std::fabs(facing) < 1e-12 || (same_facing && facing < 0)) continue;
        const Triangle3d& tri = triangles_[k];
        const Vec3d e1 = tri.b - tri.a, e2 = tri.c - tri.a;
        const Vec3d p = cross(direction, e2);
        const double inverse_det = 1 / dot(e1, p);
        const Vec3d s = origin - tri.a;
        const double u = dot(s, p) * inverse_det;
        if (u < -kBarycentricSlack || u > 1 + kBarycentricSlack) continue;
        const Vec3d q = cross(s, e1);
        const double v = dot(direction, q) * inverse_det;
        if (v < -kBarycentricSlack || u + v > 1 + kBarycentricSlack) continue;
        const double t = dot(e2, q) * inverse_det;
        if (std::fabs(t) > limit || std::fabs(t) >= best_abs) continue;
        best_abs = std::fabs(t), best_t = t, best_index = k;
      }
      continue;
    }
    uint32_t near = e.node + 1, far = n.first;
    double near_t, far_t;
    const bool near_in = line_box_entry(nodes_[near].lo, nodes_[near].hi, nodes_[near].pad, origin, direction, inverse, limit, &near_t);
    const bool far_in = line_box_entry(nodes_[far].lo, nodes_[far].hi, nodes_[far].pad, origin, direction, inverse, limit, &far_t);
    if (near_in && far_in && far_t < near_t) std::swap(near, far), std::swap(near_t, far_t);
    if (far_in && far_t <= best_abs) stack[top++] = {far, far_t};
    if (near_in && near_t <= best_abs) stack[top++] = {near, near_t};
  }
  if (best_index == kNoTriangle) return false;
  hit->t = best_t;
  hit->distance = best_t * length;
  hit->point = origin + direction * best_t;
  hit->triangle = original_[best_index];
  return true;
}

}  // namespace qmc
