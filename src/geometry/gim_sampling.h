// Sampling the parametrized surface on the pixel grid: seed 000 §1-3 (the
// geometry image: the surface resampled at the pixels of the parameter
// rectangle; regular sampling here, the adaptive sampling of §3.1 supplies
// its own column and row positions) and seed 002 (seam pairs along the cut).
//
// Interior pixel (i, j) takes the 3-D point of the parametric triangle that
// contains (column_u[i], row_v[j]), barycentric interpolation. Border pixels
// take the point at their border_arc along the boundary loop; on a run with a
// mate the position comes from the pixel's index within the run, so both
// sides of a seam are computed from the same number, and then the second copy
// is overwritten with the first bit for bit and a SeamPair is emitted.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/gim_types.h"
#include "qmc/status.h"

namespace qmc {

struct GimSampleStats {
  uint32_t clamped_pixels = 0;  // interior pixels outside every triangle (nearest triangle used)
  uint32_t seam_pairs = 0;
  double seconds = 0;
};

// column_u[i] = i, row_v[j] = j.
void regular_sampling(uint32_t width, uint32_t height, std::vector<double>* column_u, std::vector<double>* row_v);

// column_u has param.width entries, row_v param.height, both strictly
// increasing from 0 to width - 1 (height - 1). Errors: kInvalidArgument for
// sizes or sequences that do not fit param, or a cut/param mismatch.
Status sample_geometry_image(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                             const std::vector<double>& column_u, const std::vector<double>& row_v, GimSamples* out,
                             const std::function<void(double)>& progress = {}, GimSampleStats* stats = nullptr);

// Point location in the parametric domain: which disk triangle holds (u, v).
// Uniform grid buckets over the triangles' bounding boxes. Keeps references
// to uv and triangles: both must outlive the locator and stay unchanged.
class ParamTriangleLocator {
 public:
  struct Hit {
    uint32_t triangle = UINT32_MAX;  // UINT32_MAX when there are no triangles
    double b0 = 0, b1 = 0, b2 = 0;   // barycentrics, clamped to the triangle when outside
    bool inside = false;
  };
  ParamTriangleLocator(const std::vector<double>& uv, const std::vector<uint32_t>& triangles);
  Hit locate(double u, double v) const;

 private:
  const std::vector<double>& uv_;
  const std::vector<uint32_t>& triangles_;
  double min_u_ = 0, min_v_ = 0, cell_ = 1;
  uint32_t nu_ = 1, nv_ = 1;
  std::vector<uint32_t> cell_offset_, cell_items_;
  Hit nearest(double u, double v) const;
};

// The 3-D point at position `arc` (edge index + fraction, [0, n)) along the
// disk's boundary loop, linear along the edge.
void boundary_point(const GimTriMesh& mesh, const DiskCut& cut, double arc, double xyz[3]);

}  // namespace qmc
