// The geometry-image encoder's first stages (seeds 000, 002): cutting to a
// disk (kept disks, the genus-0 long path, Gu's cut graph on handles and
// holes, rejected inputs), the mean-value parametrization onto the image
// rectangle with aligned seams, and regular sampling with bit-identical seam
// pixels. Corpus meshes when ../shared/corpus is present (skipped otherwise).
#include "geometry/gim_cut.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "geometry/gim_parametrization.h"
#include "geometry/gim_sampling.h"
#include "geometry/triangle_bvh.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "corpus_dir.h"

namespace qmc {
namespace {

namespace fs = std::filesystem;

using testing::corpus_dir;

bool read_corpus(const std::string& name, GimTriMesh* out) {
  Mesh m;
  const fs::path path = fs::path(corpus_dir()) / name;
  if (!fs::exists(path) || !tools::read_mesh(path.string(), &m, nullptr).ok()) return false;
  *out = gim_mesh_from(m);
  return true;
}

// Everything the DiskCut contract promises, checked from scratch.
void expect_valid_disk(const GimTriMesh& mesh, const DiskCut& cut) {
  const size_t nv = cut.original_vertex.size(), n = cut.boundary_loop.size();
  ASSERT_EQ(cut.triangles.size(), mesh.triangles.size());
  for (size_t i = 0; i < cut.triangles.size(); ++i) ASSERT_EQ(cut.original_vertex[cut.triangles[i]], mesh.triangles[i]);
  // Half-edges of the disk: interior ones in pairs, boundary ones alone.
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < cut.triangles.size() / 3; ++t)
    for (int k = 0; k < 3; ++k) ++directed[{cut.triangles[3 * t + k], cut.triangles[3 * t + (k + 1) % 3]}];
  std::set<std::pair<uint32_t, uint32_t>> boundary, undirected;
  for (const auto& [e, count] : directed) {
    ASSERT_EQ(count, 1);
    undirected.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
    if (!directed.count({e.second, e.first})) boundary.insert(e);
  }
  // V - E + F == 1 and a single boundary loop with the disk on its left.
  EXPECT_EQ(int64_t(nv) - int64_t(undirected.size()) + int64_t(mesh.triangle_count()), 1);
  ASSERT_EQ(boundary.size(), n);
  ASSERT_EQ(cut.boundary_mate.size(), n);
  std::set<uint32_t> on_loop(cut.boundary_loop.begin(), cut.boundary_loop.end());
  EXPECT_EQ(on_loop.size(), n) << "a vertex appears twice on the boundary loop";
  int mated = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t a = cut.boundary_loop[i], b = cut.boundary_loop[(i + 1) % n];
    ASSERT_TRUE(boundary.count({a, b})) << "boundary edge " << i << " is not a boundary half-edge of the disk";
    const int32_t m = cut.boundary_mate[i];
    if (m < 0) continue;
    ++mated;
    ASSERT_LT(size_t(m), n);
    EXPECT_EQ(cut.boundary_mate[m], int32_t(i));
    // The mate is the same input edge, traversed the other way.
    EXPECT_EQ(cut.original_vertex[cut.boundary_loop[m]], cut.original_vertex[b]);
    EXPECT_EQ(cut.original_vertex[cut.boundary_loop[(m + 1) % n]], cut.original_vertex[a]);
  }
  EXPECT_EQ(mated, 2 * int(cut.cut_edge_count));
}

// Mean-value weights from the angles directly (seed 002 eq. (5)), to check
// the parametrization independently of the code that solved it.
void expect_mean_value_equations(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& p, double tol) {
  const size_t nv = cut.original_vertex.size();
  std::vector<uint8_t> on_boundary(nv, 0);
  for (uint32_t v : cut.boundary_loop) on_boundary[v] = 1;
  std::vector<std::map<uint32_t, double>> w(nv);
  auto pos = [&](uint32_t v, int k) { return mesh.positions[3 * size_t(cut.original_vertex[v]) + k]; };
  auto len = [&](uint32_t a, uint32_t b) {
    return std::sqrt(std::pow(pos(a, 0) - pos(b, 0), 2) + std::pow(pos(a, 1) - pos(b, 1), 2) +
                     std::pow(pos(a, 2) - pos(b, 2), 2));
  };
  for (size_t t = 0; t < cut.triangles.size() / 3; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t o = cut.triangles[3 * t + k], a = cut.triangles[3 * t + (k + 1) % 3],
                     b = cut.triangles[3 * t + (k + 2) % 3];
      if (on_boundary[o]) continue;
      const double la = len(o, a), lb = len(o, b), lab = len(a, b);
      const double cos_angle = std::clamp((la * la + lb * lb - lab * lab) / (2 * la * lb), -1.0, 1.0);
      const double th = std::tan(std::acos(cos_angle) / 2);
      w[o][a] += th / la, w[o][b] += th / lb;
    }
  double worst = 0;
  for (size_t v = 0; v < nv; ++v) {
    if (on_boundary[v]) continue;
    double sum = 0, u = 0, vv = 0;
    for (const auto& [j, wj] : w[v]) sum += wj, u += wj * p.uv[2 * j], vv += wj * p.uv[2 * j + 1];
    worst = std::max(worst, std::hypot(u / sum - p.uv[2 * v], vv / sum - p.uv[2 * v + 1]));
  }
  EXPECT_LT(worst, tol);
}

// Boundary vertices on the rectangle border, nodes on whole pixels, mate
// runs of equal length; no flipped parametric triangle.
void expect_valid_parametrization(const DiskCut& cut, const DiskParametrization& p, bool expect_no_flips) {
  const double W = p.width - 1.0, H = p.height - 1.0;
  for (uint32_t v : cut.boundary_loop) {
    const double u = p.uv[2 * v], w = p.uv[2 * v + 1];
    const bool on_border =
        std::fabs(u) < 1e-9 || std::fabs(w) < 1e-9 || std::fabs(u - W) < 1e-9 || std::fabs(w - H) < 1e-9;
    EXPECT_TRUE(on_border && u > -1e-9 && w > -1e-9 && u < W + 1e-9 && w < H + 1e-9)
        << "boundary vertex " << v << " at " << u << ", " << w;
  }
  uint32_t total = 0;
  for (const GimBorderRun& run : p.runs) {
    total += run.pixel_steps;
    EXPECT_GE(run.pixel_steps, 1u);
    if (run.mate >= 0) {
      EXPECT_EQ(p.runs[run.mate].pixel_steps, run.pixel_steps);
    }
    const uint32_t node = cut.boundary_loop[run.first_edge];
    const double u = p.uv[2 * node], w = p.uv[2 * node + 1];
    EXPECT_EQ(u, std::round(u));
    EXPECT_EQ(w, std::round(w));
    EXPECT_EQ(uint32_t(w) * p.width + uint32_t(u), p.border_pixels[run.first_border_pixel]);
  }
  EXPECT_EQ(total, p.border_pixels.size());
  if (!expect_no_flips) return;
  for (size_t t = 0; t < cut.triangles.size() / 3; ++t) {
    const double* a = &p.uv[2 * size_t(cut.triangles[3 * t])];
    const double* b = &p.uv[2 * size_t(cut.triangles[3 * t + 1])];
    const double* c = &p.uv[2 * size_t(cut.triangles[3 * t + 2])];
    EXPECT_GE((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), -1e-9) << "triangle " << t << " flipped";
  }
}

void expect_seams_bit_identical(const GimSamples& img) {
  for (const SeamPair& s : img.seams) {
    ASSERT_LT(s.a, s.b);
    EXPECT_EQ(std::memcmp(&img.xyz[3 * size_t(s.a)], &img.xyz[3 * size_t(s.b)], 3 * sizeof(double)), 0);
  }
}

// Every sample lies on the input surface (barycentric or boundary points).
void expect_samples_on_surface(const GimTriMesh& mesh, const GimSamples& img, double tol) {
  std::vector<Triangle3d> tris(mesh.triangle_count());
  auto v = [&](uint32_t i) {
    return Vec3d{mesh.positions[3 * size_t(i)], mesh.positions[3 * size_t(i) + 1], mesh.positions[3 * size_t(i) + 2]};
  };
  for (size_t t = 0; t < tris.size(); ++t)
    tris[t] = {v(mesh.triangles[3 * t]), v(mesh.triangles[3 * t + 1]), v(mesh.triangles[3 * t + 2])};
  const TriangleBvh bvh(tris);
  double worst = 0;
  for (size_t p = 0; p < img.xyz.size() / 3; ++p)
    worst =
        std::max(worst, bvh.closest_point({img.xyz[3 * p], img.xyz[3 * p + 1], img.xyz[3 * p + 2]}).distance_squared);
  EXPECT_LT(std::sqrt(worst), tol);
}

struct Pipeline {
  DiskCut cut;
  DiskParametrization param;
  GimSamples img;
  GimCutStats cut_stats;
  GimParamStats param_stats;
  GimSampleStats sample_stats;
  double seconds = 0;
};

Pipeline run_pipeline(const GimTriMesh& mesh, uint32_t w, uint32_t h) {
  Pipeline p;
  const auto start = std::chrono::steady_clock::now();
  Status s = cut_to_disk(mesh, &p.cut, {}, &p.cut_stats);
  EXPECT_TRUE(s.ok()) << s.to_string();
  if (!s.ok()) return p;
  s = parametrize_on_rectangle(mesh, p.cut, w, h, &p.param, {}, &p.param_stats);
  EXPECT_TRUE(s.ok()) << s.to_string();
  if (!s.ok()) return p;
  std::vector<double> cu, rv;
  regular_sampling(w, h, &cu, &rv);
  s = sample_geometry_image(mesh, p.cut, p.param, cu, rv, &p.img, {}, &p.sample_stats);
  EXPECT_TRUE(s.ok()) << s.to_string();
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

GimTriMesh generated(const Mesh& polygons) { return gim_mesh_from(tools::triangulated(polygons)); }

// ------------------------------------------------------------------ cutting

TEST(GimCut, DiskIsKeptAsIs) {
  const GimTriMesh mesh = generated(tools::make_grid(6, 4));
  DiskCut cut;
  ASSERT_TRUE(cut_to_disk(mesh, &cut).ok());
  EXPECT_EQ(cut.genus, 0);
  EXPECT_EQ(cut.input_boundary_loops, 1);
  EXPECT_EQ(cut.cut_edge_count, 0u);
  EXPECT_EQ(cut.original_vertex.size(), mesh.vertex_count());
  EXPECT_EQ(cut.boundary_loop.size(), 2u * (6 + 4));
  for (int32_t m : cut.boundary_mate) EXPECT_EQ(m, -1);
  expect_valid_disk(mesh, cut);
}

TEST(GimCut, ClosedGenusZeroIsCutAlongAPath) {
  const GimTriMesh mesh = generated(tools::make_refined_sphere(1));
  DiskCut cut;
  GimCutStats stats;
  ASSERT_TRUE(cut_to_disk(mesh, &cut, {}, &stats).ok());
  EXPECT_EQ(cut.genus, 0);
  EXPECT_EQ(cut.input_boundary_loops, 0);
  EXPECT_GT(cut.cut_edge_count, 2u);
  EXPECT_EQ(cut.boundary_loop.size(), 2u * cut.cut_edge_count);
  EXPECT_EQ(cut.original_vertex.size(), mesh.vertex_count() + cut.cut_edge_count - 1);  // path: inner vertices twice
  EXPECT_EQ(stats.cut_nodes, 2u);
  // The two ends are about antipodal on the unit sphere: a long path.
  EXPECT_GT(stats.cut_length, 3.0);
  expect_valid_disk(mesh, cut);
}

TEST(GimCut, TorusGetsGusCutGraph) {
  const GimTriMesh mesh = generated(tools::make_torus(24, 12));
  DiskCut cut;
  GimCutStats stats;
  ASSERT_TRUE(cut_to_disk(mesh, &cut, {}, &stats).ok());
  EXPECT_EQ(cut.genus, 1);
  EXPECT_EQ(cut.input_boundary_loops, 0);
  expect_valid_disk(mesh, cut);
  EXPECT_LE(stats.cut_length, stats.cut_length_before);
}

TEST(GimCut, CorpusTopologies) {
  struct Case {
    const char* name;
    int genus, loops;
  };
  int seen = 0;
  for (const Case& c :
       {Case{"tri/cathead.obj", 0, 1}, Case{"tri/camelhead.off", 0, 1}, Case{"tri/torus.obj", 1, 0},
        Case{"tri/3holes.off", 3, 0}, Case{"tri/fertility.off", 4, 0}, Case{"tri/bunny_small.off", 0, 0},
        Case{"tri/stanford-bunny.obj", 0, 5}, Case{"tri/cow.obj", -1, 0}}) {
    GimTriMesh mesh;
    if (!read_corpus(c.name, &mesh)) continue;
    ++seen;
    SCOPED_TRACE(c.name);
    DiskCut cut;
    GimCutStats stats;
    const Status s = cut_to_disk(mesh, &cut, {}, &stats);
    ASSERT_TRUE(s.ok()) << s.to_string();
    if (c.genus >= 0) {
      EXPECT_EQ(cut.genus, c.genus);
    }
    EXPECT_EQ(cut.input_boundary_loops, c.loops);
    expect_valid_disk(mesh, cut);
    std::printf(
        "[ cut      ] %-22s genus %d, %d loops, %u pinched, %u cut edges, %u nodes, %u/%u paths straightened, length "
        "%.4g -> %.4g, %.3f s\n",
        c.name, cut.genus, cut.input_boundary_loops, cut.split_fan_vertices, cut.cut_edge_count, stats.cut_nodes,
        stats.paths_straightened, stats.cut_paths, stats.cut_length_before, stats.cut_length, stats.seconds);
    if (std::string(c.name) == "tri/cow.obj") {
      EXPECT_EQ(cut.split_fan_vertices, 1u);
    }
  }
  if (seen == 0) GTEST_SKIP() << "corpus not found at " << corpus_dir();
}

TEST(GimCut, RejectsWhatItCannotCut) {
  GimTriMesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  DiskCut cut;
  // Three triangles on edge (0, 1).
  m.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  Status s = cut_to_disk(m, &cut);
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("non-manifold"), std::string::npos) << s.message();
  // Inconsistent orientation.
  m.triangles = {0, 1, 2, 0, 1, 3};
  s = cut_to_disk(m, &cut);
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("orientation"), std::string::npos) << s.message();
  // Two components (a bowtie at vertex 0 is two components once its fans split).
  m.triangles = {0, 1, 2, 0, 3, 4};
  s = cut_to_disk(m, &cut);
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("2 connected components"), std::string::npos) << s.message();
  // Bad indices and degenerate triangles.
  m.triangles = {0, 1, 9};
  EXPECT_EQ(cut_to_disk(m, &cut).code(), ErrorCode::kInvalidArgument);
  m.triangles = {0, 1, 1};
  EXPECT_EQ(cut_to_disk(m, &cut).code(), ErrorCode::kInvalidArgument);
  m.triangles = {};
  EXPECT_EQ(cut_to_disk(m, &cut).code(), ErrorCode::kInvalidArgument);
}

TEST(GimCut, PinchedVertexIsSplitPerFan) {
  const GimTriMesh grid = generated(tools::make_grid(4, 4));  // 25 vertices, corners 0, 4, 20, 24
  GimTriMesh m = grid;
  // Glue the grid's corners 0 and 24 into one vertex: a pinched vertex.
  for (uint32_t& v : m.triangles)
    if (v == 24) v = 0;
  DiskCut cut;
  const Status s = cut_to_disk(m, &cut);
  ASSERT_TRUE(s.ok()) << s.to_string();
  EXPECT_EQ(cut.split_fan_vertices, 1u);
  EXPECT_EQ(cut.genus, 0);
  EXPECT_EQ(cut.input_boundary_loops, 1);
  expect_valid_disk(m, cut);
  EXPECT_EQ(std::count(cut.original_vertex.begin(), cut.original_vertex.end(), 0u), 2);
}

// --------------------------------------------------------- parametrization

TEST(GimParam, DiskAndTorusMapWithoutFlips) {
  for (const GimTriMesh& mesh : {generated(tools::make_grid(7, 5)), generated(tools::make_torus(24, 12)),
                                 generated(tools::make_refined_sphere(1))}) {
    DiskCut cut;
    ASSERT_TRUE(cut_to_disk(mesh, &cut).ok());
    DiskParametrization p;
    GimParamStats stats;
    const Status s = parametrize_on_rectangle(mesh, cut, 65, 33, &p, {}, &stats);
    ASSERT_TRUE(s.ok()) << s.to_string();
    EXPECT_EQ(p.border_pixels.size(), 2u * 64 + 2u * 32);
    EXPECT_EQ(p.border_pixels[0], 0u);
    expect_valid_parametrization(cut, p, true);
    expect_mean_value_equations(mesh, cut, p, 1e-9);
    EXPECT_EQ(stats.flipped_triangles, 0u);
  }
}

TEST(GimParam, ProgressIsMonotoneWithinZeroOne) {
  const GimTriMesh mesh = generated(tools::make_torus(24, 12));
  std::vector<double> seen;
  auto record = [&](double f) { seen.push_back(f); };
  DiskCut cut;
  ASSERT_TRUE(cut_to_disk(mesh, &cut, record).ok());
  DiskParametrization p;
  ASSERT_TRUE(parametrize_on_rectangle(mesh, cut, 32, 32, &p, record).ok());
  std::vector<double> cu, rv;
  regular_sampling(32, 32, &cu, &rv);
  GimSamples img;
  ASSERT_TRUE(sample_geometry_image(mesh, cut, p, cu, rv, &img, record).ok());
  ASSERT_FALSE(seen.empty());
  for (double f : seen) EXPECT_TRUE(f >= 0 && f <= 1) << f;
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1.0), 3);
}

TEST(GimParam, PathEndsAvoidCorners) {
  const GimTriMesh mesh = generated(tools::make_refined_sphere(1));
  DiskCut cut;
  ASSERT_TRUE(cut_to_disk(mesh, &cut).ok());
  for (uint32_t size : {8u, 9u, 16u, 33u}) {
    DiskParametrization p;
    ASSERT_TRUE(parametrize_on_rectangle(mesh, cut, size, size, &p).ok());
    ASSERT_EQ(p.runs.size(), 2u);
    for (const GimBorderRun& run : p.runs) {
      const uint32_t pixel = p.border_pixels[run.first_border_pixel], x = pixel % size, y = pixel / size;
      EXPECT_FALSE((x == 0 || x == size - 1) && (y == 0 || y == size - 1))
          << "path end on corner pixel " << x << ", " << y;
    }
  }
}

TEST(GimParam, ImageTooSmallIsAnError) {
  const GimTriMesh mesh = generated(tools::make_torus(24, 12));
  DiskCut cut;
  ASSERT_TRUE(cut_to_disk(mesh, &cut).ok());
  DiskParametrization p;
  const Status s = parametrize_on_rectangle(mesh, cut, 2, 2, &p);
  ASSERT_GT(find_border_runs(cut).size(), 4u);  // a theta or figure-eight graph: 6 or 4+ runs
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("image too small"), std::string::npos) << s.message();
  EXPECT_EQ(parametrize_on_rectangle(mesh, cut, 1, 64, &p).code(), ErrorCode::kInvalidArgument);
}

TEST(GimParam, TorusSeamPixelsAreBitIdentical) {
  const GimTriMesh mesh = generated(tools::make_torus(32, 16));
  const Pipeline p = run_pipeline(mesh, 64, 64);
  ASSERT_FALSE(p.img.xyz.empty());
  EXPECT_EQ(p.img.width, 64u);
  EXPECT_FALSE(p.img.seams.empty());
  expect_seams_bit_identical(p.img);
  expect_samples_on_surface(mesh, p.img, 1e-9);
  // Every border pixel of a closed surface lies on a seam.
  std::set<uint32_t> seam_pixels;
  for (const SeamPair& s : p.img.seams) seam_pixels.insert(s.a), seam_pixels.insert(s.b);
  EXPECT_EQ(seam_pixels.size(), p.param.border_pixels.size());
}

TEST(GimParam, AdaptiveSequencesAreAccepted) {
  const GimTriMesh mesh = generated(tools::make_refined_sphere(1));
  DiskCut cut;
  ASSERT_TRUE(cut_to_disk(mesh, &cut).ok());
  DiskParametrization p;
  ASSERT_TRUE(parametrize_on_rectangle(mesh, cut, 20, 12, &p).ok());
  std::vector<double> cu(20), rv(12);
  for (int i = 0; i < 20; ++i) cu[i] = 19 * std::pow(i / 19.0, 1.5);
  for (int j = 0; j < 12; ++j) rv[j] = 11 * std::pow(j / 11.0, 0.7);
  GimSamples img;
  const Status s = sample_geometry_image(mesh, cut, p, cu, rv, &img);
  ASSERT_TRUE(s.ok()) << s.to_string();
  expect_seams_bit_identical(img);
  expect_samples_on_surface(mesh, img, 1e-9);
  cu[3] = cu[2];
  EXPECT_EQ(sample_geometry_image(mesh, cut, p, cu, rv, &img).code(), ErrorCode::kInvalidArgument);
}

TEST(GimParam, CorpusPipelines) {
  struct Case {
    const char* name;
    uint32_t w, h;
    bool no_flips;
  };
  int seen = 0;
  for (const Case& c : {Case{"tri/cathead.obj", 64, 64, true}, Case{"tri/camelhead.off", 180, 180, true},
                        Case{"tri/torus.obj", 128, 128, true}, Case{"tri/3holes.off", 128, 128, true},
                        Case{"tri/fertility.off", 256, 256, true}, Case{"tri/bunny_small.off", 128, 128, true},
                        Case{"tri/cow.obj", 128, 128, true}, Case{"tri/stanford-bunny.obj", 256, 256, true}}) {
    GimTriMesh mesh;
    if (!read_corpus(c.name, &mesh)) continue;
    ++seen;
    SCOPED_TRACE(c.name);
    const Pipeline p = run_pipeline(mesh, c.w, c.h);
    if (p.img.xyz.empty()) continue;
    expect_valid_disk(mesh, p.cut);
    expect_valid_parametrization(p.cut, p.param, c.no_flips);
    expect_mean_value_equations(mesh, p.cut, p.param, 1e-9);
    expect_seams_bit_identical(p.img);
    expect_samples_on_surface(mesh, p.img, 1e-9);
    std::printf(
        "[ gim      ] %-20s %ux%u: %zu tris, %u runs, %u flipped, %u degenerate, residual %.2g, %u clamped, %u seam "
        "pairs; "
        "cut %.3f s, param %.3f s, sample %.3f s, total %.3f s\n",
        c.name, c.w, c.h, mesh.triangle_count(), p.param_stats.runs, p.param_stats.flipped_triangles,
        p.param_stats.degenerate_triangles, p.param_stats.max_residual, p.sample_stats.clamped_pixels,
        p.sample_stats.seam_pairs, p.cut_stats.seconds, p.param_stats.seconds, p.sample_stats.seconds, p.seconds);
  }
  if (seen == 0) GTEST_SKIP() << "corpus not found at " << corpus_dir();
}

}  // namespace
}  // namespace qmc
