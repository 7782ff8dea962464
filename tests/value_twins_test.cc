// aTTR coding 9 (spec 15.14): the twin candidate of a value, the spec's
// example, the encoder's choice and round trips over every plane, option
// and random seams.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "common/mirror_prediction.h"
#include "common/value_twins.h"
#include "common/vertex_prediction.h"
#include "decoder/position_decoder.h"
#include "encoder/position_encoder.h"
#include "attribute_generators.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc {
namespace {

// 15.14's example: a fan of three triangles around vertex 0, mirrored across
// x = 2 (sum 4), its values mirrored across u = 10.
struct Example {
  Mesh faces;
  std::vector<uint32_t> positions = {2, 0, 0, 1, 3, 0, 0, 1, 0, 3, 3, 0, 4, 1, 0};
  std::vector<uint32_t> q = {10, 0, 0, 8, 6, 0, 5, 2, 0, 12, 6, 0, 15, 2, 0};
  uint32_t top[3] = {15, 6, 0};
  Example() {
    faces.face_sizes = {3, 3, 3};
    faces.corners = {0, 1, 2, 0, 3, 1, 0, 4, 3};
  }
  AttributeTwins twins() const { return AttributeTwins{MirrorPlane{0, 4}, &faces, positions.data(), 5}; }
};

// Values 0 - 2 have no candidate; value 3's carries the signs it found
// (none yet: +1, +1), value 4's flips u.
void expect_example_candidates(const Example& e) {
  VertexCorners values;  // mapping 0: the attribute mesh is CONN's faces
  values.build(5, e.faces.face_sizes, e.faces.corners);
  ValueTwins twins(values, e.twins(), e.top);
  const std::vector<uint32_t> activity(5, 0);
  VertexPrediction p;
  int64_t c[3];
  const auto predict = [&](uint32_t v) {
    predict_vertex(values, v, e.q.data(), activity.data(), e.top, &p);
    select_candidates(&p, (1u << p.candidates) - 1, e.top);
  };
  for (uint32_t v = 0; v < 3; ++v) {
    predict(v);
    EXPECT_FALSE(twins.find(v, e.q.data(), p, c)) << "value " << v;
    twins.decoded(v, e.q.data());
  }
  predict(3);
  EXPECT_EQ(std::vector<int64_t>(p.value, p.value + 3), (std::vector<int64_t>{13, 4, 0}));  // P*
  ASSERT_TRUE(twins.find(3, e.q.data(), p, c));
  EXPECT_EQ(std::vector<int64_t>(c, c + 3), (std::vector<int64_t>{8, 6, 0}));
  EXPECT_EQ(mirror_context(c, p.value), 3);  // dist 7
  twins.decoded(3, e.q.data());
  predict(4);
  EXPECT_EQ(std::vector<int64_t>(p.value, p.value + 3), (std::vector<int64_t>{14, 0, 0}));
  ASSERT_TRUE(twins.find(4, e.q.data(), p, c));
  EXPECT_EQ(std::vector<int64_t>(c, c + 3), (std::vector<int64_t>{15, 2, 0}));  // u flipped, v not
  EXPECT_EQ(mirror_context(c, p.value), 2);                                    // dist 3
}

TEST(ValueTwins, ExampleOfTheSpec) { expect_example_candidates(Example()); }

// Without a vertex at the image, the points a step beside it along the
// axis, down first: vertex 4 at (3, 1, 0) is vertex 2's twin (the image of
// (0, 1, 0) is (4, 1, 0)), and vertex 2 at (0, 1, 0) vertex 4's (its image
// is (1, 1, 0)); the candidates are the same. At (4, 1, 1), off the axis,
// vertex 4 is no twin.
TEST(ValueTwins, ATwinOneStepFromTheImage) {
  Example e;
  e.positions[3 * 4] = 3;
  expect_example_candidates(e);
  e.positions[3 * 4] = 4;
  e.positions[3 * 4 + 2] = 1;
  VertexCorners values;
  values.build(5, e.faces.face_sizes, e.faces.corners);
  ValueTwins twins(values, e.twins(), e.top);
  for (uint32_t v = 0; v < 4; ++v) twins.decoded(v, e.q.data());
  VertexPrediction p;
  int64_t c[3];
  EXPECT_FALSE(twins.find(4, e.q.data(), p, c));  // corner 7's vertex 4 has no twin
}

DecodedFile encoded_and_decoded(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* file) {
  EXPECT_TRUE(encode(mesh, options, file).ok());
  DecodedFile d;
  EXPECT_TRUE(decode(file->data(), file->size(), &d).ok());
  return d;
}

// On mirrored texture coordinates the encoder writes coding 9, the values
// coding 7 or 4 - 6 would give in fewer bytes; asked for files without it,
// it keeps those codings.
TEST(ValueTwins, EncoderWritesCodingNineOnMirroredTextures) {
  Mesh sphere = tools::make_mirrored_across_x(tools::triangulated(tools::make_refined_sphere(3)));
  tools::add_mirrored_texcoords(&sphere, 16, 5);
  EncodeOptions with, without;
  without.attribute_twins = false;
  std::vector<uint8_t> a, b;
  const DecodedFile twinned = encoded_and_decoded(sphere, with, &a);
  const DecodedFile plain = encoded_and_decoded(sphere, without, &b);
  ASSERT_EQ(twinned.attribute_codings.size(), 1u);
  EXPECT_EQ(twinned.attribute_codings[0].coding, 9);
  EXPECT_GE(twinned.attribute_codings[0].mirror_axis, 0);  // POSN method 9's plane: the sphere has one across each axis
  EXPECT_NE(plain.attribute_codings[0].coding, 9);
  EXPECT_EQ(twinned.mesh.attributes[0].values, plain.mesh.attributes[0].values);
  EXPECT_EQ(twinned.mesh.attributes[0].corner_values, plain.mesh.attributes[0].corner_values);
  const uint64_t twinned_bytes = twinned.attribute_codings[0].chunk_bytes, plain_bytes = plain.attribute_codings[0].chunk_bytes;
  EXPECT_LT(twinned_bytes * 10, plain_bytes * 9) << twinned_bytes << " vs " << plain_bytes;  // 10 % smaller at least
}

// Any plane (those whose images leave the grid or meet no vertex included),
// any options, random seams: what the encoder writes decodes to its integers.
TEST(ValueTwins, RoundTripsEveryPlaneAndOption) {
  std::vector<Mesh> meshes = {tools::make_mirrored_across_x(tools::triangulated(tools::make_refined_sphere(2))),
                              tools::make_mirrored_across_x(tools::make_torus(12, 8))};
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 40 + uint32_t(seed * 9);
    o.faces = 30 + uint32_t(seed * 7);
    meshes.push_back(tools::make_mirrored_across_x(tools::make_random_soup(seed, o), 0.05f));
  }
  uint64_t seed = 0;
  for (Mesh& mesh : meshes) {
    tools::add_mirrored_texcoords(&mesh, 5, ++seed);
    const MeshAttribute& a = mesh.attributes[0];
    const QuantizedPositions grid = quantize_positions(mesh.positions, 12);
    // The values' integers on a grid of 1/512, their attribute mesh.
    const uint32_t n = uint32_t(a.value_count());
    std::vector<uint32_t> q(3 * size_t(n), 0);
    uint32_t top[3] = {0, 0, 0};
    for (uint32_t i = 0; i < n; ++i)
      for (int j = 0; j < 2; ++j) {
        q[3 * i + j] = uint32_t(std::lround((a.values[2 * i + j] + 2.0f) * 512));
        top[j] = std::max(top[j], q[3 * i + j]);
      }
    Mesh values;
    values.face_sizes = mesh.face_sizes;
    values.corners = a.corner_values;
    PositionGuide guide;
    guide.vertex_of_corner = mesh.corners.data();
    guide.positions = grid.q.data();
    for (int axis = 0; axis < 3; ++axis)
      for (uint32_t sum : {0u, grid.top[size_t(axis)] - 1, grid.top[size_t(axis)], 2 * grid.top[size_t(axis)]})
        for (int options = 0; options < 8; ++options) {
          const AttributeTwins twins{MirrorPlane{axis, sum}, &mesh, grid.q.data(), uint32_t(mesh.vertex_count())};
          const ClassStart start = options & 2 ? ClassStart::kGraded : ClassStart::kFlat;
          const PredictionOrder order = options & 1 ? PredictionOrder::kGeometry : PredictionOrder::kLabels;
          const PositionGuide* g = options & 4 ? &guide : nullptr;
          const std::vector<uint8_t> stream = encode_predicted_grid(q, top, values, nullptr, CandidateChoice::kFewestBits,
                                                                    start, order, g, false, false, false, &twins);
          std::vector<uint32_t> decoded;
          const PredictedGridNames names{"aTTR", "value", "values", "component"};
          ASSERT_TRUE(decode_predicted_grid(stream.data(), stream.size(), values, n, top, names, &decoded, start,
                                            order, g, false, false, false, nullptr, &twins)
                          .ok())
              << "mesh " << seed << " axis " << axis << " sum " << sum << " options " << options;
          EXPECT_EQ(decoded, q) << "mesh " << seed << " axis " << axis << " sum " << sum << " options " << options;
        }
  }
}

}  // namespace
}  // namespace qmc
