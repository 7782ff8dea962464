// Seed 003 step II: the simplified mesh, by the quadric error metric and
// iterative edge contractions of M. Garland and P. S. Heckbert ("Surface
// Simplification using Quadric Error Metrics", SIGGRAPH 1997), on OpenMesh's
// decimater. The simplified mesh becomes the connectivity of the base mesh of
// a progressive Loop file, so it must have exactly the topology of the input:
// Loop subdivision and the inverse Loop of seed 003 §3.2 keep whatever the
// base mesh has, and a pinched vertex or a vanished hole would be carried to
// every level.
#pragma once

#include <cstdint>

#include "decoder/loop_subdivision.h"
#include "qmc/status.h"

namespace qmc {

// The topological invariants a simplification must keep. For an orientable
// surface, euler = 2 components - 2 genus - boundary_loops.
struct LoopTopology {
  uint32_t components = 0;
  uint32_t boundary_loops = 0;
  uint32_t shortest_boundary_loop = 0;  // edges; 0 when there is no boundary
  int64_t euler = 0;                    // V - E + F

  int64_t genus() const { return (2 * int64_t(components) - int64_t(boundary_loops) - euler) / 2; }
  bool operator==(const LoopTopology& o) const {
    return components == o.components && boundary_loops == o.boundary_loops && euler == o.euler;
  }
};

// The invariants of a mesh that build_loop_edges accepted (edges from it).
LoopTopology loop_topology(const LoopMesh& mesh, const LoopEdges& edges);

struct SimplifyStats {
  uint32_t input_vertices = 0, input_faces = 0;
  uint32_t unreferenced_vertices = 0;  // dropped from the input: no face uses them
  uint32_t output_vertices = 0, output_faces = 0;
  uint32_t collapses = 0;
  LoopTopology topology;  // of the input, and so of the output
  double seconds = 0;
};

// Collapses edges of `original` until it has at most `target_faces` faces or
// no collapse is allowed any more (the topology can need more faces: a torus
// has at least 14 triangles, and every hole keeps at least 3 boundary edges).
// Each collapse moves one end of an edge onto the other (halfedge collapse),
// so every vertex of the result is a vertex of the input at its input
// position, and faces keep the input's counter-clockwise orientation.
//
// A collapse is allowed only if it keeps the topology: OpenMesh's link
// condition (which also keeps every boundary loop at 3 edges or more), no
// interior edge between two boundary vertices (that would pinch the surface
// into a vertex on two boundaries), no face turning over by more than 60
// degrees. Boundaries keep their shape through penalty planes perpendicular
// to the boundary faces in the quadrics (Garland-Heckbert §6).
//
// `original` must be a manifold, consistently oriented triangle mesh (what
// build_loop_edges accepts), except that unreferenced vertices are allowed:
// they are dropped and counted in stats->unreferenced_vertices. Any other
// defect (a face repeating a vertex, an edge in three faces, two faces
// crossing an edge the same way, a vertex joining two fans, two faces on the
// same three vertices, a coordinate that is not finite) is kInvalidArgument
// naming it. The result is checked again (build_loop_edges, no duplicate
// face, same components, boundary loops and Euler characteristic); a
// violation, which would be a bug, is kInvalidArgument too. `simplified` is
// compact: the surviving vertices and faces in input order (a face may start
// at another corner). stats may be null.
Status simplify_for_loop(const LoopMesh& original, uint32_t target_faces, LoopMesh* simplified,
                         SimplifyStats* stats);

}  // namespace qmc
