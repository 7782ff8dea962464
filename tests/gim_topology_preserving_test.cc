// Topology-preserving geometry images (seed 002 "Methods"): the invariants of
// make_topology_preserving_image on a synthetic disk, on cathead with a Tutte
// embedding written here, and on corpus meshes through cut_to_disk and
// parametrize_on_rectangle (skipped when ../shared/corpus is absent).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "decoder/gim_mesh_builder.h"
#include "geometry/gim_cut.h"
#include "geometry/gim_parametrization.h"
#include "geometry/gim_topology_preserving.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "corpus_dir.h"

namespace qmc {
namespace {

namespace fs = std::filesystem;

struct Disk {
  GimTriMesh mesh;
  DiskCut cut;
  DiskParametrization param;
};

// An n x n grid of a height field, interior parameter points jittered and
// warped so that triangle areas vary (u^1.7), boundary on the rectangle.
Disk synthetic_disk(int n, uint32_t image, uint32_t seed) {
  Disk d;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  const double side = image - 1.0;
  d.param.width = d.param.height = image;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = double(i) / (n - 1), y = double(j) / (n - 1);
      d.mesh.positions.insert(d.mesh.positions.end(), {x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y)});
      const bool border = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      const double gi = border ? i : i + jitter(rng), gj = border ? j : j + jitter(rng);
      d.param.uv.push_back(side * std::pow(gi / (n - 1), 1.7));
      d.param.uv.push_back(side * gj / (n - 1));
      d.cut.original_vertex.push_back(uint32_t(j * n + i));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const uint32_t a = j * n + i, b = a + 1, c = a + n + 1, e = a + n;
      d.mesh.triangles.insert(d.mesh.triangles.end(), {a, b, c, a, c, e});
    }
  d.cut.triangles = d.mesh.triangles;
  for (int i = 0; i < n - 1; ++i) d.cut.boundary_loop.push_back(i);                      // v = 0
  for (int j = 0; j < n - 1; ++j) d.cut.boundary_loop.push_back(j * n + n - 1);          // u = max
  for (int i = n - 1; i > 0; --i) d.cut.boundary_loop.push_back((n - 1) * n + i);        // v = max
  for (int j = n - 1; j > 0; --j) d.cut.boundary_loop.push_back(j * n);                  // u = 0
  d.cut.boundary_mate.assign(d.cut.boundary_loop.size(), -1);
  d.cut.input_boundary_loops = 1;
  return d;
}

// synthetic_disk with three pockets on the v = 0 border line, as the cut
// and Floater's map make them: an ear e between boundary vertices 0 and 1, a
// strip e1, e2 between 1 and 2, and between 2 and 3 a path f1, f2 around an
// interior vertex m whose whole one-ring is on the line (so m is on it too).
Disk disk_with_pockets() {
  const int n = 8;
  Disk d = synthetic_disk(n, 64, 11);
  auto add = [&](double u, double y3) {
    const uint32_t v = uint32_t(d.cut.original_vertex.size());
    d.mesh.positions.insert(d.mesh.positions.end(), {u / 63.0, y3, 0.01 * v});
    d.cut.original_vertex.push_back(v);
    d.param.uv.push_back(u), d.param.uv.push_back(0);
    return v;
  };
  auto x = [&](uint32_t v) { return d.param.uv[2 * v]; };
  const uint32_t e = add(0.5 * (x(0) + x(1)), -0.05);
  const uint32_t e1 = add(x(1) + (x(2) - x(1)) / 3, -0.05), e2 = add(x(1) + 2 * (x(2) - x(1)) / 3, -0.06);
  const uint32_t f1 = add(x(2) + (x(3) - x(2)) / 3, -0.05), f2 = add(x(2) + 2 * (x(3) - x(2)) / 3, -0.05);
  const uint32_t m = add(0.5 * (x(2) + x(3)), -0.02);
  d.mesh.triangles.insert(d.mesh.triangles.end(),
                          {0, e, 1, 1, e1, e2, 1, e2, 2, 2, f1, m, f1, f2, m, f2, 3, m, 3, 2, m});
  d.cut.triangles = d.mesh.triangles;
  std::vector<uint32_t>& loop = d.cut.boundary_loop;  // starts 0, 1, 2, 3 along v = 0
  loop.insert(loop.begin() + 3, {f1, f2});
  loop.insert(loop.begin() + 2, {e1, e2});
  loop.insert(loop.begin() + 1, e);
  d.cut.boundary_mate.assign(loop.size(), -1);
  return d;
}

// A disk-shaped mesh as its own cut (no duplicated vertices), boundary on
// the rectangle by 3-D arc length with the four vertices nearest the corners
// moved onto them, interior by Tutte's barycentric embedding (Gauss-Seidel).
Disk tutte_disk(const Mesh& m, uint32_t image) {
  Disk d;
  d.mesh = gim_mesh_from(m);
  const size_t nv = d.mesh.vertex_count();
  d.cut.original_vertex.resize(nv);
  for (size_t v = 0; v < nv; ++v) d.cut.original_vertex[v] = uint32_t(v);
  d.cut.triangles = d.mesh.triangles;
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  const auto& t = d.mesh.triangles;
  for (size_t c = 0; c < t.size(); ++c) ++directed[{t[c], t[c - c % 3 + (c + 1) % 3]}];
  std::map<uint32_t, uint32_t> next;
  for (const auto& [e, count] : directed)
    if (!directed.count({e.second, e.first})) next[e.first] = e.second;
  uint32_t v = next.begin()->first;
  do {
    d.cut.boundary_loop.push_back(v);
    v = next[v];
  } while (v != d.cut.boundary_loop[0] && d.cut.boundary_loop.size() <= next.size());
  const size_t n = d.cut.boundary_loop.size();
  d.cut.boundary_mate.assign(n, -1);
  auto pos = [&](uint32_t a, int k) { return d.mesh.positions[3 * size_t(a) + k]; };
  std::vector<double> arc(n + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t a = d.cut.boundary_loop[i], b = d.cut.boundary_loop[(i + 1) % n];
    arc[i + 1] = arc[i] + std::hypot(pos(a, 0) - pos(b, 0), pos(a, 1) - pos(b, 1), pos(a, 2) - pos(b, 2));
  }
  const double side = image - 1.0, P = 4 * side;
  std::vector<double> s(n);
  for (size_t i = 0; i < n; ++i) s[i] = P * arc[i] / arc[n];
  for (int corner = 1; corner < 4; ++corner) {  // vertex 0 is already at corner 0
    size_t best = 1;
    for (size_t i = 1; i < n; ++i)
      if (std::fabs(s[i] - corner * side) < std::fabs(s[best] - corner * side)) best = i;
    s[best] = corner * side;
  }
  d.param.width = d.param.height = image;
  d.param.uv.assign(2 * nv, side / 2);
  std::vector<bool> fixed(nv, false);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t b = d.cut.boundary_loop[i];
    const double q = s[i];
    double u, w;
    if (q <= side) u = q, w = 0;
    else if (q <= 2 * side) u = side, w = q - side;
    else if (q <= 3 * side) u = 3 * side - q, w = side;
    else u = 0, w = 4 * side - q;
    d.param.uv[2 * b] = u, d.param.uv[2 * b + 1] = w;
    fixed[b] = true;
  }
  std::vector<std::set<uint32_t>> nb(nv);
  for (size_t c = 0; c < t.size(); ++c) nb[t[c]].insert(t[c - c % 3 + (c + 1) % 3]), nb[t[c - c % 3 + (c + 1) % 3]].insert(t[c]);
  for (int it = 0; it < 20000; ++it)
    for (size_t a = 0; a < nv; ++a) {
      if (fixed[a] || nb[a].empty()) continue;
      double su = 0, sv = 0;
      for (uint32_t b : nb[a]) su += d.param.uv[2 * b], sv += d.param.uv[2 * b + 1];
      d.param.uv[2 * a] = su / nb[a].size(), d.param.uv[2 * a + 1] = sv / nb[a].size();
    }
  return d;
}

uint64_t bits(double x) {
  uint64_t b;
  std::memcpy(&b, &x, 8);
  return b;
}

int64_t orient(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t cx, int64_t cy) {
  return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
}

// Everything the image promises, checked from the outside.
void expect_valid_image(const Disk& d, const GimSamples& g) {
  const uint32_t W = g.width, H = g.height;
  ASSERT_EQ(g.xyz.size(), 3 * size_t(W) * H);
  ASSERT_EQ(g.occupied.size(), size_t(W) * H);
  ASSERT_EQ(g.triangles.size(), d.cut.triangles.size());
  // Each disk vertex has one pixel, distinct, and the pixel holds the input
  // position bit for bit.
  std::map<uint32_t, uint32_t> pixel_of_disk;
  for (size_t c = 0; c < g.triangles.size(); ++c) {
    const uint32_t dv = d.cut.triangles[c], px = g.triangles[c];
    ASSERT_LT(px, W * H);
    auto [it, fresh] = pixel_of_disk.insert({dv, px});
    ASSERT_EQ(it->second, px) << "disk vertex " << dv << " on two pixels";
    EXPECT_EQ(g.occupied[px], 1);
    const uint32_t ov = d.cut.original_vertex[dv];
    for (int k = 0; k < 3; ++k) ASSERT_EQ(bits(g.xyz[3 * size_t(px) + k]), bits(d.mesh.positions[3 * size_t(ov) + k]));
  }
  std::set<uint32_t> pixels;
  for (auto& [dv, px] : pixel_of_disk) EXPECT_TRUE(pixels.insert(px).second) << "two vertices on pixel " << px;
  size_t occupied = 0;
  for (uint8_t o : g.occupied) occupied += o;
  EXPECT_EQ(occupied, pixel_of_disk.size());
  // Positive orientation on the grid, and blank pixels on their triangle.
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < d.mesh.positions.size(); ++i)
    lo[i % 3] = std::min(lo[i % 3], d.mesh.positions[i]), hi[i % 3] = std::max(hi[i % 3], d.mesh.positions[i]);
  const double diag = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  double worst = 0;
  for (size_t t = 0; t < g.triangles.size() / 3; ++t) {
    int64_t x[3], y[3];
    for (int i = 0; i < 3; ++i) x[i] = g.triangles[3 * t + i] % W, y[i] = g.triangles[3 * t + i] / W;
    const int64_t det = orient(x[0], y[0], x[1], y[1], x[2], y[2]);
    ASSERT_GT(det, 0) << "triangle " << t;
    for (int64_t py = *std::min_element(y, y + 3); py <= *std::max_element(y, y + 3); ++py)
      for (int64_t px = *std::min_element(x, x + 3); px <= *std::max_element(x, x + 3); ++px) {
        const int64_t w0 = orient(px, py, x[1], y[1], x[2], y[2]), w1 = orient(x[0], y[0], px, py, x[2], y[2]),
                      w2 = orient(x[0], y[0], x[1], y[1], px, py);
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        for (int k = 0; k < 3; ++k) {
          double expect = 0;
          const int64_t w[3] = {w0, w1, w2};
          for (int i = 0; i < 3; ++i) expect += double(w[i]) / det * g.xyz[3 * size_t(g.triangles[3 * t + i]) + k];
          worst = std::max(worst, std::fabs(expect - g.xyz[3 * (size_t(py) * W + size_t(px)) + k]));
        }
      }
  }
  EXPECT_LE(worst, 1e-9 * diag);
  // The mesh rebuilt from the image is the input's: same triangles, same
  // positions.
  GimTopologyInput in;
  in.width = W, in.height = H, in.occupied = &g.occupied, in.seams = &g.seams;
  in.mode = GimFaceMode::kExplicitTriangles, in.triangles = &g.triangles;
  GimTopology topo;
  ASSERT_TRUE(build_gim_topology(in, &topo).ok());
  std::set<uint32_t> used(d.cut.original_vertex.begin(), d.cut.original_vertex.end());
  EXPECT_EQ(topo.pixel_of_vertex.size(), used.size());
  ASSERT_EQ(topo.corners.size(), d.mesh.triangles.size());
  for (size_t c = 0; c < topo.corners.size(); ++c) {
    const uint32_t px = topo.pixel_of_vertex[topo.corners[c]];
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(bits(g.xyz[3 * size_t(px) + k]), bits(d.mesh.positions[3 * size_t(d.mesh.triangles[c]) + k]));
  }
}

void run_and_check(const Disk& d, const char* name, TopologyPreservingStats* st_out = nullptr) {
  GimSamples g;
  TopologyPreservingStats st;
  std::vector<double> seen;
  const Status s = make_topology_preserving_image(d.mesh, d.cut, d.param, TopologyPreservingOptions{}, &g, &st,
                                                  [&](double f) { seen.push_back(f); });
  ASSERT_TRUE(s.ok()) << name << ": " << s.to_string();
  expect_valid_image(d, g);
  EXPECT_LE(g.width, 4096u);
  EXPECT_LE(g.height, 4096u);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back(), 1.0);
  std::printf("%s: %zu disk vertices, %zu triangles -> %u x %u (%.1f px/vertex); %d area sweeps, %d stretches, "
              "%d repair rounds, %d compress passes; %.3f s (areas %.3f, placement %.3f, compression %.3f, fill %.3f)\n",
              name, d.cut.original_vertex.size(), d.cut.triangles.size() / 3, g.width, g.height,
              double(g.width) * g.height / d.cut.original_vertex.size(), st.area_sweeps, st.stretches,
              st.repair_rounds, st.compress_passes, st.seconds_total, st.seconds_areas, st.seconds_placement,
              st.seconds_compression, st.seconds_fill);
  if (st_out) *st_out = st;
}

TEST(GimTopoTest, SyntheticDisk) {
  for (uint32_t seed : {1u, 2u, 3u}) run_and_check(synthetic_disk(12, 64, seed), "synthetic 12x12");
  run_and_check(synthetic_disk(40, 256, 7), "synthetic 40x40");
}

TEST(GimTopoTest, LayoutCheckCatchesViolations) {
  const Disk d = synthetic_disk(3, 8, 1);
  PlanarDisk disk;
  disk.triangles = &d.cut.triangles;
  disk.sides = {kSideMinX | kSideMinY, kSideMinY, kSideMaxX | kSideMinY, kSideMinX, 0, kSideMaxX,
                kSideMinX | kSideMaxY, kSideMaxY, kSideMaxX | kSideMaxY};
  disk.boundary_loop = d.cut.boundary_loop;
  std::vector<int64_t> xy = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1, 0, 2, 1, 2, 2, 2};
  EXPECT_TRUE(check_integer_layout(disk, xy, 3, 3).ok());
  std::vector<int64_t> bad = xy;
  bad[8] = 2, bad[9] = 2;  // the centre onto a corner's pixel
  EXPECT_FALSE(check_integer_layout(disk, bad, 3, 3).ok());
  bad = xy;
  bad[1] = 1;  // a corner off its border line
  EXPECT_FALSE(check_integer_layout(disk, bad, 3, 3).ok());
  std::vector<int64_t> wide = {0, 0, 1, 0, 3, 0, 0, 1, 2, 1, 3, 1, 0, 2, 1, 2, 3, 2};
  EXPECT_TRUE(check_integer_layout(disk, wide, 4, 3).ok());
  wide[9] = 2;  // the centre onto the v = max line between two border vertices: degenerate
  EXPECT_FALSE(check_integer_layout(disk, wide, 4, 3).ok());
  // Vertex 1 (on v = 0) one row beyond its line: only as an outward vertex.
  std::vector<int64_t> bulge = {0, 1, 1, 0, 2, 1, 0, 2, 1, 2, 2, 2, 0, 3, 1, 3, 2, 3};
  EXPECT_FALSE(check_integer_layout(disk, bulge, 3, 4).ok());
  disk.sides[1] |= kSideOutward;
  EXPECT_TRUE(check_integer_layout(disk, bulge, 3, 4).ok());
  // A boundary that crosses itself (positive area, no triangles).
  const std::vector<uint32_t> none;
  PlanarDisk bow;
  bow.triangles = &none;
  bow.sides.assign(4, 0);
  bow.boundary_loop = {0, 1, 2, 3};
  const Status crossed = check_integer_layout(bow, {0, 0, 4, 0, 0, 2, 2, 3}, 5, 4);
  EXPECT_NE(crossed.message().find("touch or cross"), std::string::npos) << crossed.to_string();
}

TEST(GimTopoTest, ImpossibleSizeIsAnError) {
  const Disk d = synthetic_disk(10, 64, 5);  // 100 vertices
  TopologyPreservingOptions opt;
  opt.max_side = 4;
  GimSamples g;
  const Status s = make_topology_preserving_image(d.mesh, d.cut, d.param, opt, &g);
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("100 vertices"), std::string::npos) << s.message();
}

TEST(GimTopoTest, BorderPocketsBulgeOutward) {
  const Disk d = disk_with_pockets();
  run_and_check(d, "synthetic with border pockets");
  // The straight-border layout was impossible: the pocket vertices must sit
  // outside the row of the other v = 0 vertices.
  GimSamples g;
  ASSERT_TRUE(make_topology_preserving_image(d.mesh, d.cut, d.param, TopologyPreservingOptions{}, &g).ok());
  std::map<uint32_t, uint32_t> row;
  for (size_t c = 0; c < g.triangles.size(); ++c) row[d.cut.triangles[c]] = g.triangles[c] / g.width;
  const size_t first_new = 64;  // synthetic_disk(8, ...) has 64 vertices
  for (uint32_t v = first_new; v < d.cut.original_vertex.size(); ++v)
    EXPECT_LT(row[v], row[1]) << "pocket vertex " << v << " not beyond the border row";
}

// A vertex of the triangulation put into the boundary loop on a border line:
// the loop is not the disk's boundary, and the layout check refuses it.
TEST(GimTopoTest, StraightBorderTriangleIsAnError) {
  Disk d = synthetic_disk(3, 8, 1);
  d.param.uv[2 * 4] = 3.5, d.param.uv[2 * 4 + 1] = 0;  // centre onto the v = 0 line
  d.cut.boundary_loop.insert(d.cut.boundary_loop.begin() + 1, 4);
  GimSamples g;
  EXPECT_EQ(make_topology_preserving_image(d.mesh, d.cut, d.param, TopologyPreservingOptions{}, &g).code(),
            ErrorCode::kInvalidArgument);
}

std::string corpus(const char* name) { return (testing::corpus_dir() / "tri" / name).string(); }

TEST(GimTopoTest, CatheadTutte) {
  const std::string path = corpus("cathead.obj");
  if (!fs::exists(path)) GTEST_SKIP() << path << " not present";
  Mesh m;
  ASSERT_TRUE(tools::read_mesh(path, &m, nullptr).ok());
  run_and_check(tutte_disk(m, 64), "cathead (Tutte)");
}

// Cut, Floater map on a 512 x 512 rectangle, then the image; must succeed.
void cut_parametrize_and_check(const Mesh& m, const char* name) {
  Disk d;
  d.mesh = gim_mesh_from(m);
  ASSERT_TRUE(cut_to_disk(d.mesh, &d.cut).ok()) << name;
  ASSERT_TRUE(parametrize_on_rectangle(d.mesh, d.cut, 512, 512, &d.param).ok()) << name;
  run_and_check(d, name);
}

TEST(GimTopoTest, CorpusThroughCutAndParametrization) {
  // 3holes (genus 3), fertility (genus 4) and torus have ears along the cut
  // that Floater's map flattens onto a border line (see BorderPocketsBulgeOutward).
  for (const char* name : {"cathead.obj", "bunny_small.off", "cow.obj", "3holes.off", "fertility.off", "torus.obj"}) {
    const std::string path = corpus(name);
    if (!fs::exists(path)) continue;
    Mesh m;
    ASSERT_TRUE(tools::read_mesh(path, &m, nullptr).ok());
    cut_parametrize_and_check(m, name);
  }
}

TEST(GimTopoTest, GeneratedTorus) {
  cut_parametrize_and_check(tools::triangulated(tools::make_torus(24, 12)), "torus 24 x 12");
  cut_parametrize_and_check(tools::triangulated(tools::make_torus(32, 16)), "torus 32 x 16");
}

}  // namespace
}  // namespace qmc
