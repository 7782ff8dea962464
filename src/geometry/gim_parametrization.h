// Mapping the cut disk onto the image rectangle: seed 002 "Methods" (Floater
// parametrization with mean-value coordinates, eqs. (4)-(5), boundary on the
// rectangle) and seed 000 §1-3 (the parametrization the geometry image
// samples).
//
// Coordinates are in pixel units: u in [0, W - 1], v in [0, H - 1]. The
// border is walked counter-clockwise in (u, v) taken as plain numbers
// (positive signed area): from (0, 0) along v = 0 to (W - 1, 0), down
// u = W - 1 to (W - 1, H - 1), back along v = H - 1 to (0, H - 1), and up
// u = 0 to (0, 1). On screen, with rows growing downwards, that looks
// clockwise. It has P = 2 (W - 1) + 2 (H - 1) pixel steps.
//
// Seam alignment: the boundary loop splits into runs at cut nodes (a boundary
// vertex where the mate structure changes). Every run gets an integer number
// of border steps, proportional to its 3-D length, a run and its mate the
// same number, P in total, so cut nodes land on border pixels and border
// pixel k of a run and pixel (steps - k) of its mate are the same surface
// point. Within a run, boundary vertices are placed by arc length.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/gim_types.h"
#include "qmc/status.h"

namespace qmc {

struct GimParamStats {
  uint32_t runs = 0;
  uint32_t interior_vertices = 0;
  uint32_t flipped_triangles = 0;     // negative parametric area
  uint32_t degenerate_triangles = 0;  // |area| below 1e-12 of the rectangle (e.g. 3 corners on one side)
  uint32_t border_offset = 0;         // border steps the boundary start was rotated by (corner avoidance)
  double max_residual = 0;            // largest |sum_j lambda_ij (x_j - x_i)| over interior vertices, pixels
  double seconds = 0;
};

// The boundary runs of a cut, in boundary-loop order, with first_edge,
// edge_count and mate filled (pixel fields zero). The loop is split wherever
// edge i + 1's mate is not edge i's mate - 1, and at input-boundary /
// cut transitions. A loop that is one single input boundary is one run.
std::vector<GimBorderRun> find_border_runs(const DiskCut& cut);

// Floater's mean-value parametrization of the disk onto the W x H rectangle
// (W, H >= 2). Errors: kInvalidArgument for an image too small for the cut
// ("image too small for the cut: N runs, P border pixels"), a cut that does
// not match the mesh, or a solver failure. progress may be empty.
Status parametrize_on_rectangle(const GimTriMesh& mesh, const DiskCut& cut, uint32_t width, uint32_t height,
                                DiskParametrization* out, const std::function<void(double)>& progress = {},
                                GimParamStats* stats = nullptr);

// Mean-value weight of each neighbour of each interior disk vertex, as the
// solver uses them (unnormalized, seed 002 eq. (5)); CSR layout over disk
// vertices, neighbours in no particular order. Boundary vertices have none.
// Exposed for tests and for stages that move vertices afterwards.
struct MeanValueWeights {
  std::vector<uint32_t> offset;  // size disk vertices + 1
  std::vector<uint32_t> neighbour;
  std::vector<double> weight;
};
Status mean_value_weights(const GimTriMesh& mesh, const DiskCut& cut, MeanValueWeights* out);

}  // namespace qmc
