// Seed 003 step III: Suzuki et al.'s local adjustment of the control mesh so
// that its Loop limit surface fits the original (see loop_fitting.h).
#include "geometry/loop_fitting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "geometry/loop_remesher.h"

namespace qmc {
namespace {

constexpr int kDefaultIterations = 10;
// Moves below this fraction of the bounding-box diagonal no longer matter:
// quantization steps are far coarser.
constexpr double kStopMove = 1e-6;

struct Distances {
  double rms = 0, max = 0;
};

// How far the limit positions are from the surface.
Distances distances(const TriangleBvh& surface, const std::vector<double>& limits) {
  const uint32_t n = uint32_t(limits.size() / 3);
  Distances d;
  double sum = 0;
  for (uint32_t v = 0; v < n; ++v) {
    const double d2 = surface.closest_point(position_of(limits, v)).distance_squared;
    sum += d2;
    d.max = std::max(d.max, d2);
  }
  d.rms = n ? std::sqrt(sum / n) : 0;
  d.max = std::sqrt(d.max);
  return d;
}

// Signed distance from `p` along the unit `normal` to the surface's
// crossing within `reach` (facing the same way); NaN without one.
double distance_along(const TriangleBvh& surface, double reach, const Vec3d& p, const Vec3d& normal) {
  LineHit hit;
  if (!(dot(normal, normal) > 0) || !surface.nearest_line_hit(p, normal, reach, &hit, /*same_facing=*/true))
    return std::numeric_limits<double>::quiet_NaN();
  return dot(hit.point - p, normal);
}

Vec3d unit(const Vec3d& v) {
  const double length = std::sqrt(dot(v, v));
  return length > 0 ? v * (1 / length) : Vec3d{};
}

// The samples of fit_edge_points_in_the_mean, each shared by the faces
// around it: every vertex (along the area-weighted normal of its faces),
// every edge midpoint (along the mean of its faces' normals), every centroid
// (along the face normal). NaN where the line misses.
struct LevelSamples {
  std::vector<double> vertex, edge, face, area;
};

LevelSamples level_samples(const TriangleBvh& surface, double reach, const LoopMesh& level, const LoopEdges& edges) {
  LevelSamples s;
  const size_t faces = level.face_count();
  std::vector<Vec3d> face_normal(faces), vertex_normal(level.vertex_count());
  s.area.resize(faces);
  s.face.resize(faces);
  for (size_t f = 0; f < faces; ++f) {
    const Vec3d a = position_of(level.positions, level.triangles[3 * f]),
                b = position_of(level.positions, level.triangles[3 * f + 1]),
                c = position_of(level.positions, level.triangles[3 * f + 2]);
    const Vec3d n = cross(b - a, c - a);
    s.area[f] = 0.5 * std::sqrt(dot(n, n));
    face_normal[f] = unit(n);
    for (int k = 0; k < 3; ++k) vertex_normal[level.triangles[3 * f + k]] = vertex_normal[level.triangles[3 * f + k]] + n;
    s.face[f] = distance_along(surface, reach, (a + b + c) * (1.0 / 3), face_normal[f]);
  }
  s.vertex.resize(level.vertex_count());
  for (uint32_t v = 0; v < level.vertex_count(); ++v)
    s.vertex[v] = distance_along(surface, reach, position_of(level.positions, v), unit(vertex_normal[v]));
  s.edge.resize(edges.edge_count());
  for (uint32_t e = 0; e < edges.edge_count(); ++e) {
    Vec3d n = face_normal[edges.face0[e]];
    if (!edges.is_boundary(e)) n = n + face_normal[edges.face1[e]];
    const Vec3d mid = (position_of(level.positions, edges.a[e]) + position_of(level.positions, edges.b[e])) * 0.5;
    s.edge[e] = distance_along(surface, reach, mid, unit(n));
  }
  return s;
}

// Per vertex, the weighted sum and the weight of the sample distances
// around it: per face a rule exact for cubics (so for a corner's hat
// function times a quadratic sag), corners 3/60, edge midpoints 8/60, the
// centroid 27/60 of the area, each times the vertex's hat function there
// (1 at its corner, 1/2 at the midpoints of its edges, 1/3 at the centroid).
struct MeanDistance {
  std::vector<double> sum, weight;
};

// A chord of length h across a surface of radius r sags by h^2 / (8 r): a
// quarter of h would take r = h / 2. A sample farther than that from the
// surface met another part of it (on stanford-bunny, K = 2, such samples
// quadrupled the finest step: 99.9 % of the offsets set it, 12.10).
constexpr double kSagBound = 0.25;

// A sample farther than `bound` from the surface is left out.
void add_sample(double area_weight, double distance, double bound, uint32_t v, MeanDistance* m) {
  if (!(std::fabs(distance) <= bound)) return;  // also NaN: no crossing
  m->sum[v] += area_weight * distance;
  m->weight[v] += area_weight;
}

double longest_edge(const LoopMesh& level, size_t f) {
  double longest = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3d d = position_of(level.positions, level.triangles[3 * f + k]) -
                    position_of(level.positions, level.triangles[3 * f + (k + 1) % 3]);
    longest = std::max(longest, dot(d, d));
  }
  return std::sqrt(longest);
}

MeanDistance mean_distances(const LoopMesh& level, const LoopEdges& edges, const LevelSamples& s) {
  MeanDistance m;
  m.sum.assign(level.vertex_count(), 0.0);
  m.weight.assign(level.vertex_count(), 0.0);
  for (size_t f = 0; f < level.face_count(); ++f) {
    const double w = s.area[f] / 60, bound = kSagBound * longest_edge(level, f);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = level.triangles[3 * f + k];
      add_sample(3 * w, s.vertex[v], bound, v, &m);
      add_sample(4 * w, s.edge[edges.face_edge[3 * f + k]], bound, v, &m);            // edge (v, next): hat 1/2
      add_sample(4 * w, s.edge[edges.face_edge[3 * f + (k + 2) % 3]], bound, v, &m);  // edge (previous, v)
      add_sample(9 * w, s.face[f], bound, v, &m);                                      // centroid: hat 1/3
    }
  }
  return m;
}

}  // namespace

void fit_edge_points_in_the_mean(const TriangleBvh& surface, double reach, uint32_t first_edge_point,
                                 const std::vector<double>& directions, int passes, LoopMesh* level) {
  LoopEdges edges;
  if (!number_loop_edges(*level, &edges).ok()) return;
  const uint32_t edge_points = uint32_t(directions.size() / 3);
  for (int pass = 0; pass < passes; ++pass) {
    const MeanDistance m = mean_distances(*level, edges, level_samples(surface, reach, *level, edges));
    for (uint32_t e = 0; e < edge_points; ++e) {
      const uint32_t v = first_edge_point + e;
      const Vec3d d = position_of(directions, e);
      const double length = std::sqrt(dot(d, d));
      if (!(m.weight[v] > 0) || !(length > 0)) continue;
      const Vec3d moved = position_of(level->positions, v) + d * (m.sum[v] / m.weight[v] / length);
      level->positions[3 * size_t(v)] = moved.x;
      level->positions[3 * size_t(v) + 1] = moved.y;
      level->positions[3 * size_t(v) + 2] = moved.z;
    }
  }
}

std::vector<Triangle3d> loop_mesh_triangles(const LoopMesh& mesh) {
  std::vector<Triangle3d> out(mesh.face_count());
  for (size_t f = 0; f < out.size(); ++f)
    out[f] = {position_of(mesh.positions, mesh.triangles[3 * f]),
              position_of(mesh.positions, mesh.triangles[3 * f + 1]),
              position_of(mesh.positions, mesh.triangles[3 * f + 2])};
  return out;
}

void loop_limit_positions(const LoopMesh& mesh, const LoopEdges& edges, std::vector<double>* limits) {
  const uint32_t n = mesh.vertex_count();
  limits->resize(3 * size_t(n));
  for (uint32_t v = 0; v < n; ++v) {
    const Vec3d p = position_of(mesh.positions, v);
    Vec3d limit;
    if (edges.boundary_prev[v] != kNoVertex) {
      limit = (p * 4 + position_of(mesh.positions, edges.boundary_prev[v]) +
               position_of(mesh.positions, edges.boundary_next[v])) *
              (1.0 / 6);
    } else {
      const uint32_t valence = edges.valence[v];
      const double w = 3 / (8 * loop_beta(valence));
      Vec3d sum;
      for (uint32_t k = edges.neighbour_offset[v]; k < edges.neighbour_offset[v + 1]; ++k)
        sum = sum + position_of(mesh.positions, edges.neighbours[k]);
      limit = (p * w + sum) * (1 / (w + valence));
    }
    (*limits)[3 * size_t(v)] = limit.x, (*limits)[3 * size_t(v) + 1] = limit.y, (*limits)[3 * size_t(v) + 2] = limit.z;
  }
}

Status fit_control_mesh(const TriangleBvh& original, const SurfaceRim* rim, LoopMesh* control, int iterations,
                        FitStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  if (original.size() == 0) return Status(ErrorCode::kInvalidArgument, "fitting to an empty surface");
  LoopEdges edges;
  if (Status s = build_loop_edges(*control, &edges); !s.ok()) return s;
  if (iterations < 1) iterations = kDefaultIterations;
  const double stop = kStopMove * original.bbox_diagonal();
  FitStats st;
  std::vector<double> limits, normals;
  loop_limit_positions(*control, edges, &limits);
  const Distances before = distances(original, limits);
  st.initial_rms = before.rms, st.initial_max = before.max;
  const double reach = kNormalReach * original.bbox_diagonal();
  const RimAnchors anchors = rim ? rim_anchors(*rim, *control, edges) : RimAnchors{};
  for (int pass = 0; pass < iterations; ++pass) {
    limit_normals_all_vertices(*control, edges, &normals);
    double largest = 0;
    st.line_hits = st.fallbacks = st.rim_targets = 0;
    for (uint32_t v = 0; v < control->vertex_count(); ++v) {
      const Vec3d limit = position_of(limits, v);
      Vec3d target;
      if (!anchors.loop.empty() && anchors.loop[v] != kNoVertex) {
        target = rim_target(*rim, anchors, v, limit);
        ++st.rim_targets;
      } else if (onto_surface(original, limit, position_of(normals, v), reach, &target)) {
        ++st.line_hits;
      } else {
        ++st.fallbacks;
      }
      const Vec3d move = target - limit;
      largest = std::max(largest, dot(move, move));
      control->positions[3 * size_t(v)] += move.x;
      control->positions[3 * size_t(v) + 1] += move.y;
      control->positions[3 * size_t(v) + 2] += move.z;
    }
    ++st.iterations;
    st.last_max_move = std::sqrt(largest);
    loop_limit_positions(*control, edges, &limits);
    if (st.last_max_move < stop) break;
  }
  const Distances after = distances(original, limits);
  st.final_rms = after.rms, st.final_max = after.max;
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  return Status::Ok();
}

}  // namespace qmc
