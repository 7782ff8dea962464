// Attributes (spec section 15) added to generated meshes, for the
// conformance vectors and the property tests: texture coordinates with
// seams, per-vertex normals, and random per-corner tables.
#pragma once

#include <cstdint>

#include "qmc/mesh.h"

namespace qmc::tools {

// "texcoord": two charts split by the sign of each face's centroid x; a
// vertex on the boundary gets one value per chart (a seam). (u, v) is the
// vertex's (y, z) shifted by 3 in u on the second chart.
void add_chart_texcoords(Mesh* mesh);

// "texcoord" for a mesh mirrored across x = 0 (make_mirrored_across_x):
// the faces on each side a chart, (u, v) = (x, y) where the face's
// centroid has x < 0 and (x + 1, y) on the other side, so that a twin's u
// is 1 - u (a texture mirrored as 15.14 expects); about one face in
// seam_one_in gets values of its own (a seam around it).
void add_mirrored_texcoords(Mesh* mesh, uint32_t seam_one_in, uint64_t seed);

// "normal": one value per vertex, the normalized sum of its faces'
// (Newell) normals; (0, 0, 1) for a vertex without faces.
void add_vertex_normals(Mesh* mesh);

// `name`: per-corner values of `components` numbers, each vertex with 1 to 3
// values of its own chosen at random per corner, and about one corner in
// 50 referring to a value of another vertex; some values referred to by no
// corner. Values are multiples of 2^-10 in [-4, 4).
void add_random_corner_attribute(Mesh* mesh, uint64_t seed, const char* name, AttributeKind kind,
                                 uint32_t components);

// Face labels (spec 16) like an OBJ's: "material" (with references
// "m.mtl") in runs of about `run` faces over 3 values, the first faces
// unlabelled; "group" with 2 values alternating every 7 faces.
void add_face_labels(Mesh* mesh, uint64_t seed, uint32_t run);

}  // namespace qmc::tools
