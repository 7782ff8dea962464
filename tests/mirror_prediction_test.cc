// POSN method 9 (spec 14.10): the mirror candidate, its search, the
// encoder's choice and round trips over every plane.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include "common/geometry_order.h"
#include "common/mirror_prediction.h"
#include "common/vertex_prediction.h"
#include "decoder/position_decoder.h"
#include "encoder/occupied_blocks.h"
#include "encoder/position_encoder.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc {
namespace {

constexpr uint32_t kKiteTop[3] = {12, 10, 3};

Mesh kite_faces() {
  Mesh m;
  m.face_sizes = {3, 3};
  m.corners = {0, 1, 2, 1, 0, 3};
  return m;
}

// Spec 14.10's example step by step: vertex 2's candidate is the image of
// vertex 0 (D = 5, s = 3), vertex 3's the image of vertex 2 (D = 3, s = 2);
// vertices 0 and 1 have none.
TEST(MirrorCandidate, SpecExample) {
  const Mesh kite = kite_faces();
  const std::vector<uint32_t> q = {6, 0, 0, 6, 10, 0, 0, 5, 3, 12, 5, 3};
  VertexCorners corners;
  corners.build(4, kite.face_sizes, kite.corners);
  ASSERT_EQ(geometry_order(4, kite.face_sizes, kite.corners), (std::vector<uint32_t>{0, 1, 2, 3}));
  MirrorCandidates mirrors(corners, MirrorPlane{0, 12}, kKiteTop);
  const std::vector<uint32_t> order = {0, 1, 2, 3}, activity(4, 0);
  VertexPrediction p;
  int64_t c[3];
  for (uint32_t v = 0; v < 2; ++v) {
    predict_vertex_in_order(corners, order.data(), order.data(), v, q.data(), activity.data(), kKiteTop, &p);
    select_candidates(&p, (1u << p.candidates) - 1, kKiteTop);
    EXPECT_FALSE(mirrors.find(v, q.data(), p, c)) << v;
    mirrors.decoded(v, q.data());
  }
  predict_vertex_in_order(corners, order.data(), order.data(), 2, q.data(), activity.data(), kKiteTop, &p);
  ASSERT_EQ(p.candidates, 0);
  select_candidates(&p, 0, kKiteTop);
  EXPECT_EQ(std::vector<int64_t>(p.value, p.value + 3), (std::vector<int64_t>{6, 5, 0}));  // the fallback
  ASSERT_TRUE(mirrors.find(2, q.data(), p, c));
  EXPECT_EQ(std::vector<int64_t>(c, c + 3), (std::vector<int64_t>{6, 0, 0}));
  EXPECT_EQ(mirror_context(c, p.value), 3);  // D = 5
  mirrors.decoded(2, q.data());
  predict_vertex_in_order(corners, order.data(), order.data(), 3, q.data(), activity.data(), kKiteTop, &p);
  ASSERT_EQ(p.candidates, 1);
  select_candidates(&p, 1, kKiteTop);
  EXPECT_EQ(std::vector<int64_t>(p.value, p.value + 3), (std::vector<int64_t>{12, 5, 0}));  // (12, 5, -3) clamped
  ASSERT_TRUE(mirrors.find(3, q.data(), p, c));
  EXPECT_EQ(std::vector<int64_t>(c, c + 3), (std::vector<int64_t>{12, 5, 3}));
  EXPECT_EQ(mirror_context(c, p.value), 2);  // D = 3
}

// 14.10's image vertex is the first decoded at the point, and a point off
// the grid has none.
TEST(MirrorCandidate, TheFirstVertexAtAPointIsItsImageVertex) {
  GridPointTable table(4);
  const uint32_t a[3] = {1, 2, 3}, b[3] = {3, 2, 1};
  EXPECT_EQ(table.find(a), GridPointTable::kNone);
  table.insert(a, 7);
  table.insert(a, 5);
  table.insert(b, 9);
  EXPECT_EQ(table.find(a), 7u);
  EXPECT_EQ(table.find(b), 9u);
  // Vertex 1 at (2, 0, 0) has vertex 0 at (8, 0, 0) as neighbour; across
  // x = 5 (sum 10) 0's image point (2, 0, 0) holds no decoded vertex yet.
  Mesh edge;
  edge.face_sizes = {3};
  edge.corners = {0, 1, 2};
  VertexCorners corners;
  corners.build(3, edge.face_sizes, edge.corners);
  const uint32_t top[3] = {20, 20, 20};
  const std::vector<uint32_t> q = {8, 0, 0, 2, 0, 0, 5, 5, 0};
  VertexPrediction p;
  p.value[0] = p.value[1] = p.value[2] = 0;
  int64_t c[3];
  MirrorCandidates off_grid(corners, MirrorPlane{0, 30}, top);  // 0's image x = 22 > top
  off_grid.decoded(0, q.data());
  EXPECT_FALSE(off_grid.find(1, q.data(), p, c));
}

// The decoder's table of 14.10 and 14.11 reads each vertex's point from the
// positions: the first vertex inserted at a point is the one found there,
// whatever the table's key; beside a point, a step down the axis is looked at
// before a step up.
TEST(MirrorCandidate, VertexPointTableFindsTheFirstVertexAtEachPoint) {
  std::mt19937 random(49);
  std::uniform_int_distribution<uint32_t> coordinate(0, 15);  // 4,096 points for 3,000 vertices: many repeat
  const uint32_t n = 3000;
  std::vector<uint32_t> points(3 * n);
  for (uint32_t& c : points) c = coordinate(random);
  VertexPointTable table(n);
  std::map<std::array<uint32_t, 3>, uint32_t> first;
  for (uint32_t v = 0; v < n; ++v) {
    const std::array<uint32_t, 3> point = {points[3 * v], points[3 * v + 1], points[3 * v + 2]};
    const auto known = first.find(point);
    EXPECT_EQ(table.insert(points.data(), v), known == first.end() ? VertexPointTable::kNone : known->second);
    first.emplace(point, v);
  }
  uint32_t absent = 0;
  for (uint32_t x = 0; x < 16; ++x)
    for (uint32_t y = 0; y < 16; ++y)
      for (uint32_t z = 0; z < 17; ++z) {
        const uint32_t q[3] = {x, y, z};
        const auto known = first.find({x, y, z});
        const uint32_t want = known == first.end() ? VertexPointTable::kNone : known->second;
        absent += want == VertexPointTable::kNone;
        ASSERT_EQ(table.find(points.data(), q), want) << x << " " << y << " " << z;
      }
  EXPECT_GT(absent, 16u * 16u);  // z = 16 is off every point, and some others are empty
  // Beside (x, y, z) on axis 2: (x, y, z - 1) first, then (x, y, z + 1).
  int both = 0, above_only = 0;
  for (const auto& [point, v] : first) {
    const uint32_t q[3] = {point[0], point[1], point[2] + 1};
    const auto up = first.find({point[0], point[1], point[2] + 2});
    EXPECT_EQ(table.find_next_to(points.data(), q, 2), v);  // the step down, whatever is above
    both += up != first.end();
    const uint32_t lowest[3] = {point[0], point[1], 0};  // nothing below 0 (it wraps to 2^32 - 1)
    const auto at1 = first.find({point[0], point[1], 1});
    if (point[2] == 0 && at1 != first.end()) {
      EXPECT_EQ(table.find_next_to(points.data(), lowest, 2), at1->second);
      ++above_only;
    }
  }
  EXPECT_GT(both, 100);
  EXPECT_GT(above_only, 10);
}

// On a mirrored mesh the encoder writes method 9, the same integers as
// methods 4 - 8 in far fewer bytes; without the option, or on a mesh
// without a plane, methods 4 - 8.
TEST(MirrorCandidate, EncoderWritesMethodNineOnMirroredMeshes) {
  const Mesh sphere = tools::make_mirrored_across_x(tools::triangulated(tools::make_refined_sphere(3)));
  EncodeOptions with, without;
  with.near_mirror = false;  // method 10: the next test
  without.mirror_symmetry = false;
  with.axis_class_probabilities = without.axis_class_probabilities = false;  // method 13 (14.14): its own tests
  std::vector<uint8_t> a, b;
  EncodeStats sa, sb;
  ASSERT_TRUE(encode(sphere, with, &a, &sa).ok());
  ASSERT_TRUE(encode(sphere, without, &b, &sb).ok());
  DecodedFile da, db;
  ASSERT_TRUE(decode(a.data(), a.size(), &da).ok());
  ASSERT_TRUE(decode(b.data(), b.size(), &db).ok());
  EXPECT_EQ(da.quantization.method, 9);
  EXPECT_EQ(da.version_minor, 12);
  EXPECT_GE(da.quantization.mirror_axis, 0);  // the sphere has planes across each axis
  EXPECT_LT(db.quantization.method, 9);
  EXPECT_EQ(da.quantized, db.quantized);
  EXPECT_LT(a.size() * 10, b.size() * 8);  // 20 % smaller at least
  EXPECT_GT(sa.positions.vertices_by_kind[int(PredictionKind::kMirror)], sphere.vertex_count() / 3);
  const Mesh lopsided = tools::triangulated(tools::make_torus(24, 10, 1.f, 0.3f));
  Mesh bent = lopsided;
  for (size_t v = 0; v < bent.vertex_count(); ++v)  // z + 0.3 x y + 0.1 x: no plane maps it onto itself
    bent.positions[3 * v + 2] += 0.3f * bent.positions[3 * v] * bent.positions[3 * v + 1] + 0.1f * bent.positions[3 * v];
  std::vector<uint8_t> c;
  ASSERT_TRUE(encode(bent, with, &c).ok());
  DecodedFile dc;
  ASSERT_TRUE(decode(c.data(), c.size(), &dc).ok());
  EXPECT_LT(dc.quantization.method, 9);
}

// From about 130,000 vertices the mirror search's table outgrows the
// caches, and both coders then leave each vertex's bookkeeping until the
// next vertex is predicted, its slots prefetched (MirrorSource::prefetches):
// the file still decodes to the integers that a file without the plane gives.
TEST(MirrorCandidate, LargeMeshesDeferTheBookkeepingAndDecodeTheSame) {
  const Mesh grid = tools::make_grid(370, 370);  // 137,641 vertices, symmetric across x = 0 and y = 0
  const Mesh small_grid = tools::make_grid(100, 100);
  const uint32_t top[3] = {4095, 4095, 4095};
  VertexCorners corners, small_corners;
  corners.build(uint32_t(grid.vertex_count()), grid.face_sizes, grid.corners);
  small_corners.build(uint32_t(small_grid.vertex_count()), small_grid.face_sizes, small_grid.corners);
  EXPECT_TRUE(MirrorCandidates(corners, MirrorPlane{0, 4095, true}, top).prefetches());
  EXPECT_FALSE(MirrorCandidates(small_corners, MirrorPlane{0, 4095, true}, top).prefetches());
  EncodeOptions with, without;
  without.mirror_symmetry = false;
  std::vector<uint8_t> a, b;
  ASSERT_TRUE(encode(grid, with, &a).ok());
  ASSERT_TRUE(encode(grid, without, &b).ok());
  DecodedFile da, db;
  ASSERT_TRUE(decode(a.data(), a.size(), &da).ok());
  ASSERT_TRUE(decode(b.data(), b.size(), &db).ok());
  EXPECT_GE(da.quantization.method, 9);
  EXPECT_GE(da.quantization.mirror_axis, 0);
  EXPECT_LT(db.quantization.mirror_axis, 0);
  EXPECT_EQ(da.quantized, db.quantized);
  EXPECT_LT(a.size(), b.size());
}

// A linear congruential generator (Knuth's MMIX constants), so that the
// tests' points are the same on every platform.
class Lcg {
 public:
  explicit Lcg(uint64_t seed) : state_(seed) {}
  uint32_t below(uint32_t bound) {
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return uint32_t((state_ >> 33) % bound);
  }

 private:
  uint64_t state_;
};

// Points paired across x = 1500 / 2 (sum 1500) and a third as many unpaired
// beyond the pairs up to x = 4095, so the plane is far from the middle of
// the box (sum 4095): the search finds it from the pairs' sums, with every
// column looked at (300 vertices) and with a sample of them (40,000).
QuantizedPositions lopsided_mirror_grid(uint32_t pairs) {
  QuantizedPositions grid;
  grid.top = {4095, 4095, 4095};
  Lcg random(12345);
  const auto next = [&](uint32_t bound) { return random.below(bound); };
  for (uint32_t i = 0; i < pairs; ++i) {
    const uint32_t x = next(700), y = next(4096), z = next(4096);
    grid.q.insert(grid.q.end(), {x, y, z, 1500 - x, y, z});
    if (i % 3 == 0) grid.q.insert(grid.q.end(), {1501 + next(2595), next(4096), next(4096)});
  }
  grid.q.insert(grid.q.end(), {4095, 0, 0});
  return grid;
}

TEST(MirrorCandidate, SearchFindsAPlaneAwayFromTheMiddleOfTheBox) {
  for (const uint32_t pairs : {129u, 17143u}) {
    const QuantizedPositions grid = lopsided_mirror_grid(pairs);
    MirrorPlane plane;
    ASSERT_TRUE(find_mirror_plane(grid, &plane, false)) << pairs << " pairs";
    EXPECT_EQ(plane.axis, 0);
    EXPECT_EQ(plane.sum, 1500u);
  }
}

// 2,000 points paired across x = 4095 / 2 (sum 4095), each image moved on
// all three axes: by -1, 0 or 1 on each (near = true; exactly at its
// partner 1 time in 27), or by -2 or 2 on each (near = false: never within
// a step). The search's second pass (from 1,000 vertices on) counts a
// vertex within a step of the image on every axis, diagonal steps and steps
// across its blocks of 4 points included, and nothing further.
QuantizedPositions pairs_apart(bool near) {
  QuantizedPositions grid;
  grid.top = {4095, 4095, 4095};
  Lcg random(777);
  const auto next = [&](uint32_t bound) { return random.below(bound); };
  const auto offset = [&] { return near ? int(next(3)) - 1 : 4 * int(next(2)) - 2; };
  for (int i = 0; i < 1000; ++i) {
    const int x = 10 + int(next(1900)), y = 10 + int(next(4000)), z = 10 + int(next(4000));
    const int dx = offset(), dy = offset(), dz = offset();
    for (const int value : {x, y, z, 4095 - x + dx, y + dy, z + dz}) grid.q.push_back(uint32_t(value));
  }
  return grid;
}

// OccupiedBlocks against a look at each of the 27 points: points of a
// 13-point cube (blocks of 4 cut it at 4, 8 and 12), every point of the
// cube and one beyond asked, 0 included (nothing lies below it).
TEST(MirrorCandidate, OccupiedBlocksFindWhatTheTwentySevenPointsHold) {
  Lcg random(99);
  for (int round = 0; round < 20; ++round) {
    std::vector<uint32_t> q;
    std::vector<bool> held(14 * 14 * 14, false);
    for (int i = 0; i < 1 + round * 5; ++i) {
      uint32_t p[3];
      for (uint32_t& c : p) c = random.below(13);
      q.insert(q.end(), p, p + 3);
      held[p[0] + 14 * (p[1] + 14 * p[2])] = true;
    }
    const OccupiedBlocks blocks(q);
    for (int x = 0; x <= 13; ++x)
      for (int y = 0; y <= 13; ++y)
        for (int z = 0; z <= 13; ++z) {
          bool expected = false;
          for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dz = -1; dz <= 1; ++dz) {
                const int a = x + dx, b = y + dy, c = z + dz;
                if (a >= 0 && b >= 0 && c >= 0 && a < 14 && b < 14 && c < 14 && held[a + 14 * (b + 14 * c)])
                  expected = true;
              }
          const uint32_t point[3] = {uint32_t(x), uint32_t(y), uint32_t(z)};
          ASSERT_EQ(blocks.near(point), expected) << "round " << round << " at " << x << " " << y << " " << z;
        }
  }
}

TEST(MirrorCandidate, SearchCountsImagesAStepAwayOnEveryAxis) {
  MirrorPlane plane;
  EXPECT_FALSE(find_mirror_plane(pairs_apart(true), &plane, false));  // 1 in 27 exact: too few
  ASSERT_TRUE(find_mirror_plane(pairs_apart(true), &plane, true));
  EXPECT_EQ(plane.axis, 0);
  EXPECT_TRUE(plane.near_images);
  EXPECT_EQ(plane.sum, 4095u);
  EXPECT_FALSE(find_mirror_plane(pairs_apart(false), &plane, true));
}

// Method 10 (14.11): a lumpy sphere mirrored across x (its lumps break the
// planes across y and z), its box reaching further on one side (one more
// vertex at x = 1.37), so that the plane falls between grid points and the
// halves are a step apart where they round apart: method 10 finds those
// twins too (5 % smaller at 14 bits), method 9 only the exact ones.
TEST(MirrorCandidate, EncoderWritesMethodTenWhereTheHalvesAreAStepApart) {
  Mesh lumpy = tools::triangulated(tools::make_refined_sphere(3));
  for (size_t v = 0; v < lumpy.vertex_count(); ++v) {
    float* p = &lumpy.positions[3 * v];
    p[1] += 0.1f * std::sin(3 * p[0] + 2 * p[2]);
    p[2] += 0.1f * std::cos(2 * p[1] + p[0]);
  }
  Mesh sphere = tools::make_mirrored_across_x(lumpy);
  sphere.positions.insert(sphere.positions.end(), {1.37f, 0.f, 0.f});  // a vertex no face uses
  EncodeOptions near, exact;
  near.position_bits = exact.position_bits = 14;
  exact.near_mirror = false;
  near.axis_class_probabilities = exact.axis_class_probabilities = false;  // method 13 (14.14): its own tests
  std::vector<uint8_t> a, b;
  ASSERT_TRUE(encode(sphere, near, &a).ok());
  ASSERT_TRUE(encode(sphere, exact, &b).ok());
  DecodedFile da, db;
  ASSERT_TRUE(decode(a.data(), a.size(), &da).ok());
  ASSERT_TRUE(decode(b.data(), b.size(), &db).ok());
  EXPECT_EQ(da.quantization.method, 10);
  EXPECT_EQ(da.version_minor, 13);
  EXPECT_EQ(db.quantization.method, 9);
  EXPECT_EQ(da.quantization.mirror_axis, 0);
  EXPECT_EQ(da.quantized, db.quantized);
  EXPECT_LT(a.size() * 100, b.size() * 97) << a.size() << " vs " << b.size();  // 3 % smaller at least
}

// Any plane, those whose images leave the grid included, and any features:
// what the encoder writes decodes to its integers.
TEST(MirrorCandidate, RoundTripsEveryPlane) {
  std::vector<Mesh> meshes = {tools::make_mirrored_across_x(tools::make_refined_sphere(2)),
                              tools::make_mirrored_across_x(tools::triangulated(tools::make_torus(12, 8)))};
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 40 + uint32_t(seed * 9);
    o.faces = 30 + uint32_t(seed * 7);
    meshes.push_back(tools::make_mirrored_across_x(tools::make_random_soup(seed, o), 0.05f));
  }
  for (const Mesh& mesh : meshes) {
    const QuantizedPositions grid = quantize_positions(mesh.positions, 12);
    for (int axis = 0; axis < 3; ++axis)
      for (uint32_t sum : {0u, grid.top[size_t(axis)] - 1, grid.top[size_t(axis)], 2 * grid.top[size_t(axis)]})
        for (int features : {0, 7, 8, 15}) {  // 8: method 10's near image vertices
          const MirrorPlane plane{axis, sum, features >= 8};
          const std::vector<uint8_t> payload = encode_predicted_positions(
              grid, mesh, nullptr, CandidateChoice::kFewestBits, ClassStart::kGraded, PredictionOrder::kGeometry,
              features & 1, features & 2, features & 4, &plane);  // features 8 and 15: 0 and 7 with method 10
          ASSERT_FALSE(payload.empty());
          QuantizationInfo info;
          std::vector<uint32_t> q;
          std::vector<float> positions;
          ASSERT_TRUE(decode_positions(payload.data(), payload.size(), mesh, uint32_t(mesh.vertex_count()), &info,
                                       &q, &positions)
                          .ok());
          EXPECT_EQ(info.method, features >= 8 ? 10 : 9);
          EXPECT_EQ(info.mirror_axis, axis);
          EXPECT_EQ(info.mirror_sum, sum);
          EXPECT_EQ(info.features, features & 7);
          EXPECT_EQ(q, grid.q);
        }
  }
}

}  // namespace
}  // namespace qmc
