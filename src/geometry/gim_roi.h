// Seed 000 §4: geometry images with an enhanced region of interest. The ROI,
// given on the input mesh, is carried into the parameter domain; the domain
// is split into the ROI's bounding rectangle and four regions around it
// (figure 6c); per-pixel sample positions then move within their 1-rings
// towards higher-weight regions, so that more samples land in the ROI; and
// the directed Hausdorff adjustment of §3.3 may follow over the ROI alone
// (gim_hausdorff.h, HausdorffAdjustInput::gim_face_mask; roi_face_mask).
//
// Why per-pixel positions and not the column/row lines: a line moved
// towards the ROI would also crowd the regions above/below (left/right of)
// it, which is what the four-region weighting is meant to prevent; the
// seed's p_new moves single samples. The image then keeps its grid
// connectivity but pixel (x, y) is sampled at its own (u, v), so the
// regular sampler (which takes lines) cannot be used; sample_at_pixel_uv
// does it with gim_sampling.h's ParamTriangleLocator.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/gim_types.h"
#include "qmc/status.h"

namespace qmc {

// The ROI file, plain text, one item per line, '#' to the end of a line a
// comment, blank lines ignored, tokens separated by spaces or tabs:
//   vertex I J K ...                  input vertex indices (0-based)
//   face I J K ...                    input triangle indices (0-based)
//   box XMIN YMIN ZMIN XMAX YMAX ZMAX  the input vertices inside this closed box
// Keywords may repeat (their lists add up; several boxes are a union).
// Errors name the line: an unknown keyword, a token that is not a
// non-negative integer (vertex, face) or a finite number (box), a box
// without exactly 6 numbers or with a minimum above its maximum, and a file
// that selects nothing.
struct RoiBox {
  double lo[3], hi[3];
};
struct RegionOfInterest {
  std::vector<uint32_t> vertices;
  std::vector<uint32_t> faces;
  std::vector<RoiBox> boxes;
};
Status parse_roi_file(const std::string& text, RegionOfInterest* out);

// The ROI's bounding rectangle in the parameter domain (pixel units): over
// the parameter positions of the disk vertices of the ROI's vertices, of the
// corners of its faces and of the vertices in its boxes. (A cut vertex has
// several disk copies; all count.) Errors: indices out of range, or nothing
// of the ROI on the mesh (an empty box).
struct RoiRect {
  double u0 = 0, v0 = 0, u1 = 0, v1 = 0;
  bool contains(double u, double v) const { return u >= u0 && u <= u1 && v >= v0 && v <= v1; }
};
Status roi_parameter_rect(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                          const RegionOfInterest& roi, RoiRect* rect);

// Region of a parameter point: 4 for the ROI rectangle, else 0 above it
// (v < v0), 1 below (v > v1), 2 left (u < u0), 3 right (u > u1).
int roi_region(const RoiRect& rect, double u, double v);

struct RoiSamplingOptions {
  double roi_weight = 8;        // the non-ROI regions get 1..4, see roi_adapt_sampling
  // Stop once this many pixels lie in the ROI rectangle; 0: twice as many
  // as at the start ("the increasing number ... is defined by user").
  uint32_t target_roi_samples = 0;
  uint32_t max_sweeps = 200;    // sweeps over all pixels
  uint32_t max_halvings = 8;    // a move that would fold a grid cell is halved at most this often
};

struct RoiSamplingStats {
  double n_ideal[4] = {0, 0, 0, 0};  // of the last sweep, per non-ROI region
  double surplus[4] = {0, 0, 0, 0};  // samples there minus n_ideal
  double weight[5] = {0, 0, 0, 0, 0};
  uint32_t roi_samples_before = 0, roi_samples_after = 0;
  uint32_t sweeps = 0;
  uint64_t moves = 0, blocked_moves = 0;  // blocked: every halving would fold a cell
};

// Moves the per-pixel parameter positions (2 per pixel, W x H, initially
// e.g. the column/row lines) within their 1-rings:
//   p_new = sum_i w_i |p0 - p_i| p_i / sum_i w_i |p0 - p_i|
// over the 6 neighbours of the grid triangulated along (x,y)-(x+1,y+1)
// (the seed's six-term sum), w_i the weight of the region p_i lies in. Per
// sweep: n_ideal = (n_c / |V|) W H with n_c the parametrized vertices in the
// region and |V| all of them; the four non-ROI regions, sorted by samples
// minus n_ideal from most surplus to most lacking, get weights 1, 2, 3, 4;
// the ROI gets options.roi_weight. Pixels move one at a time (Gauss-Seidel);
// a move is halved while it would make one of the pixel's four grid cells
// non-convex or flipped, so the grid never folds; pixels on the image
// border and pixels flagged in `fixed` (seam pixels; may be null) never
// move. Stops at the target count, after a sweep that moves nothing, or
// after max_sweeps.
Status roi_adapt_sampling(const DiskParametrization& param, const RoiRect& rect, uint32_t width, uint32_t height,
                          const std::vector<uint8_t>* fixed, const RoiSamplingOptions& options,
                          std::vector<double>* pixel_uv, RoiSamplingStats* stats,
                          const std::function<void(double)>& progress = {});

// Pixel uv from sample lines: (column_u[x], row_v[y]).
std::vector<double> pixel_uv_from_lines(const std::vector<double>& column_u, const std::vector<double>& row_v);

// Resamples samples->xyz at the per-pixel parameter positions: each pixel
// not flagged in `keep` (seam pixels, whose values the regular sampler made
// identical; may be null) takes the barycentric interpolation of the disk
// triangle holding its (u, v) (the nearest one, clamped, if none does).
Status sample_at_pixel_uv(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                          const std::vector<double>& pixel_uv, const std::vector<uint8_t>* keep,
                          GimSamples* samples);

// One byte per GIM triangle (raster-index triangles): 1 when the centroid
// of its parameter triangle lies in the ROI rectangle.
std::vector<uint8_t> roi_face_mask(const std::vector<double>& pixel_uv, const std::vector<uint32_t>& triangles,
                                   const RoiRect& rect);

// The pixels the ROI stage leaves alone (for `fixed` and `keep` above): the
// image border, whose samples the regular sampler takes along the boundary
// loop (border_arc) rather than from a triangle, and every pixel of a seam
// pair, whose mates must stay identical.
std::vector<uint8_t> roi_fixed_pixels(const GimSamples& samples);

// Pixels in any seam pair.
std::vector<uint8_t> seam_pixels(const GimSamples& samples);

}  // namespace qmc
