// qmc tools: surface-to-surface distance between two polygon meshes, the way
// Metro measures it (P. Cignoni, C. Rocchini, R. Scopigno, "Metro: Measuring
// Error on Simplified Surfaces", Computer Graphics Forum 17(2), 1998).
//
// Unlike mesh_metrics.h, nothing here needs a vertex correspondence: the two
// meshes may have different vertices, faces and connectivity.
//
// Surfaces. Every face is fan-triangulated from its first corner: corners
// (c0 c1 ... ck-1) give triangles (c0 ci ci+1), i = 1..k-2. Triangles of zero
// area are skipped, because they add nothing to the surface measure and have
// no interior to project onto (their vertices are still vertex samples).
//
// Sampling. `samples` points are spread over each surface area-uniformly
// (systematic sampling along the cumulative area, then a uniform point inside
// the chosen triangle), from our own splitmix64 generator, so a seed gives the
// same points on every platform. All vertices that some face references are
// added as samples too, so that corners -- where the largest deviations of a
// quantized or simplified mesh tend to sit -- are never missed.
//
// One-sided distance X -> Y, with d(x, Y) the exact Euclidean distance from
// x to the nearest point of Y's triangles (a BVH over Y's triangles, exact
// point-triangle distance):
//   max  = max d(x, Y) over area samples and vertices of X
//   mean = (1/n) sum d(x_i, Y)            over the n area samples x_i
//   rms  = sqrt((1/n) sum d(x_i, Y)^2)    over the n area samples x_i
// Distances up to 2^-40 times the largest |coordinate| of A and B count as
// 0: that is rounding noise of the double arithmetic, far below what float
// input coordinates can express, and it would otherwise keep coincident
// surfaces at 1e-17 rather than 0.
// Area samples estimate the integrals (1/Area(X)) int_X d(x,Y) dx and
// (1/Area(X)) int_X d(x,Y)^2 dx -- seed 003 section 4.1's L2 distance; vertex
// samples would bias them towards densely tessellated regions, so they only
// enter the maximum.
//
// Symmetric values (seed 003 section 4.1; seed 000 section 3.2 eq. (1)):
//   hausdorff = max(max_AB, max_BA)
//   l2        = max(rms_AB, rms_BA)      Metro's symmetric RMS ("L2") error
//   mean      = max(mean_AB, mean_BA)
// Relative values divide by the bounding-box diagonal of A (over all of A's
// positions, as Metro and mesh_metrics.h do), so A should be the original.
//
// PSNR, seed 002 eq. (1):  PSNR = 20 log10(peak / d)  [dB], where peak is the
// bounding-box diagonal (of A) and d the symmetric Hausdorff RMS error, i.e.
// `l2` above: the sampled surface-to-surface RMS, maximised over the two
// directions. Eq. (1) is defined over surfaces, not over corresponding
// vertices, so there is no per-vertex variant; `qmc compare` prints this one.
// Identical surfaces (l2 == 0) give PSNR = +infinity.
//
// Sampled maxima never exceed the true one-sided Hausdorff distances; the
// true value is reached when it is attained at a vertex, and otherwise
// approached as `samples` grows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/triangle_bvh.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc::tools {

// The geometry and the nearest-triangle search are the geometry library's
// (src/geometry/triangle_bvh.h); these names keep the tools' spelling.
using qmc::point_triangle_distance_squared;
using qmc::TriangleBvh;
using qmc::Vec3d;
using Triangle = qmc::Triangle3d;

// The non-degenerate triangles of `mesh`'s faces (fan from each face's first
// corner), in face order; *degenerate counts the skipped zero-area ones and
// *vertices receives, sorted, the vertices that some face references. Either
// pointer may be null. A corner index out of range or face sizes that do not
// add up to corners.size() give kInvalidArgument.
qmc::Status fan_triangulate(const qmc::Mesh& mesh, std::vector<Triangle>* triangles, size_t* degenerate,
                            std::vector<uint32_t>* vertices);

double triangle_area(const Triangle& t);

struct SurfaceSample {
  Vec3d point;
  uint32_t triangle;  // index into the triangles that were sampled
};

// `count` points spread area-uniformly over `triangles` (none if the total
// area is zero): each triangle receives count * area / total_area samples,
// rounded up or down, and each sample is uniform within its triangle.
// Deterministic in `seed`. Samples come in triangle order.
std::vector<SurfaceSample> sample_surface(const std::vector<Triangle>& triangles, size_t count, uint64_t seed);

struct MeshDistanceOptions {
  size_t samples = 200000;  // area samples on each of the two surfaces
  uint64_t seed = 1;
  // Called now and then with the distance queries done so far and in all,
  // e.g. to show progress; may be empty.
  std::function<void(size_t done, size_t total)> progress;
};

struct OneSidedDistance {
  double max = 0, mean = 0, rms = 0;
  size_t area_samples = 0, vertex_samples = 0;
};

struct SurfaceInfo {
  size_t triangles = 0, degenerate = 0;  // degenerate: zero-area triangles skipped
  size_t referenced_vertices = 0;
  double area = 0;
};

struct MeshDistance {
  SurfaceInfo a, b;
  OneSidedDistance a_to_b, b_to_a;
  double hausdorff = 0, l2 = 0, mean = 0;  // symmetric, see the top of this file
  double bbox_diagonal = 0;                // of A: the normaliser and the PSNR peak
  double psnr_db = 0;                      // seed 002 eq. (1); +infinity when l2 == 0

  double relative(double distance) const { return bbox_diagonal > 0 ? distance / bbox_diagonal : 0; }
};

// Measures A against B as described at the top of this file. A mesh without
// a single non-degenerate triangle has no surface to measure against and
// gives kInvalidArgument, as do the failures of fan_triangulate.
qmc::Status measure_mesh_distance(const qmc::Mesh& a, const qmc::Mesh& b, const MeshDistanceOptions& options,
                                  MeshDistance* out);

}  // namespace qmc::tools
