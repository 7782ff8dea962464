// Tests for tools/lib/mesh_generators: counts, topology (Euler
// characteristic, consistent orientation), determinism, soup options.
#include "mesh_generators.h"

#include <gtest/gtest.h>

#include "mesh_test_support.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace qmc::tools {
namespace {

using qmc::Mesh;

using namespace qmc::testing;

bool same_bits(const Mesh& a, const Mesh& b) {
  return a.positions.size() == b.positions.size() &&
         std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(float)) == 0 &&
         a.face_sizes == b.face_sizes && a.corners == b.corners;
}

TEST(MeshGenerators, Tetrahedron) {
  const Mesh mesh = make_tetrahedron();
  expect_valid(mesh);
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.face_count(), 4u);
  EXPECT_EQ(euler_characteristic(mesh), 2);
  expect_closed_and_oriented(mesh);
  EXPECT_GT(signed_volume6(mesh), 0);
}

TEST(MeshGenerators, Cube) {
  const Mesh mesh = make_cube();
  expect_valid(mesh);
  EXPECT_EQ(mesh.vertex_count(), 8u);
  EXPECT_EQ(mesh.face_sizes, std::vector<uint32_t>(6, 4));
  EXPECT_EQ(euler_characteristic(mesh), 2);
  expect_closed_and_oriented(mesh);
  EXPECT_DOUBLE_EQ(signed_volume6(mesh), 6 * 8.0);  // the cube [-1,1]^3 has volume 8
}

TEST(MeshGenerators, QuadSphere) {
  for (int n : {1, 2, 5, 16}) {
    const Mesh mesh = make_quad_sphere(n);
    expect_valid(mesh);
    EXPECT_EQ(mesh.vertex_count(), 6u * n * n + 2) << n;
    EXPECT_EQ(mesh.face_sizes, std::vector<uint32_t>(6 * n * n, 4)) << n;
    EXPECT_EQ(euler_characteristic(mesh), 2) << n;
    expect_closed_and_oriented(mesh);
    EXPECT_GT(signed_volume6(mesh), 0);
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
      const float* p = &mesh.positions[3 * v];
      EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-6);
    }
  }
  EXPECT_EQ(make_quad_sphere(0).vertex_count(), 8u);  // treated as n = 1
}

TEST(MeshGenerators, Torus) {
  const Mesh mesh = make_torus(12, 8, 2.f, 0.5f);
  expect_valid(mesh);
  EXPECT_EQ(mesh.vertex_count(), 96u);
  EXPECT_EQ(mesh.face_sizes, std::vector<uint32_t>(96, 4));
  EXPECT_EQ(euler_characteristic(mesh), 0);
  expect_closed_and_oriented(mesh);
  EXPECT_GT(signed_volume6(mesh), 0);
  // The integer sine and cosine agree with libm to float precision.
  const double kTwoPi = 6.283185307179586;
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 8; ++j) {
      const double u = kTwoPi * i / 12;
      const double v = kTwoPi * j / 8;
      const float* p = &mesh.positions[3 * (i * 8 + j)];
      EXPECT_NEAR(p[0], (2 + 0.5 * std::cos(v)) * std::cos(u), 1e-6);
      EXPECT_NEAR(p[1], (2 + 0.5 * std::cos(v)) * std::sin(u), 1e-6);
      EXPECT_NEAR(p[2], 0.5 * std::sin(v), 1e-6);
    }
  }
  EXPECT_EQ(make_torus(1, 2).vertex_count(), 9u);  // treated as 3 x 3
}

TEST(MeshGenerators, Grid) {
  const Mesh mesh = make_grid(7, 4);
  expect_valid(mesh);
  EXPECT_EQ(mesh.vertex_count(), 8u * 5);
  EXPECT_EQ(mesh.face_sizes, std::vector<uint32_t>(28, 4));
  EXPECT_EQ(euler_characteristic(mesh), 1);
  // Interior edges are used once each way; the 2 * (7 + 4) boundary edges once.
  size_t boundary = 0;
  const auto edges = directed_edges(mesh);
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1);
    if (edges.count({edge.second, edge.first}) == 0) ++boundary;
  }
  EXPECT_EQ(boundary, 22u);
  // Corners of the domain, flat rim, bump in the middle, all faces facing +z.
  EXPECT_EQ(mesh.positions[0], -1.f);
  EXPECT_EQ(mesh.positions[1], -1.f);
  EXPECT_EQ(mesh.positions[2], 0.f);
  const Mesh even = make_grid(2, 2);
  EXPECT_EQ(even.positions[3 * 4 + 2], 0.125f);
  EXPECT_EQ(make_grid(0, -3).face_count(), 1u);
}

TEST(MeshGenerators, Prism) {
  for (int n : {3, 4, 17}) {
    const Mesh mesh = make_prism(n);
    expect_valid(mesh);
    EXPECT_EQ(mesh.vertex_count(), 2u * n);
    std::vector<uint32_t> sizes(n, 4);
    sizes.push_back(n);
    sizes.push_back(n);
    EXPECT_EQ(mesh.face_sizes, sizes);
    EXPECT_EQ(euler_characteristic(mesh), 2);
    expect_closed_and_oriented(mesh);
    EXPECT_GT(signed_volume6(mesh), 0);
  }
}

TEST(MeshGenerators, SoupIsDeterministic) {
  const RandomSoupOptions options;
  EXPECT_TRUE(same_bits(make_random_soup(42, options), make_random_soup(42, options)));
  EXPECT_FALSE(same_bits(make_random_soup(42, options), make_random_soup(43, options)));
}

// The exact output is pinned, so a platform or compiler that produced other
// bits (or an accidental change to a generator) fails here.
TEST(MeshGenerators, OutputIsPinned) {
  EXPECT_EQ(fingerprint(make_random_soup(42, RandomSoupOptions())), 0xb54030720ef2b4a8ull);
  EXPECT_EQ(fingerprint(make_torus(24, 12)), 0xca1447e819e2f29dull);
  EXPECT_EQ(fingerprint(make_quad_sphere(7)), 0x300a0bc4284f141dull);
  EXPECT_EQ(fingerprint(make_grid(9, 5)), 0x07f7c08191548739ull);
  EXPECT_EQ(fingerprint(make_prism(13)), 0x52ce2ba6d1317038ull);
}

struct SoupStats {
  size_t unreferenced = 0;
  size_t faces_with_repeats = 0;
  bool has_coincident_positions = false;
};

SoupStats soup_stats(const Mesh& mesh) {
  SoupStats stats;
  std::vector<bool> used(mesh.vertex_count(), false);
  size_t first = 0;
  for (uint32_t size : mesh.face_sizes) {
    std::set<uint32_t> distinct(mesh.corners.begin() + first, mesh.corners.begin() + first + size);
    if (distinct.size() < size) ++stats.faces_with_repeats;
    for (uint32_t v : distinct) used[v] = true;
    first += size;
  }
  for (bool u : used) stats.unreferenced += u ? 0 : 1;
  std::set<std::vector<float>> seen;
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (!seen.insert({mesh.positions.begin() + 3 * v, mesh.positions.begin() + 3 * v + 3}).second) {
      stats.has_coincident_positions = true;
    }
  }
  return stats;
}

TEST(MeshGenerators, SoupRespectsOptions) {
  for (uint64_t seed = 0; seed < 20; ++seed) {
    const RandomSoupOptions options;
    const Mesh mesh = make_random_soup(seed, options);
    expect_valid(mesh);
    EXPECT_EQ(mesh.vertex_count(), options.vertices);
    EXPECT_EQ(mesh.face_count(), options.faces);
    for (uint32_t size : mesh.face_sizes) {
      EXPECT_GE(size, options.min_degree);
      EXPECT_LE(size, options.max_degree);
    }
    const SoupStats stats = soup_stats(mesh);
    EXPECT_EQ(stats.unreferenced, options.unreferenced) << seed;
    EXPECT_GE(stats.faces_with_repeats, 1u) << seed;
  }

  RandomSoupOptions options;
  options.vertices = 1000;
  options.faces = 400;
  options.min_degree = 4;
  options.max_degree = 4;
  options.unreferenced = 17;
  options.repeated_corners = false;
  const Mesh mesh = make_random_soup(7, options);
  expect_valid(mesh);
  EXPECT_EQ(mesh.face_sizes, std::vector<uint32_t>(400, 4));
  const SoupStats stats = soup_stats(mesh);
  EXPECT_EQ(stats.unreferenced, 17u);
  EXPECT_EQ(stats.faces_with_repeats, 0u);
  EXPECT_TRUE(stats.has_coincident_positions);
}

TEST(MeshGenerators, SoupEdgeCases) {
  RandomSoupOptions options;
  options.vertices = 0;
  EXPECT_EQ(make_random_soup(1, options).face_count(), 0u);

  // Degrees below 3 are raised; too few vertices force repeats but stay valid.
  options.vertices = 3;
  options.faces = 10;
  options.min_degree = 1;
  options.max_degree = 2;
  options.unreferenced = 100;
  Mesh mesh = make_random_soup(1, options);
  expect_valid(mesh);
  EXPECT_EQ(mesh.face_sizes, std::vector<uint32_t>(10, 3));
  EXPECT_EQ(soup_stats(mesh).unreferenced, 2u);  // one vertex must remain for the faces

  options.faces = 0;
  mesh = make_random_soup(1, options);
  EXPECT_EQ(mesh.vertex_count(), 3u);
  EXPECT_EQ(mesh.face_count(), 0u);
}

}  // namespace
}  // namespace qmc::tools
