// qmc_decoder_split_mesh (include/qmc/qmc.h) against the rule it states,
// worked out by brute force from the same decoder's mesh and corner values:
// one vertex per distinct (mesh vertex, value of every corner attribute),
// numbered in the order of their first corners, and qmc_mesh's fans over
// them.
#include <gtest/gtest.h>

#include <ctime>
#include <map>
#include <string>
#include <vector>

#include "attribute_generators.h"
#include "mesh_generators.h"
#include "qmc/encoder.h"
#include "qmc/qmc.h"

namespace qmc {
namespace {

struct Split {
  std::vector<uint32_t> first_corner, triangles;
};

// tools::make_vertex_star's `spokes` triangles around vertex 0 with a
// texture coordinate per corner: the centre's corner of triangle i takes
// value i mod `groups`, each rim corner a value of its own. The centre is
// then split into `groups` vertices, the rim not at all: groups + 2 spokes.
Mesh star(uint32_t spokes, uint32_t groups) {
  Mesh m = tools::make_vertex_star(spokes);
  MeshAttribute uv;
  uv.name = "texcoord";
  uv.kind = AttributeKind::kTextureCoordinate;
  uv.components = 2;
  for (uint32_t g = 0; g < groups; ++g) uv.values.insert(uv.values.end(), {0.1f * float(g), 0});
  for (uint32_t rim = 0; rim < 2 * spokes; ++rim) uv.values.insert(uv.values.end(), {float(rim) / float(spokes), 1});
  for (uint32_t i = 0; i < spokes; ++i)
    uv.corner_values.insert(uv.corner_values.end(), {i % groups, groups + 2 * i, groups + 2 * i + 1});
  m.attributes.push_back(uv);
  return m;
}

std::vector<uint8_t> encoded(const Mesh& mesh) {
  std::vector<uint8_t> file;
  EncodeStats stats;
  const Status s = encode(mesh, EncodeOptions{}, &file, &stats);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return file;
}

// The split by the C API, and by brute force from the C API's mesh and
// corner values: a map from (vertex, values) to the split vertex.
void split_both_ways(const std::vector<uint8_t>& file, Split* api, Split* brute) {
  qmc_decoder* d = qmc_decoder_create(nullptr);
  ASSERT_NE(d, nullptr);
  ASSERT_EQ(qmc_decoder_decode(d, file.data(), file.size()), QMC_OK) << qmc_decoder_message(d);
  qmc_split_mesh s;
  ASSERT_EQ(qmc_decoder_split_mesh(d, &s), QMC_OK);
  api->first_corner.assign(s.first_corner, s.first_corner + s.vertex_count);
  api->triangles.assign(s.triangles, s.triangles + 3 * size_t(s.triangle_count));
  qmc_split_mesh_free(&s);

  qmc_mesh mesh;
  ASSERT_EQ(qmc_decoder_mesh(d, QMC_FINEST, &mesh), QMC_OK);
  std::vector<qmc_corner_attribute> attributes(size_t(qmc_decoder_corner_attribute_count(d)));
  for (size_t i = 0; i < attributes.size(); ++i)
    ASSERT_EQ(qmc_decoder_corner_attribute(d, int(i), &attributes[i]), QMC_OK);
  std::map<std::vector<uint32_t>, uint32_t> vertex_of_key;
  std::vector<uint32_t> of_corner(mesh.corner_count);
  for (uint32_t k = 0; k < mesh.corner_count; ++k) {
    std::vector<uint32_t> key{mesh.corners[k]};
    for (const qmc_corner_attribute& a : attributes) key.push_back(a.corner_values[k]);
    const auto [it, added] = vertex_of_key.emplace(key, uint32_t(brute->first_corner.size()));
    if (added) brute->first_corner.push_back(k);
    of_corner[k] = it->second;
  }
  for (uint32_t f = 0, first = 0; f < mesh.face_count; first += mesh.face_sizes[f++])
    for (uint32_t k = 1; k + 1 < mesh.face_sizes[f]; ++k)
      brute->triangles.insert(brute->triangles.end(),
                              {of_corner[first], of_corner[first + k], of_corner[first + k + 1]});
  for (qmc_corner_attribute& a : attributes) qmc_corner_attribute_free(&a);
  qmc_mesh_free(&mesh);
  qmc_decoder_destroy(d);
}

// A vertex of 3,000 corners in 100 groups of equal values: beyond the 32
// split vertices a corner is compared with, the corners are set aside and
// sorted by their values, whose order is not the corners'; and in 7 groups,
// all compared.
TEST(SplitMesh, AFanCentreOfManyCornersSplitsIntoItsGroups) {
  for (const uint32_t groups : {100u, 7u}) {
    const uint32_t spokes = 3000;
    Split api, brute;
    split_both_ways(encoded(star(spokes, groups)), &api, &brute);
    EXPECT_EQ(api.first_corner.size(), size_t(2 * spokes + groups)) << groups << " groups";
    EXPECT_EQ(api.first_corner, brute.first_corner) << groups << " groups";
    EXPECT_EQ(api.triangles, brute.triangles) << groups << " groups";
  }
}

// 200,000 values at one vertex: comparing each corner with the split
// vertices before it took 31 s of CPU on the development machine; sorting
// them, under a tenth of a second. A generous bound, as the encoder's
// complexity tests have (encoder_test.cc).
TEST(SplitMesh, AFanOfTwoHundredThousandValuesAtOneVertexSplitsInLinearithmicTime) {
  const uint32_t spokes = 200000;
  const std::vector<uint8_t> file = encoded(star(spokes, spokes));
  qmc_decoder* d = qmc_decoder_create(nullptr);
  ASSERT_EQ(qmc_decoder_decode(d, file.data(), file.size()), QMC_OK) << qmc_decoder_message(d);
  qmc_split_mesh s;
  const std::clock_t start = std::clock();
  ASSERT_EQ(qmc_decoder_split_mesh(d, &s), QMC_OK);
  const double cpu_seconds = double(std::clock() - start) / CLOCKS_PER_SEC;
  EXPECT_EQ(s.vertex_count, 3 * spokes);
  EXPECT_LT(cpu_seconds, 10.0);
  qmc_split_mesh_free(&s);
  qmc_decoder_destroy(d);
}

// Meshes of seams in charts and of random values per corner, one and two
// corner attributes, polygons fanned.
TEST(SplitMesh, RandomCornerValuesAsTheRuleSays) {
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    Mesh mesh = seed % 2 ? tools::triangulated(tools::make_refined_sphere(1 + int(seed % 3)))
                         : tools::make_scrambled(tools::make_torus(6 + int(seed % 4), 4), seed);
    tools::add_chart_texcoords(&mesh);
    if (seed % 3 != 0) tools::add_random_corner_attribute(&mesh, seed, "a", AttributeKind::kGeneric, 1);
    Split api, brute;
    split_both_ways(encoded(mesh), &api, &brute);
    EXPECT_EQ(api.first_corner, brute.first_corner) << "seed " << seed;
    EXPECT_EQ(api.triangles, brute.triangles) << "seed " << seed;
  }
}

}  // namespace
}  // namespace qmc
