// The input of the progressive encoder made a manifold oriented triangle
// mesh without changing its surface (spec/qmc-format.md 12.10: the levels
// approximate the input's surface, never its vertices, so nothing the file
// could have carried is lost). Faces that repeat a vertex (no area) and
// second copies of a face on the same three vertices are left out; two faces
// are joined across an edge only where exactly two faces share it and run it
// opposite ways, every other edge is cut open into boundary edges; a vertex
// whose corners then form several fans becomes one vertex per fan, at the
// same position. A manifold oriented mesh comes out unchanged.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "decoder/loop_subdivision.h"

namespace qmc {

struct ManifoldCut {
  uint32_t faces_without_area = 0;  // a vertex repeated in the face
  uint32_t duplicate_faces = 0;     // the three vertices of an earlier face
  uint32_t edges_cut = 0;           // in three or more faces, or run the same way by two
  uint32_t vertices_added = 0;      // one per fan beyond a vertex's first
  bool changed() const { return faces_without_area || duplicate_faces || edges_cut || vertices_added; }
};

// `mesh`'s indices must name its vertices; `out` may not be `mesh`.
ManifoldCut cut_to_manifold(const LoopMesh& mesh, LoopMesh* out);

// Every face of `mesh` that repeats no vertex as {its three vertices in
// increasing order, the face}, sorted: faces on the same three vertices come
// next to each other, the earliest first.
std::vector<std::array<uint32_t, 4>> faces_by_vertex_set(const LoopMesh& mesh);

}  // namespace qmc
