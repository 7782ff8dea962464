// Known answers for the attribute part of `qmc compare`
// (tools/lib/attribute_distance.h): corners found again through positions
// and faces, value distances, normal angles and texture stretch.
#include "attribute_distance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "attribute_generators.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace {

using qmc::AttributeKind;
using qmc::Mesh;
using qmc::MeshAttribute;
using qmc::tools::AttributeComparison;
using qmc::tools::AttributeDistance;
using qmc::tools::compare_attributes;

constexpr double kTolerance = 1e-3;

// A torus of quads with the two-chart texture coordinates (a seam) and
// vertex normals.
Mesh textured_torus() {
  Mesh m = qmc::tools::make_torus(12, 8);
  qmc::tools::add_chart_texcoords(&m);
  qmc::tools::add_vertex_normals(&m);
  return m;
}

AttributeComparison compare(const Mesh& a, const Mesh& b) {
  AttributeComparison c;
  const qmc::Status s = compare_attributes(a, b, kTolerance, &c);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return c;
}

const AttributeDistance& named(const AttributeComparison& c, const std::string& name) {
  for (const AttributeDistance& d : c.attributes)
    if (d.name == name) return d;
  ADD_FAILURE() << "no comparison of " << name;
  static const AttributeDistance none;
  return none;
}
// The reference named() returns lives in c: a comparison that dies with the
// statement would leave it dangling.
const AttributeDistance& named(AttributeComparison&& c, const std::string& name) = delete;

// Renumbers the vertices backwards, lists the faces backwards and starts
// each face at its second corner, carrying every corner's value indices.
Mesh reordered(const Mesh& m) {
  Mesh out = m;
  const uint32_t n = uint32_t(m.vertex_count());
  for (uint32_t v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) out.positions[3 * size_t(n - 1 - v) + k] = m.positions[3 * size_t(v) + k];
  std::vector<uint32_t> start(m.face_count() + 1, 0);
  for (size_t f = 0; f < m.face_count(); ++f) start[f + 1] = start[f] + m.face_sizes[f];
  out.face_sizes.clear();
  out.corners.clear();
  for (MeshAttribute& at : out.attributes) at.corner_values.clear();
  for (size_t f = m.face_count(); f-- > 0;) {
    const uint32_t d = m.face_sizes[f];
    out.face_sizes.push_back(d);
    for (uint32_t k = 0; k < d; ++k) {
      const uint32_t corner = start[f] + (k + 1) % d;
      out.corners.push_back(n - 1 - m.corners[corner]);
      for (size_t j = 0; j < m.attributes.size(); ++j)
        out.attributes[j].corner_values.push_back(m.attributes[j].corner_values[corner]);
    }
  }
  return out;
}

// Every polygon split into a fan of triangles from its first corner, as a
// codec that triangulates does.
Mesh fanned(const Mesh& m) {
  Mesh out = m;
  out.face_sizes.clear();
  out.corners.clear();
  for (MeshAttribute& at : out.attributes) at.corner_values.clear();
  for (uint32_t f = 0, c = 0; f < m.face_count(); c += m.face_sizes[f], ++f)
    for (uint32_t i = 1; i + 1 < m.face_sizes[f]; ++i)
      for (uint32_t k : {c, c + i, c + i + 1}) {
        out.corners.push_back(m.corners[k]);
        for (size_t j = 0; j < m.attributes.size(); ++j)
          out.attributes[j].corner_values.push_back(m.attributes[j].corner_values[k]);
      }
  out.face_sizes.assign(out.corners.size() / 3, 3);
  return out;
}

MeshAttribute& attribute(Mesh* m, const std::string& name) {
  for (MeshAttribute& at : m->attributes)
    if (at.name == name) return at;
  throw std::runtime_error("no attribute " + name);
}

TEST(AttributeDistance, AMeshAgainstItselfHasNoError) {
  const Mesh a = textured_torus();
  const AttributeComparison c = compare(a, a);
  EXPECT_EQ(c.faces_matched, a.face_count());
  EXPECT_EQ(c.faces_ambiguous, 0u);
  EXPECT_EQ(c.match_radius, 0);
  ASSERT_EQ(c.attributes.size(), 2u);
  const AttributeDistance& uv = named(c, "texcoord");
  EXPECT_EQ(uv.corners, a.corners.size());
  EXPECT_EQ(uv.distance_max, 0);
  EXPECT_EQ(uv.stretch_triangles, 2 * a.face_count());
  EXPECT_NEAR(uv.stretch_l2, 1, 1e-12);
  EXPECT_NEAR(uv.stretch_max, 1, 1e-12);
  EXPECT_NEAR(uv.stretch_p99, 1, 1e-12);
  EXPECT_EQ(uv.flipped + uv.collapsed, 0u);
  const AttributeDistance& normal = named(c, "normal");
  EXPECT_EQ(normal.angle_corners, a.corners.size());
  EXPECT_NEAR(normal.angle_max_degrees, 0, 1e-5);
}

TEST(AttributeDistance, OtherOrderOfVerticesFacesAndCornersMatchesEveryCorner) {
  const Mesh a = textured_torus();
  const AttributeComparison c = compare(a, reordered(a));
  EXPECT_EQ(c.faces_matched, a.face_count());
  EXPECT_EQ(named(c, "texcoord").distance_max, 0);
  EXPECT_EQ(named(c, "normal").distance_max, 0);
  EXPECT_NEAR(named(c, "texcoord").stretch_max, 1, 1e-12);
}

TEST(AttributeDistance, TrianglesOfTheOutputAreFoundInTheInputsPolygons) {
  const Mesh a = textured_torus();
  const AttributeComparison c = compare(a, fanned(a));
  EXPECT_EQ(c.faces_b, 2 * a.face_count());
  EXPECT_EQ(c.faces_matched, 2 * a.face_count());
  EXPECT_EQ(named(c, "texcoord").distance_max, 0);
  // And the other way round: A's triangles are not B's quads.
  EXPECT_EQ(compare(fanned(a), a).faces_matched, 0u);
}

TEST(AttributeDistance, TextureScaledTwiceAlongUStretchesEveryTriangleByTwo) {
  const Mesh a = textured_torus();
  Mesh b = a;
  MeshAttribute& uv = attribute(&b, "texcoord");
  double largest_u = 0;
  for (size_t i = 0; i < uv.value_count(); ++i) {
    largest_u = std::max(largest_u, std::fabs(double(uv.values[2 * i])));
    uv.values[2 * i] *= 2;
  }
  const AttributeComparison c = compare(a, b);
  const AttributeDistance& d = named(c, "texcoord");
  // J = diag(2, 1): s1 = 2, s2 = 1, L2 = sqrt((4 + 1) / 2).
  EXPECT_NEAR(d.stretch_l2, std::sqrt(2.5), 1e-9);
  EXPECT_NEAR(d.stretch_max, 2, 1e-9);
  EXPECT_NEAR(d.stretch_p99, 2, 1e-9);
  EXPECT_EQ(d.flipped, 0u);
  EXPECT_NEAR(d.distance_max, largest_u, 1e-6);
}

TEST(AttributeDistance, MirroredTextureFlipsEveryTriangle) {
  const Mesh a = textured_torus();
  Mesh b = a;
  MeshAttribute& uv = attribute(&b, "texcoord");
  for (size_t i = 0; i < uv.value_count(); ++i) uv.values[2 * i] = -uv.values[2 * i];
  const AttributeComparison c = compare(a, b);
  const AttributeDistance& d = named(c, "texcoord");
  EXPECT_EQ(d.flipped, d.stretch_triangles);
  EXPECT_NEAR(d.stretch_l2, 1, 1e-9);  // a reflection neither stretches nor squeezes
}

TEST(AttributeDistance, NormalsTurnedTenDegreesAreTenDegreesOff) {
  const Mesh a = textured_torus();
  Mesh b = a;
  MeshAttribute& n = attribute(&b, "normal");
  const double t = 10 * 3.14159265358979323846 / 180;
  for (size_t i = 0; i < n.value_count(); ++i) {
    const double x = n.values[3 * i], y = n.values[3 * i + 1];
    n.values[3 * i] = float(std::cos(t) * x - std::sin(t) * y);
    n.values[3 * i + 1] = float(std::sin(t) * x + std::cos(t) * y);
  }
  const AttributeComparison c = compare(a, b);
  const AttributeDistance& d = named(c, "normal");
  // Each normal turns about z by 10 degrees: its angle to itself is 10
  // degrees times its length in the xy plane, at most 10.
  EXPECT_LE(d.angle_max_degrees, 10 + 1e-4);
  EXPECT_GT(d.angle_max_degrees, 9.9);
  EXPECT_GT(d.angle_mean_degrees, 1);
}

TEST(AttributeDistance, PairsByNameThenByKindAndListsTheRest) {
  Mesh a = textured_torus();
  Mesh b = a;
  attribute(&b, "texcoord").name = "uv";
  b.attributes.pop_back();  // B has no normals
  a.attributes.push_back(a.attributes[0]);
  a.attributes.back().name = "lightmap";  // a second set of texture coordinates, in A alone
  const AttributeComparison c = compare(a, b);
  ASSERT_EQ(c.attributes.size(), 1u);
  EXPECT_EQ(c.attributes[0].name, "texcoord");
  EXPECT_EQ(c.attributes[0].name_in_b, "uv");
  EXPECT_EQ(c.only_in_a, (std::vector<std::string>{"normal", "lightmap"}));
  EXPECT_TRUE(c.only_in_b.empty());
}

TEST(AttributeDistance, AVertexMovedFarLeavesItsFacesOut) {
  const Mesh a = textured_torus();
  Mesh b = a;
  b.positions[0] += 0.5f;
  const AttributeComparison c = compare(a, b);
  EXPECT_EQ(c.vertices_unmatched, 1u);
  EXPECT_EQ(c.faces_matched, a.face_count() - 4);  // the torus's vertex 0 is in 4 quads
  EXPECT_EQ(named(c, "texcoord").corners, 4 * (a.face_count() - 4));
}

TEST(AttributeDistance, TwoCoincidentFacesAreAmbiguous) {
  Mesh a;
  a.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  a.face_sizes = {3, 3};
  a.corners = {0, 1, 2, 3, 4, 5};
  MeshAttribute uv;
  uv.name = "texcoord";
  uv.kind = AttributeKind::kTextureCoordinate;
  uv.components = 2;
  uv.values = {0, 0, 1, 0, 0, 1, 5, 5, 6, 5, 5, 6};
  uv.corner_values = {0, 1, 2, 3, 4, 5};
  a.attributes.push_back(uv);
  const AttributeComparison c = compare(a, a);
  EXPECT_EQ(c.faces_ambiguous, 2u);
  EXPECT_EQ(c.faces_matched, 0u);
  EXPECT_EQ(c.attributes[0].corners, 0u);
}

TEST(AttributeDistance, RejectsAValueIndexOutOfRange) {
  const Mesh a = textured_torus();
  Mesh b = a;
  attribute(&b, "normal").corner_values[5] = 1u << 30;
  AttributeComparison c;
  EXPECT_EQ(compare_attributes(a, b, kTolerance, &c).code(), qmc::ErrorCode::kInvalidArgument);
  EXPECT_EQ(compare_attributes(a, a, 0, &c).code(), qmc::ErrorCode::kInvalidArgument);
}

// A round trip through the codec: every face found again, the texture
// coordinates within half a grid step per component, the normals within a
// degree (10 bits on the octahedral grid), and the texture barely stretched.
TEST(AttributeDistance, DecodedFileIsWithinItsQuantization) {
  const Mesh a = textured_torus();
  qmc::EncodeOptions options;
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(qmc::encode(a, options, &bytes).ok());
  qmc::DecodedFile decoded;
  ASSERT_TRUE(qmc::decode(bytes.data(), bytes.size(), &decoded).ok());
  const AttributeComparison c = compare(a, decoded.mesh);
  EXPECT_EQ(c.faces_matched, a.face_count());
  EXPECT_GT(c.match_radius, 0);
  const AttributeDistance& uv = named(c, "texcoord");
  EXPECT_EQ(uv.corners, a.corners.size());
  const qmc::AttributeCoding& grid = decoded.attribute_codings[0];
  ASSERT_TRUE(grid.on_grid());
  EXPECT_GT(uv.distance_max, 0);
  EXPECT_LE(uv.distance_max, std::hypot(grid.step[0], grid.step[1]) / 2 * (1 + 1e-6));
  EXPECT_NEAR(uv.stretch_l2, 1, 0.01);
  EXPECT_EQ(uv.flipped + uv.collapsed, 0u);
  const AttributeDistance& normal = named(c, "normal");
  EXPECT_GT(normal.angle_max_degrees, 0);
  EXPECT_LT(normal.angle_max_degrees, 1);
}

}  // namespace
