// How near a decoded progressive level is to the input surface: the closed
// loop of spec/qmc-format.md 12.10 that keeps every level nearer the input
// than the level before (issue 17). The measure is seed 003 §4.1's L2, the
// larger of the two one-sided RMS distances over the surfaces' areas, which
// the encoder estimates by the edge-midpoint rule (each triangle's squared
// distance integrated from its three edge midpoints, weight area / 3; exact
// where the other surface is locally a plane) instead of random samples so
// that it can afford it at every level: the level's edge midpoints against
// the input's triangles, the input's (a fixed share of them on a large input)
// against a BVH of the level's, built per call. Each midpoint is measured
// once, for both of its faces. A surface of few triangles (a coarse level, a
// small input) is cut into fours first, until it has thousands: the same
// surface, a finer rule.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "decoder/loop_subdivision.h"
#include "geometry/triangle_bvh.h"

namespace qmc {

class LevelDistance {
 public:
  // `input` is a BVH over `input_mesh`'s triangles; of the input's edge
  // midpoints about `most_input_samples` are measured, a pseudo-random share
  // (the same for every level, so that two levels are compared on the same
  // points).
  LevelDistance(const TriangleBvh& input, const LoopMesh& input_mesh, size_t most_input_samples = SIZE_MAX);

  // max(RMS of level -> input, RMS of input -> level); +infinity for a level
  // of no area.
  double operator()(const LoopMesh& level) const;

 private:
  const TriangleBvh& input_;
  std::vector<double> input_points_, input_weights_;  // 3 doubles, 1 weight a point
};

}  // namespace qmc
