// Where a progressive level strays from the input surface, moves its
// vertices back, both ways: a level point far from the input is pulled to its
// closest input point, an input point far from the level pulls the level's
// closest point towards it (the two one-sided distances of seed 003 §4.1 and
// of Metro's Hausdorff distance; the closest-point iteration of P. J. Besl and
// N. D. McKay, "A method for registration of 3-D shapes", IEEE PAMI 14(2),
// 1992, here per vertex and local). Each round solves one sparse least-squares
// system over the vertices near the far points, with the points of those
// triangles that are near already kept near, and a membrane term that keeps
// the moves of neighbouring vertices alike. The encoder codes the moves as
// LEVL code 4's vertex corrections (spec/qmc-format.md 12.7.2).
#pragma once

#include <cstdint>
#include <vector>

#include "decoder/loop_subdivision.h"
#include "geometry/triangle_bvh.h"
#include "qmc/status.h"

namespace qmc {

struct DeviationFitOptions {
  double max_deviation = 0;  // absolute; the fit aims below it (kAimedShare)
  int rounds = 10;
};

struct DeviationFitStats {
  int rounds = 0;                // rounds run (fewer when nothing was far)
  uint32_t free_vertices = 0;    // vertices the last round could move
  size_t far_input_points = 0;   // of the surface samples, before the last round
  size_t far_level_points = 0;   // of the level's vertices, edge midpoints and centroids, likewise
};

// Twice the median of the longest edges of `level`'s triangles: how densely
// the fit samples both surfaces.
double sample_spacing(const LoopMesh& level);

// The input points the fit measures the level against: every vertex a
// triangle of `surface` uses, and per triangle its edge midpoints and
// centroid, or for a triangle longer than `spacing` a grid as fine (a fixed
// cover of thin and of large triangles too, unlike random area samples).
std::vector<Vec3d> deviation_samples(const LoopMesh& surface, double spacing);

// The largest distance from a sample to `level`'s triangles and from a
// point of `level` (its vertices, edge midpoints and centroids, and a grid as
// deviation_samples's on its triangles longer than sample_spacing(level)) to
// `surface`: the measure the fit works to.
double two_sided_deviation(const TriangleBvh& surface, const std::vector<Vec3d>& samples, const LoopMesh& level);

// New positions for `level` (3 per vertex), which are `level`'s own where
// nothing is far; `surface` the input's triangles, `samples` from
// deviation_samples. kInvalidArgument if the options are not positive or
// (an internal fault) a round's system cannot be factorised.
Status fit_to_max_deviation(const TriangleBvh& surface, const std::vector<Vec3d>& samples, const LoopMesh& level,
                            const DeviationFitOptions& options, std::vector<double>* positions,
                            DeviationFitStats* stats);

}  // namespace qmc
