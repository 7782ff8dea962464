// Topology-preserving geometry images (TPGIM), seed 002 "Methods": every disk
// vertex of the cut mesh moves to its own integer pixel, no triangle folds
// over or degenerates, and the blank pixels between the vertices are filled
// by each triangle's affine map onto its 3-D triangle. The mesh rebuilt from
// the occupied pixels, the explicit triangle list and the seams is the input
// mesh exactly (binary64 samples), with no resampling.
//
// Steps, and where they are implemented:
//  1. "Gaining nearly uniform distribution": the geometry phase of
//     capacity-constrained Delaunay triangulation (eq. 2), no retriangulation
//     (gim_topology_preserving.cc, equalize_triangle_areas).
//  2. "Relaxed grid" (eq. 3) and "moving to integer points without repetition
//     or fold-over", stretching x3, repair, and compression by deleting blank
//     rows / columns (gim_integer_placement.cc, place_on_integer_grid).
//  3. "TPGIM generation by shape deformation" (gim_affine_fill.cc,
//     fill_by_shape_deformation).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/gim_types.h"
#include "qmc/status.h"

namespace qmc {

struct TopologyPreservingOptions {
  // Step 1: at most this many sweeps over the vertices; stops earlier once a
  // sweep lowers the area variance by less than energy_threshold (relative),
  // the seed's 1e-3.
  int max_area_sweeps = 200;
  double energy_threshold = 1e-3;
  // Step 1 also slides boundary vertices along their border line (corners,
  // kSideOutward vertices and the other corners of their triangles stay):
  // Floater's boundary spacing follows 3-D arc length, which crowds
  // some border stretches.
  bool slide_boundary = true;
  // Step 2: repair rounds per grid scale, then the grid is stretched x3
  // (at most max_stretches times) and placement starts again.
  int repair_rounds = 12;
  int max_stretches = 14;
  // Compression: passes alternate columns / rows; first passes that close
  // at most half of each gap (at most 128, until nothing moves), then at
  // most 2 * compress_rounds passes that close gaps entirely.
  int compress_rounds = 24;
  // The image may not exceed these (the seed counts width >= 8000 a failure).
  uint32_t max_side = 4096;
  uint64_t max_pixels = uint64_t(1) << 26;
};

struct TopologyPreservingStats {
  uint32_t width = 0, height = 0;
  // Step 1.
  int area_sweeps = 0;
  double area_variance_before = 0, area_variance_after = 0;  // of triangle areas / mean^2
  uint32_t area_moves_rejected = 0;  // vertex moves not taken (fold, thinner triangle, singular system)
  // Step 2.
  double grid_spacing = 0;          // S of eq. (3) in parametrization pixels
  int stretches = 0;                // x3 stretches before every vertex had a place
  int repair_rounds = 0;            // relaxation rounds, all scales together
  uint32_t vertices_repaired = 0;   // moves away from the nearest integer point
  uint64_t placed_width = 0, placed_height = 0;  // the grid before compression
  int compress_passes = 0;
  // Step 3.
  uint64_t pixels_in_triangles = 0;   // pixels filled by a triangle's affine map (vertex pixels included)
  uint64_t pixels_outside = 0;        // blank pixels given the nearest triangle's clamped value
  // Seconds per step.
  double seconds_areas = 0, seconds_placement = 0, seconds_compression = 0, seconds_fill = 0, seconds_total = 0;
};

// The whole pipeline. `cut` and `param` must describe the same disk
// (param.uv has two values per cut.original_vertex entry, boundary vertices
// on the W x H rectangle's border, positive signed area in (u, v)).
// Output: out->width/height, occupied = 1 exactly at vertex pixels, xyz at
// vertex pixels = mesh.positions of the vertex (binary64 copies), triangles =
// cut.triangles as raster indices (input order), seams chaining the pixels of
// every input vertex that the cut duplicated (a < b). Every blank pixel is
// filled (step 3). The result is checked before it is returned (see
// check_integer_layout); a violation is an error, never an image.
//
// Departure from the seed's layout: the seed keeps the whole boundary on the
// image rectangle. Floater's parametrization puts consecutive boundary
// vertices on one straight border side, so an "ear" (a triangle a, b, c with
// boundary edges a-b and b-c, common where the cut runs along two edges of
// one triangle) gets three collinear corners and can never be positive. Such
// a middle vertex (and every middle vertex of a longer pocket of degenerate
// border triangles) is marked kSideOutward and placed outside its border
// line: with the boundary counter-clockwise, a triangle a, b, c over the
// boundary path a -> b -> c is positive exactly when b is on the outer side
// of a-c. The image boundary is then the rectangle with small bulges; pixels
// outside every triangle are blank and filled like any other blank pixel.
// Errors (kInvalidArgument): inconsistent inputs, a vertex that cannot be
// placed within the stretch budget, an image beyond max_side / max_pixels.
// stats may be null; progress (may be empty) receives fractions in [0, 1].
Status make_topology_preserving_image(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                                      const TopologyPreservingOptions& options, GimSamples* out,
                                      TopologyPreservingStats* stats = nullptr,
                                      const std::function<void(double)>& progress = {});

// --- The steps, exposed for tests and for other layouts. ---

// Which border lines a disk vertex lies on (bit set); 0 = interior, two bits =
// a corner. "Min" is u = 0 / v = 0, "max" u = W - 1 / v = H - 1.
// kSideOutward (with exactly one line bit) marks a boundary vertex that is
// the middle of a degenerate border triangle: it is placed strictly outside
// that line (see make_topology_preserving_image).
enum GimBorderSide : uint8_t { kSideMinX = 1, kSideMaxX = 2, kSideMinY = 4, kSideMaxY = 8, kSideOutward = 16 };

// A planar triangulated disk: the triangles (positive orientation) and the
// border line(s) of each boundary vertex.
struct PlanarDisk {
  const std::vector<uint32_t>* triangles = nullptr;  // 3 per triangle, over vertices
  std::vector<uint8_t> sides;                        // GimBorderSide bits per vertex
  std::vector<uint32_t> boundary_loop;               // positive orientation
};

// The corners (3 t + i) at every vertex, in triangle order; CSR over vertices.
struct VertexCorners {
  std::vector<uint32_t> offset, corner;
};
VertexCorners vertex_corners(const std::vector<uint32_t>& triangles, size_t vertex_count);

// Step 1 on uv (2 per vertex, in a [0, w] x [0, h] rectangle): Xu et al.'s
// geometry phase of CCDT. Each free vertex moves to the point that minimizes
// the variance of its incident triangle areas (a 2 x 2 solve; 1-D along the
// border line), halving the move until no incident triangle that was
// positive turns non-positive and the smallest incident triangle height does
// not drop (the seed's control against large angles: equal areas alone give
// long thin triangles, which need a finer grid). Measured on bunny_small
// from a 512 x 512 Floater map: without step 1 a 228 x 197 image, plain
// eq. 2 (200 sweeps, an earlier compression schedule) 594 x 604, with this
// control 199 x 164, with border sliding too 192 x 136. Bounded by
// options.max_area_sweeps.
void equalize_triangle_areas(const PlanarDisk& disk, const TopologyPreservingOptions& options, std::vector<double>* uv,
                             TopologyPreservingStats* stats);

// Step 2: integer pixel coordinates (2 per vertex, int64) for the vertices,
// from uv in a [0, w] x [0, h] rectangle. *width / *height receive the image
// size. See gim_integer_placement.cc for the strategy.
Status place_on_integer_grid(const PlanarDisk& disk, const std::vector<double>& uv, double w, double h,
                             const TopologyPreservingOptions& options, std::vector<int64_t>* xy, uint64_t* width,
                             uint64_t* height, TopologyPreservingStats* stats,
                             const std::function<void(double)>& progress = {});

// The invariants of a topology-preserving layout, exactly (int64): every
// vertex inside the image, no two on one pixel, every triangle of positive
// orientation, the boundary vertices of each border line (kSideOutward ones
// excepted) on one common line with no vertex beyond it except outward ones,
// and the boundary loop a simple polygon (no two non-adjacent edges touch,
// no adjacent pair folds back) of positive area. Positive triangles of a
// triangulated disk inside a simple boundary of winding one cover every
// point once: the layout is an embedding. The first violation is the error.
Status check_integer_layout(const PlanarDisk& disk, const std::vector<int64_t>& xy, uint64_t width, uint64_t height);

// Step 3: every pixel of the width x height image gets 3-D coordinates. A
// pixel inside (or on) a triangle of the layout takes the barycentric
// combination of that triangle's 3-D corners (the seed's rotate / affine /
// rotate back, which is this affine map); a pixel outside every triangle the
// closest point of the nearest triangle. Vertex pixels get their positions
// as exact copies. positions: 3 per vertex. out->xyz is resized.
void fill_by_shape_deformation(const std::vector<uint32_t>& triangles, const std::vector<int64_t>& xy,
                               const std::vector<double>& positions, uint32_t width, uint32_t height,
                               std::vector<double>* xyz, uint64_t* pixels_in_triangles, uint64_t* pixels_outside);

}  // namespace qmc
