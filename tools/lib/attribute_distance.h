// qmc tools: how far the attributes of a mesh B (decoded, or another codec's
// output) are from those of the original A, at corresponding corners; the
// attribute part of `qmc compare` (issue 16).
//
// Correspondence. Attributes live on corners, and a codec that keeps the
// connectivity keeps every face's corners, though maybe in another order of
// vertices and faces, and with its positions moved by quantization. So:
//  - each vertex of B is matched to the vertices of A within a radius r of
//    it: the largest distance of a vertex of B to its nearest vertex of A,
//    counting only those within `vertex_tolerance` (a quantized vertex is
//    within the quantization's error bound of its own vertex, so r does not
//    exceed that bound and comes close to it);
//  - each face of B is matched to a face of A that has all of B's corners,
//    in the same cyclic order: of the same degree (rotations allowed), or
//    larger when B is a triangle (a codec that triangulates polygons);
//  - the corners of matched faces are compared. Faces of B without a match
//    (another connectivity, a remeshed surface, a vertex moved too far), and
//    those that several faces of A fit (vertices of A closer together than
//    the tolerance, e.g. closer than a quantization step: the positions
//    cannot tell which face it was), are counted and left out.
//
// Values. An attribute of A is compared with B's attribute of the same name,
// else with B's first one of the same kind and component count not taken by
// name. Per corner pair, the Euclidean distance of the two values; for
// normals also the angle between the two directions,
//   angle = atan2(|a x b|, a . b)   (degrees; corners where either normal is
//   zero are counted and left out);
// for texture coordinates also the stretch of each triangle of B's faces
// (fan from the first corner, matched corners) as a map from A's texture
// coordinates to B's: the affine map J with J (p_i - p_0) = (q_i - q_0), of
// singular values s1 >= s2, whose L2 stretch is sqrt((s1^2 + s2^2) / 2)
// (P. V. Sander, J. Snyder, S. J. Gortler, H. Hoppe, "Texture mapping
// progressive meshes", SIGGRAPH 2001, section 3, applied to the map between
// the two parametrizations rather than from the surface):
//   stretch_l2  = sqrt(sum w (s1^2 + s2^2) / 2 / sum w), w = area of A's
//                 texture triangle: 1 when B's coordinates are A's;
//   stretch_max = the largest max(s1, 1 / s2) of a triangle: how much the
//                 worst triangle's texture is stretched or squeezed (tiny
//                 texture triangles, a few quantization steps wide, give the
//                 largest values);
//   stretch_p99 = the same for 99 % of A's texture area: the smallest value
//                 that the triangles of at least 99 % of the area stay within;
//   flipped     = triangles whose texture turned over (det J < 0);
//   collapsed   = triangles whose texture B reduced to no area (left out of
//                 stretch_max; as infinite stretch in stretch_p99);
// A's triangles with no texture area are counted and left out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc::tools {

struct AttributeDistance {
  std::string name;  // A's
  AttributeKind kind = AttributeKind::kGeneric;
  uint32_t components = 0;
  std::string name_in_b;
  size_t corners = 0;                      // corner pairs compared
  double distance_max = 0, distance_rms = 0;  // of the values, in the attribute's units
  // Normals (kind kNormal, 3 components):
  size_t angle_corners = 0, zero_normals = 0;
  double angle_max_degrees = 0, angle_mean_degrees = 0, angle_rms_degrees = 0;
  // Texture coordinates (kind kTextureCoordinate, 2 components):
  size_t stretch_triangles = 0, no_area_in_a = 0, flipped = 0, collapsed = 0;
  double stretch_l2 = 1, stretch_max = 1, stretch_p99 = 1;
};

struct AttributeComparison {
  double vertex_tolerance = 0;  // as given
  double match_radius = 0;      // r
  size_t faces_b = 0, faces_matched = 0, vertices_unmatched = 0;
  size_t faces_ambiguous = 0;  // of B's faces, those that several faces of A fit (not compared)
  std::vector<AttributeDistance> attributes;  // A's attributes that B has
  std::vector<std::string> only_in_a, only_in_b;
};

// Compares the attributes of B with A's as described above. vertex_tolerance
// is in model units (> 0). Corner or value indices out of range give
// kInvalidArgument.
qmc::Status compare_attributes(const qmc::Mesh& a, const qmc::Mesh& b, double vertex_tolerance,
                               AttributeComparison* out);

}  // namespace qmc::tools
