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

// The triangles of `m` whose corners all have x <= `most` (every vertex kept).
LoopMesh left_part(const LoopMesh& m, double most) {
  LoopMesh half = m;
  half.triangles.clear();
  for (size_t f = 0; f < m.face_count(); ++f) {
    bool left = true;
    for (int k = 0; k < 3; ++k) left = left && m.positions[3 * size_t(m.triangles[3 * f + k])] <= most;
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
  EXPECT_NEAR(LevelDistance(bvh, input)(left_part(input, 0)), std::sqrt(1.0 / 6), 1e-12);
}

// A share of the input's midpoints (here about 40 of its 208) stands for
// all of them: on a parallel copy every midpoint is the offset away.
TEST(LevelDistance, AShareOfTheInputsMidpointsMeasuresTheSame) {
  const LoopMesh input = flat_grid(0);
  const TriangleBvh bvh(loop_mesh_triangles(input));
  EXPECT_NEAR(LevelDistance(bvh, input, 40)(flat_grid(-0.5)), 0.5, 1e-12);
}

// A level of two triangles over the square, the input the part x <= 1/2 of
// it: the level is max(x - 1/2, 0) away, RMS sqrt((1/4) 2 int_{1/2}^1
// (x - 1/2)^2 dx) = sqrt(1/48) = 0.1443. The midpoint rule on the level's
// own five edges finds 1/2 at one midpoint and 0 at the others: sqrt(1/24) =
// 0.2041. The measure cuts a coarse level's triangles (and those of a small
// input) into fours until there are thousands of them.
TEST(LevelDistance, ACoarseLevelIsMeasuredOverItsTrianglesNotOnlyAtItsEdges) {
  const LoopMesh input = left_part(flat_grid(0), 0.5);
  const TriangleBvh bvh(loop_mesh_triangles(input));
  LoopMesh level;
  level.positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  level.triangles = {0, 1, 2, 0, 2, 3};
  EXPECT_NEAR(LevelDistance(bvh, input)(level), std::sqrt(1.0 / 48), 1e-3);
}

}  // namespace
}  // namespace qmc
