// Two-sided local fitting of a level to the input (deviation_fit.h).
#include "geometry/deviation_fit.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/loop_fitting.h"

namespace qmc {
namespace {

// The fit aims at this share of the deviation asked for: what a round leaves
// near the bound, rounding the moves to the correction step and the points
// between samples then push over it (stanford-bunny, camelhead: the
// sampled maximum came out 1.3 - 1.5 times the aim).
constexpr double kAimedShare = 0.7;
// Weights of a point's pull: 1 where it is farther than the aim,
// kNearWeight where it is near already (it keeps the fitted triangles on
// the input); the membrane term per edge. Each round applies the whole of
// its solution. Measured on stanford-bunny at K = 2 (8 bits, step scale
// 5.66, max deviation 7.65e-4 of the diagonal): with 0.8 of each solution
// applied the Hausdorff distance after ten rounds was 1.03e-3 of the
// diagonal, with all of it 9.58e-4; a near weight of 0.3 instead of 0.15
// gave the same distance for 176 more bytes.
constexpr double kNearWeight = 0.15;
constexpr double kMembraneWeight = 0.1;
// Rings of neighbours around the far points' vertices that may move too.
constexpr int kFreeRings = 1;
// A tiny diagonal term, so that a vertex no pull reaches stays solvable.
constexpr double kAnchorWeight = 1e-6;

// Both surfaces are sampled as densely as the level's edges: a triangle up
// to `spacing` long, twice the median of the level's longest edges, at its
// corners, edge midpoints and centroid; a longer one on a grid as fine, of n
// steps per side, n at most kMostSteps (the input's large triangles at
// stanford-bunny's holes, a level triangle stretched across one, a cube's
// faces under a level of many small triangles would otherwise go unseen
// between samples).
constexpr uint32_t kMostSteps = 32;

double longest_edge(const Triangle3d& t) {
  return std::sqrt(std::max({dot(t.b - t.a, t.b - t.a), dot(t.c - t.b, t.c - t.b), dot(t.a - t.c, t.a - t.c)}));
}

// Twice the median of the triangles' longest edges (0 for none).
double spacing_of(const std::vector<Triangle3d>& triangles) {
  std::vector<double> longest;
  longest.reserve(triangles.size());
  for (const Triangle3d& t : triangles) longest.push_back(longest_edge(t));
  if (longest.empty()) return 0;
  std::nth_element(longest.begin(), longest.begin() + std::ptrdiff_t(longest.size() / 2), longest.end());
  return 2 * longest[longest.size() / 2];
}

// Per triangle, the grid's n for `spacing` (1: corners, midpoints and centroid).
std::vector<uint32_t> sample_steps(const std::vector<Triangle3d>& triangles, double spacing) {
  std::vector<uint32_t> steps(triangles.size(), 1);
  if (!(spacing > 0)) return steps;
  for (size_t f = 0; f < triangles.size(); ++f)
    steps[f] = uint32_t(std::clamp(std::ceil(longest_edge(triangles[f]) / spacing), 1.0, double(kMostSteps)));
  return steps;
}

using Weights = std::array<double, 3>;

// The barycentric weights of the grid of n steps per side (the lattice of
// order 2 n, its points a half step apart: n = 1 gives the edge midpoints)
// and of the centroid; the corners (a weight of 1) only `with_corners`.
std::vector<Weights> grid_weights(uint32_t n, bool with_corners) {
  std::vector<Weights> out;
  for (const Weights& w : lattice_points(2 * n))
    if (with_corners || (w[0] != 1 && w[1] != 1 && w[2] != 1)) out.push_back(w);
  out.push_back({1. / 3, 1. / 3, 1. / 3});
  return out;
}

// grid_weights(n, true) for n = 1 .. kMostSteps, made once.
const std::vector<Weights>& level_weights(uint32_t n) {
  static const std::vector<std::vector<Weights>> all = [] {
    std::vector<std::vector<Weights>> w(kMostSteps + 1);
    for (uint32_t k = 1; k <= kMostSteps; ++k) w[k] = grid_weights(k, true);
    return w;
  }();
  return all[n];
}

// Per triangle of `level`, its grid's n at the level's own spacing.
std::vector<uint32_t> level_steps(const LoopMesh& level) {
  const std::vector<Triangle3d> triangles = loop_mesh_triangles(level);
  return sample_steps(triangles, spacing_of(triangles));
}

// sum_k w[k] x P[v[k]] should move to `target`, with a weight.
struct Pull {
  uint32_t v[3];
  double w[3];
  Vec3d target;
  double weight;
};

Vec3d level_point(const LoopMesh& level, uint32_t f, const Weights& w) {
  const uint32_t* t = &level.triangles[3 * size_t(f)];
  return position_of(level.positions, t[0]) * w[0] + position_of(level.positions, t[1]) * w[1] +
         position_of(level.positions, t[2]) * w[2];
}

// Barycentric weights of x, a point of the triangle (a, b, c).
void barycentric(const Triangle3d& t, const Vec3d& x, double w[3]) {
  const Vec3d u = t.b - t.a, v = t.c - t.a, d = x - t.a;
  const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), du = dot(d, u), dv = dot(d, v);
  const double det = uu * vv - uv * uv;
  if (!(det > 0)) {
    w[0] = 1, w[1] = w[2] = 0;
    return;
  }
  w[1] = std::clamp((vv * du - uv * dv) / det, 0.0, 1.0);
  w[2] = std::clamp((uu * dv - uv * du) / det, 0.0, 1.0);
  w[0] = std::max(0.0, 1 - w[1] - w[2]);
  const double sum = w[0] + w[1] + w[2];
  for (int k = 0; k < 3; ++k) w[k] /= sum;
}

bool inside(const std::vector<char>& region, const uint32_t* t) { return region[t[0]] && region[t[1]] && region[t[2]]; }

// The rounds of the fit over one level. Each round marks the vertices of
// far points of either side in `core` (kept from round to round), frees them
// and kFreeRings around them, pulls every sample that lands on a free
// triangle and every level point of one, and moves the free vertices by the
// least-squares solution. Between rounds only what a move
// can change is measured again: the level points of triangles with a moved
// vertex, and the samples that were far or whose nearest triangle moved (a
// sample near an unmoved triangle stays near).
class DeviationFit {
 public:
  // `edges`: the level's (number_loop_edges), for its vertices' neighbours.
  DeviationFit(const TriangleBvh& surface, const std::vector<Vec3d>& samples, const LoopEdges& edges,
               LoopMesh* level, double aim)
      : surface_(surface), samples_(samples), edges_(edges), level_(*level), aim2_(aim * aim),
        steps_(level_steps(*level)), core_(level->vertex_count(), 0), moved_(level->vertex_count(), 1),
        far_face_(level->face_count(), 0), closest_(samples.size()) {}

  // *far: whether a point was far; if none was, nothing moved.
  Status round(DeviationFitStats* stats, bool* far) {
    const std::vector<Triangle3d> triangles = loop_mesh_triangles(level_);
    const TriangleBvh near(triangles);
    measure(near, stats);
    *far = stats->far_input_points + stats->far_level_points > 0;
    if (!*far) return Status::Ok();
    const std::vector<char> region = grown(core_);
    std::vector<Pull> pulls;
    collect_input_pulls(triangles, region, &pulls);
    collect_level_pulls(region, &pulls);
    moved_ = region;
    return solve(region, pulls, stats);
  }

 private:
  bool touches_moved(uint32_t f) const {
    const uint32_t* t = &level_.triangles[3 * size_t(f)];
    return moved_[t[0]] || moved_[t[1]] || moved_[t[2]];
  }
  bool far_sample(size_t i) const { return closest_[i].distance_squared > aim2_; }

  void measure(const TriangleBvh& near, DeviationFitStats* stats) {
    stats->far_input_points = stats->far_level_points = 0;
    for (size_t i = 0; i < samples_.size(); ++i) {
      if (first_ || far_sample(i) || touches_moved(closest_[i].triangle)) closest_[i] = near.closest_point(samples_[i]);
      if (far_sample(i)) ++stats->far_input_points, mark(closest_[i].triangle);
    }
    for (uint32_t f = 0; f < level_.face_count(); ++f) {
      if (first_ || touches_moved(f)) {
        far_face_[f] = 0;
        for (const Weights& w : level_weights(steps_[f]))
          far_face_[f] += surface_.distance_squared(level_point(level_, f, w)) > aim2_;
      }
      if (far_face_[f]) stats->far_level_points += far_face_[f], mark(f);
    }
    first_ = false;
  }

  // The neighbours of vertex v.
  const uint32_t* ring_begin(uint32_t v) const { return edges_.neighbours.data() + edges_.neighbour_offset[v]; }
  const uint32_t* ring_end(uint32_t v) const { return edges_.neighbours.data() + edges_.neighbour_offset[v + 1]; }

  void mark(uint32_t f) {
    for (int k = 0; k < 3; ++k) core_[level_.triangles[3 * size_t(f) + k]] = 1;
  }

  std::vector<char> grown(std::vector<char> region) const {
    for (int r = 0; r < kFreeRings; ++r) {
      std::vector<char> next = region;
      for (uint32_t v = 0; v < region.size(); ++v)
        if (region[v])
          for (const uint32_t* u = ring_begin(v); u != ring_end(v); ++u) next[*u] = 1;
      region.swap(next);
    }
    return region;
  }

  void collect_input_pulls(const std::vector<Triangle3d>& triangles, const std::vector<char>& region,
                           std::vector<Pull>* pulls) const {
    for (size_t i = 0; i < samples_.size(); ++i) {
      const uint32_t* t = &level_.triangles[3 * size_t(closest_[i].triangle)];
      if (!inside(region, t)) continue;
      Pull p{{t[0], t[1], t[2]}, {0, 0, 0}, samples_[i], far_sample(i) ? 1.0 : kNearWeight};
      barycentric(triangles[closest_[i].triangle], closest_[i].point, p.w);
      pulls->push_back(p);
    }
  }

  void collect_level_pulls(const std::vector<char>& region, std::vector<Pull>* pulls) const {
    for (uint32_t f = 0; f < level_.face_count(); ++f) {
      const uint32_t* t = &level_.triangles[3 * size_t(f)];
      if (!inside(region, t)) continue;
      for (const Weights& w : level_weights(steps_[f])) {
        const SurfacePoint s = surface_.closest_point(level_point(level_, f, w));
        pulls->push_back({{t[0], t[1], t[2]}, {w[0], w[1], w[2]}, s.point, s.distance_squared > aim2_ ? 1.0 : kNearWeight});
      }
    }
  }

  // The normal equations of sum weight |sum w_k (P_k + d_k) - target|^2 +
  // kMembraneWeight sum over edges |d_u - d_v|^2 (d = 0 outside the region).
  Status solve(const std::vector<char>& region, const std::vector<Pull>& pulls, DeviationFitStats* stats) {
    std::vector<int> index(region.size(), -1);
    std::vector<uint32_t> free;
    for (uint32_t v = 0; v < region.size(); ++v)
      if (region[v]) index[v] = int(free.size()), free.push_back(v);
    const int n = int(free.size());
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
    for (const Pull& p : pulls) {
      const Vec3d now = position_of(level_.positions, p.v[0]) * p.w[0] + position_of(level_.positions, p.v[1]) * p.w[1] +
                        position_of(level_.positions, p.v[2]) * p.w[2];
      const Vec3d r = p.target - now;
      for (int a = 0; a < 3; ++a) {
        const int i = index[p.v[a]];
        for (int b = 0; b < 3; ++b) entries.emplace_back(i, index[p.v[b]], p.weight * p.w[a] * p.w[b]);
        rhs(i, 0) += p.weight * p.w[a] * r.x, rhs(i, 1) += p.weight * p.w[a] * r.y, rhs(i, 2) += p.weight * p.w[a] * r.z;
      }
    }
    for (int i = 0; i < n; ++i) {
      for (const uint32_t* u = ring_begin(free[size_t(i)]); u != ring_end(free[size_t(i)]); ++u) {
        entries.emplace_back(i, i, kMembraneWeight);
        if (index[*u] >= 0) entries.emplace_back(i, index[*u], -kMembraneWeight);
      }
      entries.emplace_back(i, i, kAnchorWeight);
    }
    Eigen::SparseMatrix<double> system(n, n);
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
    if (solver.info() != Eigen::Success)
      return Status(ErrorCode::kInvalidArgument, "internal: the deviation fit's system has no factorisation");
    const Eigen::MatrixXd moves = solver.solve(rhs);
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) level_.positions[3 * size_t(free[size_t(i)]) + size_t(a)] += moves(i, a);
    stats->free_vertices = uint32_t(n);
    return Status::Ok();
  }

  const TriangleBvh& surface_;
  const std::vector<Vec3d>& samples_;
  const LoopEdges& edges_;
  LoopMesh& level_;
  const double aim2_;
  const std::vector<uint32_t> steps_;  // per triangle, its sampling grid (of the level given)
  std::vector<char> core_, moved_;
  std::vector<uint32_t> far_face_;  // far points of each triangle, as of its last measure
  std::vector<SurfacePoint> closest_;
  bool first_ = true;
};

}  // namespace

double sample_spacing(const LoopMesh& level) { return spacing_of(loop_mesh_triangles(level)); }

std::vector<Vec3d> deviation_samples(const LoopMesh& surface, double spacing) {
  std::vector<Vec3d> out;
  std::vector<char> used(surface.vertex_count(), 0);
  for (uint32_t v : surface.triangles) used[v] = 1;
  for (uint32_t v = 0; v < surface.vertex_count(); ++v)
    if (used[v]) out.push_back(position_of(surface.positions, v));
  const std::vector<Triangle3d> triangles = loop_mesh_triangles(surface);
  const std::vector<uint32_t> steps = sample_steps(triangles, spacing);
  for (size_t f = 0; f < triangles.size(); ++f) {
    const Triangle3d& t = triangles[f];
    for (const Weights& w : grid_weights(steps[f], false)) out.push_back(t.a * w[0] + t.b * w[1] + t.c * w[2]);
  }
  return out;
}

double two_sided_deviation(const TriangleBvh& surface, const std::vector<Vec3d>& samples, const LoopMesh& level) {
  const std::vector<Triangle3d> triangles = loop_mesh_triangles(level);
  const TriangleBvh near(triangles);
  double most = 0;
  for (const Vec3d& x : samples) most = std::max(most, near.distance_squared(x));
  const std::vector<uint32_t> steps = sample_steps(triangles, spacing_of(triangles));
  for (uint32_t f = 0; f < level.face_count(); ++f)
    for (const Weights& w : level_weights(steps[f]))
      most = std::max(most, surface.distance_squared(level_point(level, f, w)));
  return std::sqrt(most);
}

Status fit_to_max_deviation(const TriangleBvh& surface, const std::vector<Vec3d>& samples, const LoopMesh& level,
                            const DeviationFitOptions& options, std::vector<double>* positions,
                            DeviationFitStats* stats) {
  *stats = DeviationFitStats{};
  if (!(options.max_deviation > 0) || options.rounds < 1)
    return Status(ErrorCode::kInvalidArgument, "the deviation fit needs a positive deviation and rounds");
  LoopEdges edges;
  if (Status s = number_loop_edges(level, &edges); !s.ok())
    return Status(ErrorCode::kInvalidArgument, "internal: the level's edges: " + s.message());
  LoopMesh fitted = level;
  DeviationFit fit(surface, samples, edges, &fitted, kAimedShare * options.max_deviation);
  for (int r = 0; r < options.rounds; ++r) {
    bool far = false;
    if (Status s = fit.round(stats, &far); !s.ok()) return s;
    if (!far) break;
    stats->rounds = r + 1;
  }
  *positions = std::move(fitted.positions);
  return Status::Ok();
}

}  // namespace qmc
