// Seed 003 steps IV-VI: subdivide the adjusted mesh, displace every vertex of
// the subdivided mesh along its Loop limit normal onto the original surface
// (§3.1.2, after Lee, Moreton and Hoppe, "Displaced Subdivision Surfaces",
// SIGGRAPH 2000), which gives the semi-regular remesh C_K, then undo the
// subdivision level by level with the inverse Loop of §3.2: only the vertex
// points carry information, and "vertex-point mask applied to C_{j-1} =
// vertex points of C_j" is a square system (eqs. 1-4) solved by
// Gauss-Seidel.
#pragma once

#include <cstdint>
#include <vector>

#include "decoder/loop_subdivision.h"
#include "geometry/triangle_bvh.h"
#include "qmc/status.h"

namespace qmc {

// The unit Loop limit normal of every vertex of `m` (3 per vertex), outward
// for counter-clockwise faces. Interior vertex with one-ring p_0..p_{n-1}
// counter-clockwise: u = sum cos(2 pi j / n) p_j, v = sum sin(2 pi j / n) p_j,
// normal u x v (seed 003 §3.1.2). Boundary vertex with neighbours p_0..p_k
// counter-clockwise (p_0 and p_k on the boundary), after Hoppe et al.,
// "Piecewise Smooth Surface Reconstruction" (SIGGRAPH 1994): along = p_0 -
// p_k; across = p_0 + p_1 - 2 v (k = 1), p_1 - v (k = 2), otherwise
// -(sin t (p_0 + p_k) + (2 cos t - 2) sum_{i=1}^{k-1} sin(i t) p_i) with
// t = pi / k, all pointing into the surface; normal along x across. Where
// these vanish (a degenerate ring) the normalized sum of the incident face
// normals is used instead, and where that vanishes too, 0.
void limit_normals_all_vertices(const LoopMesh& m, const LoopEdges& e, std::vector<double>* normals);

// How far lines along limit normals are followed, times the bounding-box
// diagonal of the original: farther crossings belong to other parts of the
// surface.
inline constexpr double kNormalReach = 0.05;

// Where seed 003 §3.1.2 puts a point p with limit normal `normal` (any
// length): the nearest crossing, forward or backward, of the line along the
// normal with a triangle of `surface` that faces the same way (a thin part's
// far side faces the other way), within `reach`; failing that (or for a zero
// normal), the closest point of the surface. True for a crossing.
bool onto_surface(const TriangleBvh& surface, const Vec3d& p, const Vec3d& normal, double reach, Vec3d* target);

struct RemeshStats {
  uint32_t vertices = 0;     // of the remesh C_K
  uint32_t line_hits = 0;    // vertices moved along their limit normal
  uint32_t fallbacks = 0;    // vertices moved to the closest point instead
  double max_move = 0;       // largest distance a vertex of the subdivided mesh moved
  // Per inverse step j = K..1 (index K - j): Gauss-Seidel sweeps and the final
  // largest residual, relative to the size of the right-hand side.
  std::vector<int> inverse_iterations;
  std::vector<double> inverse_residual;
  double subdivide_seconds = 0, displace_seconds = 0, inverse_seconds = 0;
};

// Steps IV-VI for `levels` = K >= 0 levels. control[j], j = 0..K, has exactly
// the vertices and faces, in the same order, of `adjusted_base` subdivided j
// times by build_loop_edges + loop_subdivide; control[K] is the remesh (every
// vertex on the original surface), and control[j - 1] the exact solution (to
// a relative residual of 1e-12, or after 500 sweeps) of the vertex-point
// system for control[j]'s vertex points; control[0] is the base mesh.
//
// Each vertex of the subdivided mesh moves onto_surface along its limit
// normal, within kNormalReach of the bounding-box diagonal. With K >= 3 so
// does each vertex of every level 1..K-1 before that level is subdivided
// again, so that the normals of the next level start near the surface (as
// normal meshes are built level by level: Guskov, Vidimce, Sweldens and
// Schroeder, "Normal Meshes", SIGGRAPH 2000); the inverse steps then
// overwrite control[0..K-1] as above.
//
// `bvh` is the original's triangles (loop_mesh_triangles(original)).
// Errors: adjusted_base that build_loop_edges rejects (its error), levels
// above 8, or a subdivided mesh beyond 32-bit indices (kInvalidArgument).
Status remesh(const LoopMesh& original, const TriangleBvh& bvh, const LoopMesh& adjusted_base, int levels,
              std::vector<LoopMesh>* control, RemeshStats* stats = nullptr);

// The inverse Loop step of seed 003 §3.2 on its own: the positions x (3 per
// vertex of `coarse`) with vertex-point mask(x) = vertex_points, where
// `vertex_points` are the first coarse.vertex_count() positions of a level
// subdivided from `coarse` (whose positions are ignored). Gauss-Seidel from
// x = vertex_points until the largest residual is below 1e-12 times the
// largest of the bounding-box diagonal and the largest coordinate magnitude
// of vertex_points, or `max_sweeps` sweeps; returns the sweeps done and sets
// *residual to the final relative residual.
int inverse_loop_vertex_points(const LoopEdges& coarse_edges, const std::vector<double>& vertex_points,
                               int max_sweeps, std::vector<double>* x, double* residual);

}  // namespace qmc
