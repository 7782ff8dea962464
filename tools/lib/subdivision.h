// qmc tools: Catmull-Clark subdivision (E. Catmull and J. Clark, "Recursively
// generated B-spline surfaces on arbitrary topological meshes", 1978).
//
// Used to rebuild the quad test meshes of the thesis the project reproduces:
// the refined 60-quad sphere series and the 17412-quad cow (the triangle cow
// refined once), and the ~1M-quad sphere of the benchmarks.
//
// Written here rather than taken from a mesh library so that the output
// (numbering and bits) is fixed by this file alone: the same input gives the
// same mesh on every platform. Arithmetic is in double; the only products are
// of a float-valued coordinate by a small integer or a power of two, which are
// exact in double, so a compiler fusing multiply-adds cannot change a result.
#pragma once

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc::tools {

// One step of Catmull-Clark subdivision of a manifold polygon mesh with or
// without boundary. Every output face is a quad.
//
// Rules: face point = centroid; interior edge point = average of the two ends
// and the two adjacent face points; boundary edge point = midpoint; interior
// vertex of valence n: (Q + 2R + (n-3)S)/n with Q the average of the adjacent
// face points, R the average of the incident edge midpoints, S the old
// position; boundary vertex: (a + 6S + b)/8 with a, b its two boundary
// neighbours. A vertex no face uses keeps its position.
//
// Numbering:
//  * vertices: the input vertices first (index kept, position moved), then
//    one face point per input face in face order, then one edge point per
//    edge, edges numbered in order of first appearance walking the faces and
//    their corners (edge i of a face runs from corner i to corner i+1), then
//    the extra copies of pinched vertices described below;
//  * faces: for each input face in order, one quad per corner i, namely
//    (v_i, e_i, f, e_{i-1}) -- vertex, edge point of the outgoing edge, face
//    point, edge point of the incoming edge -- which keeps the input face's
//    orientation.
//
// Pinched vertices (where several fans of faces meet at one vertex without
// sharing an edge, e.g. two cones touching at their tips) are split: each fan
// is subdivided as if it had its own copy of the vertex, with the interior or
// boundary rule applied to that fan alone. The fan holding the vertex's first
// corner (walking faces and corners in order) keeps the input index; every
// further fan gets a new vertex, appended after the edge points in order of
// input vertex and then of first corner. The output is then manifold, and
// has V + F + E + (number of extra fans) vertices.
//
// Rejected with ErrorCode::kInvalidArgument (and *out left unchanged): a
// mesh that breaks the qmc::Mesh invariants (face of fewer than 3 corners,
// corner count mismatch, index out of range), a face with two consecutive
// equal corners, an edge used by three or more face sides, two faces that
// traverse an edge in the same direction (inconsistent orientation), and an
// output too large for 32-bit indices.
qmc::Status catmull_clark(const qmc::Mesh& in, qmc::Mesh* out);

}  // namespace qmc::tools
