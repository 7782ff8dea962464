// The guided rule of spec section 15.12 (aTTR coding 7): the spec's
// example, the side taken from a triangle across the edge, and round trips
// of texture coordinates through the encoder and decoder.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "attribute_generators.h"
#include "common/vertex_prediction.h"
#include "mesh_generators.h"
#include "splitmix64.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc {
namespace {

constexpr int64_t kOne = 65536;

// Positions p[0] = (0, 0, 0), p[1] = (4, 0, 0), p[3] = (0, 3, 0); values (one
// per vertex, q of 3 components, the third 0) q[0] = (10, 10), q[1] = (18, 10).
struct Example {
  std::vector<uint32_t> positions = {0, 0, 0, 4, 0, 0, 0, 0, 0, 0, 3, 0};
  std::vector<uint32_t> q = {10, 10, 0, 18, 10, 0, 14, 16, 0, 0, 0, 0};
  std::vector<uint32_t> activity = std::vector<uint32_t>(4, 0);
  uint32_t top[3] = {100, 100, 0};
};

// Value 3 predicted over the faces (values are vertices: mapping 0), with
// the guide or, if guide is null, without.
VertexPrediction predict_value_3(const std::vector<uint32_t>& sizes, const std::vector<uint32_t>& corners,
                                 PositionGuide* guide) {
  Example e;
  VertexCorners mesh;
  mesh.build(4, sizes, corners);
  if (guide) {
    guide->vertex_of_corner = corners.data();
    guide->positions = e.positions.data();
  }
  VertexPrediction p;
  predict_vertex(mesh, 3, e.q.data(), e.activity.data(), e.top, &p, guide);
  return p;
}

// 15.12's example: value 3 at corner (3, 0, 1) of a lone triangle; a = 0,
// b = 1, no o, so sigma = omega = +1: the candidate (10, 16).
TEST(GuidedRule, ExampleOfTheSpec) {
  const std::vector<uint32_t> sizes = {3}, corners = {3, 0, 1};
  PositionGuide guide;
  VertexPrediction p = predict_value_3(sizes, corners, &guide);
  ASSERT_EQ(p.candidates, 1);
  EXPECT_EQ(p.candidate[0][0], 10 * kOne);
  EXPECT_EQ(p.candidate[0][1], 16 * kOne);
  EXPECT_EQ(p.candidate[0][2], 0);
  EXPECT_EQ(p.scale, 8u);  // |D| = |(8, 0)|
  EXPECT_EQ(guide.orientation, 1);
  // Without the guide, the lone triangle gives no candidate at all.
  EXPECT_EQ(predict_value_3(sizes, corners, nullptr).candidates, 0);
}

// The triangle (0, 1, 2) across the edge has o = 2 at (14, 16), above the
// edge from a to b (W = 8 x 6 > 0): sigma = -1, the candidate below it,
// (10, 4), and omega becomes -1 for the values after.
TEST(GuidedRule, SideOppositeTheTriangleAcross) {
  PositionGuide guide;
  const VertexPrediction p = predict_value_3({3, 3}, {0, 1, 2, 3, 0, 1}, &guide);
  ASSERT_EQ(p.candidates, 1);  // the guided candidate instead of the parallelogram 0 + 1 - 2
  EXPECT_EQ(p.candidate[0][0], 10 * kOne);
  EXPECT_EQ(p.candidate[0][1], 4 * kOne);
  EXPECT_EQ(guide.orientation, -1);
}

// Texture coordinates of a flattened, irregular surface: coding 7 is chosen,
// decodes to the same grid points as coding 4 does, and is smaller.
TEST(GuidedRule, CodingSevenCarriesTheSameValuesSmaller) {
  Mesh m = tools::triangulated(tools::make_grid(20, 20));
  tools::SplitMix64 random(5);
  for (size_t v = 0; v < m.vertex_count(); ++v)
    for (int a = 0; a < 2; ++a) m.positions[3 * v + a] += 0.03f * (float(random.next() % 2001) / 1000.f - 1.f);
  MeshAttribute uv{"texcoord", AttributeKind::kTextureCoordinate, 2, {}, m.corners};
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    uv.values.push_back(m.positions[3 * v]);
    uv.values.push_back(m.positions[3 * v + 1]);
  }
  m.attributes.push_back(uv);
  std::vector<uint8_t> guided, plain;
  EncodeOptions options;
  EncodeStats stats;
  ASSERT_TRUE(encode(m, options, &guided, &stats).ok());
  EXPECT_TRUE(stats.attributes[0].guided);
  const uint64_t guided_bytes = stats.attributes[0].chunk_bytes;
  options.attribute_guided = false;
  ASSERT_TRUE(encode(m, options, &plain, &stats).ok());
  EXPECT_FALSE(stats.attributes[0].guided);
  EXPECT_LT(guided_bytes, stats.attributes[0].chunk_bytes);
  DecodedFile a, b;
  ASSERT_TRUE(decode(guided.data(), guided.size(), &a).ok());
  ASSERT_TRUE(decode(plain.data(), plain.size(), &b).ok());
  EXPECT_EQ(a.attribute_codings[0].coding, 7);
  EXPECT_EQ(a.mesh.attributes[0].values, b.mesh.attributes[0].values);
  EXPECT_EQ(a.mesh.attributes[0].corner_values, b.mesh.attributes[0].corner_values);
}

}  // namespace
}  // namespace qmc
