// Tests for tools/lib/subdivision (Catmull-Clark) and the sphere series built
// on it: counts, numbering, topology (Euler characteristic, closedness,
// orientation, boundaries), positions against known answers and against a
// naive map-based evaluation of the rules, pinched vertices, rejection of
// non-manifold input, determinism, and the thesis's cow (corpus, skipped when
// absent).
#include "subdivision.h"

#include <gtest/gtest.h>

#include "mesh_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh_generators.h"
#include "mesh_io.h"
#include "corpus_dir.h"

namespace qmc::tools {
namespace {

namespace fs = std::filesystem;
using qmc::Mesh;
using namespace qmc::testing;

// Directed edges whose reverse is absent: the boundary.
size_t boundary_edge_count(const Mesh& mesh) {
  const auto edges = directed_edges(mesh);
  size_t count = 0;
  for (const auto& [e, n] : edges) count += edges.count({e.second, e.first}) ? 0 : 1;
  return count;
}

bool all_quads(const Mesh& mesh) {
  return std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](uint32_t s) { return s == 4; });
}


std::vector<double> position(const Mesh& mesh, size_t v) {
  return {mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
}

void expect_position(const Mesh& mesh, size_t v, double x, double y, double z) {
  EXPECT_FLOAT_EQ(mesh.positions[3 * v], static_cast<float>(x)) << "vertex " << v;
  EXPECT_FLOAT_EQ(mesh.positions[3 * v + 1], static_cast<float>(y)) << "vertex " << v;
  EXPECT_FLOAT_EQ(mesh.positions[3 * v + 2], static_cast<float>(z)) << "vertex " << v;
}

uint64_t fingerprint(const Mesh& mesh) {
  uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a over the little-endian bytes
  auto mix = [&hash](uint32_t value) {
    for (int i = 0; i < 4; ++i) hash = (hash ^ ((value >> (8 * i)) & 0xff)) * 0x100000001b3ull;
  };
  for (float p : mesh.positions) {
    uint32_t bits;
    static_assert(sizeof bits == sizeof p);
    std::memcpy(&bits, &p, sizeof bits);
    mix(bits);
  }
  for (uint32_t s : mesh.face_sizes) mix(s);
  for (uint32_t c : mesh.corners) mix(c);
  return hash;
}

Mesh subdivide(const Mesh& in) {
  Mesh out;
  const Status s = catmull_clark(in, &out);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return out;
}

// The rules evaluated the slow, obvious way (maps keyed by vertex pairs),
// for manifold meshes without pinched vertices. Returns positions in the
// order catmull_clark promises.
std::vector<double> reference_positions(const Mesh& mesh) {
  const size_t nv = mesh.vertex_count();
  auto p = [&](uint32_t v, int a) { return static_cast<double>(mesh.positions[3 * size_t{v} + a]); };
  std::vector<std::vector<double>> face_point;
  std::map<Edge, std::vector<size_t>> edge_faces;
  std::vector<Edge> edge_order;
  size_t first = 0;
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t size = mesh.face_sizes[f];
    std::vector<double> c(3, 0);
    for (uint32_t i = 0; i < size; ++i) {
      for (int a = 0; a < 3; ++a) c[a] += p(mesh.corners[first + i], a) / size;
      const uint32_t u = mesh.corners[first + i];
      const uint32_t w = mesh.corners[first + (i + 1) % size];
      const Edge e{std::min(u, w), std::max(u, w)};
      if (!edge_faces.count(e)) edge_order.push_back(e);
      edge_faces[e].push_back(f);
    }
    face_point.push_back(c);
    first += size;
  }
  std::vector<double> out;
  for (uint32_t v = 0; v < nv; ++v) {
    std::set<size_t> faces;
    std::vector<uint32_t> neighbours, boundary_neighbours;
    for (const auto& [e, fs] : edge_faces) {
      if (e.first != v && e.second != v) continue;
      const uint32_t other = e.first == v ? e.second : e.first;
      neighbours.push_back(other);
      if (fs.size() == 1) boundary_neighbours.push_back(other);
      faces.insert(fs.begin(), fs.end());
    }
    for (int a = 0; a < 3; ++a) {
      double value = p(v, a);
      if (boundary_neighbours.size() == 2) {
        value = (p(boundary_neighbours[0], a) + 6 * p(v, a) + p(boundary_neighbours[1], a)) / 8;
      } else if (!neighbours.empty()) {
        const double n = static_cast<double>(neighbours.size());
        double q = 0, r = 0;
        for (size_t f : faces) q += face_point[f][a] / static_cast<double>(faces.size());
        for (uint32_t w : neighbours) r += (p(v, a) + p(w, a)) / 2 / n;
        value = (q + 2 * r + (n - 3) * p(v, a)) / n;
      }
      out.push_back(value);
    }
  }
  for (const auto& c : face_point) out.insert(out.end(), c.begin(), c.end());
  for (const Edge& e : edge_order) {
    const auto& fs = edge_faces[e];
    for (int a = 0; a < 3; ++a) {
      out.push_back(fs.size() == 1 ? (p(e.first, a) + p(e.second, a)) / 2
                                   : (p(e.first, a) + p(e.second, a) + face_point[fs[0]][a] + face_point[fs[1]][a]) / 4);
    }
  }
  return out;
}

void expect_matches_reference(const Mesh& in, const Mesh& out) {
  const std::vector<double> expected = reference_positions(in);
  ASSERT_EQ(out.positions.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    ASSERT_NEAR(out.positions[i], expected[i], 1e-6) << "vertex " << i / 3 << " axis " << i % 3;
  }
}

// Quads follow (v_i, e_i, f, e_{i-1}) for every input face and corner; v_i
// is the input vertex, or its copy for a further fan of a pinched vertex.
void expect_numbering(const Mesh& in, const Mesh& out) {
  const uint32_t nv = static_cast<uint32_t>(in.vertex_count());
  const uint32_t nf = static_cast<uint32_t>(in.face_count());
  const size_t split_base = nv + nf + undirected_edges(in).size();  // extra copies of pinched vertices
  ASSERT_EQ(out.face_count(), in.corners.size());
  size_t first = 0;
  size_t quad = 0;
  for (uint32_t f = 0; f < nf; ++f) {
    const uint32_t size = in.face_sizes[f];
    for (uint32_t i = 0; i < size; ++i, ++quad) {
      const uint32_t* q = &out.corners[4 * quad];
      if (q[0] != in.corners[first + i]) {
        EXPECT_GE(q[0], split_base);
      }
      EXPECT_EQ(q[2], nv + f);
      EXPECT_GE(q[1], nv + nf);
      EXPECT_GE(q[3], nv + nf);
      // The outgoing edge point of corner i is the incoming one of corner i+1.
      const uint32_t* next = &out.corners[4 * (quad - i + (i + 1) % size)];
      EXPECT_EQ(q[1], next[3]);
    }
    first += size;
  }
}

TEST(CatmullClark, CubeCountsAndKnownPositions) {
  const Mesh cube = make_cube();
  const Mesh out = subdivide(cube);
  EXPECT_EQ(out.vertex_count(), 26u);
  EXPECT_EQ(out.face_count(), 24u);
  EXPECT_TRUE(all_quads(out));
  expect_closed_and_oriented(out);
  EXPECT_GT(signed_volume6(out), 0);
  expect_numbering(cube, out);

  // Corner (valence 3): Q = (1,1,1)/3, R = (2,2,2)/3, so (Q + 2R)/3 = 5/9.
  for (uint32_t v = 0; v < 8; ++v) {
    const double s = 5.0 / 9.0;
    expect_position(out, v, (v & 1) ? s : -s, (v & 2) ? s : -s, (v & 4) ? s : -s);
  }
  // Face points: the face centres, in face order (-x +x -y +y -z +z).
  expect_position(out, 8, -1, 0, 0);
  expect_position(out, 9, 1, 0, 0);
  expect_position(out, 10, 0, -1, 0);
  expect_position(out, 11, 0, 1, 0);
  expect_position(out, 12, 0, 0, -1);
  expect_position(out, 13, 0, 0, 1);
  // First edge, 0-4 along z at x = y = -1, between faces -x and -y:
  // ((-1,-1,-1) + (-1,-1,1) + (-1,0,0) + (0,-1,0)) / 4.
  expect_position(out, 14, -0.75, -0.75, 0);
  expect_matches_reference(cube, out);
}

TEST(CatmullClark, MatchesReferenceOnClosedMeshes) {
  for (const Mesh& mesh : {make_tetrahedron(), make_cube(), make_prism(5), make_torus(9, 5), make_quad_sphere(3),
                           make_deltoidal_hexecontahedron()}) {
    const Mesh out = subdivide(mesh);
    expect_matches_reference(mesh, out);
    expect_numbering(mesh, out);
  }
}

TEST(CatmullClark, TopologyIsPreserved) {
  for (const Mesh& mesh : {make_tetrahedron(), make_cube(), make_prism(7), make_torus(8, 5), make_quad_sphere(4)}) {
    const Mesh once = subdivide(mesh);
    const Mesh twice = subdivide(once);
    for (const Mesh* m : {&once, &twice}) {
      EXPECT_TRUE(all_quads(*m));
      EXPECT_EQ(euler_characteristic(*m), euler_characteristic(mesh));
      expect_closed_and_oriented(*m);
      EXPECT_GT(signed_volume6(*m), 0);
    }
    // V' = V + F + E, F' = number of corners.
    EXPECT_EQ(once.vertex_count(), mesh.vertex_count() + mesh.face_count() + undirected_edges(mesh).size());
    EXPECT_EQ(once.face_count(), mesh.corners.size());
  }
}

TEST(CatmullClark, GridBoundary) {
  const Mesh grid = make_grid(3, 2);
  const Mesh out = subdivide(grid);
  EXPECT_EQ(out.vertex_count(), grid.vertex_count() + grid.face_count() + undirected_edges(grid).size());
  EXPECT_EQ(out.face_count(), 24u);
  EXPECT_EQ(euler_characteristic(out), 1);
  EXPECT_EQ(boundary_edge_count(out), 2 * boundary_edge_count(grid));
  expect_matches_reference(grid, out);
  expect_numbering(grid, out);

  // The corner (-1,-1,0) has boundary neighbours (-1/3,-1,0) and (-1,0,0)
  // (the bump vanishes on the border): (a + 6v + b) / 8.
  expect_position(out, 0, (-1.0 / 3 - 6 - 1) / 8, (-1 - 6 + 0) / 8.0, 0);
  // Boundary edge points are midpoints: the first edge is 0-1.
  const uint32_t edge_base = static_cast<uint32_t>(grid.vertex_count() + grid.face_count());
  expect_position(out, edge_base, (-1 - 1.0 / 3) / 2, -1, 0);
  // The border stays in the plane z = 0 and on the square's sides.
  for (size_t v = 0; v < grid.vertex_count(); ++v) {
    const std::vector<double> p = position(grid, v);
    if (std::abs(p[0]) == 1 || std::abs(p[1]) == 1) {
      EXPECT_EQ(out.positions[3 * v + 2], 0.f) << v;
    }
  }
}

TEST(CatmullClark, MixedDegreesAndBoundary) {
  // A square and a triangle sharing an edge, plus a pentagon on the square's
  // far side: open, degrees 3, 4, 5.
  Mesh mesh;
  mesh.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0.5f, 0.25f, -1, 0, 0, -1.5f, 0.5f, 0, -1, 1, 0.5f};
  mesh.face_sizes = {4, 3, 5};
  mesh.corners = {0, 1, 2, 3, 1, 4, 2, 0, 3, 7, 6, 5};
  const Mesh out = subdivide(mesh);
  EXPECT_EQ(out.face_count(), 12u);
  EXPECT_EQ(out.vertex_count(), 8u + 3 + 10);
  EXPECT_EQ(euler_characteristic(out), 1);
  expect_matches_reference(mesh, out);
  expect_numbering(mesh, out);
}

TEST(CatmullClark, UnreferencedVertexKeepsItsPlace) {
  Mesh mesh = make_cube();
  mesh.positions.insert(mesh.positions.begin() + 9, {7, 8, 9});  // new vertex 3
  for (uint32_t& c : mesh.corners) c += c >= 3 ? 1 : 0;
  const Mesh out = subdivide(mesh);
  EXPECT_EQ(out.vertex_count(), 27u);
  expect_position(out, 3, 7, 8, 9);
  expect_position(out, 0, -5.0 / 9, -5.0 / 9, -5.0 / 9);
}

TEST(CatmullClark, PinchedVertexIsSplitPerFan) {
  // Two tetrahedra touching at vertex 0 only.
  Mesh a = make_tetrahedron();
  Mesh mesh = a;
  const std::vector<float> shifted = {1, 1, 1, 1, 3, 3, 3, 1, 3, 3, 3, 1};  // a copy mirrored through (1,1,1)
  mesh.positions.insert(mesh.positions.end(), shifted.begin() + 3, shifted.end());
  for (size_t f = 0; f < a.face_count(); ++f) {
    mesh.face_sizes.push_back(3);
    for (int i = 2; i >= 0; --i) {  // reversed: the mirror flips orientation
      const uint32_t c = a.corners[3 * f + i];
      mesh.corners.push_back(c == 0 ? 0 : c + 3);
    }
  }
  const Mesh out = subdivide(mesh);
  // V + F + E + one extra fan = 7 + 8 + 12 + 1.
  ASSERT_EQ(out.vertex_count(), 28u);
  EXPECT_EQ(out.face_count(), 24u);
  expect_closed_and_oriented(out);
  EXPECT_EQ(euler_characteristic(out), 4);  // two spheres
  // Each copy of the pinch is where that tetrahedron alone would put it.
  const Mesh alone = subdivide(a);
  expect_position(out, 0, alone.positions[0], alone.positions[1], alone.positions[2]);
  expect_position(out, 27, 2 - alone.positions[0], 2 - alone.positions[1], 2 - alone.positions[2]);
  // The second tetrahedron's quads at the pinch use the extra vertex.
  size_t uses_extra = 0;
  for (uint32_t c : out.corners) uses_extra += c == 27 ? 1 : 0;
  EXPECT_EQ(uses_extra, 3u);
  // The output is manifold: a second step has no fans to split.
  const Mesh twice = subdivide(out);
  EXPECT_EQ(twice.vertex_count(), out.vertex_count() + out.face_count() + undirected_edges(out).size());
}

TEST(CatmullClark, RejectsNonManifoldInput) {
  Mesh untouched;
  untouched.positions = {1, 2, 3};
  auto expect_rejected = [&](const Mesh& mesh, const std::string& fragment) {
    Mesh out = untouched;
    const Status s = catmull_clark(mesh, &out);
    EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument) << fragment;
    EXPECT_NE(s.message().find(fragment), std::string::npos) << s.message();
    EXPECT_EQ(out.positions, untouched.positions);
    EXPECT_TRUE(out.corners.empty());
  };
  // Three triangles on edge 0-1.
  Mesh fin;
  fin.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  fin.face_sizes = {3, 3, 3};
  fin.corners = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  expect_rejected(fin, "non-manifold");
  // Two triangles running along 0->1 in the same direction.
  Mesh flipped = fin;
  flipped.face_sizes = {3, 3};
  flipped.corners = {0, 1, 2, 0, 1, 3};
  expect_rejected(flipped, "inconsistent orientation");
  // One face of a cube reversed.
  Mesh cube = make_cube();
  std::reverse(cube.corners.begin(), cube.corners.begin() + 4);
  expect_rejected(cube, "inconsistent orientation");
  // Degenerate edge, bad index, short face, size mismatch.
  Mesh degenerate = fin;
  degenerate.face_sizes = {4};
  degenerate.corners = {0, 1, 1, 2};
  expect_rejected(degenerate, "degenerate edge");
  Mesh bad_index = fin;
  bad_index.face_sizes = {3};
  bad_index.corners = {0, 1, 5};
  expect_rejected(bad_index, "missing vertex");
  Mesh short_face = fin;
  short_face.face_sizes = {2};
  short_face.corners = {0, 1};
  expect_rejected(short_face, "fewer than 3");
  Mesh mismatch = fin;
  mismatch.face_sizes = {3};
  expect_rejected(mismatch, "do not add up");
}

TEST(CatmullClark, EmptyMeshAndDeterminism) {
  Mesh empty;
  EXPECT_TRUE(subdivide(empty).positions.empty());
  const Mesh torus = make_torus(10, 6);
  EXPECT_EQ(fingerprint(subdivide(torus)), fingerprint(subdivide(torus)));
}

TEST(SphereSeries, DeltoidalHexecontahedron) {
  const Mesh dh = make_deltoidal_hexecontahedron();
  EXPECT_EQ(dh.vertex_count(), 62u);
  EXPECT_EQ(dh.face_count(), 60u);
  EXPECT_TRUE(all_quads(dh));
  EXPECT_EQ(undirected_edges(dh).size(), 120u);
  EXPECT_EQ(euler_characteristic(dh), 2);
  expect_closed_and_oriented(dh);
  EXPECT_GT(signed_volume6(dh), 0);
  // Valences: 12 icosahedron vertices of 5, 20 face centres of 3, 30 edge
  // vertices of 4, in that order.
  std::vector<int> valence(dh.vertex_count(), 0);
  for (uint32_t c : dh.corners) ++valence[c];
  for (size_t v = 0; v < 62; ++v) EXPECT_EQ(valence[v], v < 12 ? 5 : v < 32 ? 3 : 4) << v;
  for (size_t v = 0; v < 62; ++v) {
    const std::vector<double> p = position(dh, v);
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 2e-7);
  }
  // Kites: every face has its valence-5 tip first and its valence-3 tip third.
  for (size_t f = 0; f < 60; ++f) {
    EXPECT_EQ(valence[dh.corners[4 * f]], 5);
    EXPECT_EQ(valence[dh.corners[4 * f + 2]], 3);
  }
  // Vertex 0 is (0, 1, phi) normalised.
  const double phi = (1 + std::sqrt(5.0)) / 2;
  const double length = std::sqrt(1 + phi * phi);
  expect_position(dh, 0, 0, 1 / length, phi / length);
}

TEST(SphereSeries, RefinedSphereCounts) {
  EXPECT_EQ(fingerprint(make_refined_sphere(0)), fingerprint(make_deltoidal_hexecontahedron()));
  const size_t expected_faces[] = {60, 240, 960, 3840};
  for (int levels = 1; levels <= 3; ++levels) {
    const Mesh sphere = make_refined_sphere(levels);
    EXPECT_EQ(sphere.face_count(), expected_faces[levels]);
    EXPECT_EQ(sphere.vertex_count(), expected_faces[levels] + 2);
    EXPECT_TRUE(all_quads(sphere));
    expect_closed_and_oriented(sphere);
    EXPECT_GT(signed_volume6(sphere), 0);
    for (size_t v = 0; v < sphere.vertex_count(); ++v) {
      const std::vector<double> p = position(sphere, v);
      EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 2e-7);
    }
  }
  const Mesh thesis = make_refined_sphere(5);
  EXPECT_EQ(thesis.face_count(), 61440u);
  EXPECT_EQ(thesis.vertex_count(), 61442u);
  EXPECT_EQ(make_refined_sphere(-1).face_count(), 60u);
}

// As in mesh_generators_test: the exact bits are pinned, so a platform or
// compiler that rounds differently (or an accidental change) fails here.
TEST(SphereSeries, OutputIsPinned) {
  EXPECT_EQ(fingerprint(make_deltoidal_hexecontahedron()), 0xc6ffb178fe5d3fc5ull);
  EXPECT_EQ(fingerprint(make_refined_sphere(3)), 0x7f92a827107ef1b1ull);
  EXPECT_EQ(fingerprint(subdivide(make_grid(4, 3))), 0xa13fb4c0ba546476ull);
}

using testing::corpus_dir;

// The thesis's 17412-quad cow. cow.obj is closed with one pinched vertex;
// splitting it gives V + F + E + 1 = 2903 + 5804 + 8706 + 1 = 17414 vertices,
// the count the thesis reports.
TEST(CatmullClark, CorpusCow) {
  const fs::path path = corpus_dir() / "tri" / "cow.obj";
  if (!fs::exists(path)) GTEST_SKIP() << "corpus not found at " << corpus_dir() << " (set QMC_CORPUS_DIR)";
  Mesh cow;
  std::vector<std::string> warnings;
  const Status read = read_mesh(path.string(), &cow, &warnings);
  ASSERT_TRUE(read.ok()) << read.to_string();
  ASSERT_EQ(cow.vertex_count(), 2903u);
  ASSERT_EQ(cow.face_count(), 5804u);
  EXPECT_EQ(undirected_edges(cow).size(), 8706u);
  const Mesh out = subdivide(cow);
  EXPECT_EQ(out.face_count(), 17412u);
  EXPECT_EQ(out.vertex_count(), 17414u);
  EXPECT_TRUE(all_quads(out));
  expect_closed_and_oriented(out);
  EXPECT_EQ(euler_characteristic(out), 2);  // the split pinch leaves a sphere
  expect_numbering(cow, out);
}

}  // namespace
}  // namespace qmc::tools
