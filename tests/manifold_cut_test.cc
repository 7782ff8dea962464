// The progressive encoder's input made manifold without changing its surface
// (src/geometry/manifold_cut.h, spec 12.10): every defect the simplifier
// refuses is cut or left out, a manifold mesh comes out unchanged, and a
// non-manifold mesh goes through the whole encoder.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "decoder/loop_subdivision.h"
#include "geometry/manifold_cut.h"
#include "loop_mesh_support.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "random_polygon_mesh.h"

namespace qmc {
namespace {

LoopMesh five_points(std::vector<uint32_t> triangles) {
  LoopMesh m;
  for (int v = 0; v < 5; ++v) m.positions.insert(m.positions.end(), {double(v % 2), double(v / 2), double(v % 3)});
  m.triangles = std::move(triangles);
  return m;
}

// The corner positions of every face, as a sorted list of faces: the surface
// without its vertex numbers.
std::vector<std::array<double, 9>> surface_of(const LoopMesh& m) {
  std::vector<std::array<double, 9>> faces(m.face_count());
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) faces[f][3 * k + a] = m.positions[3 * size_t(m.triangles[3 * f + k]) + a];
  std::sort(faces.begin(), faces.end());
  return faces;
}

// Spec 12.5's check (build_loop_edges) on the vertices that faces use, as
// the simplifier leaves the others out before it.
void expect_manifold(const LoopMesh& m, const std::string& what) {
  LoopMesh used;
  std::vector<uint32_t> label(m.vertex_count(), kNoVertex);
  for (uint32_t v : m.triangles)
    if (label[v] == kNoVertex) label[v] = used.vertex_count(), used.positions.resize(used.positions.size() + 3);
  for (uint32_t v : m.triangles) used.triangles.push_back(label[v]);
  LoopEdges edges;
  const Status s = build_loop_edges(used, &edges);
  EXPECT_TRUE(s.ok()) << what << ": " << s.message();
}

TEST(ManifoldCut, ThreeFacesOnOneEdgeAreCutApartAlongIt) {
  LoopMesh out;
  const ManifoldCut cut = cut_to_manifold(five_points({0, 1, 2, 1, 0, 3, 1, 0, 4}), &out);
  EXPECT_EQ(cut.edges_cut, 1u);
  // Nothing is joined any more: vertices 0 and 1 are in three fans each.
  EXPECT_EQ(cut.vertices_added, 4u);
  EXPECT_EQ(out.vertex_count(), 9u);
  expect_manifold(out, "a book of three pages");
}

TEST(ManifoldCut, TwoFacesRunningAnEdgeTheSameWayAreCutApartAlongIt) {
  LoopMesh out;
  const ManifoldCut cut = cut_to_manifold(five_points({0, 1, 2, 0, 1, 3}), &out);
  EXPECT_EQ(cut.edges_cut, 1u);
  EXPECT_EQ(cut.vertices_added, 2u);
  expect_manifold(out, "an edge run the same way");
}

TEST(ManifoldCut, AVertexOfTwoFansBecomesTwoVerticesAtOnePoint) {
  LoopMesh out;
  const ManifoldCut cut = cut_to_manifold(five_points({0, 1, 2, 0, 3, 4}), &out);
  EXPECT_EQ(cut.edges_cut, 0u);
  EXPECT_EQ(cut.vertices_added, 1u);
  ASSERT_EQ(out.vertex_count(), 6u);
  EXPECT_EQ(out.triangles, (std::vector<uint32_t>{0, 1, 2, 5, 3, 4}));
  EXPECT_TRUE(std::equal(out.positions.begin() + 15, out.positions.end(), out.positions.begin()));
  expect_manifold(out, "a bow tie");
}

TEST(ManifoldCut, FacesOfNoAreaAndSecondCopiesAreLeftOut) {
  LoopMesh out;
  const ManifoldCut cut = cut_to_manifold(five_points({0, 0, 1, 0, 1, 2, 1, 2, 0, 2, 1, 3}), &out);
  EXPECT_EQ(cut.faces_without_area, 1u);
  EXPECT_EQ(cut.duplicate_faces, 1u);
  EXPECT_EQ(out.triangles, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
  EXPECT_EQ(cut.vertices_added, 0u);
  expect_manifold(out, "no area, a second copy");
}

TEST(ManifoldCut, AManifoldMeshComesOutUnchanged) {
  for (const Mesh& mesh : {tools::make_torus(12, 8), tools::make_quad_sphere(6), tools::make_grid(5, 4)}) {
    const LoopMesh in = loop_mesh_of(mesh);
    LoopMesh out;
    EXPECT_FALSE(cut_to_manifold(in, &out).changed());
    EXPECT_EQ(out.triangles, in.triangles);
    EXPECT_EQ(out.positions, in.positions);
  }
}

// Random meshes with 1 - 3 non-manifold defects each: the cut is manifold
// and has the faces of the input, corner for corner at the same points.
TEST(ManifoldCut, RandomNonManifoldMeshesComeOutManifoldWithTheSameSurface) {
  int changed = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    RandomPolygonMeshOptions o;
    o.seed = seed, o.max_degree = 3, o.components = 1 + int(seed % 3), o.genus = int(seed % 4);
    o.holes = int(seed / 4 % 3), o.non_manifold = true;
    const LoopMesh in = loop_mesh_of(make_random_polygon_mesh(o));
    LoopMesh out;
    const ManifoldCut cut = cut_to_manifold(in, &out);
    changed += cut.changed();
    expect_manifold(out, "seed " + std::to_string(seed));
    EXPECT_EQ(out.face_count() + cut.faces_without_area + cut.duplicate_faces, in.face_count()) << seed;
    if (cut.faces_without_area == 0 && cut.duplicate_faces == 0) {
      EXPECT_EQ(surface_of(out), surface_of(in)) << seed;
    }
  }
  EXPECT_EQ(changed, 60);
}

// Two tori that touch at one vertex: refused before the cut ("joins two
// separate fans"), now coded in levels that all decode.
TEST(ManifoldCut, TwoToriTouchingAtAVertexAreCodedInLevels) {
  Mesh a = tools::triangulated(tools::make_torus(16, 8)), b = a;
  const uint32_t n = uint32_t(a.vertex_count());
  // b is a turned half way about the vertical line through a's vertex 0 (on
  // the outer equator): the two touch there, side by side.
  for (size_t v = 0; v < n; ++v)
    for (int axis : {0, 1}) b.positions[3 * v + axis] = 2 * a.positions[axis] - b.positions[3 * v + axis];
  a.positions.insert(a.positions.end(), b.positions.begin() + 3, b.positions.end());
  for (uint32_t c : b.corners) a.corners.push_back(c == 0 ? 0 : n + c - 1);
  a.face_sizes.insert(a.face_sizes.end(), b.face_sizes.begin(), b.face_sizes.end());
  EncodeOptions options;
  options.progressive_levels = 2;
  std::vector<uint8_t> file;
  EncodeStats stats;
  const Status s = encode(a, options, &file, &stats);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(stats.loop.vertices_added, 1u);
  EXPECT_EQ(stats.loop.edges_cut, 0u);
  DecodedFile decoded;
  ASSERT_TRUE(decode(file.data(), file.size(), &decoded).ok());
  EXPECT_EQ(decoded.levels.size(), 3u);
}

// The random meshes of the test above (fewer of them, larger) through the
// whole progressive encoder and the decoder.
TEST(ManifoldCut, RandomNonManifoldMeshesAreCodedInLevels) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    RandomPolygonMeshOptions o;
    o.seed = seed, o.max_degree = 3, o.components = 1 + int(seed % 3), o.genus = int(seed % 4);
    o.holes = int(seed / 4 % 3), o.non_manifold = true, o.target_faces = 80 + int(seed % 7) * 30;
    EncodeOptions options;
    options.progressive_levels = 2;
    std::vector<uint8_t> file;
    EncodeStats stats;
    const Status s = encode(tools::triangulated(make_random_polygon_mesh(o)), options, &file, &stats);
    ASSERT_TRUE(s.ok()) << seed << ": " << s.message();
    EXPECT_TRUE(stats.loop.edges_cut + stats.loop.vertices_added + stats.loop.faces_without_area_dropped +
                    stats.loop.duplicate_faces_dropped > 0) << seed;
    DecodedFile decoded;
    ASSERT_TRUE(decode(file.data(), file.size(), &decoded).ok()) << seed;
    EXPECT_EQ(decoded.levels.size(), 3u) << seed;
  }
}

}  // namespace
}  // namespace qmc
