// Progressive Loop levels, spec/qmc-format.md section 12: the subdivision
// rules, the limit normals, the 1-bit/9-bit code, the chunk order, and the
// streaming decoder that shows each level as it lands.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "decoder/loop_level_decoder.h"
#include "decoder/loop_subdivision.h"
#include "encoder/encoder_internal.h"
#include "encoder/loop_level_encoder.h"
#include "analytic_loop_files.h"
#include "chunk_list.h"
#include "loop_mesh_support.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"

namespace qmc {
namespace {

Mesh triangle_torus() { return tools::triangulated(tools::make_torus(12, 8)); }
Mesh triangle_grid() { return tools::triangulated(tools::make_grid(6, 5)); }

const LevelTargets sphere_targets = tools::unit_sphere_targets();

// A progressive file of `base` with `levels` levels aiming at `targets`.
std::vector<uint8_t> progressive_file(const Mesh& base, int levels, const LevelTargets& targets, int bits = 12,
                                      EncodeStats* stats = nullptr) {
  std::vector<uint8_t> out;
  const Status s = tools::make_loop_file(base, levels, targets, bits, &out, stats);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return out;
}

// Largest |radius - 1| over the vertices from `first` on.
double max_radius_error(const LoopLevel& level, size_t first = 0) {
  double worst = 0;
  for (size_t i = 3 * first; i < level.positions.size(); i += 3) {
    const double* p = &level.positions[i];
    worst = std::fmax(worst, std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0));
  }
  return worst;
}

TEST(LoopBeta, ExactWhereCosineIsExactAndCloseToLoopsFormulaElsewhere) {
  EXPECT_EQ(loop_beta(3), 3.0 / 16.0);
  EXPECT_EQ(loop_beta(6), 1.0 / 16.0);
  EXPECT_EQ(loop_beta(4), (0.625 - 0.375 * 0.375) / 4.0);
  for (uint32_t n = 2; n < 200; ++n) {
    const double c = std::cos(2 * M_PI / n), inner = 0.375 + 0.25 * c;
    EXPECT_NEAR(loop_beta(n), (0.625 - inner * inner) / n, 1e-16) << n;
  }
  // The check values that spec 12.4 prints.
  char text[64];
  std::snprintf(text, sizeof text, "%a", loop_beta(5));
  EXPECT_STREQ(text, "0x1.58722191a02d6p-4");
  std::snprintf(text, sizeof text, "%a", loop_beta(7));
  EXPECT_STREQ(text, "0x1.919cb59d1c909p-5");
}

TEST(LoopEdges, NumberedInFaceOrderWithTheirFacesAndRings) {
  const LoopMesh octahedron = loop_mesh_of(tools::make_octahedron());
  LoopEdges e;
  ASSERT_TRUE(build_loop_edges(octahedron, &e).ok());
  EXPECT_EQ(e.edge_count(), 12u);
  // Face 0 is (4 0 2): its edges come first, as (4 0), (0 2), (2 4).
  EXPECT_EQ(e.a[0], 4u);
  EXPECT_EQ(e.b[0], 0u);
  EXPECT_EQ(e.c[0], 2u);
  EXPECT_EQ(e.a[1], 0u);
  EXPECT_EQ(e.b[1], 2u);
  EXPECT_EQ(e.a[2], 2u);
  EXPECT_EQ(e.b[2], 4u);
  for (uint32_t i = 0; i < e.edge_count(); ++i) EXPECT_FALSE(e.is_boundary(i));
  for (uint32_t v = 0; v < 6; ++v) EXPECT_EQ(e.valence[v], 4u);
  // Neighbours are listed by increasing edge index.
  EXPECT_EQ(e.neighbours[e.neighbour_offset[4]], 0u);
  EXPECT_EQ(e.neighbours[e.neighbour_offset[4] + 1], 2u);
}

TEST(LoopEdges, RejectWhatSection12_2Forbids) {
  LoopEdges e;
  LoopMesh m;
  m.positions.assign(3 * 5, 0.0);
  m.triangles = {0, 1, 2, 0, 2, 1, 0, 1, 3};  // edge (0 1) in three faces
  EXPECT_NE(build_loop_edges(m, &e).message().find("more than two faces"), std::string::npos);
  m.triangles = {0, 1, 2, 0, 1, 3};  // (0 1) crossed the same way twice
  EXPECT_NE(build_loop_edges(m, &e).message().find("same way"), std::string::npos);
  m.triangles = {0, 1, 2, 0, 2, 3};  // vertex 4 in no face
  EXPECT_NE(build_loop_edges(m, &e).message().find("vertex 4 is in no face"), std::string::npos);
  m.triangles = {0, 1, 1};
  EXPECT_NE(build_loop_edges(m, &e).message().find("repeats a vertex"), std::string::npos);
  // Two triangles touching at vertex 0 only: a bow tie.
  m.positions.assign(3 * 5, 0.0);
  m.triangles = {0, 1, 2, 0, 3, 4};
  EXPECT_NE(build_loop_edges(m, &e).message().find("more than two boundary edges"), std::string::npos);
  // Two closed fans sharing a vertex (two tetrahedra glued at a corner).
  Mesh two = tools::make_tetrahedron();
  const Mesh second = tools::make_tetrahedron();
  for (size_t i = 3; i < second.positions.size(); ++i) two.positions.push_back(second.positions[i] + 3);
  for (uint32_t c : second.corners) {
    two.corners.push_back(c == 0 ? 0 : c + 3);
    if (two.corners.size() % 3 == 0) two.face_sizes.push_back(3);
  }
  EXPECT_NE(build_loop_edges(loop_mesh_of(two), &e).message().find("two separate fans"), std::string::npos);
  m.triangles.clear();
  EXPECT_FALSE(build_loop_edges(m, &e).ok());
}

TEST(LoopSubdivide, CountsTopologyAndFacesAsSection12_5) {
  for (const Mesh& mesh : {tools::make_octahedron(), triangle_torus(), triangle_grid()}) {
    LoopMesh coarse = loop_mesh_of(mesh), fine;
    LoopEdges e, fine_edges;
    ASSERT_TRUE(build_loop_edges(coarse, &e).ok());
    loop_subdivide(coarse, e, &fine);
    EXPECT_EQ(fine.vertex_count(), coarse.vertex_count() + e.edge_count());
    EXPECT_EQ(fine.face_count(), 4 * coarse.face_count());
    ASSERT_TRUE(build_loop_edges(fine, &fine_edges).ok());
    // Euler characteristic V - E + F is kept.
    EXPECT_EQ(int64_t(fine.vertex_count()) - fine_edges.edge_count() + fine.face_count(),
              int64_t(coarse.vertex_count()) - e.edge_count() + coarse.face_count());
    // The first face's four children, in the order of 12.5 step 3.
    const uint32_t V = coarse.vertex_count();
    const uint32_t* t = coarse.triangles.data();
    const uint32_t m0 = V + e.face_edge[0], m1 = V + e.face_edge[1], m2 = V + e.face_edge[2];
    const std::vector<uint32_t> expected = {t[0], m0, m2, t[1], m1, m0, t[2], m2, m1, m0, m1, m2};
    EXPECT_EQ(std::vector<uint32_t>(fine.triangles.begin(), fine.triangles.begin() + 12), expected);
  }
}

TEST(LoopSubdivide, MasksOnAFlatGridStayFlatAndNormalsPointUp) {
  Mesh grid = triangle_grid();
  for (size_t i = 2; i < grid.positions.size(); i += 3) grid.positions[i] = 0;  // z = 0
  LoopMesh coarse = loop_mesh_of(grid), fine;
  LoopEdges e;
  ASSERT_TRUE(build_loop_edges(coarse, &e).ok());
  loop_subdivide(coarse, e, &fine);
  std::vector<double> normals;
  edge_point_normals(fine, e, coarse.vertex_count(), &normals);
  for (size_t i = 2; i < fine.positions.size(); i += 3) EXPECT_EQ(fine.positions[i], 0.0);
  for (size_t i = 0; i < normals.size(); i += 3) {
    EXPECT_EQ(normals[i], 0.0);
    EXPECT_EQ(normals[i + 1], 0.0);
    EXPECT_GT(normals[i + 2], 0.0) << "edge " << i / 3 << (e.is_boundary(uint32_t(i / 3)) ? " (boundary)" : "");
  }
  // The boundary rules: a boundary edge point is the midpoint of its edge.
  for (uint32_t i = 0; i < e.edge_count(); ++i) {
    if (!e.is_boundary(i)) continue;
    for (int k = 0; k < 2; ++k)
      EXPECT_EQ(fine.positions[3 * (coarse.vertex_count() + i) + k],
                0.5 * (coarse.positions[3 * e.a[i] + k] + coarse.positions[3 * e.b[i] + k]));
  }
}

TEST(LoopSubdivide, InteriorMasksAsWrittenOnTheOctahedron) {
  LoopMesh coarse = loop_mesh_of(tools::make_octahedron()), fine;
  LoopEdges e;
  ASSERT_TRUE(build_loop_edges(coarse, &e).ok());
  loop_subdivide(coarse, e, &fine);
  // Vertex +z (label 4): its 4 neighbours sum to 0 in x, y and to 0 in z,
  // so it becomes (1 - 4 beta(4)) * (0, 0, 1).
  EXPECT_EQ(fine.positions[3 * 4 + 2], 1.0 - 4.0 * loop_beta(4));
  // Edge (4 0) with c = 2 and d = 3: 3/8 (z + x) + 1/8 (y - y).
  const double* p = &fine.positions[3 * coarse.vertex_count()];
  EXPECT_EQ(p[0], 0.375);
  EXPECT_EQ(p[1], 0.0);
  EXPECT_EQ(p[2], 0.375);
}

TEST(LoopLevels, OctahedronToSphereConvergesLevelByLevel) {
  for (int levels = 1; levels <= 5; ++levels) {
    const std::vector<uint8_t> file = progressive_file(tools::loop_octahedron(), levels, sphere_targets, 16);
    DecodedFile decoded;
    const Status s = decode(file.data(), file.size(), &decoded);
    ASSERT_TRUE(s.ok()) << s.to_string();
    ASSERT_EQ(decoded.levels.size(), size_t(levels) + 1);
    EXPECT_EQ(decoded.loop_level_count, levels);
    EXPECT_EQ(decoded.version_minor, 3);
    for (int j = 1; j <= levels; ++j) {
      const LoopLevel& level = decoded.levels[j];
      EXPECT_EQ(level.face_count(), 8u << (2 * j));
      // Edge points were displaced onto the sphere, up to the 7-bit step and
      // the tangential part the normal cannot carry; vertex points follow
      // the masks, and the mesh closes in on the sphere level by level.
      const double edge_error = max_radius_error(level, decoded.levels[j - 1].vertex_count());
      EXPECT_LT(edge_error, 0.01) << "level " << j;
      if (j >= 2) {
        EXPECT_LT(max_radius_error(level), max_radius_error(decoded.levels[j - 1])) << "level " << j;
      }
    }
    // The final mesh is the finest level, in binary32.
    EXPECT_EQ(decoded.mesh.vertex_count(), decoded.levels.back().vertex_count());
    EXPECT_EQ(decoded.mesh.positions[0], float(decoded.levels.back().positions[0]));
  }
}

// Edge points aim radially at the sphere of the given radius.
LevelTargets sphere_of_radius(double radius) {
  return [radius](int, const LoopMesh& fine, const std::vector<double>& normals, uint32_t coarse_vertices,
                  std::vector<double>* targets) {
    targets->resize(normals.size());
    for (size_t i = 0; i < normals.size(); i += 3) {
      const double* q = &fine.positions[3 * size_t(coarse_vertices) + i];
      const double r = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      for (int k = 0; k < 3; ++k) (*targets)[i + k] = q[k] * radius / r;
    }
  };
}

// RMS over the vertices of |radius - 1|.
double rms_off_unit_sphere(const std::vector<double>& positions) {
  double sum = 0;
  for (size_t i = 0; i < positions.size(); i += 3) {
    const double r = std::sqrt(positions[i] * positions[i] + positions[i + 1] * positions[i + 1] +
                               positions[i + 2] * positions[i + 2]);
    sum += (r - 1) * (r - 1);
  }
  return std::sqrt(sum / double(positions.size() / 3));
}

// Spec 12.10's closed loop: the encoder's targets (here a sphere of radius
// 3 around a base fitted to the unit sphere) would leave level 1 farther
// from the input (the unit sphere) than the base; the judge measures that
// and codes the level towards the alternative instead, and so every level.
TEST(LoopLevels, TheClosedLoopCodesTheAlternativeWhereTheTargetsWouldMoveALevelAway) {
  LevelJudge judge;
  judge.distance = [](const LoopMesh& level) { return rms_off_unit_sphere(level.positions); };
  judge.alternatives = {{1, sphere_of_radius(1.0)}};
  const LevelJudge* const judges[] = {nullptr, &judge};
  for (const LevelJudge* j : judges) {
    std::vector<uint8_t> file;
    ASSERT_TRUE(tools::make_loop_file(tools::loop_octahedron(), 3, sphere_of_radius(3.0), 16, &file, nullptr,
                                      PositionMethod::kDeltas, 0, false, j)
                    .ok());
    DecodedFile decoded;
    ASSERT_TRUE(decode(file.data(), file.size(), &decoded).ok());
    std::vector<double> distance;
    for (const LoopLevel& level : decoded.levels) distance.push_back(rms_off_unit_sphere(level.positions));
    if (!j) {
      EXPECT_GT(distance[1], distance[0]) << "the encoder's own targets move level 1 away";
      continue;
    }
    for (int level = 1; level <= 3; ++level) EXPECT_LT(distance[level], distance[level - 1]) << "level " << level;
    EXPECT_EQ(decoded.levels.size(), 4u);
  }
}

TEST(LoopLevels, DecoderReproducesTheEncodersClosedLoopBitForBit) {
  const Mesh torus = triangle_torus();
  std::vector<LoopLevel> encoder_side;
  // Targets: the predicted point pushed out by a pattern along the normal.
  const LevelTargets bumpy = [&](int level, const LoopMesh& fine, const std::vector<double>& normals,
                                 uint32_t coarse_vertices, std::vector<double>* targets) {
    targets->resize(normals.size());
    for (size_t e = 0; e < normals.size() / 3; ++e) {
      const double* n = &normals[3 * e];
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double push = (e % 7 == 0 ? 0.0 : 0.01 * std::sin(double(e))) / level;
      for (int k = 0; k < 3; ++k)
        (*targets)[3 * e + k] = fine.positions[3 * (coarse_vertices + e) + k] + push * n[k] / len;
    }
  };
  EncodeStats stats;
  const std::vector<uint8_t> file = progressive_file(torus, 3, bumpy, 12, &stats);
  DecodedFile decoded;
  ASSERT_TRUE(decode(file.data(), file.size(), &decoded).ok());
  ASSERT_EQ(stats.loop.levels.size(), 4u);
  for (int j = 1; j <= 3; ++j) {
    EXPECT_EQ(decoded.levels[j].zero_displacements, stats.loop.levels[j].zeros);
    EXPECT_EQ(decoded.levels[j].step, stats.loop.levels[j].step);
    EXPECT_EQ(decoded.levels[j].chunk_bytes, stats.loop.levels[j].bytes);
    EXPECT_GT(decoded.levels[j].edge_points, decoded.levels[j].zero_displacements);
  }
  // Genus 1 survives: V - E + F = 0 at every level.
  for (const LoopLevel& level : decoded.levels) {
    LoopEdges e;
    ASSERT_TRUE(build_loop_edges(level, &e).ok());
    EXPECT_EQ(int64_t(level.vertex_count()) - e.edge_count() + level.face_count(), 0);
  }
}

// Section 12.7.1: code 2 carries the same integers as code 0, so every
// level decodes to the same binary64 positions; from a few hundred edges on
// it is also shorter.
TEST(LoopLevels, DisplacementCode2GivesCode0sLevelsInFewerBytes) {
  for (const Mesh& base : {triangle_torus(), triangle_grid(), tools::loop_octahedron()}) {
    std::vector<uint8_t> files[2];
    EncodeStats stats[2];
    for (int i = 0; i < 2; ++i) {
      const Status s = tools::make_loop_file(base, 3, sphere_targets, 12, &files[i], &stats[i],
                                             PositionMethod::kDeltas, i == 0 ? 0 : 2);
      ASSERT_TRUE(s.ok()) << s.to_string();
    }
    DecodedFile code0, code2;
    ASSERT_TRUE(decode(files[0].data(), files[0].size(), &code0).ok());
    ASSERT_TRUE(decode(files[1].data(), files[1].size(), &code2).ok());
    EXPECT_EQ(code0.version_minor, 3);
    EXPECT_EQ(code2.version_minor, 5);
    ASSERT_EQ(code0.levels.size(), code2.levels.size());
    for (size_t j = 1; j < code0.levels.size(); ++j) {
      EXPECT_EQ(code0.levels[j].positions, code2.levels[j].positions) << "level " << j;
      EXPECT_EQ(stats[1].loop.levels[j].code, 2);
      if (stats[1].loop.levels[j].edge_points >= 500) {  // small levels: the range coder's start costs more
        EXPECT_LT(stats[1].loop.levels[j].bytes, stats[0].loop.levels[j].bytes) << "level " << j;
      }
    }
    EXPECT_EQ(canonical_output(code0).size(), canonical_output(code2).size());
  }
}

// Section 12.7.2: a file with code 4 at level `corrected` and its twin
// without the corrections (the same displacements, code 2).
struct CorrectedPair {
  DecodedFile plain, corrected;
  EncodeStats stats;
};
CorrectedPair corrected_pair(const Mesh& base, int levels, const LevelCorrector& corrector) {
  CorrectedPair pair;
  std::vector<uint8_t> files[2];
  EXPECT_TRUE(tools::make_loop_file(base, levels, sphere_targets, 12, &files[0], nullptr, PositionMethod::kDeltas, 2)
                  .ok());
  const Status s = tools::make_loop_file(base, levels, sphere_targets, 12, &files[1], &pair.stats,
                                         PositionMethod::kDeltas, 2, false, nullptr, &corrector);
  EXPECT_TRUE(s.ok()) << s.to_string();
  EXPECT_TRUE(decode(files[0].data(), files[0].size(), &pair.plain).ok());
  EXPECT_TRUE(decode(files[1].data(), files[1].size(), &pair.corrected).ok());
  return pair;
}

// Each listed vertex moves by its offsets times the correction step, one
// rounding per operation; every other vertex, and every level below, is
// where the file without corrections puts it.
TEST(LoopLevels, Code4MovesExactlyTheListedVerticesOfItsLevel) {
  const double step = 0x1p-14;
  const CorrectedPair pair = corrected_pair(tools::loop_octahedron(), 3, tools::sphere_corrections(3, step, {3}));
  EXPECT_EQ(pair.corrected.version_minor, 14);
  EXPECT_EQ(pair.plain.version_minor, 5);
  for (size_t j = 1; j < 3; ++j) EXPECT_EQ(pair.corrected.levels[j].positions, pair.plain.levels[j].positions);
  const LoopLevel& plain = pair.plain.levels[3];
  const LoopLevel& corrected = pair.corrected.levels[3];
  ASSERT_EQ(pair.stats.loop.levels[3].code, 4);
  EXPECT_GT(corrected.corrected_vertices, 20u);
  EXPECT_EQ(corrected.corrected_vertices, pair.stats.loop.levels[3].corrected_vertices);
  size_t moved = 0;
  for (uint32_t v = 0; v < plain.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      const double before = plain.positions[3 * v + a], after = corrected.positions[3 * v + a];
      if (v % 3 != 0) {
        EXPECT_EQ(after, before) << "vertex " << v;
        continue;
      }
      const double offset = std::nearbyint((after - before) / step);
      EXPECT_EQ(after, before + offset * step) << "vertex " << v;
      moved += after != before;
    }
  }
  EXPECT_GT(moved, 0u);
  // Radially onto the sphere, to within the step.
  for (uint32_t v = 0; v < corrected.vertex_count(); v += 3) {
    const double* p = &corrected.positions[3 * size_t(v)];
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, step) << "vertex " << v;
  }
}

// Corrections below the finest level are level j's positions: level j + 1
// subdivides the corrected level.
TEST(LoopLevels, Code4CorrectionsBelowTheFinestAreSubdividedFurther) {
  const CorrectedPair pair = corrected_pair(tools::loop_octahedron(), 2, tools::sphere_corrections(1, 0x1p-10, {1}));
  ASSERT_EQ(pair.stats.loop.levels[1].code, 4);
  EXPECT_NE(pair.corrected.levels[1].positions, pair.plain.levels[1].positions);
  LoopEdges edges;
  ASSERT_TRUE(number_loop_edges(pair.corrected.levels[1], &edges).ok());
  LoopMesh subdivided;
  loop_subdivide(pair.corrected.levels[1], edges, &subdivided);
  // Level 2 has no corrections: its vertex points are level 1's corrected
  // vertices under the masks of 12.5 step 1.
  ASSERT_EQ(pair.corrected.levels[2].corrected_vertices, 0u);
  for (uint32_t v = 0; v < pair.corrected.levels[1].vertex_count(); ++v)
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(pair.corrected.levels[2].positions[3 * v + a], subdivided.positions[3 * v + a]) << "vertex " << v;
}

// Section 12.7.2's example: a level of 10 vertices (a tetrahedron's 4 and
// its 6 edge points), corrections (3; 2, 0, -1) and (7; 0, 0, 5).
TEST(LoopLevels, Section12_7_2sExampleDecodesToItsMoves) {
  LoopMesh base;
  const Mesh tetrahedron = tools::make_tetrahedron();
  base.positions.assign(tetrahedron.positions.begin(), tetrahedron.positions.end());
  base.triangles = tetrahedron.corners;
  LoopEdges edges;
  ASSERT_TRUE(build_loop_edges(base, &edges).ok());
  ASSERT_EQ(base.vertex_count() + edges.edge_count(), 10u);
  LevelCode code;
  code.step = 0.5;
  code.m.assign(edges.edge_count(), 0);
  code.correction_step = 0.25;
  code.corrections = {{3, {2, 0, -1}}, {7, {0, 0, 5}}};
  const std::vector<uint8_t> payload = corrected_level_payload(1, edges, base.vertex_count(), code);
  LevelCode decoded;
  ASSERT_TRUE(decode_level_code(payload.data(), payload.size(), 1, edges, base.vertex_count(), &decoded).ok());
  ASSERT_EQ(decoded.corrections.size(), 2u);
  EXPECT_EQ(decoded.corrections[1].vertex, 7u);
  EXPECT_EQ(decoded.corrections[0].offset[2], -1);
  EXPECT_EQ(decoded.corrections[1].offset[2], 5);
  LoopMesh plain, fine;
  loop_subdivide(base, edges, &plain);
  ASSERT_TRUE(decode_level(payload.data(), payload.size(), 1, base, edges, &fine).ok());
  for (uint32_t v = 0; v < 10; ++v) {
    const double expected[3] = {v == 3 ? 0.5 : 0.0, 0.0, v == 3 ? -0.25 : v == 7 ? 1.25 : 0.0};
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(fine.positions[3 * v + a], plain.positions[3 * v + a] + expected[a]) << "vertex " << v;
  }
  EXPECT_EQ(fine.corrected_vertices, 2u);
}

TEST(LoopLevels, StreamingShowsEachLevelWhenItsChunkLands) {
  const std::vector<uint8_t> file = progressive_file(tools::make_octahedron(), 3, sphere_targets);
  DecodedFile whole;
  ASSERT_TRUE(decode(file.data(), file.size(), &whole).ok());
  // Chunk ends, from the decoder's own chunk list.
  std::vector<std::pair<uint64_t, int>> ends;  // offset after the chunk, level complete after it
  int level = -1;
  for (const ChunkInfo& c : whole.chunks) {
    if (c.type == kChunkPositions) level = 0;
    if (c.type == kChunkLevel) ++level;
    ends.push_back({c.offset + 12 + c.length, level});
  }
  StreamDecoder stream;
  size_t next = 0;
  for (size_t i = 0; i < file.size(); ++i) {
    ASSERT_TRUE(stream.feed(&file[i], 1).ok());
    while (next < ends.size() && ends[next].first <= i + 1) ++next;
    const int expected = next == 0 ? -1 : ends[next - 1].second;
    ASSERT_EQ(stream.complete_level(), expected) << "after byte " << i;
    if (expected >= 0) {
      EXPECT_EQ(stream.level_count(), 3);
      EXPECT_EQ(stream.file().levels[size_t(expected)].positions, whole.levels[size_t(expected)].positions);
    }
  }
  EXPECT_TRUE(stream.finish().ok());
  EXPECT_TRUE(stream.complete());
}

// --- invalid files (section 12.1) ---------------------------------------

using tools::Chunk;
using tools::find_chunk;
using tools::join_chunks;
using tools::split_chunks;

Status decode_chunks(const std::vector<Chunk>& chunks) {
  const std::vector<uint8_t> file = join_chunks(chunks);
  DecodedFile decoded;
  return decode(file.data(), file.size(), &decoded);
}

class InvalidLevels : public ::testing::Test {
 protected:
  void SetUp() override { chunks = split_chunks(progressive_file(tools::make_octahedron(), 2, sphere_targets)); }
  void expect(const std::vector<Chunk>& c, ErrorCode code, const char* words) {
    const Status s = decode_chunks(c);
    EXPECT_EQ(s.code(), code) << s.to_string();
    EXPECT_NE(s.message().find(words), std::string::npos) << s.to_string();
  }
  std::vector<Chunk> chunks;
};

TEST_F(InvalidLevels, TheUntouchedFileDecodes) { EXPECT_TRUE(decode_chunks(chunks).ok()); }

TEST_F(InvalidLevels, ALevelBeforeItsBase) {
  std::vector<Chunk> c = chunks;
  const size_t level = find_chunk(c, kChunkLevel), posn = find_chunk(c, kChunkPositions);
  std::swap(c[level], c[posn]);
  expect(c, ErrorCode::kChunkOrder, "LEVL before POSN");
}

TEST_F(InvalidLevels, LevelsOutOfOrderOrMissing) {
  std::vector<Chunk> c = chunks;
  std::swap(c[find_chunk(c, kChunkLevel)], c[find_chunk(c, kChunkLevel, 1)]);
  expect(c, ErrorCode::kBadChunkPayload, "level field 2, expected 1");
  c = chunks;
  c.erase(c.begin() + std::ptrdiff_t(find_chunk(c, kChunkLevel, 1)));
  expect(c, ErrorCode::kChunkOrder, "QEND after 1 of 2 levels");
  c = chunks;
  c.insert(c.begin() + std::ptrdiff_t(find_chunk(c, kChunkEnd)), c[find_chunk(c, kChunkLevel, 1)]);
  expect(c, ErrorCode::kChunkOrder, "beyond the 2 levels");
}

TEST_F(InvalidLevels, LoopMisplacedRepeatedOrMalformed) {
  std::vector<Chunk> c = chunks;
  const size_t loop = find_chunk(c, kChunkLoop);
  std::swap(c[loop], c[loop + 1]);  // after CONN
  expect(c, ErrorCode::kChunkOrder, "LOOP after CONN");
  c = chunks;
  c.insert(c.begin() + std::ptrdiff_t(loop), c[loop]);
  expect(c, ErrorCode::kChunkOrder, "a second LOOP");
  c = chunks;
  c.erase(c.begin() + std::ptrdiff_t(loop));
  expect(c, ErrorCode::kChunkOrder, "LEVL without LOOP");
  c = chunks;
  c[loop].payload = {9, 0};
  expect(c, ErrorCode::kBadChunkPayload, "level_count 9");
  c[loop].payload = {2, 1};
  expect(c, ErrorCode::kUnsupportedFeature, "scheme 1");
  c[loop].payload = {2};
  expect(c, ErrorCode::kBadChunkPayload, "not 2");
  c = chunks;
  c.insert(c.begin() + std::ptrdiff_t(find_chunk(c, kChunkLevel)), Chunk{kChunkOrder, {0}});
  expect(c, ErrorCode::kChunkOrder, "oRDR in a progressive file");
}

TEST_F(InvalidLevels, WrongCountsStepsAndCodes) {
  std::vector<Chunk> c = chunks;
  Chunk& level = c[find_chunk(c, kChunkLevel)];
  const std::vector<uint8_t> good = level.payload;
  level.payload[2] = uint8_t(good[2] + 1);  // edge_count (12 fits one varint byte)
  expect(c, ErrorCode::kBadChunkPayload, "edge_count 13 but level 0 has 12 edges");
  level.payload = good;
  level.payload[1] = 1;
  expect(c, ErrorCode::kUnsupportedFeature, "displacement code 1");
  for (double step : {0.0, -1.0, double(NAN), double(INFINITY)}) {
    level.payload = good;
    std::memcpy(&level.payload[3], &step, 8);
    expect(c, ErrorCode::kBadChunkPayload, "step is not a finite number greater than zero");
  }
  level.payload.assign(good.begin(), good.begin() + 11);  // no stream at all
  expect(c, ErrorCode::kLimitExceeded, "12 displacement codes cannot fit");
  level.payload = good;
  level.payload.pop_back();
  const Status s = decode_chunks(c);
  EXPECT_TRUE(s.code() == ErrorCode::kTruncated || s.code() == ErrorCode::kLimitExceeded) << s.to_string();
  level.payload = good;
  level.payload.push_back(0);
  expect(c, ErrorCode::kBadChunkPayload, "left over");
  // A 9-bit code of magnitude zero: flag 1, sign 0, 0000000 as the first code.
  level.payload = good;
  level.payload[11] = 0x80;
  level.payload[12] = 0x00;
  expect(c, ErrorCode::kBadSymbol, "magnitude 0");
}

TEST_F(InvalidLevels, BaseMeshesLevelsCannotRefine) {
  // A quad base (the cube) in a file with LOOP.
  EncodeOptions options;
  FileConnectivity conn;
  EncodeStats st;
  ASSERT_TRUE(choose_connectivity(tools::make_cube(), options, &conn, &st).ok());
  std::vector<Chunk> c = chunks;
  c[find_chunk(c, kChunkConnectivity)].payload = conn.payload;
  expect(c, ErrorCode::kBadChunkPayload, "has 4 corners, not 3");
}

}  // namespace
}  // namespace qmc
