// Known-answer tests for the error metrics used by the benchmarks.
#include "mesh_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using qmc::Mesh;
using qmc::tools::correspondence_error;
using qmc::tools::ErrorMetrics;
using qmc::tools::nearest_vertex_error;

// Unit cube corners plus one unreferenced vertex at the centre; one quad
// face so the mesh is not pure geometry.
Mesh cube_corners() {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.positions.push_back(static_cast<float>(i & 1));
    m.positions.push_back(static_cast<float>((i >> 1) & 1));
    m.positions.push_back(static_cast<float>((i >> 2) & 1));
  }
  m.positions.insert(m.positions.end(), {0.5f, 0.5f, 0.5f});
  m.face_sizes = {4};
  m.corners = {0, 1, 3, 2};
  return m;
}

Mesh shifted(const Mesh& m, float dx, float dy, float dz) {
  Mesh out = m;
  for (size_t i = 0; i < out.vertex_count(); ++i) {
    out.positions[3 * i] += dx;
    out.positions[3 * i + 1] += dy;
    out.positions[3 * i + 2] += dz;
  }
  return out;
}

// Returns a copy whose vertex i is m's vertex order[i].
Mesh permuted(const Mesh& m, const std::vector<uint32_t>& order) {
  Mesh out;
  for (uint32_t o : order) {
    for (int a = 0; a < 3; ++a) out.positions.push_back(m.positions[3 * o + a]);
  }
  return out;
}

std::vector<uint32_t> reversed_order(size_t n) {
  std::vector<uint32_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = static_cast<uint32_t>(n - 1 - i);
  return order;
}

TEST(MeshMetrics, BoundingBoxOfOriginal) {
  const Mesh m = shifted(cube_corners(), 10, 0, 0);
  const ErrorMetrics e = nearest_vertex_error(m, m);
  EXPECT_DOUBLE_EQ(e.max_bbox_side, 1.0);
  EXPECT_DOUBLE_EQ(e.bbox_diagonal, std::sqrt(3.0));
  EXPECT_EQ(e.compared, 9u);
  EXPECT_EQ(e.max_error, 0.0);
  EXPECT_EQ(e.rms_error, 0.0);
}

TEST(MeshMetrics, CorrespondenceOfShiftedCopy) {
  const Mesh m = cube_corners();
  const Mesh d = shifted(m, 0.03f, 0.04f, 0);  // every vertex moves by 0.05
  std::vector<uint32_t> identity(m.vertex_count());
  for (size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<uint32_t>(i);
  const ErrorMetrics e = correspondence_error(m, d, identity);
  EXPECT_EQ(e.compared, 9u);
  EXPECT_NEAR(e.max_error, 0.05, 1e-6);
  EXPECT_NEAR(e.rms_error, 0.05, 1e-6);
}

TEST(MeshMetrics, CorrespondenceOfPermutedCopyIsExact) {
  const Mesh m = cube_corners();
  const auto order = reversed_order(m.vertex_count());
  const ErrorMetrics e = correspondence_error(m, permuted(m, order), order);
  EXPECT_EQ(e.compared, 9u);
  EXPECT_EQ(e.max_error, 0.0);
}

TEST(MeshMetrics, CorrespondenceWithWrongMappingSeesTheError) {
  const Mesh m = cube_corners();
  const auto order = reversed_order(m.vertex_count());
  std::vector<uint32_t> identity(m.vertex_count());
  for (size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<uint32_t>(i);
  // Decoded vertex i is original 8 - i but is claimed to be original i; the
  // worst pair, e.g. (1,1,1) against (1,0,0), is a face diagonal apart.
  const ErrorMetrics e = correspondence_error(m, permuted(m, order), identity);
  EXPECT_NEAR(e.max_error, std::sqrt(2.0), 1e-6);
}

TEST(MeshMetrics, CorrespondenceContractViolationsAreInfinite) {
  const Mesh m = cube_corners();
  const std::vector<uint32_t> too_short = {0, 1};
  EXPECT_TRUE(std::isinf(correspondence_error(m, m, too_short).max_error));
  std::vector<uint32_t> out_of_range(m.vertex_count(), 0);
  out_of_range[3] = 1000;
  const ErrorMetrics e = correspondence_error(m, m, out_of_range);
  EXPECT_TRUE(std::isinf(e.max_error));
  EXPECT_EQ(e.compared, 9u);
}

TEST(MeshMetrics, NearestOfShiftedCopy) {
  // Shift 0.1 along x: each original vertex's nearest decoded vertex is its
  // own shifted copy (others are at least 0.4 away).
  const Mesh m = cube_corners();
  const ErrorMetrics e = nearest_vertex_error(m, shifted(m, 0.1f, 0, 0));
  EXPECT_EQ(e.compared, 9u);
  EXPECT_NEAR(e.max_error, 0.1, 1e-6);
  EXPECT_NEAR(e.rms_error, 0.1, 1e-6);
}

TEST(MeshMetrics, NearestIgnoresVertexOrder) {
  const Mesh m = cube_corners();
  const ErrorMetrics e = nearest_vertex_error(m, permuted(m, reversed_order(m.vertex_count())));
  EXPECT_EQ(e.max_error, 0.0);
}

TEST(MeshMetrics, NearestCountsUnreferencedAndMissingVertices) {
  // Decoded lost the unreferenced centre vertex: its nearest is a corner.
  const Mesh m = cube_corners();
  Mesh d = m;
  d.positions.resize(8 * 3);
  const ErrorMetrics e = nearest_vertex_error(m, d);
  EXPECT_EQ(e.compared, 9u);
  EXPECT_NEAR(e.max_error, std::sqrt(0.75), 1e-6);
  EXPECT_NEAR(e.rms_error, std::sqrt(0.75 / 9), 1e-6);
}

TEST(MeshMetrics, NearestForQueriesFarOutsideDecodedBox) {
  Mesh m;
  m.positions = {100, 0, 0, -50, 0, 0};
  const Mesh d = cube_corners();
  const ErrorMetrics e = nearest_vertex_error(m, d);
  EXPECT_NEAR(e.max_error, std::sqrt(99.0 * 99.0 + 0), 1e-4);  // (100,0,0) to (1,0,0)
  EXPECT_NEAR(e.rms_error, std::sqrt((99.0 * 99.0 + 50.0 * 50.0) / 2), 1e-4);
}

TEST(MeshMetrics, EmptyMeshes) {
  const Mesh empty;
  const ErrorMetrics both = nearest_vertex_error(empty, empty);
  EXPECT_EQ(both.compared, 0u);
  EXPECT_EQ(both.max_error, 0.0);
  EXPECT_EQ(both.rms_error, 0.0);
  EXPECT_EQ(both.bbox_diagonal, 0.0);
  EXPECT_EQ(correspondence_error(empty, empty, {}).compared, 0u);

  // Nothing decoded for a non-empty original: nothing to be near to.
  const ErrorMetrics lost = nearest_vertex_error(cube_corners(), empty);
  EXPECT_EQ(lost.compared, 9u);
  EXPECT_TRUE(std::isinf(lost.max_error));

  // Nothing in the original: no distances, whatever was decoded.
  EXPECT_EQ(nearest_vertex_error(empty, cube_corners()).compared, 0u);
}

TEST(MeshMetrics, FlatMeshDoesNotDegenerateTheGrid) {
  // All points in the z = 0 plane on a 100 x 100 lattice; decoded is offset
  // by 0.25 in z so every nearest distance is exactly 0.25.
  Mesh m;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) m.positions.insert(m.positions.end(), {float(x), float(y), 0});
  }
  const ErrorMetrics e = nearest_vertex_error(m, shifted(m, 0, 0, 0.25f));
  EXPECT_EQ(e.compared, 10000u);
  EXPECT_NEAR(e.max_error, 0.25, 1e-6);
  EXPECT_NEAR(e.rms_error, 0.25, 1e-6);
}

TEST(MeshMetrics, NearestMatchesBruteForceOnRandomClouds) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> uniform(-1, 1);
  std::exponential_distribution<float> clustered(8);  // dense near 0, sparse tail
  Mesh original, decoded;
  for (int i = 0; i < 2000; ++i) {
    for (int a = 0; a < 3; ++a) original.positions.push_back(uniform(rng) * 1.2f);
  }
  for (int i = 0; i < 1500; ++i) {
    for (int a = 0; a < 3; ++a) decoded.positions.push_back(clustered(rng) * (a == 1 ? -1 : 1));
  }
  double max_d2 = 0, sum_d2 = 0;
  for (size_t i = 0; i < original.vertex_count(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < decoded.vertex_count(); ++j) {
      double d2 = 0;
      for (int a = 0; a < 3; ++a) {
        const double d = double(original.positions[3 * i + a]) - decoded.positions[3 * j + a];
        d2 += d * d;
      }
      best = std::min(best, d2);
    }
    max_d2 = std::max(max_d2, best);
    sum_d2 += best;
  }
  const ErrorMetrics e = nearest_vertex_error(original, decoded);
  EXPECT_DOUBLE_EQ(e.max_error, std::sqrt(max_d2));
  EXPECT_NEAR(e.rms_error, std::sqrt(sum_d2 / 2000), 1e-12);
}

}  // namespace
