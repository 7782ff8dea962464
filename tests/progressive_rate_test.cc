// Rate control of progressive files (spec 12.10, informative): the finest
// level's step scale, the prepare/code split of ProgressiveEncoder, and the
// search of tools/lib/progressive_rate.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh_distance.h"
#include "mesh_generators.h"
#include "progressive_rate.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc {
namespace {

// A triangulated torus with ripples, so that every level has displacements
// to code.
Mesh rippled_torus() {
  Mesh mesh = tools::triangulated(tools::make_torus(48, 24));
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    float* p = &mesh.positions[3 * v];
    const float ripple = 1 + 0.04f * std::sin(9 * std::atan2(p[1], p[0]));
    p[0] *= ripple, p[1] *= ripple;
  }
  return mesh;
}

EncodeOptions progressive(int levels, double step_scale = 1) {
  EncodeOptions o;
  o.progressive_levels = levels;
  o.finest_step_scale = step_scale;
  return o;
}

// A sphere with six limbs, narrow lobes along the axes: the base of K = 3
// (120 triangles) is a round blob, and normals from its subdivision cross the
// limbs far from where the finest level needs its points (spec 12.10).
Mesh six_limbs() {
  Mesh mesh = tools::triangulated(tools::make_refined_sphere(3));
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    float* p = &mesh.positions[3 * v];
    double limbs = 0;
    for (int a = 0; a < 3; ++a) limbs += std::pow(double(p[a]) * p[a], 8);
    for (int a = 0; a < 3; ++a) p[a] = float(p[a] * (1 + 1.5 * limbs));
  }
  return mesh;
}

tools::MeshDistance distance(const Mesh& input, const Mesh& level, size_t samples) {
  tools::MeshDistanceOptions options;
  options.samples = samples;
  tools::MeshDistance d;
  EXPECT_TRUE(tools::measure_mesh_distance(input, level, options, &d).ok());
  return d;
}

double relative_l2(const Mesh& input, const Mesh& level) {
  const tools::MeshDistance d = distance(input, level, 20000);
  return d.relative(d.l2);
}

// Encodes `mesh` with K levels and expects each level nearer the input than
// the one before.
void expect_levels_approach(const Mesh& mesh, int levels, const char* what) {
  std::vector<uint8_t> file;
  ASSERT_TRUE(encode(mesh, progressive(levels), &file).ok());
  DecodedFile decoded;
  ASSERT_TRUE(decode(file.data(), file.size(), &decoded).ok());
  ASSERT_EQ(decoded.levels.size(), size_t(levels) + 1);
  double coarser = relative_l2(mesh, level_mesh(decoded.levels[0]));
  std::printf("%s, K = %d, base: L2 %.3e of the diagonal\n", what, levels, coarser);
  for (int j = 1; j <= levels; ++j) {
    const double l2 = relative_l2(mesh, level_mesh(decoded.levels[j]));
    EXPECT_LT(l2, coarser) << what << ", K = " << levels << ", level " << j;
    std::printf("%s, K = %d, level %d: L2 %.3e of the diagonal\n", what, levels, j, l2);
    coarser = l2;
  }
}

TEST(ProgressiveEncoder, EachLevelOfASixLimbedShapeIsCloserThanTheOneBefore) {
  for (int levels : {3, 4}) expect_levels_approach(six_limbs(), levels, "six limbs");
}

// A torus of 576 triangles at K = 4 has a base of 32 triangles, 16
// vertices (the fewest the encoder simplifies to, spec 12.10), whose
// subdivision sags to a thin ring inside the tube unless it is fitted over
// its subdivision (loop_surface_fit.h).
TEST(ProgressiveEncoder, EachLevelOfATorusFromASixteenVertexBaseIsCloserThanTheOneBefore) {
  expect_levels_approach(tools::triangulated(tools::make_torus(24, 12)), 4, "torus");
}

// 576 / 4^K triangles would be 9 at K = 3, 2 at K = 4, 0 at K = 5; the base
// keeps 32.
TEST(ProgressiveEncoder, TheBaseKeepsAtLeast32Triangles) {
  for (int levels : {3, 4, 5}) {
    std::vector<uint8_t> file;
    EncodeStats stats;
    ASSERT_TRUE(encode(tools::triangulated(tools::make_torus(24, 12)), progressive(levels), &file, &stats).ok());
    EXPECT_EQ(stats.loop.target_base_faces, 32u) << levels;
    EXPECT_EQ(stats.loop.levels[0].faces, stats.loop.target_base_faces) << levels;
    EXPECT_EQ(stats.loop.levels[0].vertices, stats.loop.target_base_faces / 2) << levels;  // a torus: V = F / 2
  }
}

// A cube's 12 triangles: the base keeps half of them (5 vertices), not a
// quarter (a tetrahedron, from which levels 3 - 4 of K = 4 moved away).
TEST(ProgressiveEncoder, EachLevelOfACubeFromAFiveVertexBaseIsCloserThanTheOneBefore) {
  const Mesh cube = tools::triangulated(tools::make_cube());
  std::vector<uint8_t> file;
  EncodeStats stats;
  ASSERT_TRUE(encode(cube, progressive(4), &file, &stats).ok());
  EXPECT_EQ(stats.loop.target_base_faces, 6u);
  EXPECT_EQ(stats.loop.levels[0].vertices, 5u);
  expect_levels_approach(cube, 4, "cube");
}

double relative_hausdorff(const Mesh& input, const Mesh& level) {
  const tools::MeshDistance d = distance(input, level, 50000);
  return d.relative(d.hausdorff);
}

// Section 12.7.2: the six limbs' finest level at K = 3 strays at the limbs'
// tips; with a max deviation the encoder moves it back there, codes the
// moves as corrections (LEVL code 4, format 1.14), and the Hausdorff
// distance falls while L2 does not rise.
TEST(ProgressiveEncoder, MaxDeviationCorrectsWhereTheFinestLevelStrays) {
  const Mesh limbs = six_limbs();
  std::vector<uint8_t> plain, corrected;
  EncodeStats plain_stats, stats;
  ASSERT_TRUE(encode(limbs, progressive(3), &plain, &plain_stats).ok());
  EncodeOptions options = progressive(3);
  options.max_deviation = 2e-3;
  ASSERT_TRUE(encode(limbs, options, &corrected, &stats).ok());
  const LoopLevelStats& finest = stats.loop.levels.back();
  ASSERT_EQ(finest.code, 4);
  EXPECT_GT(finest.corrected_vertices, 0u);
  EXPECT_GT(stats.loop.deviation_before, options.max_deviation);
  EXPECT_LT(stats.loop.deviation_after, 0.6 * stats.loop.deviation_before);
  DecodedFile a, b;
  ASSERT_TRUE(decode(plain.data(), plain.size(), &a).ok());
  ASSERT_TRUE(decode(corrected.data(), corrected.size(), &b).ok());
  EXPECT_EQ(b.version_minor, 14);
  EXPECT_EQ(b.levels.back().corrected_vertices, finest.corrected_vertices);
  for (size_t j = 0; j + 1 < a.levels.size(); ++j) EXPECT_EQ(a.levels[j].positions, b.levels[j].positions) << j;
  const double h_plain = relative_hausdorff(limbs, level_mesh(a.levels.back()));
  const double h_corrected = relative_hausdorff(limbs, level_mesh(b.levels.back()));
  std::printf("six limbs, K = 3: Hausdorff %.3e -> %.3e of the diagonal, %zu -> %zu bytes, %u vertices corrected\n",
              h_plain, h_corrected, plain.size(), corrected.size(), finest.corrected_vertices);
  EXPECT_LT(h_corrected, 0.6 * h_plain);
  EXPECT_LE(relative_l2(limbs, level_mesh(b.levels.back())), relative_l2(limbs, level_mesh(a.levels.back())));
}

// Where the finest level is within the deviation asked for, nothing is
// corrected and the file is the one without the option.
TEST(ProgressiveEncoder, MaxDeviationAlreadyMetAddsNothing) {
  const Mesh torus = rippled_torus();
  std::vector<uint8_t> plain, loose;
  EncodeStats stats;
  ASSERT_TRUE(encode(torus, progressive(2), &plain).ok());
  EncodeOptions options = progressive(2);
  options.max_deviation = 0.5;
  ASSERT_TRUE(encode(torus, options, &loose, &stats).ok());
  EXPECT_EQ(loose, plain);
  EXPECT_LT(stats.loop.deviation_before, 0.5);
  EXPECT_NE(stats.loop.levels.back().code, 4);
}

TEST(ProgressiveEncoder, MaxDeviationIsAProgressiveOptionOfAFractionOfTheDiagonal) {
  std::vector<uint8_t> file;
  EncodeOptions options;
  options.max_deviation = 1e-3;
  EXPECT_EQ(encode(rippled_torus(), options, &file).code(), ErrorCode::kInvalidArgument);
  options = progressive(2);
  for (double bad : {-1e-3, 1.0, double(NAN)}) {
    options.max_deviation = bad;
    EXPECT_EQ(encode(rippled_torus(), options, &file).code(), ErrorCode::kInvalidArgument) << bad;
  }
}

TEST(ProgressiveEncoder, PrepareThenCodeGivesTheBytesOfEncode) {
  const Mesh mesh = rippled_torus();
  std::vector<uint8_t> whole, coded;
  ASSERT_TRUE(encode(mesh, progressive(2), &whole).ok());
  ProgressiveEncoder encoder;
  ASSERT_TRUE(encoder.prepare(mesh, progressive(2)).ok());
  ASSERT_TRUE(encoder.code(progressive(2), &coded).ok());
  EXPECT_EQ(coded, whole);
}

TEST(ProgressiveEncoder, CodesOnlyWhatWasPrepared) {
  ProgressiveEncoder encoder;
  std::vector<uint8_t> out;
  EXPECT_EQ(encoder.code(progressive(2), &out).code(), ErrorCode::kInvalidArgument);  // before prepare()
  ASSERT_TRUE(encoder.prepare(rippled_torus(), progressive(2)).ok());
  EXPECT_EQ(encoder.code(progressive(3), &out).code(), ErrorCode::kInvalidArgument);
}

TEST(ProgressiveEncoder, PrepareChecksTheMeshAsEncodeDoes) {
  Mesh bad_corner = rippled_torus();
  bad_corner.corners[7] = uint32_t(bad_corner.vertex_count());
  Mesh not_finite = rippled_torus();
  not_finite.positions[4] = std::numeric_limits<float>::infinity();
  for (const Mesh& mesh : {bad_corner, not_finite}) {
    ProgressiveEncoder encoder;
    EXPECT_EQ(encoder.prepare(mesh, progressive(1)).code(), ErrorCode::kInvalidArgument);
    std::vector<uint8_t> out;
    EXPECT_EQ(encoder.code(progressive(1), &out).code(), ErrorCode::kInvalidArgument);  // nothing prepared
  }
}

TEST(FinestStepScale, ScalesTheFinestStepAndTheSquareRootBelow) {
  const Mesh mesh = rippled_torus();
  std::vector<uint8_t> plain, coarse;
  EncodeStats a, b;
  ASSERT_TRUE(encode(mesh, progressive(2), &plain, &a).ok());
  ASSERT_TRUE(encode(mesh, progressive(2, 4), &coarse, &b).ok());
  // Level 1 aims at the same targets from the same base: its least-error
  // step is the same, times sqrt(4).
  EXPECT_DOUBLE_EQ(b.loop.levels[1].step, 2 * a.loop.levels[1].step);
  EXPECT_GT(b.loop.levels[2].step, a.loop.levels[2].step);
  EXPECT_LT(coarse.size(), plain.size());
  DecodedFile decoded;
  EXPECT_TRUE(decode(coarse.data(), coarse.size(), &decoded).ok());
}

TEST(FinestStepScale, OutsideOneToSixtyFourIsRefused) {
  const Mesh mesh = rippled_torus();
  std::vector<uint8_t> out;
  for (double scale : {0.5, 64.5, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_EQ(encode(mesh, progressive(1, scale), &out).code(), ErrorCode::kInvalidArgument) << scale;
}

tools::RateSearch small_search() {
  tools::RateSearch s;
  s.levels = {1, 2};
  s.position_bits = {10, 12};
  s.step_scales = {1, 4};
  s.samples = 20000;
  return s;
}

TEST(ProgressiveRate, ErrorTargetGivesTheSmallestMeasuredFileWithinIt) {
  const Mesh mesh = rippled_torus();
  // The error of the most accurate candidate of K = 2, loosened a little:
  // reachable, and not by every candidate.
  tools::RateChoice probe;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {1e-9, 0}, small_search(), {}, &probe).ok());
  double best = 1;
  for (const tools::RatePoint& p : probe.tried)
    if (p.relative_l2 > 0) best = std::min(best, p.relative_l2);
  EXPECT_EQ(probe.chosen, -1);  // 1e-9 is out of reach
  const double target = 1.2 * best;

  tools::RateChoice choice;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {target, 0}, small_search(), {}, &choice).ok());
  ASSERT_GE(choice.chosen, 0);
  const tools::RatePoint& chosen = choice.tried[size_t(choice.chosen)];
  EXPECT_LE(chosen.relative_l2, target);
  EXPECT_EQ(chosen.bytes, choice.bytes.size());
  for (const tools::RatePoint& p : choice.tried) {
    if (p.relative_l2 >= 0 && p.relative_l2 <= target) {
      EXPECT_GE(p.bytes, chosen.bytes);
    }
  }
  EXPECT_NEAR(choice.distance.relative(choice.distance.l2), chosen.relative_l2, 1e-15);
}

// Where the error crosses the target between two scales of the grid, the
// search goes on at their geometric means: with scales {1, 16} and two
// refinements, 4 and then 8 (4 within the target) or 2 (4 not).
TEST(ProgressiveRate, ErrorTargetRefinesTheScaleBetweenTheGrid) {
  const Mesh mesh = rippled_torus();
  tools::RateSearch s;
  s.levels = {1};
  s.position_bits = {12};
  s.samples = 20000;
  const auto l2_at = [&](double scale) {
    tools::RateSearch one = s;
    one.step_scales = {scale};
    tools::RateChoice probe;
    EXPECT_TRUE(tools::choose_progressive(mesh, {}, {1e-9, 0}, one, {}, &probe).ok());
    return probe.tried.back().relative_l2;
  };
  const double fine = l2_at(1), coarse = l2_at(16);
  ASSERT_LT(fine, coarse);
  const double target = std::sqrt(fine * coarse);

  s.step_scales = {1, 16};
  tools::RateChoice grid;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {target, 0}, s, {}, &grid).ok());
  s.refinements = 2;
  tools::RateChoice refined;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {target, 0}, s, {}, &refined).ok());
  std::vector<double> scales;
  for (const tools::RatePoint& p : refined.tried) scales.push_back(p.step_scale);
  ASSERT_EQ(scales.size(), grid.tried.size() + 2);
  EXPECT_EQ(scales[scales.size() - 2], 4.0);
  const tools::RatePoint& at4 = refined.tried[scales.size() - 2];
  const bool four_within = at4.relative_l2 >= 0 ? at4.relative_l2 <= target : true;  // unmeasured: not smaller
  EXPECT_EQ(scales.back(), four_within ? 8.0 : 2.0);
  ASSERT_GE(grid.chosen, 0);
  ASSERT_GE(refined.chosen, 0);
  EXPECT_LE(refined.tried[size_t(refined.chosen)].relative_l2, target);
  EXPECT_LE(refined.bytes.size(), grid.bytes.size());
}

TEST(ProgressiveRate, HausdorffTargetBoundsTheHausdorffDistance) {
  const Mesh mesh = rippled_torus();
  tools::RateChoice probe;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {0, 0, 1e-9}, small_search(), {}, &probe).ok());
  EXPECT_EQ(probe.chosen, -1);
  double best = 1;
  for (const tools::RatePoint& p : probe.tried)
    if (p.relative_hausdorff > 0) best = std::min(best, p.relative_hausdorff);
  const double target = 1.2 * best;
  tools::RateChoice choice;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {0, 0, target}, small_search(), {}, &choice).ok());
  ASSERT_GE(choice.chosen, 0);
  const tools::RatePoint& chosen = choice.tried[size_t(choice.chosen)];
  EXPECT_LE(chosen.relative_hausdorff, target);
  EXPECT_NEAR(choice.distance.relative(choice.distance.hausdorff), chosen.relative_hausdorff, 1e-15);
  for (const tools::RatePoint& p : choice.tried) {
    if (p.relative_hausdorff >= 0 && p.relative_hausdorff <= target) {
      EXPECT_GE(p.bytes, chosen.bytes);
    }
  }
}

TEST(ProgressiveRate, SizeTargetGivesTheMostAccurateFileThatFits) {
  const Mesh mesh = rippled_torus();
  std::vector<uint8_t> reference;
  ASSERT_TRUE(encode(mesh, progressive(2, 4), &reference).ok());
  const uint64_t limit = reference.size() + 200;
  tools::RateChoice choice;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {0, limit}, small_search(), {}, &choice).ok());
  ASSERT_GE(choice.chosen, 0);
  const tools::RatePoint& chosen = choice.tried[size_t(choice.chosen)];
  EXPECT_LE(choice.bytes.size(), limit);
  for (const tools::RatePoint& p : choice.tried) {
    if (p.relative_l2 >= 0) {
      EXPECT_LE(p.bytes, limit);
      EXPECT_GE(p.relative_l2, chosen.relative_l2);
    }
  }
  tools::RateChoice none;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {0, 100}, small_search(), {}, &none).ok());
  EXPECT_EQ(none.chosen, -1);
}

// A size target refines likewise, toward the smallest scale (the most
// accurate file) that fits: between 16 (fits) and 1 (does not), 4, then 2
// (4 fits) or 8 (4 does not).
TEST(ProgressiveRate, SizeTargetRefinesTheScaleBetweenTheGrid) {
  const Mesh mesh = rippled_torus();
  std::vector<uint8_t> fine, coarse;
  ASSERT_TRUE(encode(mesh, progressive(1, 1), &fine).ok());
  ASSERT_TRUE(encode(mesh, progressive(1, 16), &coarse).ok());
  ASSERT_LT(coarse.size(), fine.size());
  const uint64_t limit = (fine.size() + coarse.size()) / 2;
  tools::RateSearch s;
  s.levels = {1};
  s.position_bits = {12};
  s.step_scales = {1, 16};
  s.samples = 20000;
  tools::RateChoice grid;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {0, limit}, s, {}, &grid).ok());
  s.refinements = 2;
  tools::RateChoice refined;
  ASSERT_TRUE(tools::choose_progressive(mesh, {}, {0, limit}, s, {}, &refined).ok());
  ASSERT_GE(grid.chosen, 0);
  ASSERT_GE(refined.chosen, 0);
  std::vector<double> scales;
  for (const tools::RatePoint& p : refined.tried) scales.push_back(p.step_scale);
  ASSERT_EQ(scales.size(), grid.tried.size() + 2);
  const auto tried_at = [&](double scale) { return std::count(scales.begin(), scales.end(), scale) > 0; };
  EXPECT_TRUE(tried_at(4.0));
  std::vector<uint8_t> at4;
  ASSERT_TRUE(encode(mesh, progressive(1, 4), &at4).ok());
  EXPECT_TRUE(tried_at(at4.size() <= limit ? 2.0 : 8.0));
  EXPECT_LE(refined.bytes.size(), limit);
  EXPECT_LE(refined.tried[size_t(refined.chosen)].step_scale, 16.0);
  EXPECT_LE(refined.tried[size_t(refined.chosen)].relative_l2, grid.tried[size_t(grid.chosen)].relative_l2);
}

TEST(ProgressiveRate, DefaultLevelsKeepAThousandBaseTriangles) {
  EXPECT_EQ(tools::default_progressive_levels(69451), 3);  // stanford-bunny: base 1,085
  EXPECT_EQ(tools::default_progressive_levels(29170), 2);  // armadillo: 1,823 (K = 3 would leave 455)
  EXPECT_EQ(tools::default_progressive_levels(9000), 1);   // fertility
  EXPECT_EQ(tools::default_progressive_levels(4000), 1);   // 1,000 at K = 1
  EXPECT_EQ(tools::default_progressive_levels(100), 1);    // at least one level
  EXPECT_EQ(tools::default_progressive_levels(size_t(1) << 40), 8);
}

TEST(ProgressiveRate, OneTargetExactly) {
  tools::RateChoice choice;
  EXPECT_EQ(tools::choose_progressive(rippled_torus(), {}, {1e-3, 1000}, small_search(), {}, &choice).code(),
            ErrorCode::kInvalidArgument);
  EXPECT_EQ(tools::choose_progressive(rippled_torus(), {}, {0, 0}, small_search(), {}, &choice).code(),
            ErrorCode::kInvalidArgument);
  EXPECT_EQ(tools::choose_progressive(rippled_torus(), {}, {1e-3, 0, 1e-3}, small_search(), {}, &choice).code(),
            ErrorCode::kInvalidArgument);
}

}  // namespace
}  // namespace qmc
