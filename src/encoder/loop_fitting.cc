// Seed 003 step III: Suzuki et al.'s local adjustment of the control mesh so
// that its Loop limit surface fits the original (see loop_fitting.h).
#include "encoder/loop_fitting.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "encoder/loop_remesher.h"

namespace qmc {
namespace {

constexpr int kDefaultIterations = 10;
// Moves below this fraction of the bounding-box diagonal no longer matter:
// quantization steps are far coarser.
constexpr double kStopMove = 1e-6;

Vec3d vertex(const std::vector<double>& positions, uint32_t v) {
  return {positions[3 * size_t(v)], positions[3 * size_t(v) + 1], positions[3 * size_t(v) + 2]};
}

struct Distances {
  double rms = 0, max = 0;
};

// How far the limit positions are from the surface.
Distances distances(const TriangleBvh& surface, const std::vector<double>& limits) {
  const uint32_t n = uint32_t(limits.size() / 3);
  Distances d;
  double sum = 0;
  for (uint32_t v = 0; v < n; ++v) {
    const double d2 = surface.closest_point(vertex(limits, v)).distance_squared;
    sum += d2;
    d.max = std::max(d.max, d2);
  }
  d.rms = n ? std::sqrt(sum / n) : 0;
  d.max = std::sqrt(d.max);
  return d;
}

}  // namespace

std::vector<Triangle3d> loop_mesh_triangles(const LoopMesh& mesh) {
  std::vector<Triangle3d> out(mesh.face_count());
  for (size_t f = 0; f < out.size(); ++f)
    out[f] = {vertex(mesh.positions, mesh.triangles[3 * f]), vertex(mesh.positions, mesh.triangles[3 * f + 1]),
              vertex(mesh.positions, mesh.triangles[3 * f + 2])};
  return out;
}

void loop_limit_positions(const LoopMesh& mesh, const LoopEdges& edges, std::vector<double>* limits) {
  const uint32_t n = mesh.vertex_count();
  limits->resize(3 * size_t(n));
  for (uint32_t v = 0; v < n; ++v) {
    const Vec3d p = vertex(mesh.positions, v);
    Vec3d limit;
    if (edges.boundary_prev[v] != kNoVertex) {
      limit = (p * 4 + vertex(mesh.positions, edges.boundary_prev[v]) + vertex(mesh.positions, edges.boundary_next[v])) *
              (1.0 / 6);
    } else {
      const uint32_t valence = edges.valence[v];
      const double w = 3 / (8 * loop_beta(valence));
      Vec3d sum;
      for (uint32_t k = edges.neighbour_offset[v]; k < edges.neighbour_offset[v + 1]; ++k)
        sum = sum + vertex(mesh.positions, edges.neighbours[k]);
      limit = (p * w + sum) * (1 / (w + valence));
    }
    (*limits)[3 * size_t(v)] = limit.x, (*limits)[3 * size_t(v) + 1] = limit.y, (*limits)[3 * size_t(v) + 2] = limit.z;
  }
}

Status fit_control_mesh(const TriangleBvh& original, LoopMesh* control, int iterations, FitStats* stats) {
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
  for (int pass = 0; pass < iterations; ++pass) {
    limit_normals_all_vertices(*control, edges, &normals);
    double largest = 0;
    st.line_hits = st.fallbacks = 0;
    for (uint32_t v = 0; v < control->vertex_count(); ++v) {
      const Vec3d limit = vertex(limits, v);
      Vec3d target;
      if (onto_surface(original, limit, vertex(normals, v), reach, &target))
        ++st.line_hits;
      else
        ++st.fallbacks;
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
