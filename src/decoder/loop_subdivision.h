// Loop subdivision with reproducible binary64 arithmetic: the reconstruction
// of progressive levels, spec/qmc-format.md section 12 (seed 003 §3.1.1,
// §3.1.2 and §3.2.3; C. Loop, "Smooth Subdivision Surfaces Based on
// Triangles", 1987; boundary tangents after Hoppe et al., SIGGRAPH 1994).
//
// Every function here performs exactly the operations, in exactly the order,
// that section 12 prescribes, so that two conforming decoders produce the
// same bits. The encoder uses the same functions for its closed loop.
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/decoder.h"
#include "qmc/status.h"

namespace qmc {

inline constexpr uint32_t kNoVertex = 0xFFFFFFFFu;

// A triangle mesh whose positions are binary64: one level of a progressive
// stream (section 12.2), the public LoopLevel of qmc/decoder.h (positions x y
// z per vertex, 3 vertex indices per counter-clockwise face).
using LoopMesh = LoopLevel;

// The edges of a LoopMesh in the order of section 12.3: an edge is numbered
// when it is first met going through the faces in order and, in each face
// (v0 v1 v2), through (v0 v1), (v1 v2), (v2 v0).
struct LoopEdges {
  // Per edge: a, b = the edge as first met (a -> b in its first face),
  // c = the third vertex of that face, d = the third vertex of the other
  // face (kNoVertex on a boundary edge).
  std::vector<uint32_t> a, b, c, d;
  // Per edge: the face where it was first met and the corner k of that face
  // with (f[k], f[k+1]) = (a, b); then the other face, with (g[k], g[k+1]) =
  // (b, a) (kNoVertex on a boundary edge).
  std::vector<uint32_t> face0, corner0, face1, corner1;
  // 3 per face: the edge index of (v0 v1), (v1 v2), (v2 v0).
  std::vector<uint32_t> face_edge;
  // Per vertex: number of incident edges (the valence n of section 12.4), and
  // for a boundary vertex its two boundary neighbours in edge order
  // (kNoVertex for an interior vertex).
  std::vector<uint32_t> valence, boundary_prev, boundary_next;
  // Per vertex: its neighbours, listed by increasing edge index (section
  // 12.4 sums them in this order); offsets index `neighbours`.
  std::vector<uint32_t> neighbour_offset, neighbours;

  uint32_t edge_count() const { return uint32_t(a.size()); }
  bool is_boundary(uint32_t e) const { return d[e] == kNoVertex; }
};

// Builds the edge table and checks that the mesh is what section 12.2
// requires of a level: triangles with three distinct corners, every vertex
// used, every edge in one or two faces (two faces crossing it in opposite
// directions), every vertex's faces a single fan. A mesh that is not is
// `bad_chunk_payload` with the reason.
Status build_loop_edges(const LoopMesh& mesh, LoopEdges* edges);

// The same edge table with section 12.2's rules 1-4, which come free while
// numbering, but not the fan check (rule 5): for a level loop_subdivide made
// from a valid level, which keeps every rule (section 12.2), so only the
// base mesh pays for the check.
Status number_loop_edges(const LoopMesh& mesh, LoopEdges* edges);

// beta(n) of section 12.4 for n >= 2, computed as section 12.4 prescribes
// (a fixed polynomial for cos(2 pi / n), so that every platform agrees).
double loop_beta(uint32_t n);

// Section 12.5: one Loop step. `fine` gets the vertex points (same indices),
// then the edge points (vertex_count + edge index), and 4 faces per coarse
// face. Positions only from the masks; no displacement.
void loop_subdivide(const LoopMesh& coarse, const LoopEdges& edges, LoopMesh* fine);

// Section 12.6: the (unnormalized) Loop limit normal of every edge point of
// `fine` = loop_subdivide(coarse), 3 doubles per coarse edge, computed from
// fine's positions.
void edge_point_normals(const LoopMesh& fine, const LoopEdges& coarse_edges, uint32_t coarse_vertex_count,
                        std::vector<double>* normals);

}  // namespace qmc
