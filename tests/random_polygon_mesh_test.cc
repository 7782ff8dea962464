// Tests for tools/lib/random_polygon_mesh: the topology of each generated
// mesh (components, Euler characteristic, boundary loops, genus, manifoldness,
// orientation, degrees, valence-2 vertices, non-manifold defects) is
// recomputed here from the face list alone, by brute force with maps and
// union-find, and compared with what the options asked for.
#include "mesh_test_support.h"
#include "random_polygon_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace qmc {
namespace {

using testing::expect_valid;
using testing::fingerprint;

using Face = std::vector<uint32_t>;
using Edge = std::pair<uint32_t, uint32_t>;

std::vector<Face> faces_of(const Mesh& mesh) {
  std::vector<Face> faces;
  size_t first = 0;
  for (uint32_t size : mesh.face_sizes) {
    faces.emplace_back(mesh.corners.begin() + first, mesh.corners.begin() + first + size);
    first += size;
  }
  return faces;
}

Edge undirected(uint32_t a, uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

// The lexicographically smallest rotation: equal for two listings of the
// same cycle, whatever corner they start at.
Face canonical(const Face& face) {
  Face best = face;
  for (size_t r = 1; r < face.size(); ++r) {
    Face rotated(face.begin() + r, face.end());
    rotated.insert(rotated.end(), face.begin(), face.begin() + r);
    best = std::min(best, rotated);
  }
  return best;
}

class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), size_t{0}); }
  size_t find(size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  bool unite(size_t a, size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[a] = b;
    return true;
  }

 private:
  std::vector<size_t> parent_;
};


// ---------------------------------------------------------------------------
// Topology from the face list.

struct Component {
  int64_t vertices = 0, edges = 0, faces = 0;
  int64_t boundary_loops = 0;
  int64_t euler() const { return vertices - edges + faces; }
  // Closed orientable genus after capping every boundary loop with a disk.
  int64_t twice_genus() const { return 2 - euler() - boundary_loops; }
};

// Components of faces connected through shared (undirected) edges.
std::vector<Component> components_of(const Mesh& mesh) {
  const std::vector<Face> faces = faces_of(mesh);
  std::map<Edge, std::vector<size_t>> faces_on_edge;
  for (size_t f = 0; f < faces.size(); ++f) {
    for (size_t i = 0; i < faces[f].size(); ++i) faces_on_edge[undirected(faces[f][i], faces[f][(i + 1) % faces[f].size()])].push_back(f);
  }
  UnionFind face_sets(faces.size());
  for (const auto& [edge, list] : faces_on_edge) {
    for (size_t f : list) face_sets.unite(list[0], f);
  }
  std::map<size_t, size_t> index_of_root;
  for (size_t f = 0; f < faces.size(); ++f) index_of_root.emplace(face_sets.find(f), index_of_root.size());
  std::vector<Component> components(index_of_root.size());
  std::vector<std::set<uint32_t>> vertices(components.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    const size_t c = index_of_root[face_sets.find(f)];
    ++components[c].faces;
    vertices[c].insert(faces[f].begin(), faces[f].end());
  }
  // Boundary loops: connected pieces of the graph of edges with one face.
  UnionFind boundary(mesh.vertex_count());
  std::vector<std::set<uint32_t>> boundary_vertices(components.size());
  for (const auto& [edge, list] : faces_on_edge) {
    const size_t c = index_of_root[face_sets.find(list[0])];
    ++components[c].edges;
    if (list.size() != 1) continue;
    boundary_vertices[c].insert({edge.first, edge.second});
    components[c].boundary_loops -= boundary.unite(edge.first, edge.second) ? 1 : 0;
  }
  for (size_t c = 0; c < components.size(); ++c) {
    components[c].vertices = static_cast<int64_t>(vertices[c].size());
    components[c].boundary_loops += static_cast<int64_t>(boundary_vertices[c].size());
  }
  return components;
}

// Distinct neighbours of each vertex through face edges.
std::vector<std::set<uint32_t>> neighbours_of(const Mesh& mesh) {
  std::vector<std::set<uint32_t>> neighbours(mesh.vertex_count());
  for (const Face& face : faces_of(mesh)) {
    for (size_t i = 0; i < face.size(); ++i) {
      const uint32_t a = face[i];
      const uint32_t b = face[(i + 1) % face.size()];
      neighbours[a].insert(b);
      neighbours[b].insert(a);
    }
  }
  return neighbours;
}

size_t unused_vertex_count(const Mesh& mesh) {
  std::vector<bool> used(mesh.vertex_count(), false);
  for (uint32_t v : mesh.corners) used[v] = true;
  return static_cast<size_t>(std::count(used.begin(), used.end(), false));
}

// Groups of the faces around each vertex, two faces being linked when they
// share an edge at that vertex. Identical cycles count once.
std::vector<std::vector<size_t>> fan_sizes(const Mesh& mesh) {
  std::vector<Face> faces = faces_of(mesh);
  std::set<Face> seen;
  std::vector<Face> distinct;
  for (const Face& face : faces) {
    if (seen.insert(canonical(face)).second) distinct.push_back(face);
  }
  std::vector<std::vector<size_t>> faces_at(mesh.vertex_count());
  std::map<Edge, std::vector<size_t>> faces_on_edge;
  for (size_t f = 0; f < distinct.size(); ++f) {
    for (size_t i = 0; i < distinct[f].size(); ++i) {
      faces_at[distinct[f][i]].push_back(f);
      faces_on_edge[undirected(distinct[f][i], distinct[f][(i + 1) % distinct[f].size()])].push_back(f);
    }
  }
  std::vector<std::vector<size_t>> sizes(mesh.vertex_count());
  for (uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    std::vector<size_t>& around = faces_at[v];
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    UnionFind fans(around.size());
    auto local = [&around](size_t f) { return static_cast<size_t>(std::lower_bound(around.begin(), around.end(), f) - around.begin()); };
    for (size_t f : around) {
      const Face& face = distinct[f];
      for (size_t i = 0; i < face.size(); ++i) {
        const uint32_t a = face[i];
        const uint32_t b = face[(i + 1) % face.size()];
        if (a != v && b != v) continue;
        for (size_t other : faces_on_edge[undirected(a, b)]) fans.unite(local(f), local(other));
      }
    }
    std::map<size_t, size_t> fan_size;
    for (size_t i = 0; i < around.size(); ++i) ++fan_size[fans.find(i)];
    for (const auto& [root, size] : fan_size) sizes[v].push_back(size);
  }
  return sizes;
}

// Edge- and vertex-manifold, consistently oriented, simple faces, no
// duplicate faces.
void expect_oriented_manifold(const Mesh& mesh) {
  std::map<Edge, int> directed;
  std::set<Face> cycles;
  for (const Face& face : faces_of(mesh)) {
    EXPECT_EQ(std::set<uint32_t>(face.begin(), face.end()).size(), face.size()) << "a face repeats a vertex";
    EXPECT_TRUE(cycles.insert(canonical(face)).second) << "a face is listed twice";
    for (size_t i = 0; i < face.size(); ++i) ++directed[{face[i], face[(i + 1) % face.size()]}];
  }
  // Each direction at most once: at most two faces per edge, and two only
  // when they run in opposite directions.
  for (const auto& [edge, count] : directed) EXPECT_EQ(count, 1) << "edge " << edge.first << "->" << edge.second;
  const auto fans = fan_sizes(mesh);
  for (uint32_t v = 0; v < mesh.vertex_count(); ++v) EXPECT_LE(fans[v].size(), 1u) << "vertex " << v << " has several fans";
}

// ---------------------------------------------------------------------------
// Non-manifold defects, each recognised from the face list.

struct Defects {
  bool book_edge = false, pinched_vertex = false, flipped_face = false, duplicate_face = false, repeated_vertex = false;
  bool any() const { return book_edge || pinched_vertex || flipped_face || duplicate_face || repeated_vertex; }
};

Defects find_defects(const Mesh& mesh) {
  Defects found;
  std::map<Face, int> copies;
  for (const Face& face : faces_of(mesh)) {
    found.repeated_vertex |= std::set<uint32_t>(face.begin(), face.end()).size() != face.size();
    found.duplicate_face |= ++copies[canonical(face)] > 1;
  }
  // Over distinct cycles: which cycles use each directed and undirected edge.
  std::map<Edge, std::set<size_t>> by_direction;
  std::map<Edge, std::set<size_t>> by_edge;
  size_t id = 0;
  for (const auto& [face, count] : copies) {
    for (size_t i = 0; i < face.size(); ++i) {
      const uint32_t a = face[i];
      const uint32_t b = face[(i + 1) % face.size()];
      by_direction[{a, b}].insert(id);
      by_edge[undirected(a, b)].insert(id);
    }
    ++id;
  }
  for (const auto& [edge, cycles] : by_edge) found.book_edge |= cycles.size() >= 3;
  for (const auto& [edge, cycles] : by_direction) found.flipped_face |= cycles.size() == 2 && by_edge[undirected(edge.first, edge.second)].size() == 2;
  for (const auto& sizes : fan_sizes(mesh)) {
    found.pinched_vertex |= std::count_if(sizes.begin(), sizes.end(), [](size_t size) { return size >= 2; }) >= 2;
  }
  return found;
}

// ---------------------------------------------------------------------------

struct DegreeRange {
  int min, max;
};

RandomPolygonMeshOptions varied_options(uint64_t seed) {
  static const DegreeRange kRanges[] = {{3, 8}, {3, 3}, {3, 4}, {4, 4}, {4, 8}, {3, 6}, {4, 5}};
  static const int kTargets[] = {20, 60, 150};
  RandomPolygonMeshOptions options;
  options.seed = seed;
  options.components = 1 + static_cast<int>(seed % 3);
  options.genus = static_cast<int>(seed % 5);
  options.holes = static_cast<int>((seed / 5) % 7);
  options.min_degree = kRanges[seed % 7].min;
  options.max_degree = kRanges[seed % 7].max;
  options.target_faces = kTargets[(seed / 7) % 3];
  options.valence_two = (seed / 2) % 2 == 0;
  options.isolated_vertices = static_cast<int>(seed % 4);
  return options;
}

TEST(RandomPolygonMesh, ManifoldMeshesHaveTheRequestedTopology) {
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE(seed);
    const RandomPolygonMeshOptions options = varied_options(seed);
    RandomPolygonMeshInfo info;
    const Mesh mesh = make_random_polygon_mesh(options, &info);
    ASSERT_NO_FATAL_FAILURE(expect_valid(mesh));
    EXPECT_EQ(info.components, options.components);
    EXPECT_EQ(info.genus_per_component, options.genus);
    EXPECT_EQ(info.boundary_loops, options.components * options.holes);
    EXPECT_EQ(info.non_manifold_defects, 0);

    const std::vector<Component> components = components_of(mesh);
    ASSERT_EQ(components.size(), static_cast<size_t>(options.components));
    for (const Component& component : components) {
      EXPECT_EQ(component.boundary_loops, options.holes);
      EXPECT_EQ(component.twice_genus(), 2 * options.genus) << "V-E+F " << component.euler();
    }
    expect_oriented_manifold(mesh);
    EXPECT_FALSE(find_defects(mesh).any());
    for (uint32_t size : mesh.face_sizes) {
      EXPECT_GE(size, static_cast<uint32_t>(options.min_degree));
      EXPECT_LE(size, static_cast<uint32_t>(options.max_degree));
    }
    EXPECT_EQ(unused_vertex_count(mesh), static_cast<size_t>(options.isolated_vertices));
  }
}

TEST(RandomPolygonMesh, DefaultOptionsGiveEveryDegreeAndValenceTwoVertices) {
  std::map<uint32_t, int> degrees;
  int valence_two = 0;
  size_t faces = 0;
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    RandomPolygonMeshOptions options;
    options.seed = seed;
    const Mesh mesh = make_random_polygon_mesh(options);
    for (uint32_t size : mesh.face_sizes) ++degrees[size];
    for (const auto& neighbours : neighbours_of(mesh)) valence_two += neighbours.size() == 2 ? 1 : 0;
    faces += mesh.face_count();
  }
  for (uint32_t degree = 3; degree <= 8; ++degree) EXPECT_GT(degrees[degree], 0) << "degree " << degree;
  EXPECT_EQ(degrees.begin()->first, 3u);
  EXPECT_EQ(degrees.rbegin()->first, 8u);
  EXPECT_GT(valence_two, 0);
  // About target_faces (60) faces each.
  EXPECT_GT(faces, 300u * 40);
  EXPECT_LT(faces, 300u * 90);
}

TEST(RandomPolygonMesh, WithoutValenceTwoEveryVertexHasValenceThreeOrMore) {
  for (uint64_t seed = 1; seed <= 100; ++seed) {
    SCOPED_TRACE(seed);
    RandomPolygonMeshOptions options = varied_options(seed);
    options.valence_two = false;
    options.isolated_vertices = 0;
    for (const auto& neighbours : neighbours_of(make_random_polygon_mesh(options))) EXPECT_GE(neighbours.size(), 3u);
  }
}

TEST(RandomPolygonMesh, NonManifoldMeshesHaveDetectableDefects) {
  Defects seen;
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE(seed);
    RandomPolygonMeshOptions options = varied_options(seed);
    options.non_manifold = true;
    RandomPolygonMeshInfo info;
    const Mesh mesh = make_random_polygon_mesh(options, &info);
    ASSERT_NO_FATAL_FAILURE(expect_valid(mesh));
    EXPECT_GE(info.non_manifold_defects, 1);
    EXPECT_LE(info.non_manifold_defects, 3);
    EXPECT_EQ(unused_vertex_count(mesh), static_cast<size_t>(options.isolated_vertices));
    const Defects found = find_defects(mesh);
    EXPECT_TRUE(found.any());
    seen.book_edge |= found.book_edge;
    seen.pinched_vertex |= found.pinched_vertex;
    seen.flipped_face |= found.flipped_face;
    seen.duplicate_face |= found.duplicate_face;
    seen.repeated_vertex |= found.repeated_vertex;
  }
  EXPECT_TRUE(seen.book_edge);
  EXPECT_TRUE(seen.pinched_vertex);
  EXPECT_TRUE(seen.flipped_face);
  EXPECT_TRUE(seen.duplicate_face);
  EXPECT_TRUE(seen.repeated_vertex);
}

bool same_bits(const Mesh& a, const Mesh& b) {
  return a.positions.size() == b.positions.size() &&
         std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(float)) == 0 &&
         a.face_sizes == b.face_sizes && a.corners == b.corners;
}

TEST(RandomPolygonMesh, SameSeedGivesTheSameMesh) {
  for (uint64_t seed = 1; seed <= 50; ++seed) {
    RandomPolygonMeshOptions options = varied_options(seed);
    options.non_manifold = seed % 2 == 0;
    RandomPolygonMeshInfo first_info;
    RandomPolygonMeshInfo second_info;
    const Mesh first = make_random_polygon_mesh(options, &first_info);
    EXPECT_TRUE(same_bits(first, make_random_polygon_mesh(options, &second_info))) << seed;
    EXPECT_EQ(first_info.non_manifold_defects, second_info.non_manifold_defects);
    options.seed += 1000;
    EXPECT_FALSE(same_bits(first, make_random_polygon_mesh(options))) << seed;
  }
}


TEST(RandomPolygonMesh, OutputIsPinned) {
  RandomPolygonMeshOptions options;
  options.seed = 2024;
  options.components = 2;
  options.genus = 2;
  options.holes = 3;
  options.isolated_vertices = 3;
  EXPECT_EQ(fingerprint(make_random_polygon_mesh(options)), 0x6deff5ea076d3472ull);
  options.non_manifold = true;
  EXPECT_EQ(fingerprint(make_random_polygon_mesh(options)), 0x00169cf2f7165467ull);
}

// min_degree is clamped to [3, 4] and max_degree raised to it; counts below
// their minimum are raised.
TEST(RandomPolygonMesh, OutOfRangeOptionsAreClamped) {
  RandomPolygonMeshOptions options;
  options.components = 0;
  options.genus = -1;
  options.holes = -2;
  options.min_degree = 6;
  options.max_degree = 2;
  options.isolated_vertices = -3;
  RandomPolygonMeshInfo info;
  const Mesh mesh = make_random_polygon_mesh(options, &info);
  for (uint32_t size : mesh.face_sizes) EXPECT_EQ(size, 4u);
  const std::vector<Component> components = components_of(mesh);
  ASSERT_EQ(components.size(), 1u);
  EXPECT_EQ(components[0].euler(), 2);
  EXPECT_EQ(components[0].boundary_loops, 0);
  EXPECT_EQ(unused_vertex_count(mesh), 0u);
  EXPECT_EQ(info.components, 1);
  EXPECT_EQ(info.genus_per_component, 0);
  EXPECT_EQ(info.boundary_loops, 0);
}

// Tests built on the generator must not depend on generation order.
TEST(RandomPolygonMesh, VerticesFacesAndStartingCornersAreShuffled) {
  bool isolated_not_last = false;
  bool face_starts_elsewhere = false;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    RandomPolygonMeshOptions options;
    options.seed = seed;
    options.isolated_vertices = 3;
    const Mesh mesh = make_random_polygon_mesh(options);
    std::vector<bool> used(mesh.vertex_count(), false);
    for (uint32_t v : mesh.corners) used[v] = true;
    for (size_t v = 0; v + 3 < mesh.vertex_count(); ++v) isolated_not_last |= !used[v];
    for (const Face& face : faces_of(mesh)) face_starts_elsewhere |= face[0] != *std::min_element(face.begin(), face.end());
  }
  EXPECT_TRUE(isolated_not_last);
  EXPECT_TRUE(face_starts_elsewhere);
}

}  // namespace
}  // namespace qmc
