// POSN method 14 (spec section 14.15): the surface lattice. The fine axis
// and the lattice's bucket on the spec's example, and round trips of the
// encoder's placement: every vertex within k steps per axis of its input,
// the surfaces as near each other as the grid's, fewer bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "common/geometry_order.h"
#include "common/position_coding.h"
#include "common/surface_lattice.h"
#include "common/vertex_prediction.h"
#include "mesh_distance.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "random_polygon_mesh.h"
#include "roundtrip_check.h"
#include "surface_lattice_choice.h"

namespace qmc {
namespace {

// 14.15's example: v = 4 at P = (100, 200, 300), in the faces (4, 0, 1) and
// (4, 2, 3), so that along(f, 0, +1) and along(f, 0, -1) of v's corners are
// u = 0, w = 1 and u = 2, w = 3.
struct SpecExample {
  SpecExample() {
    corners.build(5, {3, 3}, {4, 0, 1, 4, 2, 3});
    q = {110, 200, 301, 100, 212, 299, 100, 188, 302, 90, 200, 300, 0, 0, 0};
  }
  VertexCorners corners;
  std::vector<uint32_t> q;
  const int64_t P[3] = {100, 200, 300};
};

TEST(SurfaceLattice, SpecExampleFineAxisIsX) {
  SpecExample e;
  const PredictionVisit visit(e.corners, PredictionOrder::kLabels);
  // N = (-12, 10, 120) + (0, -20, -120) = (-12, -10, 0): x.
  EXPECT_EQ(lattice_fine_axis(visit, 4, 4, e.q.data(), e.P), 0);
}

TEST(SurfaceLattice, CornersWithANeighbourNotDecodedDoNotCount) {
  SpecExample e;
  const PredictionVisit visit(e.corners, PredictionOrder::kLabels);
  // Visited third (labels 0 .. 2 decoded): the second corner's w = 3 is not,
  // so N = (-12, 10, 120) alone: z.
  EXPECT_EQ(lattice_fine_axis(visit, 4, 3, e.q.data(), e.P), 2);
  // Visited second: no corner has both neighbours decoded, N = 0, no lattice.
  EXPECT_EQ(lattice_fine_axis(visit, 4, 1, e.q.data(), e.P), -1);
}

TEST(SurfaceLattice, SpecExampleBuckets) {
  // t0 = 22; x (fine): bitlen(22) = 5. y after r_x = -3: t = floor((22 + 9) / 2) = 15,
  // coarse with k = 4: bitlen(floor(15 / 4)) = 2.
  const uint32_t magnitude[3] = {3, 0, 0};
  EXPECT_EQ(position_bucket(22, magnitude, 0), 5);
  EXPECT_EQ(position_estimate(22, magnitude, 1), 15u);
  EXPECT_EQ(estimate_bucket(position_estimate(22, magnitude, 1) / 4), 2);
}

TEST(SurfaceLattice, FlatNeighboursAlongZKeepZFine) {
  // A fan in the plane z = 7 around P: every cross product lies along z.
  VertexCorners corners;
  corners.build(5, {3, 3, 3}, {4, 0, 1, 4, 1, 2, 4, 2, 3});
  const std::vector<uint32_t> q = {30, 10, 7, 20, 30, 7, 5, 20, 7, 5, 5, 7, 0, 0, 0};
  const PredictionVisit visit(corners, PredictionOrder::kLabels);
  const int64_t P[3] = {15, 15, 7};
  EXPECT_EQ(lattice_fine_axis(visit, 4, 4, q.data(), P), 2);
}

DecodedFile encode_and_decode(const Mesh& mesh, const EncodeOptions& options, EncodeStats* stats) {
  std::vector<uint8_t> bytes;
  EXPECT_TRUE(encode(mesh, options, &bytes, stats).ok());
  DecodedFile file;
  EXPECT_TRUE(decode(bytes.data(), bytes.size(), &file).ok());
  return file;
}

size_t posn_bytes(const EncodeStats& stats) {
  for (const ChunkStats& c : stats.chunks)
    if (c.type == kChunkPositions) return size_t(c.bytes);
  return 0;
}

double surface_l2(const Mesh& a, const Mesh& b) {
  tools::MeshDistanceOptions options;
  options.samples = 20000;
  tools::MeshDistance d;
  EXPECT_TRUE(tools::measure_mesh_distance(a, b, options, &d).ok());
  return d.l2;
}

// A smooth sphere of 10,242 vertices (residuals of a few grid steps) and its
// file on the 12-bit grid.
struct SmoothSphere {
  const Mesh sphere = tools::make_jittered_sphere(5, 0.01f, 3);
  EncodeOptions grid = [] {
    EncodeOptions o;
    o.position_bits = 12;
    return o;
  }();
  EncodeStats grid_stats;
  const DecodedFile on_grid = encode_and_decode(sphere, grid, &grid_stats);
};

TEST(SurfaceLattice, EncoderPlacesVerticesWithinKStepsAndCodesFewerBytes) {
  const SmoothSphere s;
  const Mesh& sphere = s.sphere;
  const EncodeStats& grid_stats = s.grid_stats;
  for (int k : {2, 4}) {
    EncodeOptions options = s.grid;
    options.surface_lattice = k;
    EncodeStats stats;
    const DecodedFile file = encode_and_decode(sphere, options, &stats);
    EXPECT_EQ(stats.positions.method, 14);
    EXPECT_EQ(file.quantization.method, 14);
    EXPECT_EQ(file.quantization.lattice, k);
    EXPECT_EQ(file.version_minor, 19);
    // The faces as they were, every vertex within k steps per axis (the check's bound).
    const tools::RoundTripReport report = tools::check_round_trip(sphere, file);
    EXPECT_TRUE(report.ok()) << k << ": " << report.face_mismatch << report.position_mismatch;
    EXPECT_LT(posn_bytes(stats), posn_bytes(grid_stats)) << k;
    EXPECT_EQ(stats.positions.lattice_payload_bytes + 12, posn_bytes(stats)) << k;
    EXPECT_EQ(stats.positions.grid_payload_bytes + 12, posn_bytes(grid_stats)) << k;
    // Moves along the surface: some vertex more than half a step from its grid point.
    EXPECT_GT(report.max_error, 0.5 * grid_stats.positions.error_bound) << k;
  }
}

TEST(SurfaceLattice, TheGridIsKeptWhereTheLatticeCostsMore) {
  // On this smooth sphere the residuals span a few steps: with k = 16 the fine
  // axis moves further than the coarse ones save, and the grid's file is kept.
  const SmoothSphere s;
  EncodeOptions options = s.grid;
  options.surface_lattice = 16;
  EncodeStats stats;
  const DecodedFile file = encode_and_decode(s.sphere, options, &stats);
  EXPECT_EQ(stats.positions.method, s.grid_stats.positions.method);
  EXPECT_EQ(file.quantization.lattice, 1);
  EXPECT_EQ(file.quantized, s.on_grid.quantized);
  EXPECT_GT(stats.positions.lattice_payload_bytes, stats.positions.grid_payload_bytes);
  EXPECT_EQ(stats.positions.grid_payload_bytes + 12, posn_bytes(s.grid_stats));
}

TEST(SurfaceLattice, SurfacesStayAsNearAsTheGridsAtFourSteps) {
  const Mesh sphere = tools::make_jittered_sphere(5, 0.01f, 5);
  EncodeOptions options;
  options.position_bits = 10;
  EncodeStats stats;
  const double grid_l2 = surface_l2(sphere, encode_and_decode(sphere, options, &stats).mesh);
  options.surface_lattice = 4;
  const double lattice_l2 = surface_l2(sphere, encode_and_decode(sphere, options, &stats).mesh);
  EXPECT_LT(lattice_l2, 1.3 * grid_l2);
}

TEST(SurfaceLattice, RandomPolygonMeshesRoundTrip) {
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    RandomPolygonMeshOptions shape;
    shape.seed = seed;
    shape.components = 1 + int(seed % 3);
    shape.genus = int(seed % 2);
    shape.holes = int(seed % 4);
    shape.non_manifold = seed % 5 == 0;
    shape.isolated_vertices = int(seed % 3);
    const Mesh mesh = make_random_polygon_mesh(shape);
    EncodeOptions options;
    options.position_bits = 8 + int(seed % 9);
    options.surface_lattice = 2 + int(seed % 15);
    std::vector<uint8_t> bytes;
    EncodeStats stats;
    ASSERT_TRUE(encode(mesh, options, &bytes, &stats).ok()) << seed;
    DecodedFile file;
    ASSERT_TRUE(decode(bytes.data(), bytes.size(), &file).ok()) << seed;
    const tools::RoundTripReport report = tools::check_round_trip(mesh, file);
    EXPECT_TRUE(report.ok()) << seed << ": " << report.face_mismatch << report.position_mismatch;
  }
}

// --surface-lattice auto at 12 bits, 20,000 samples a distance: the factor
// kept and every file tried.
struct LatticeChoice {
  int factor = 0;
  std::vector<tools::LatticeTrial> trials;
};
LatticeChoice choose_at_12_bits(const Mesh& mesh) {
  EncodeOptions options;
  options.position_bits = 12;
  LatticeChoice choice;
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  const Status s = tools::choose_surface_lattice(mesh, options, 20000, &choice.factor, &bytes, &stats, &choice.trials);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return choice;
}

TEST(SurfaceLatticeChoice, AJitteredSphereTakesTheSmallestFileWithinTheGridsL2) {
  // qmc-meshgen jittered-sphere 4 5
  const LatticeChoice choice = choose_at_12_bits(tools::make_jittered_sphere(4, 0.3f, 5));
  const int factor = choice.factor;
  const std::vector<tools::LatticeTrial>& trials = choice.trials;
  ASSERT_EQ(trials.size(), 1 + std::size(tools::kLatticeTrialFactors));
  const tools::LatticeTrial& grid = trials.front();
  EXPECT_EQ(grid.factor, 1);
  ASSERT_GT(factor, 1);
  // No smaller lattice file within the grid's L2 was passed over.
  const auto chosen = std::find_if(trials.begin(), trials.end(),
                                   [&](const tools::LatticeTrial& t) { return t.factor == factor; });
  ASSERT_NE(chosen, trials.end());
  EXPECT_TRUE(chosen->on_lattice);
  EXPECT_LE(chosen->l2, grid.l2);
  EXPECT_LT(chosen->bytes, grid.bytes);
  for (const tools::LatticeTrial& t : trials) {
    if (t.on_lattice && t.l2 <= grid.l2) {
      EXPECT_GE(t.bytes, chosen->bytes) << t.factor;
    }
  }
}

TEST(SurfaceLatticeChoice, ARegularTorusKeepsTheGrid) {
  EXPECT_EQ(choose_at_12_bits(tools::triangulated(tools::make_torus(48, 24))).factor, 1);
}

TEST(SurfaceLattice, GridsOfMoreThan24BitsAreRefused) {
  EncodeOptions options;
  options.position_bits = 25;
  options.surface_lattice = 4;
  std::vector<uint8_t> bytes;
  const Status s = encode(tools::make_refined_sphere(1), options, &bytes);
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("2^24"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace qmc
