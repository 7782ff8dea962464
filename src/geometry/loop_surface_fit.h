// A control mesh fitted so that its Loop subdivision surface, not only the
// limit positions of its vertices, lies on the input: least squares over the
// subdivision masks, as Hoppe et al. fit subdivision surfaces to points
// ("Piecewise Smooth Surface Reconstruction", SIGGRAPH 1994, section 4.2) and
// Lee, Moreton and Hoppe fit the control mesh of a displaced subdivision
// surface ("Displaced Subdivision Surfaces", SIGGRAPH 2000, section 4.2).
//
// Why (spec 12.10, informative): fit_control_mesh puts the limit positions
// of the base's vertices on the input, and between them the subdivision
// surface of a base of a few dozen vertices sags far inside the input's
// thinner parts. A 24 x 12 torus at K = 3 (a base of 11 vertices): the base
// subdivided 3 times was 0.087 of the diagonal from the input with every
// vertex limit on it, a third of the remesh's normals missed the input, and
// the remesh, every vertex on the input, was still 0.08 away; fitted here,
// 0.008 and 0.0013.
#pragma once

#include <cstdint>
#include <vector>

#include "decoder/loop_subdivision.h"
#include "geometry/triangle_bvh.h"
#include "qmc/status.h"

namespace qmc {

struct SurfaceFitStats {
  int passes = 0;
  double initial_rms = 0, final_rms = 0;  // of the residuals of the last pass's first and last targets
};

// Moves the interior vertices of `control` (boundary vertices stay where
// fit_control_mesh and its rim put them) to reduce the sum, over the control
// mesh and its `subdivisions` Loop steps, of
//  - the squared distance from each vertex of the level to the closest point
//    of `surface` (the control mesh's own vertices weighted down, see
//    kControlMeshWeight), and, on the subdivided levels,
//  - the squared distance from each of `points` (3 doubles each, points of
//    the input surface) to the level's vertex nearest it, scaled by the ratio
//    of the level's vertices to points, so that the two directions weigh
//    alike and the surface is covered, not only approached.
// Each pass takes those targets, then one step along the gradient (the
// residuals carried back through the transposed masks) with the exact line
// search of the quadratic it gives. `control` must be a mesh
// number_loop_edges accepts; anything else is returned as its error, as is
// `subdivisions` below 1 (kInvalidArgument).
Status fit_subdivided_surface(const TriangleBvh& surface, const std::vector<double>& points, int subdivisions,
                              int passes, LoopMesh* control, SurfaceFitStats* stats = nullptr);

}  // namespace qmc
