// The distance of a progressive level to the input that the encoder's closed
// loop measures (src/geometry/level_distance.h, spec 12.10): seed 003 §4.1's
// L2 by the edge-midpoint rule, exact where the other surface is a plane.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/level_distance.h"
#include "geometry/loop_fitting.h"
#include "mesh_generators.h"

namespace qmc {
namespace {

// The 8 x 8 grid over [-1, 1]^2, triangulated, flat at height z: x = 0 and
// every multiple of 1/4 are grid lines.
LoopMesh flat_grid(double z) {
  const Mesh grid = tools::triangulated(tools::make_grid(8, 8));
  LoopMesh m;
  m.positions.assign(grid.positions.begin(), grid.positions.end());
  for (size_t v = 0; v < grid.vertex_count(); ++v) m.positions[3 * v + 2] = z;
  m.triangles = grid.corners;
  return m;
}

// The triangles of `m` whose corners all have x <= 0 (every vertex kept).
LoopMesh left_half(const LoopMesh& m) {
  LoopMesh half = m;
  half.triangles.clear();
  for (size_t f = 0; f < m.face_count(); ++f) {
    bool left = true;
    for (int k = 0; k < 3; ++k) left = left && m.positions[3 * size_t(m.triangles[3 * f + k])] <= 0;
    if (left) half.triangles.insert(half.triangles.end(), &m.triangles[3 * f], &m.triangles[3 * f + 3]);
  }
  return half;
}

TEST(LevelDistance, TheInputItselfIsAtDistanceZero) {
  const LoopMesh input = flat_grid(0);
  const TriangleBvh bvh(loop_mesh_triangles(input));
  EXPECT_EQ(LevelDistance(bvh, input)(input), 0.0);
}

TEST(LevelDistance, AParallelCopyIsItsOffsetAway) {
  const LoopMesh input = flat_grid(0);
  const TriangleBvh bvh(loop_mesh_triangles(input));
  EXPECT_NEAR(LevelDistance(bvh, input)(flat_grid(0.25)), 0.25, 1e-12);
}

// The level lies on the input, so level -> input is 0; the input's right
// half is x away from it: RMS over the whole square, sqrt((1/2) int_0^1 x^2
// dx) = sqrt(1/6). A measure of the level's side alone would call it exact.
TEST(LevelDistance, ALevelCoveringHalfTheInputIsFarFromTheOtherHalf) {
  const LoopMesh input = flat_grid(0);
  const TriangleBvh bvh(loop_mesh_triangles(input));
  EXPECT_NEAR(LevelDistance(bvh, input)(left_half(input)), std::sqrt(1.0 / 6), 1e-12);
}

// A share of the input's midpoints (here about 40 of its 208) stands for
// all of them: on a parallel copy every midpoint is the offset away.
TEST(LevelDistance, AShareOfTheInputsMidpointsMeasuresTheSame) {
  const LoopMesh input = flat_grid(0);
  const TriangleBvh bvh(loop_mesh_triangles(input));
  EXPECT_NEAR(LevelDistance(bvh, input, 40)(flat_grid(-0.5)), 0.5, 1e-12);
}

}  // namespace
}  // namespace qmc
