// The deviation fit of the progressive encoder (src/geometry/deviation_fit.h,
// spec 12.10 informative): how it samples the two surfaces, and that it moves
// a level only where the level strays.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/deviation_fit.h"
#include "geometry/loop_fitting.h"
#include "loop_mesh_support.h"

namespace qmc {
namespace {

LoopMesh grid() { return loop_mesh_of(tools::make_grid(20, 20)); }  // 800 triangles over [-1, 1]^2

// A triangle no longer than the spacing gives its edge midpoints and
// centroid; a longer one the points of a grid of n = ceil(longest / spacing)
// steps a side, a half step apart, corners left out (each vertex is a sample
// once), and its centroid.
TEST(DeviationFit, SamplesALongTriangleOnAGridAsFineAsTheSpacing) {
  LoopMesh two;
  two.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 10, 10, 0, 20, 10, 0, 10, 20, 0};
  two.triangles = {0, 1, 2, 3, 4, 5};
  const std::vector<Vec3d> samples = deviation_samples(two, 2.0);
  // 6 vertices; 3 + 1 for the small triangle; the large one (longest edge
  // 10 sqrt 2, n = 8): the 153 points of a grid of 16 half steps, less 3
  // corners, and the centroid.
  EXPECT_EQ(samples.size(), 6u + 4u + 151u);
  EXPECT_EQ(deviation_samples(two, 0.0).size(), 6u + 4u + 4u);  // no spacing: midpoints and centroids alone
}

TEST(DeviationFit, ALevelOnTheInputStaysWhereItIs) {
  const LoopMesh input = grid();
  const TriangleBvh surface(loop_mesh_triangles(input));
  const std::vector<Vec3d> samples = deviation_samples(input, sample_spacing(input));
  EXPECT_LT(two_sided_deviation(surface, samples, input), 1e-12);  // rounding of the sample points alone
  std::vector<double> positions;
  DeviationFitStats stats;
  ASSERT_TRUE(fit_to_max_deviation(surface, samples, input, {0.01, 20}, &positions, &stats).ok());
  EXPECT_EQ(positions, input.positions);
  EXPECT_EQ(stats.rounds, 0);
}

// A spike of 0.3 on one vertex of the level: the fit brings it back within
// the deviation asked for, and moves no vertex far from it.
TEST(DeviationFit, PullsASpikeBackAndLeavesTheRestAlone) {
  const LoopMesh input = grid();
  LoopMesh level = input;
  const uint32_t tip = 10 * 21 + 10;  // the grid's centre vertex
  level.positions[3 * tip + 2] += 0.3;
  const TriangleBvh surface(loop_mesh_triangles(input));
  const std::vector<Vec3d> samples = deviation_samples(input, sample_spacing(level));
  EXPECT_NEAR(two_sided_deviation(surface, samples, level), 0.3, 0.02);
  std::vector<double> positions;
  DeviationFitStats stats;
  ASSERT_TRUE(fit_to_max_deviation(surface, samples, level, {0.05, 20}, &positions, &stats).ok());
  EXPECT_GE(stats.rounds, 1);
  LoopMesh fitted = level;
  fitted.positions = positions;
  EXPECT_LT(two_sided_deviation(surface, samples, fitted), 0.05);
  for (uint32_t v = 0; v < level.vertex_count(); ++v) {
    const double dx = std::fabs(double(v % 21) - 10), dy = std::fabs(double(v / 21) - 10);
    if (std::max(dx, dy) <= 4) continue;
    for (int a = 0; a < 3; ++a) EXPECT_EQ(positions[3 * v + a], level.positions[3 * v + a]) << "vertex " << v;
  }
}

TEST(DeviationFit, RefusesANonPositiveDeviation) {
  const LoopMesh input = grid();
  const TriangleBvh surface(loop_mesh_triangles(input));
  std::vector<double> positions;
  DeviationFitStats stats;
  EXPECT_FALSE(fit_to_max_deviation(surface, {}, input, {0.0, 10}, &positions, &stats).ok());
  EXPECT_FALSE(fit_to_max_deviation(surface, {}, input, {0.1, 0}, &positions, &stats).ok());
}

}  // namespace
}  // namespace qmc
