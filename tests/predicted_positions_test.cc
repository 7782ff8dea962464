// POSN method 1 (spec section 14): the prediction rules on the spec's own
// example and on shapes they are exact for, the mask decisions, the grids
// users can state, and round trips through encode and decode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>

#include "common/geometry_order.h"
#include "common/position_coding.h"
#include "common/range_coder.h"
#include "common/vertex_prediction.h"
#include "decoder/position_decoder.h"
#include "encoder/position_encoder.h"
#include "encoder/residual_costs.h"
#include "geometry_order_rule.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "roundtrip_check.h"

namespace qmc {
namespace {

constexpr int64_t kOne = 65536;
const uint32_t kTop[3] = {4095, 4095, 4095};

// 14.3.2's activity of each vertex from its three residuals.
std::vector<uint32_t> activity_of(const std::vector<int32_t>& residual) {
  std::vector<uint32_t> activity(residual.size() / 3, 0);
  for (size_t i = 0; i < residual.size(); ++i) activity[i / 3] += uint32_t(std::abs(residual[i]));
  return activity;
}

VertexPrediction predict(const Mesh& faces, uint32_t v, const std::vector<uint32_t>& q,
                         const std::vector<int32_t>& residual) {
  VertexCorners corners;
  corners.build(uint32_t(q.size() / 3), faces.face_sizes, faces.corners);
  VertexPrediction p;
  predict_vertex(corners, v, q.data(), activity_of(residual).data(), kTop, &p);
  return p;
}

Mesh faces(std::vector<uint32_t> sizes, std::vector<uint32_t> corners) {
  Mesh m;
  m.face_sizes = std::move(sizes);
  m.corners = std::move(corners);
  return m;
}

// Spec 14.3.4, step by step.
TEST(PredictedPositions, SpecWorkedExample) {
  const Mesh two = faces({3, 3}, {0, 1, 2, 2, 1, 3});
  const std::vector<uint32_t> q = {10, 10, 5, 20, 10, 5, 15, 20, 5, 0, 0, 0};
  const std::vector<int32_t> r = {0, 0, 0, 3, -1, 0, 0, 2, 2, 0, 0, 0};
  VertexPrediction p = predict(two, 3, q, r);
  ASSERT_EQ(p.candidates, 1);
  EXPECT_EQ(p.candidate[0][0], 25 * kOne);
  EXPECT_EQ(p.candidate[0][1], 20 * kOne);
  EXPECT_EQ(p.candidate[0][2], 5 * kOne);
  EXPECT_EQ(p.scale, 10u);
  VertexPrediction none = p;  // no candidate selected: 14.3.2's fallback, the neighbours' mean
  select_candidates(&none, 0, kTop);
  EXPECT_EQ(none.kind, PredictionKind::kNeighbours);
  EXPECT_EQ(none.value[0], 18);  // (20 + 15) / 2 rounded half up
  EXPECT_EQ(none.value[1], 15);
  EXPECT_EQ(none.value[2], 5);
  EXPECT_EQ(p.neighbour_activity, 4u);
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.kind, PredictionKind::kSingle);
  EXPECT_EQ(p.value[0], 25);
  EXPECT_EQ(p.value[1], 20);
  EXPECT_EQ(p.value[2], 5);
}

// Without decoded neighbours: the previous vertex, and for vertex 0 the
// middle of the grid (14.3.2).
TEST(PredictedPositions, FallbackWithoutNeighbours) {
  const Mesh none;
  const std::vector<uint32_t> q = {7, 8, 9, 0, 0, 0};
  const std::vector<int32_t> r = {1, -2, 3, 0, 0, 0};
  VertexPrediction first = predict(none, 0, q, r);
  select_candidates(&first, 0, kTop);
  EXPECT_EQ(first.kind, PredictionKind::kPrevious);
  EXPECT_EQ(first.value[0], 2047);
  VertexPrediction second = predict(none, 1, q, r);
  select_candidates(&second, 0, kTop);
  EXPECT_EQ(second.value[0], 7);
  EXPECT_EQ(second.value[2], 9);
  EXPECT_EQ(second.neighbour_activity, 6u);  // |r| of vertex 0
}

// 14.3.1: the backward run of a quad is the parallelogram, exact on one.
TEST(PredictedPositions, QuadRunIsExactOnAParallelogram) {
  const Mesh quad = faces({4}, {0, 1, 2, 3});
  const std::vector<uint32_t> q = {100, 100, 50, 300, 120, 60, 350, 400, 90, 0, 0, 0};
  VertexPrediction p = predict(quad, 3, q, std::vector<int32_t>(12, 0));
  ASSERT_EQ(p.candidates, 1);  // d = 4: no forward run
  EXPECT_EQ(p.weight[0], 2);
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.value[0], 100 + 350 - 300);
  EXPECT_EQ(p.value[1], 100 + 400 - 120);
  EXPECT_EQ(p.value[2], 50 + 90 - 60);
}

// 14.3.1: c_5 makes the run exact (to rounding) on a regular pentagon.
TEST(PredictedPositions, PentagonRunFollowsARegularPentagon) {
  const Mesh pentagon = faces({5}, {0, 1, 2, 3, 4});
  std::vector<uint32_t> q;
  for (int k = 0; k < 5; ++k) {
    const double angle = 2 * M_PI * k / 5;
    q.insert(q.end(), {uint32_t(std::lround(2000 + 1000 * std::cos(angle))),
                       uint32_t(std::lround(2000 + 1000 * std::sin(angle))), 7});
  }
  VertexPrediction p = predict(pentagon, 4, q, std::vector<int32_t>(15, 0));
  ASSERT_EQ(p.candidates, 2);  // backward (3, 2, 1) and forward (0, 1, 2), both decoded
  for (unsigned mask : {1u, 2u, 3u}) {
    select_candidates(&p, mask, kTop);
    EXPECT_NEAR(double(p.value[0]), double(q[12]), 3.0) << mask;
    EXPECT_NEAR(double(p.value[1]), double(q[13]), 3.0) << mask;
    EXPECT_EQ(p.value[2], 7);
  }
}

// 14.3.1: a quad strip continued across the edge (p1, p2): 2 p1 - y.
TEST(PredictedPositions, StripContinuesAcrossAnEdge) {
  // Quad 0 = (0, 1, 2, 3) below, quad 1 = (0, 4, 5, 1) above, on a grid:
  //   4 5      y = 110
  //   0 1      y = 100
  //   3 2      y = 90
  const Mesh strip = faces({4, 4}, {0, 1, 2, 3, 0, 4, 5, 1});
  const std::vector<uint32_t> q = {100, 100, 0, 110, 100, 0, 110, 90, 0, 100, 90, 0, 0, 0, 0, 0, 0, 0};
  VertexPrediction p = predict(strip, 4, q, std::vector<int32_t>(18, 0));
  ASSERT_EQ(p.candidates, 1);  // along -1 is 0, along -2 is 1: the strip over quad 0 gives 2 q0 - q3
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.value[0], 100);
  EXPECT_EQ(p.value[1], 110);
}

// 14.2: at most 8 corners are examined per search. Degenerate triangles
// (0, 1, 0) use them up before the triangle (0, 1, 2) across which vertex
// 3's parallelogram lies.
TEST(PredictedPositions, SearchExaminesAtMostEightCorners) {
  for (int degenerate : {7, 8}) {
    Mesh m;
    for (int i = 0; i < degenerate; ++i) {
      m.face_sizes.push_back(3);
      m.corners.insert(m.corners.end(), {0, 1, 0});
    }
    m.face_sizes.insert(m.face_sizes.end(), {3, 3});
    m.corners.insert(m.corners.end(), {0, 1, 2, 1, 0, 3});
    const std::vector<uint32_t> q = {0, 0, 0, 100, 0, 0, 50, 100, 0, 0, 0, 0};
    const VertexPrediction p = predict(m, 3, q, std::vector<int32_t>(12, 0));
    EXPECT_EQ(p.candidates, degenerate == 7 ? 1 : 0) << degenerate << " degenerate faces";
  }
}

// A mesh of triangles only finds its corners' neighbours without per-corner
// tables. The same triangles with a quad on four further vertices take the
// general path; every prediction of the triangles' vertices is the same.
TEST(PredictedPositions, TrianglesOnlyMeshPredictsAsTheGeneralTablesDo) {
  tools::RandomSoupOptions soup;
  soup.vertices = 60;
  soup.faces = 400;  // some vertices of more than 12 corners: sorted links
  soup.min_degree = soup.max_degree = 3;
  for (const Mesh& triangles : {tools::make_random_soup(7, soup), tools::triangulated(tools::make_torus(9, 5)),
                                tools::make_vertex_star(20), tools::make_book(5)}) {
    const uint32_t n = uint32_t(triangles.vertex_count());
    Mesh mixed = triangles;
    mixed.face_sizes.push_back(4);
    mixed.corners.insert(mixed.corners.end(), {n, n + 1, n + 2, n + 3});
    VertexCorners fast, general;
    fast.build(n, triangles.face_sizes, triangles.corners);
    general.build(n + 4, mixed.face_sizes, mixed.corners);
    for (uint32_t k = 0; k < triangles.corners.size(); ++k) {
      ASSERT_EQ(fast.face(k), general.face(k));
      ASSERT_EQ(fast.degree(k), 3u);
      for (int step = -3; step <= 3; ++step) ASSERT_EQ(fast.along(k, step), general.along(k, step)) << k << " " << step;
    }
    std::vector<uint32_t> q;
    std::vector<int32_t> residual;
    for (uint32_t i = 0; i < 3 * (n + 4); ++i) {
      q.push_back(uint32_t((uint64_t(i) * 2654435761u) % 4096));
      residual.push_back(int32_t(i % 7) - 3);
    }
    for (uint32_t v = 0; v < n; ++v) {
      VertexPrediction a, b;
      predict_vertex(fast, v, q.data(), activity_of(residual).data(), kTop, &a);
      predict_vertex(general, v, q.data(), activity_of(residual).data(), kTop, &b);
      ASSERT_EQ(a.candidates, b.candidates) << "vertex " << v;
      for (int c = 0; c < a.candidates; ++c) {
        EXPECT_EQ(a.weight[c], b.weight[c]);
        for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(a.candidate[c][axis], b.candidate[c][axis]);
      }
      select_candidates(&a, 0, kTop);  // the fallbacks
      select_candidates(&b, 0, kTop);
      for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(a.value[axis], b.value[axis]);
      EXPECT_EQ(a.neighbour_activity, b.neighbour_activity);
      EXPECT_EQ(a.scale, b.scale);
    }
  }
}

// 14.4: the mask decisions round trip, the last bit implied when no other is set.
TEST(PredictedPositions, CandidateMaskDecisions) {
  PositionResidualModel encoder_model(kTop), decoder_model(kTop);
  RangeEncoder enc;
  const int counts[] = {2, 3, 4, 4, 2, 1, 0};
  const unsigned masks[] = {2, 5, 8, 15, 1, 1, 0};
  for (int i = 0; i < 7; ++i) EXPECT_EQ(code_candidate_mask(&enc, &encoder_model, counts[i], masks[i]), masks[i]);
  const std::vector<uint8_t> bytes = enc.finish();
  RangeDecoder dec(bytes.data(), bytes.size());
  for (int i = 0; i < 7; ++i) EXPECT_EQ(code_candidate_mask(&dec, &decoder_model, counts[i], 0), masks[i]) << i;
  EXPECT_EQ(dec.unread(), 0u);
  EXPECT_FALSE(dec.overrun());
}

// 14.4.1's example: in method 3, bucket 5's "class > j" starts at 150 for
// j = 0 (e = -4, clamped to -3), 1200 for j = 4 (e = 0), 1700 for j = 5 and
// 1950 from j = 7 on; the same in every group. Method 1 starts all at 1024.
TEST(PredictedPositions, GradedClassStartFollowsTheBucket) {
  const PositionResidualModel flat(kTop), graded(kTop, ClassStart::kGraded);
  for (int g = 0; g < kPositionGroups; ++g) {
    EXPECT_EQ(graded.cls[g][5][0], 150);
    EXPECT_EQ(graded.cls[g][5][2], 300);
    EXPECT_EQ(graded.cls[g][5][3], 700);
    EXPECT_EQ(graded.cls[g][5][4], 1200);
    EXPECT_EQ(graded.cls[g][5][5], 1700);
    EXPECT_EQ(graded.cls[g][5][6], 1900);
    EXPECT_EQ(graded.cls[g][5][7], 1950);
    EXPECT_EQ(graded.cls[g][5][29], 1950);
    EXPECT_EQ(graded.cls[g][0][0], 1700);  // bucket 0: e = 0 - 0 + 1 = 1
    for (int b = 0; b < kPositionBuckets; ++b)
      for (int j = 0; j < kPositionMaxClass; ++j) EXPECT_EQ(flat.cls[g][b][j], 1024);
  }
  EXPECT_EQ(graded.sign[0], 1024);
  EXPECT_EQ(graded.use[0][0][0], 1024);
}

// 14.5's costing: what ResidualCosts says a residual costs is what the
// coding template counts decision by decision, for models that coding has
// adapted, in every bucket and class, both signs, each axis's own k.
TEST(PredictedPositions, ResidualCostsAreTheDecisionsTheCoderCodes) {
  const uint32_t top[3] = {4095, 300, 65535};
  std::mt19937 rng(3);
  const auto random_residual = [&](int axis) {
    const uint32_t magnitude = rng() % (top[axis] + 1) >> (rng() % 17);
    return SignedResidual{magnitude, magnitude != 0 && rng() % 2 == 1};
  };
  const auto random_prediction = [&] {
    VertexPrediction p;
    p.kind = rng() % 2 ? PredictionKind::kSingle : PredictionKind::kSeveral;
    p.neighbour_activity = rng() % 3 == 0 ? 0 : rng() % (1u << (rng() % 20));
    p.scale = rng() % (1u << (rng() % 22));
    return p;
  };
  PositionResidualModel model(top);
  RangeEncoder adapting;
  for (int round = 0; round < 20; ++round) {
    for (int v = 0; v < 200; ++v) {  // coding adapts the probabilities
      const VertexPrediction p = random_prediction();
      uint32_t magnitude[3] = {0, 0, 0};
      for (int a = 0; a < 3; ++a) {
        const SignedResidual r = random_residual(a);
        magnitude[a] = r.magnitude;
        code_position_residual(&adapting, &model, p, magnitude, a, r);
      }
    }
    ResidualCosts costs(model);
    for (int v = 0; v < 200; ++v) {
      const VertexPrediction p = random_prediction();
      uint32_t magnitude[3] = {0, 0, 0};
      for (int a = 0; a < 3; ++a) {
        const SignedResidual r = random_residual(a);
        magnitude[a] = r.magnitude;
        CostMeter meter;
        code_position_residual(&meter, &model, p, magnitude, a, r);
        EXPECT_NEAR(costs.axis(p, magnitude, a, r.negative), meter.bits, 1e-9)
            << "round " << round << " axis " << a << " residual " << r.magnitude;
      }
    }
  }
}

std::vector<uint8_t> encode_with(const Mesh& mesh, const EncodeOptions& options, EncodeStats* stats = nullptr) {
  std::vector<uint8_t> out;
  const Status s = encode(mesh, options, &out, stats);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return out;
}

DecodedFile decode_all(const std::vector<uint8_t>& bytes) {
  DecodedFile file;
  const Status s = decode(bytes.data(), bytes.size(), &file);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return file;
}

// A mesh encoded with `options` and with `feature` turned off: the files and
// what they decode to.
struct WithAndWithout {
  std::vector<uint8_t> with_bytes, without_bytes;
  DecodedFile with, without;
};

WithAndWithout with_and_without(const Mesh& mesh, EncodeOptions options, bool EncodeOptions::*feature) {
  // Methods 5 - 8 against the method before them: without 14.10's mirror
  // candidate (method 9), which these symmetric meshes would take, and
  // without 14.14's class probabilities per axis (method 13), which every
  // mesh of 1,000 vertices or more takes; with CONN coding 7, as the
  // version each file says is its POSN method's (coding 8 would make it 1.18).
  if (feature != &EncodeOptions::mirror_symmetry) options.mirror_symmetry = false;
  if (feature != &EncodeOptions::axis_class_probabilities) options.axis_class_probabilities = false;
  options.polygon_quad_contexts = false;
  WithAndWithout r;
  r.with_bytes = encode_with(mesh, options);
  r.with = decode_all(r.with_bytes);
  options.*feature = false;
  r.without_bytes = encode_with(mesh, options);
  r.without = decode_all(r.without_bytes);
  return r;
}

// Round trips of generated meshes of every kind the predictor meets.
TEST(PredictedPositions, RoundTripsGeneratedMeshes) {
  std::vector<Mesh> meshes = {tools::make_quad_sphere(6), tools::make_torus(20, 9), tools::make_prism(9),
                              tools::triangulated(tools::make_refined_sphere(3)),
                              tools::make_deltoidal_hexecontahedron()};
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 50 + uint32_t(seed * 7);
    o.faces = 40 + uint32_t(seed * 5);
    meshes.push_back(tools::make_random_soup(seed, o));
  }
  meshes.push_back(tools::make_scrambled(tools::make_torus(8, 6), 3));
  for (size_t i = 0; i < meshes.size(); ++i)
    for (int bits : {4, 12, 20}) {
      EncodeOptions options;
      options.position_bits = bits;
      options.position_method = PositionMethod::kPredicted;
      // Method 3 (1.7) under 1,000 vertices (14.5), or method 1 (1.5, 1.6 with coding 7); with the
      // geometry order (at 4 and 20 bits) method 4 (1.8) or, on a mesh with quads, 5 (1.9) where
      // smaller, either as 6 or 7 (1.10) where 14.8's contexts make it smaller, under 1,000 vertices
      // only when smaller than method 1 or 3.
      options.graded_class_start = bits != 12;
      options.geometry_order = bits != 12;
      options.mirror_symmetry = false;  // the torus is symmetric: method 9 (14.10) has tests of its own
      options.edge_extrapolation = false;  // method 12 (14.13) too
      EncodeStats stats;
      const DecodedFile file = decode_all(encode_with(meshes[i], options, &stats));
      const bool small = meshes[i].vertex_count() < 1000;
      const int label_method = options.graded_class_start && small ? 3 : 1;
      const bool quads = std::count(meshes[i].face_sizes.begin(), meshes[i].face_sizes.end(), 4u) > 0;
      const int method = stats.positions.method, geometry_method = method >= 6 ? method - 2 : method;
      if (options.geometry_order && !small)
        EXPECT_TRUE(geometry_method == 4 || (quads && geometry_method == 5)) << method;
      else if (options.geometry_order)
        EXPECT_TRUE(geometry_method == 4 || (quads && geometry_method == 5) || method == label_method) << method;
      else
        EXPECT_EQ(stats.positions.method, label_method);
      EXPECT_EQ(file.quantization.method, stats.positions.method);
      EXPECT_EQ(file.quantization.graded_start, options.graded_class_start && small);
      // Every vertex counted once by its kind, whichever order was kept (14.5).
      uint32_t counted = 0;
      for (uint32_t n : stats.positions.vertices_by_kind) counted += n;
      EXPECT_EQ(counted, file.mesh.vertex_count()) << "mesh " << i;
      EXPECT_EQ(file.version_minor, stats.polygon.coding == kPolygonQuadContextCoded ? 18  // 5.4.10's coding 8
                                    : stats.positions.method >= 6                 ? 10
                                    : stats.positions.method == 5                 ? 9
                                    : stats.positions.method == 4 ? 8
                                    : stats.positions.method == 3 ? 7
                                    : stats.polygon.coding == kPolygonContextCoded ? 6
                                                                                   : 5);
      const tools::RoundTripReport r = tools::check_round_trip(meshes[i], file);
      EXPECT_TRUE(r.faces_equal) << "mesh " << i << ": " << r.face_mismatch;
      EXPECT_TRUE(r.positions_within_bound) << "mesh " << i << " at " << bits << " bits: " << r.position_mismatch;
      // 14.5: the other choice of candidates codes the same values.
      options.candidate_choice = CandidateChoice::kNearest;
      const DecodedFile nearest = decode_all(encode_with(meshes[i], options));
      EXPECT_EQ(nearest.quantized, file.quantized) << "mesh " << i;
    }
}

// 14.5: the encoder starts graded (method 3) under 1,000 vertices only.
TEST(PredictedPositions, GradedStartUnderAThousandVertices) {
  EncodeOptions label_order;
  label_order.geometry_order = false;
  for (const auto& [rings, expected] : {std::pair{30u, 3}, std::pair{40u, 1}}) {  // 900 and 1,200 vertices
    EncodeStats stats;
    const DecodedFile file = decode_all(encode_with(tools::make_torus(rings, 30), label_order, &stats));
    EXPECT_EQ(file.mesh.vertex_count(), 30u * rings);
    EXPECT_EQ(stats.positions.method, expected);
    EXPECT_EQ(file.quantization.method, expected);
  }
}

// On the per-axis grid every method carries the same integers: identical output.
TEST(PredictedPositions, PerAxisGridGivesMethodZerosPositions) {
  const Mesh torus = tools::make_torus(12, 7, 2.f, 0.3f);
  EncodeOptions options;
  options.position_grid = PositionGrid::kPerAxis;
  options.position_method = PositionMethod::kDeltas;
  const DecodedFile deltas = decode_all(encode_with(torus, options));
  EXPECT_EQ(deltas.quantization.method, 0);
  options.position_method = PositionMethod::kPredicted;
  options.geometry_order = false;
  for (bool graded : {false, true}) {
    options.graded_class_start = graded;
    const DecodedFile predicted = decode_all(encode_with(torus, options));
    EXPECT_EQ(predicted.quantization.method, graded ? 3 : 1);
    EXPECT_EQ(deltas.quantized, predicted.quantized);
    EXPECT_EQ(deltas.mesh.positions, predicted.mesh.positions);
  }
}

// The uniform grid is Draco's: the largest side in 2^bits - 1 steps.
TEST(PredictedPositions, UniformGridStep) {
  const Mesh torus = tools::make_torus(12, 7, 2.f, 0.3f);  // sides 4.6, 4.6, 0.6
  EncodeOptions options;
  options.position_bits = 10;
  EncodeStats stats;
  const DecodedFile file = decode_all(encode_with(torus, options, &stats));
  const double side = double(file.quantization.max[0]) - double(file.quantization.min[0]);
  EXPECT_DOUBLE_EQ(file.quantization.step[0], file.quantization.step[2]);
  EXPECT_NEAR(file.quantization.step[0], side / 1023, 1e-9);
  EXPECT_EQ(file.quantization.top[0], 1023u);
  EXPECT_LT(file.quantization.top[2], 200u);
}

// --step and --max-error (14.1): the step asked for, the error promised.
TEST(PredictedPositions, StepAndMaxErrorOptions) {
  const Mesh sphere = tools::triangulated(tools::make_refined_sphere(3));
  EncodeOptions by_step;
  by_step.position_step = 0.004;
  const DecodedFile stepped = decode_all(encode_with(sphere, by_step));
  EXPECT_EQ(stepped.quantization.step[0], 0.004);
  for (double e : {0.01, 0.001, 1e-5}) {
    EncodeOptions by_error;
    by_error.max_position_error = e;
    const DecodedFile file = decode_all(encode_with(sphere, by_error));
    const tools::RoundTripReport r = tools::check_round_trip(sphere, file);
    EXPECT_TRUE(r.positions_within_bound);
    EXPECT_LE(r.max_error, e) << e;
    EXPECT_GT(r.max_error, e / 4) << "a grid much finer than asked for: " << e;
  }
}

TEST(PredictedPositions, OptionsTheFormatCannotCarry) {
  const Mesh cube = tools::make_cube();
  std::vector<uint8_t> out;
  EncodeOptions tiny;
  tiny.position_step = 1e-12;  // 2^40 steps across the cube
  EXPECT_EQ(encode(cube, tiny, &out).code(), ErrorCode::kInvalidArgument);
  EncodeOptions deltas_on_uniform;
  deltas_on_uniform.position_method = PositionMethod::kDeltas;
  EXPECT_EQ(encode(cube, deltas_on_uniform, &out).code(), ErrorCode::kInvalidArgument);
  EncodeOptions both;
  both.position_step = 0.1;
  both.max_position_error = 0.1;
  EXPECT_EQ(encode(cube, both, &out).code(), ErrorCode::kInvalidArgument);
  EncodeOptions below_float;
  below_float.max_position_error = 1e-30;
  EXPECT_EQ(encode(cube, below_float, &out).code(), ErrorCode::kInvalidArgument);
}

// 14.1's bound: vertices that cost no decision go to method 0, same output.
TEST(PredictedPositions, CoincidentVerticesFallBackToMethodZero) {
  Mesh points;
  for (int i = 0; i < 6000; ++i) points.positions.insert(points.positions.end(), {1.5f, -2.f, 0.25f});
  EncodeStats stats;
  const DecodedFile file = decode_all(encode_with(points, EncodeOptions{}, &stats));
  EXPECT_EQ(stats.positions.method, 0);
  ASSERT_EQ(file.mesh.vertex_count(), 6000u);
  EXPECT_EQ(file.mesh.positions[0], 1.5f);
  EXPECT_EQ(file.mesh.positions[3 * 5999 + 1], -2.f);
}

// The faces with every vertex u renamed rank(u) (spec 14.6).
Mesh renamed_by(const Mesh& m, const std::vector<uint32_t>& order) {
  std::vector<uint32_t> rank(order.size());
  for (uint32_t i = 0; i < order.size(); ++i) rank[order[i]] = i;
  Mesh out = faces(m.face_sizes, m.corners);
  for (uint32_t& c : out.corners) c = rank[c];
  return out;
}

// Spec 14.6's example: vertex 4 closes two faces before 3 closes one.
TEST(GeometryOrder, SpecExample) {
  const Mesh m = faces({3, 3, 3, 3}, {0, 1, 2, 0, 2, 4, 1, 4, 2, 0, 3, 1});
  const std::vector<uint32_t> order = geometry_order(5, m.face_sizes, m.corners);
  EXPECT_EQ(order, (std::vector<uint32_t>{0, 1, 2, 4, 3}));
  EXPECT_EQ(renamed_by(m, order).corners, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 1, 3, 2, 0, 4, 1}));
}

// 14.6: a face with w at two corners does not close on w; vertex 2, which
// no face uses, comes by the last branch once nothing closes.
TEST(GeometryOrder, FaceWithAVertexTwiceClosesOnNothing) {
  const Mesh m = faces({4, 3}, {0, 1, 3, 3, 0, 1, 4});
  const std::vector<uint32_t> order = geometry_order(5, m.face_sizes, m.corners);
  EXPECT_EQ(order, (std::vector<uint32_t>{0, 1, 4, 2, 3}));  // counting face 0 for 3 gives 0, 1, 3, 4, 2
}

// The sets of labels give the order the rule's text gives, on soups with
// repeated corners, unused vertices and many parts.
TEST(GeometryOrder, SetsFollowTheRule) {
  std::vector<Mesh> meshes = {tools::triangulated(tools::make_refined_sphere(2))};
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 20 + uint32_t(seed * 3);
    o.faces = 10 + uint32_t(seed * 4);
    o.max_degree = 3 + uint32_t(seed % 6);
    meshes.push_back(tools::make_random_soup(seed, o));
  }
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Mesh& m = meshes[i];
    EXPECT_EQ(geometry_order(uint32_t(m.vertex_count()), m.face_sizes, m.corners),
              fuzz::geometry_order_by_the_rule(uint32_t(m.vertex_count()), m))
        << "mesh " << i;
  }
}

// 14.6 defines method 4 by renaming the faces; the coder predicts over the
// original faces with ranks instead. The two give the same stream.
TEST(GeometryOrder, RanksGiveWhatRenamingGives) {
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 40 + uint32_t(seed * 5);
    o.faces = 30 + uint32_t(seed * 6);
    const Mesh soup = seed % 3 == 0 ? tools::triangulated(tools::make_refined_sphere(2)) : tools::make_random_soup(seed, o);
    const uint32_t n = uint32_t(soup.vertex_count());
    std::vector<uint32_t> q(3 * size_t(n));
    for (size_t k = 0; k < q.size(); ++k) q[k] = uint32_t((k * 2654435761u + seed * 97) % 4096);
    const std::vector<uint32_t> order = geometry_order(n, soup.face_sizes, soup.corners);
    std::vector<uint32_t> q_in_order(q.size());
    for (uint32_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) q_in_order[3 * size_t(i) + a] = q[3 * size_t(order[i]) + a];
    const Mesh faces_of_soup = faces(soup.face_sizes, soup.corners);
    EXPECT_EQ(encode_predicted_grid(q, kTop, faces_of_soup, nullptr, CandidateChoice::kFewestBits, ClassStart::kFlat,
                                    PredictionOrder::kGeometry),
              encode_predicted_grid(q_in_order, kTop, renamed_by(soup, order), nullptr, CandidateChoice::kFewestBits))
        << "seed " << seed;
  }
}

// 14.6: method 4 carries the integers method 1 carries, in 1.8 files; a
// 1.7 file (geometry_order off) keeps method 1.
TEST(GeometryOrder, MethodFourCarriesMethodOnesIntegers) {
  const Mesh sphere = tools::triangulated(tools::make_refined_sphere(3));  // 3,842 vertices: start 0
  EncodeOptions options;
  options.mirror_symmetry = false;  // the sphere is symmetric: method 9 (14.10) has tests of its own
  options.axis_class_probabilities = false;  // method 13 (14.14) too
  EncodeStats stats;
  const DecodedFile four = decode_all(encode_with(sphere, options, &stats));
  EXPECT_EQ(four.quantization.method, 4);
  EXPECT_FALSE(four.quantization.graded_start);
  EXPECT_EQ(four.version_minor, 8);
  options.geometry_order = false;
  const DecodedFile one = decode_all(encode_with(sphere, options));
  EXPECT_EQ(one.quantization.method, 1);
  EXPECT_EQ(one.version_minor, 6);
  EXPECT_EQ(four.quantized, one.quantized);
  EXPECT_EQ(four.mesh.positions, one.mesh.positions);
  // Nearly every vertex of a closed mesh has two candidates or more in the geometry order.
  const uint32_t several = stats.positions.vertices_by_kind[int(PredictionKind::kSeveral)];
  EXPECT_GT(several, sphere.vertex_count() * 9 / 10);
}

// Spec 14.7's example: two quads on z = x y. Method 4's candidate for
// vertex 5 is one short in z; the twist of face 0 across the edge (3, 1)
// makes it exact.
TEST(QuadTwist, SpecExample) {
  const Mesh two = faces({4, 4}, {0, 1, 3, 2, 1, 4, 5, 3});
  const std::vector<uint32_t> q = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1, 2, 0, 0, 2, 1, 2};
  VertexCorners corners;
  corners.build(6, two.face_sizes, two.corners);
  const std::vector<uint32_t> order = geometry_order(6, two.face_sizes, two.corners);
  ASSERT_EQ(order, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  const std::vector<uint32_t> activity(6, 0);
  VertexPrediction four, five;
  predict_vertex_in_order(corners, order.data(), order.data(), 5, q.data(), activity.data(), kTop, &four);
  predict_vertex_in_order(corners, order.data(), order.data(), 5, q.data(), activity.data(), kTop, &five, nullptr,
                          true);
  ASSERT_EQ(four.candidates, 1);
  ASSERT_EQ(five.candidates, 1);
  EXPECT_EQ(four.candidate[0][2], 1 * kOne);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(five.candidate[0][a], kOne * q[15 + a]) << "axis " << a;
  EXPECT_EQ(five.scale, four.scale);  // the difference vector is p1 - p2 either way
}

// 14.6's visit of a mesh's n vertices with its ranks, for predicting vertex
// after vertex as a decoder does (every activity 0: no candidate depends on it).
struct GeometryVisit {
  GeometryVisit(const Mesh& faces, uint32_t n)
      : order(geometry_order(n, faces.face_sizes, faces.corners)), rank(n), activity(n, 0) {
    corners.build(n, faces.face_sizes, faces.corners);
    for (uint32_t i = 0; i < n; ++i) rank[order[i]] = i;
  }
  VertexPrediction predict(uint32_t i, const std::vector<uint32_t>& q, const uint32_t top[3], bool quad_twist,
                           bool triangle_twist) const {
    VertexPrediction p;
    predict_vertex_in_order(corners, order.data(), rank.data(), i, q.data(), activity.data(), top, &p, nullptr,
                            quad_twist, triangle_twist);
    return p;
  }
  VertexCorners corners;
  std::vector<uint32_t> order, rank, activity;
};

// 14.7: on a regular grid of quads, the runs' candidates (weight 2; the
// strips' have weight 1) of a quadratic function, its mixed term included,
// are exact wherever a twist is found; method 4's parallelogram misses the
// mixed term every time.
TEST(QuadTwist, QuadraticGridIsExact) {
  constexpr uint32_t n = 12;
  Mesh grid;
  std::vector<uint32_t> q;
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) q.insert(q.end(), {5 * i + 3 * i * i, 7 * j + j * j, 100 + 2 * i * j});
  for (uint32_t j = 0; j + 1 < n; ++j)
    for (uint32_t i = 0; i + 1 < n; ++i) {
      grid.face_sizes.push_back(4);
      grid.corners.insert(grid.corners.end(), {j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i});
    }
  const GeometryVisit visit(grid, n * n);
  const uint32_t top[3] = {1000, 1000, 1000};
  int runs = 0, exact_four = 0, exact_five = 0;
  for (uint32_t i = 0; i < n * n; ++i) {
    const VertexPrediction four = visit.predict(i, q, top, false, false), five = visit.predict(i, q, top, true, false);
    ASSERT_EQ(four.candidates, five.candidates);
    const uint32_t v = visit.order[i];
    const auto exact = [&](const VertexPrediction& p, int k) {
      return p.candidate[k][0] == kOne * q[3 * v] && p.candidate[k][1] == kOne * q[3 * v + 1] &&
             p.candidate[k][2] == kOne * q[3 * v + 2];
    };
    for (int k = 0; k < four.candidates; ++k) {
      if (four.weight[k] != 2) continue;
      ++runs;
      exact_four += exact(four, k);
      exact_five += exact(five, k);
    }
  }
  EXPECT_EQ(runs, int((n - 1) * (n - 1)));  // one quad closes on each vertex off row 0 and column 0
  EXPECT_EQ(exact_four, 0);
  EXPECT_GT(exact_five, runs * 9 / 10);
}

// 14.8's example: two candidates 226,608 units of 2^-16 apart (3 grid
// steps) take context 2; equal ones 0; 1,024 steps apart or more 11; and
// every decision takes context 0 in the methods without 14.8.
TEST(MaskContexts, SpecExample) {
  const uint32_t top[3] = {4095, 4095, 4095};
  const PositionResidualModel with(top, ClassStart::kFlat, true), without(top);
  VertexPrediction p;
  p.candidates = 2;
  const int64_t c0[3] = {25 * kOne, 20 * kOne, 5 * kOne}, c1[3] = {24 * kOne, 22 * kOne + 30000, 5 * kOne};
  std::copy(c0, c0 + 3, p.candidate[0]);
  std::copy(c1, c1 + 3, p.candidate[1]);
  EXPECT_EQ(mask_context(with, p), 2);
  EXPECT_EQ(mask_context(without, p), 0);
  std::copy(c0, c0 + 3, p.candidate[1]);
  EXPECT_EQ(mask_context(with, p), 0);
  p.candidate[1][0] += 65535;  // less than a grid step apart
  EXPECT_EQ(mask_context(with, p), 0);
  p.candidate[1][0] += 1;  // one step: bitlen(1) = 1
  EXPECT_EQ(mask_context(with, p), 1);
  p.candidate[1][2] += 1022 * kOne;  // 1,023 steps
  EXPECT_EQ(mask_context(with, p), 10);
  p.candidate[1][2] += kOne;
  EXPECT_EQ(mask_context(with, p), 11);
  p.candidate[1][2] = int64_t(1) << 48;  // the largest distances stay at 11
  EXPECT_EQ(mask_context(with, p), 11);
  // The largest pair counts: a third candidate 5 steps from the first.
  p.candidates = 3;
  std::copy(c0, c0 + 3, p.candidate[1]);
  std::copy(c0, c0 + 3, p.candidate[2]);
  p.candidate[2][1] -= 5 * kOne;
  EXPECT_EQ(mask_context(with, p), 3);
}

// 14.5, 14.8: from 10,000 vertices the encoder writes method 6 (format
// 1.10) with the integers method 4 carries; on terraces, where a
// parallelogram across a cliff is far off and the others agree, in fewer
// bytes. Without mask_contexts, method 4; under 10,000 vertices too.
TEST(MaskContexts, EncoderWritesMethodSixWhereItIsSmaller) {
  EncodeOptions options;
  options.position_bits = 16;
  options.mirror_symmetry = false;  // the terraces are symmetric: method 9 (14.10) has tests of its own
  options.axis_class_probabilities = false;  // method 13 (14.14) too
  const WithAndWithout r = with_and_without(tools::make_terraces(100, 4, 9), options, &EncodeOptions::mask_contexts);
  EXPECT_EQ(r.with.quantization.method, 6);
  EXPECT_EQ(r.with.version_minor, 10);
  EXPECT_EQ(r.without.quantization.method, 4);
  EXPECT_EQ(r.with.quantized, r.without.quantized);
  EXPECT_LT(r.with_bytes.size(), r.without_bytes.size());
  EXPECT_EQ(decode_all(encode_with(tools::make_terraces(98, 4, 9), options)).quantization.method, 4);  // 9,801
}

// Methods 6 and 7 written for any mesh (14.8 forced, as the vectors are),
// and method 8 with every features byte that has the twist of triangles
// (14.9 forced), decode to the integers methods 4 and 5 carry.
TEST(MaskContexts, RoundTripsGeneratedMeshes) {
  std::vector<Mesh> meshes = {tools::make_refined_sphere(2), tools::triangulated(tools::make_torus(20, 9)),
                              tools::make_terraces(12, 3, 2), tools::triangulated(tools::make_refined_sphere(2))};
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 40 + uint32_t(seed * 9);
    o.faces = 30 + uint32_t(seed * 7);
    meshes.push_back(tools::make_random_soup(seed, o));
  }
  for (const Mesh& mesh : meshes)
    for (int features : {2, 3, 4, 5, 6, 7}) {  // 14.9's bits: 1 quad twist, 2 contexts, 4 triangle twist
      const QuantizedPositions grid = quantize_positions(mesh.positions, 12);
      const std::vector<uint8_t> payload =
          encode_predicted_positions(grid, mesh, nullptr, CandidateChoice::kFewestBits, ClassStart::kFlat,
                                     PredictionOrder::kGeometry, features & 1, features & 2, features & 4);
      ASSERT_FALSE(payload.empty());
      QuantizationInfo info;
      std::vector<uint32_t> q;
      std::vector<float> positions;
      ASSERT_TRUE(decode_positions(payload.data(), payload.size(), mesh, uint32_t(mesh.vertex_count()), &info, &q,
                                   &positions)
                      .ok());
      EXPECT_EQ(info.method, features & 4 ? 8 : features & 1 ? 7 : 6);
      EXPECT_EQ(info.features, features);
      EXPECT_EQ(q, grid.q);
    }
}

// 14.5, 14.7: the encoder writes method 5 (format 1.9) on a smooth quad
// mesh, with the integers method 4 carries; without quad_twist, method 4.
TEST(QuadTwist, EncoderWritesMethodFiveWhereItIsSmaller) {
  const Mesh sphere = tools::make_refined_sphere(3);  // quads, 3,842 vertices
  const WithAndWithout r = with_and_without(sphere, EncodeOptions{}, &EncodeOptions::quad_twist);
  EXPECT_EQ(r.with.quantization.method, 5);
  EXPECT_EQ(r.with.version_minor, 9);
  EXPECT_EQ(r.without.quantization.method, 4);
  EXPECT_EQ(r.without.version_minor, 8);
  EXPECT_EQ(r.with.quantized, r.without.quantized);
  EXPECT_LT(r.with_bytes.size(), r.without_bytes.size());
  // A mesh of triangles has no quad to twist: method 4, format 1.8 (without 14.10's mirror candidate).
  EncodeOptions no_mirror;
  no_mirror.mirror_symmetry = false;
  no_mirror.axis_class_probabilities = false;  // nor 14.14's probabilities per axis (method 13)
  const DecodedFile triangles = decode_all(encode_with(tools::triangulated(sphere), no_mirror));
  EXPECT_EQ(triangles.quantization.method, 4);
}


// Spec 14.9's example: vertex 7's parallelogram across the edge (2, 1)
// misses z = 3 + 3 i j by 3; the twists of the edges (0, 1) and (0, 2),
// around vertex 0 of six triangles, say so. lambda starts at 0, learns 1
// from vertex 7 itself, and 1/2 once a vertex with the same twist and no
// error follows.
TEST(TriangleTwist, SpecExample) {
  const Mesh hexagon = faces({3, 3, 3, 3, 3, 3, 3}, {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 1, 1, 7, 2});
  const std::vector<uint32_t> q = {10, 10, 3, 20, 10, 3, 10, 20, 3, 0, 20, 0, 0, 10, 3, 10, 0, 3, 20, 0, 0, 20, 20, 6};
  VertexCorners corners;
  corners.build(8, hexagon.face_sizes, hexagon.corners);
  const std::vector<uint32_t> order = geometry_order(8, hexagon.face_sizes, hexagon.corners);
  ASSERT_EQ(order, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  const std::vector<uint32_t> activity(8, 0);
  VertexPrediction p;
  predict_vertex_in_order(corners, order.data(), order.data(), 7, q.data(), activity.data(), kTop, &p, nullptr,
                          false, true);
  ASSERT_EQ(p.candidates, 1);
  EXPECT_EQ(p.candidate[0][0], 20 * kOne);
  EXPECT_EQ(p.candidate[0][1], 20 * kOne);
  EXPECT_EQ(p.candidate[0][2], 3 * kOne);
  ASSERT_EQ(p.triangle_twisted, 1u);
  EXPECT_EQ(p.triangle_twist[0][0], 0);
  EXPECT_EQ(p.triangle_twist[0][1], 0);
  EXPECT_EQ(p.triangle_twist[0][2], 3 * kOne);  // 2^15 (0 + 0 + 3 + 3)

  TriangleTwistWeight weight;
  weight.apply(&p);
  EXPECT_EQ(p.twist_weight, 0);
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.value[2], 3);  // lambda 0: the parallelogram
  weight.learn(p, &q[21]);   // t = e = 48 in z: N = D = 2304
  weight.apply(&p);
  EXPECT_EQ(p.twist_weight, 256);
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.value[2], 6);  // exact
  const uint32_t on_the_parallelogram[3] = {20, 20, 3};
  weight.learn(p, on_the_parallelogram);  // e = 0: N = 2304, D = 4608
  weight.apply(&p);
  EXPECT_EQ(p.twist_weight, 128);
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.value[2], 5);  // 3 + floor((128 x 196608 + 2^23) / 2^24)

  // Without the triangle twist no candidate carries one.
  predict_vertex_in_order(corners, order.data(), order.data(), 7, q.data(), activity.data(), kTop, &p);
  EXPECT_EQ(p.triangle_twisted, 0u);
}

// A regular triangulation of a quadratic function on the lattice (i, j):
// around a vertex of six triangles the twist equals the mixed difference a
// parallelogram misses, whatever its direction, so every twisted candidate
// plus its twist is exact, and the plain parallelograms miss wherever the
// quadratic terms are felt.
TEST(TriangleTwist, QuadraticLatticeIsExact) {
  constexpr uint32_t n = 14;
  Mesh lattice;
  std::vector<uint32_t> q;
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) q.insert(q.end(), {20 * i + i * i, 20 * j + j * j + i, 300 + 2 * i * j + j * j});
  for (uint32_t j = 0; j + 1 < n; ++j)
    for (uint32_t i = 0; i + 1 < n; ++i) {
      const uint32_t o = j * n + i, a = o + 1, b = o + n, v = o + n + 1;
      lattice.face_sizes.insert(lattice.face_sizes.end(), {3, 3});
      lattice.corners.insert(lattice.corners.end(), {o, a, b, a, v, b});
    }
  const GeometryVisit visit(lattice, n * n);
  int twisted = 0, exact_plain = 0, exact_twisted = 0;
  for (uint32_t i = 0; i < n * n; ++i) {
    const VertexPrediction p = visit.predict(i, q, kTop, false, true);
    const uint32_t v = visit.order[i];
    for (int k = 0; k < p.candidates; ++k) {
      if (!(p.triangle_twisted >> k & 1)) continue;
      ++twisted;
      bool plain = true, with_twist = true;
      for (int a = 0; a < 3; ++a) {
        plain = plain && p.candidate[k][a] == kOne * q[3 * v + a];
        with_twist = with_twist && p.candidate[k][a] + p.triangle_twist[k][a] == kOne * q[3 * v + a];
      }
      exact_plain += plain;
      exact_twisted += with_twist;
    }
  }
  EXPECT_GT(twisted, int(n * n));  // interior vertices meet one or more
  EXPECT_EQ(exact_twisted, twisted);
  EXPECT_EQ(exact_plain, 0);
}

// 14.5, 14.9: on a regular torus of triangles the encoder writes method 8
// (format 1.11, features 4: the triangle twist alone) with the integers
// method 4 carries, in fewer bytes; without triangle_twist, method 4. On an
// irregular mesh the pass of predictions keeps method 4.
TEST(TriangleTwist, EncoderWritesMethodEightWhereItPays) {
  const Mesh torus = tools::triangulated(tools::make_torus(48, 32));
  const WithAndWithout r = with_and_without(torus, EncodeOptions{}, &EncodeOptions::triangle_twist);
  EXPECT_EQ(r.with.quantization.method, 8);
  EXPECT_EQ(r.with.quantization.features, 4);
  EXPECT_EQ(r.with.version_minor, 11);
  EXPECT_EQ(r.without.quantization.method, 4);
  EXPECT_EQ(r.with.quantized, r.without.quantized);
  EXPECT_LT(r.with_bytes.size() * 10, r.without_bytes.size() * 9);  // more than 10 % smaller
  tools::RandomSoupOptions o;
  o.vertices = 400;
  o.faces = 600;
  EXPECT_NE(decode_all(encode_with(tools::make_random_soup(7, o), EncodeOptions{})).quantization.method, 8);
}


// Spec 14.12's example: 14.3.4's triangles on the file's grid, vertex 3
// predicted across the edge (2, 1) from o = 0, whose offset from the edge's
// middle is 0.1 of e = q[1] - q[2].
TEST(Shear, SpecExample) {
  const Mesh two = faces({3, 3}, {0, 1, 2, 2, 1, 3});
  const std::vector<uint32_t> q = {0, 0, 0, 10, 0, 0, 5, 10, 0, 16, 9, 0};
  VertexCorners corners;
  corners.build(4, two.face_sizes, two.corners);
  const std::vector<uint32_t> order = geometry_order(4, two.face_sizes, two.corners);
  ASSERT_EQ(order, (std::vector<uint32_t>{0, 1, 2, 3}));
  const std::vector<uint32_t> activity(4, 0);
  const auto predicted = [&](int k) {
    VertexPrediction p;
    predict_vertex_in_order(corners, order.data(), order.data(), 3, q.data(), activity.data(), kTop, &p, nullptr,
                            false, false, k);
    EXPECT_EQ(p.candidates, 1);
    EXPECT_EQ(p.scale, 10u);  // 14.3.1's difference b - o, unsheared
    return p;
  };
  VertexPrediction p = predicted(16);  // f = floor(2^15 x 25 / 125) = 6553
  EXPECT_EQ(p.candidate[0][0], 15 * kOne + 32765);  // floor(16 x 6553 x 5 / 16)
  EXPECT_EQ(p.candidate[0][1], 10 * kOne - 65530);  // floor(16 x 6553 x -10 / 16)
  EXPECT_EQ(p.candidate[0][2], 0);
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.value[0], 15);
  EXPECT_EQ(p.value[1], 9);  // 9.00009 rounded half up; the vertex is at (16, 9)
  p = predicted(8);
  EXPECT_EQ(p.candidate[0][0], 15 * kOne + 16382);  // floor(8 x 6553 x 5 / 16) = floor(16382.5)
  EXPECT_EQ(p.candidate[0][1], 10 * kOne - 32765);
  select_candidates(&p, 1, kTop);
  EXPECT_EQ(p.value[1], 10);  // 9.50004 rounds up
  p = predicted(0);  // no shear: 14.3.4's parallelogram
  EXPECT_EQ(p.candidate[0][0], 15 * kOne);
  EXPECT_EQ(p.candidate[0][1], 10 * kOne);
}

// The fraction is clamped to +-2 (o far along a short edge), and grid
// integers up to 2^30 are shifted into 15 bits before the products (15.12's
// shift) without changing a fraction they give exactly.
TEST(Shear, FractionClampedAndLargeIntegersShifted) {
  const Mesh two = faces({3, 3}, {0, 1, 2, 2, 1, 3});
  const std::vector<uint32_t> order = {0, 1, 2, 3};
  VertexCorners corners;
  corners.build(4, two.face_sizes, two.corners);
  const std::vector<uint32_t> activity(4, 0);
  const uint32_t top[3] = {(1u << 30) - 1, (1u << 30) - 1, (1u << 30) - 1};
  VertexPrediction p;
  // e = (1, 0, 0), g = 2 o - a - b = (999, 10, 0): t / (2 ee) = 499.5, clamped to 2.
  const std::vector<uint32_t> short_edge = {600, 5, 0, 101, 0, 0, 100, 0, 0, 0, 0, 0};
  predict_vertex_in_order(corners, order.data(), order.data(), 3, short_edge.data(), activity.data(), top, &p,
                          nullptr, false, false, 16);
  ASSERT_EQ(p.candidates, 1);
  EXPECT_EQ(p.candidate[0][0], (100 + 101 - 600 + 2) * kOne);
  EXPECT_EQ(p.candidate[0][1], -5 * kOne);
  // e = (2^29, 0, 0), g = (2^28, 2^29, 0): shifted by 16, f = 2^14 (o a quarter of e from the middle).
  const uint32_t big = 1u << 27;
  const std::vector<uint32_t> large = {3 * big, 2 * big, 0, 4 * big, 0, 0, 0, 0, 0, 0, 0, 0};
  predict_vertex_in_order(corners, order.data(), order.data(), 3, large.data(), activity.data(), top, &p, nullptr,
                          false, false, 16);
  ASSERT_EQ(p.candidates, 1);
  EXPECT_EQ(p.candidate[0][0], int64_t(2 * big) * kOne);  // a + b - o = big, plus e / 4 = big
  EXPECT_EQ(p.candidate[0][1], -int64_t(2 * big) * kOne);
}

// The encoder writes method 11 where the shear codes smaller (an irregular
// triangulation), the same integers, and keeps its earlier method where it
// does not (a regular one) and under 1,000 vertices.
TEST(Shear, EncoderWritesMethodElevenWhereItPays) {
  const Mesh sphere = tools::make_jittered_sphere(3, 0.3f, 11);
  const WithAndWithout r = with_and_without(sphere, EncodeOptions{}, &EncodeOptions::shear);
  EXPECT_EQ(r.with.quantization.method, 11);
  EXPECT_GE(r.with.quantization.shear, 1);
  EXPECT_LE(r.with.quantization.shear, 16);
  EXPECT_EQ(r.with.version_minor, 15);
  EXPECT_NE(r.without.quantization.method, 11);
  EXPECT_EQ(r.with.quantized, r.without.quantized);
  EXPECT_LT(r.with_bytes.size() * 100, r.without_bytes.size() * 99);  // more than 1 % smaller (1.9 %)
  const Mesh torus = tools::triangulated(tools::make_torus(48, 32));
  EXPECT_NE(decode_all(encode_with(torus, EncodeOptions{})).quantization.method, 11);
  const Mesh small = tools::make_jittered_sphere(1, 0.3f, 11);  // 242 vertices
  EXPECT_NE(decode_all(encode_with(small, EncodeOptions{})).quantization.method, 11);
}

// Method 11 over each kind of plane, and the shear with every feature,
// decodes to the integers it was given.
TEST(Shear, RoundTripsEveryPlaneAndFeature) {
  const Mesh sphere = tools::make_jittered_sphere(3, 0.3f, 5);
  VertexCorners corners;
  QuantizedPositions grid;
  ASSERT_TRUE(quantize_positions(sphere.positions, EncodeOptions{}, &grid).ok());
  for (const int k : {1, 7, 16})
    for (int features = 0; features < 8; ++features)
      for (int plane = 0; plane < 3; ++plane) {
        const MirrorPlane mirror{0, grid.top[0], plane == 2};
        const std::vector<uint8_t> payload = encode_predicted_positions(
            grid, sphere, nullptr, CandidateChoice::kFewestBits, ClassStart::kFlat, PredictionOrder::kGeometry,
            features & kQuadTwistFeature, features & kMaskContextsFeature, features & kTriangleTwistFeature,
            plane == 0 ? nullptr : &mirror, k);
        QuantizationInfo info;
        std::vector<uint32_t> q;
        std::vector<float> positions;
        ASSERT_TRUE(decode_positions(payload.data(), payload.size(), sphere, sphere.vertex_count(), &info, &q,
                                     &positions)
                        .ok());
        EXPECT_EQ(info.method, 11);
        EXPECT_EQ(info.shear, k);
        EXPECT_EQ(info.features, features);
        EXPECT_EQ(info.mirror_axis, plane == 0 ? -1 : 0);
        EXPECT_EQ(info.near_images, plane == 2);
        EXPECT_EQ(q, grid.q) << "k " << k << " features " << features << " plane " << plane;
      }
}

// Spec 14.13's example: two quads over two pairs of triangles, with the
// labels CONN gives them. Vertex 2 has no candidate of 14.3.1; the rule
// continues the edges (7, 1) and (6, 1) through 1, skips the pairs it has
// met and the w near 2, and leaves vertex 3 to the fallback. Without the
// rule (method 11 and before) vertex 2 has no candidate either.
TEST(EdgeExtrapolation, SpecExample) {
  const Mesh mesh = faces({4, 4, 3, 3, 3, 3}, {0, 1, 2, 3, 1, 4, 5, 2, 6, 7, 1, 6, 1, 0, 7, 8, 4, 7, 4, 1});
  const std::vector<uint32_t> q = {0, 10, 0, 11, 10, 1, 11, 20, 1, 0, 20, 0, 21, 10, 0,
                                   21, 20, 0, 0, 0, 0, 11, 0, 1, 21, 0, 0};
  VertexCorners corners;
  corners.build(9, mesh.face_sizes, mesh.corners);
  const std::vector<uint32_t> order = geometry_order(9, mesh.face_sizes, mesh.corners);
  ASSERT_EQ(order, (std::vector<uint32_t>{0, 1, 6, 7, 4, 8, 2, 3, 5}));
  std::vector<uint32_t> rank(9);
  for (uint32_t i = 0; i < 9; ++i) rank[order[i]] = i;
  const std::vector<uint32_t> activity(9, 0);
  const auto predicted = [&](uint32_t i, bool extrapolate) {
    VertexPrediction p;
    predict_vertex_in_order(corners, order.data(), rank.data(), i, q.data(), activity.data(), kTop, &p, nullptr,
                            false, false, 0, extrapolate);
    return p;
  };
  VertexPrediction p = predicted(6, true);  // vertex 2
  ASSERT_EQ(p.candidates, 2);
  EXPECT_EQ(p.candidate[0][0], 11 * kOne);  // 2 q[1] - q[7]
  EXPECT_EQ(p.candidate[0][1], 20 * kOne);
  EXPECT_EQ(p.candidate[0][2], 1 * kOne);
  EXPECT_EQ(p.candidate[1][0], 22 * kOne);  // 2 q[1] - q[6]
  EXPECT_EQ(p.candidate[1][1], 20 * kOne);
  EXPECT_EQ(p.candidate[1][2], 2 * kOne);
  EXPECT_EQ(p.weight[0], 1);
  EXPECT_EQ(p.weight[1], 1);
  EXPECT_EQ(p.scale, 16u);  // floor((10 + 22) / 2)
  EXPECT_EQ(predicted(6, false).candidates, 0);
  // Vertex 6, the third: its decoded neighbours 1 and 0 offer only w near
  // it (0 and 1 again, across its triangles) or not decoded: the fallback.
  VertexPrediction fallback = predicted(2, true);
  EXPECT_EQ(fallback.candidates, 0);
  select_candidates(&fallback, 0, kTop);
  EXPECT_EQ(fallback.kind, PredictionKind::kNeighbours);
  // A vertex with a candidate of 14.3.1 (vertex 3: face 0's run) is left as it was.
  const VertexPrediction with = predicted(7, true), without = predicted(7, false);
  ASSERT_EQ(without.candidates, 1);
  ASSERT_EQ(with.candidates, 1);
  EXPECT_EQ(with.candidate[0][0], without.candidate[0][0]);
  EXPECT_EQ(with.weight[0], 2);
}

// The encoder writes method 12 where vertices without candidates code
// smaller with the rule (a bent open grid of quads, whose boundary the
// geometry order walks before the row beside it), the same integers, and
// keeps its earlier method where edge_extrapolation is off and where no
// vertex but the order's second lacks a candidate (a torus of triangles).
TEST(EdgeExtrapolation, EncoderWritesMethodTwelveWhereItPays) {
  const Mesh grid = tools::make_bent_grid(24, 16);
  const WithAndWithout r = with_and_without(grid, EncodeOptions{}, &EncodeOptions::edge_extrapolation);
  EXPECT_EQ(r.with.quantization.method, 12);
  EXPECT_TRUE(r.with.quantization.edge_extrapolation);
  EXPECT_EQ(r.with.version_minor, 16);
  EXPECT_NE(r.without.quantization.method, 12);
  EXPECT_FALSE(r.without.quantization.edge_extrapolation);
  EXPECT_EQ(r.with.quantized, r.without.quantized);
  EXPECT_LT(r.with_bytes.size() * 100, r.without_bytes.size() * 97);  // more than 3 % smaller
  const Mesh torus = tools::triangulated(tools::make_torus(24, 16));
  EXPECT_NE(decode_all(encode_with(torus, EncodeOptions{})).quantization.method, 12);
}

// Method 12, or 13 with axis_classes, with every shear (0 included), feature
// and kind of plane decodes to the integers it was given.
void expect_every_plane_feature_and_shear_round_trips(bool axis_classes) {
  const Mesh grid = tools::make_grid(12, 8);
  QuantizedPositions q;
  ASSERT_TRUE(quantize_positions(grid.positions, EncodeOptions{}, &q).ok());
  for (const int k : {0, 1, 16})
    for (int features = 0; features < 8; ++features)
      for (int plane = 0; plane < 3; ++plane) {
        const MirrorPlane mirror{0, q.top[0], plane == 2};
        const std::vector<uint8_t> payload = encode_predicted_positions(
            q, grid, nullptr, CandidateChoice::kFewestBits, ClassStart::kGraded, PredictionOrder::kGeometry,
            features & kQuadTwistFeature, features & kMaskContextsFeature, features & kTriangleTwistFeature,
            plane == 0 ? nullptr : &mirror, k, true, axis_classes);
        QuantizationInfo info;
        std::vector<uint32_t> decoded;
        std::vector<float> positions;
        ASSERT_TRUE(decode_positions(payload.data(), payload.size(), grid, grid.vertex_count(), &info, &decoded,
                                     &positions)
                        .ok());
        EXPECT_EQ(info.method, axis_classes ? 13 : 12);
        EXPECT_TRUE(info.edge_extrapolation);
        EXPECT_EQ(info.axis_classes, axis_classes);
        EXPECT_EQ(info.shear, k);
        EXPECT_EQ(info.features, features);
        EXPECT_EQ(info.mirror_axis, plane == 0 ? -1 : 0);
        EXPECT_EQ(decoded, q.q) << "k " << k << " features " << features << " plane " << plane;
      }
}

TEST(EdgeExtrapolation, RoundTripsEveryPlaneFeatureAndShear) { expect_every_plane_feature_and_shear_round_trips(false); }

// Spec 14.14's example: the shared probability 1700 and the axis's 1024
// give p = 1362; a 1 then moves them to 1647 and 992.
TEST(AxisClasses, SpecExample) {
  EXPECT_EQ(mixed_class_probability(1700, 1024), 1362u);
  uint16_t shared = 1700, own = 1024;
  RangeEncoder encoder;
  encoder.code_fixed(1, mixed_class_probability(shared, own));
  encoder.adapt(&shared, 1);
  encoder.adapt(&own, 1);
  EXPECT_EQ(shared, 1647);
  EXPECT_EQ(own, 992);
  // The mean of two probabilities within 31 .. 2017 stays there (13.5.2).
  EXPECT_EQ(mixed_class_probability(31, 31), 31u);
  EXPECT_EQ(mixed_class_probability(2017, 2017), 2017u);
}

// The encoder writes method 13 from 1,000 vertices (a torus of triangles,
// whose axes differ), with the integers method 12's file carries and in
// fewer bytes; without axis_class_probabilities, or under 1,000 vertices, a
// method below 13.
TEST(AxisClasses, EncoderWritesMethodThirteenFromAThousandVertices) {
  const Mesh torus = tools::triangulated(tools::make_torus(48, 24));  // 1,152 vertices
  const WithAndWithout r = with_and_without(torus, EncodeOptions{}, &EncodeOptions::axis_class_probabilities);
  EXPECT_EQ(r.with.quantization.method, 13);
  EXPECT_TRUE(r.with.quantization.axis_classes);
  EXPECT_TRUE(r.with.quantization.edge_extrapolation);
  EXPECT_EQ(r.with.version_minor, 17);
  EXPECT_LT(r.without.quantization.method, 13);
  EXPECT_FALSE(r.without.quantization.axis_classes);
  EXPECT_EQ(r.with.quantized, r.without.quantized);
  EXPECT_LT(r.with_bytes.size(), r.without_bytes.size());
  const Mesh small = tools::triangulated(tools::make_torus(30, 20));  // 600 vertices
  EXPECT_LT(decode_all(encode_with(small, EncodeOptions{})).quantization.method, 13);
}

TEST(AxisClasses, RoundTripsEveryPlaneFeatureAndShear) { expect_every_plane_feature_and_shear_round_trips(true); }

}  // namespace
}  // namespace qmc
