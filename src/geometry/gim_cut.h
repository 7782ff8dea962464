// Cutting a triangle mesh into a topological disk, the first stage of the
// geometry-image encoder: seed 002 "Methods", "Euler circuit cutting to obtain
// a topological disk" / "Initial cut" / "Euler circuit cutting" (after Gu et
// al.'s cut graph), and seed 000 §1-3 (the geometry-image pipeline it feeds).
//
// - Already a disk (genus 0, one boundary loop): kept as it is.
// - Closed genus 0: cut along a long path, approximately between the two
//   farthest vertices (two Dijkstra sweeps on edge lengths), the shortest edge
//   path between them (seed 002: "the path between the two points with the
//   farthest coordinates").
// - Otherwise (handles and/or several boundary loops): Gu's cut graph. A
//   spanning tree of the dual graph from a seed triangle, the edges it does
//   not cross (which include every input-boundary edge), pruned of dangling
//   edges; then seed 002's straightening: the cut graph's nodes of degree
//   != 2 and the paths between them, each path replaced by a constrained
//   shortest path that touches no other cut path (a bounded number of passes).
//   Seed 002's Euler circuit of the doubled graph is the disk's boundary
//   loop: every cut path appears on it twice, once per side, in circuit
//   order, which is how DiskCut::boundary_loop / boundary_mate present it.
// The mesh is then opened along the cut: every vertex becomes one disk vertex
// per wedge (fan sector between cut or boundary edges), and the result is
// checked (one boundary loop, V - E + F == 1) before it is returned.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "geometry/gim_types.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

struct GimCutStats {
  uint32_t vertices_used = 0;          // referenced input vertices (after fan splitting)
  uint32_t unreferenced_vertices = 0;  // ignored
  uint32_t cut_nodes = 0;              // cut-graph vertices of degree != 2 (after pruning)
  uint32_t cut_paths = 0;              // paths between cut nodes
  uint32_t paths_straightened = 0;     // replacements kept by the straightening passes
  double cut_length_before = 0;        // 3-D length of the cut before / after straightening
  double cut_length = 0;
  double seconds = 0;
};

// Opens `mesh` into a disk. Errors (kInvalidArgument) name the offending
// element: non-triangle data, out-of-range indices, degenerate triangles
// (a repeated corner), an edge with more than two triangles, inconsistent
// orientation, several connected components ("3 connected components
// (1200, 40, 8 triangles); the geometry image takes one"). Pinched vertices
// (several fans) are split, one disk vertex set per fan (counted in
// DiskCut::split_fan_vertices). Unreferenced vertices are ignored.
// progress (may be empty) receives fractions in [0, 1]. Never prints.
Status cut_to_disk(const GimTriMesh& mesh, DiskCut* out, const std::function<void(double)>& progress = {},
                   GimCutStats* stats = nullptr);

// The encoder's polygon mesh as a GimTriMesh: positions widened to binary64,
// polygons fan-triangulated from their first corner (*polygons_split, if not
// null, counts the faces of degree > 3 so callers can say so).
GimTriMesh gim_mesh_from(const Mesh& mesh, size_t* polygons_split = nullptr);

}  // namespace qmc
