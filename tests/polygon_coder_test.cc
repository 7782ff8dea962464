// The polygon coder (spec/qmc-format.md 5.4): the spec's symbol tables,
// hand-made streams read like the spec's examples, every corpus mesh, and
// thousands of random manifold and non-manifold polygon meshes, all of which
// must come back exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/polygon_symbol_coding.h"
#include "common/polygon_symbols.h"
#include "decoder/connectivity_decoder.h"
#include "decoder/polygon_spirale_reversi.h"
#include "encoder/polygon_connectivity_encoder.h"
#include "encoder/polygon_surface.h"
#include "encoder/polygon_traversal_encoder.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "random_polygon_mesh.h"
#include "roundtrip_check.h"
#include "corpus_dir.h"

namespace qmc {
namespace {

namespace fs = std::filesystem;

// Encodes with the polygon coder and checks the decoded file face by face.
::testing::AssertionResult polygon_round_trip(const Mesh& mesh, EncodeStats* stats = nullptr,
                                              ConnectivityChoice choice = ConnectivityChoice::kPolygon) {
  EncodeOptions options;
  options.connectivity = choice;
  std::vector<uint8_t> bytes;
  EncodeStats local;
  if (Status s = encode(mesh, options, &bytes, stats ? stats : &local); !s.ok())
    return ::testing::AssertionFailure() << "encode: " << s.to_string();
  DecodedFile file;
  if (Status s = decode(bytes.data(), bytes.size(), &file); !s.ok())
    return ::testing::AssertionFailure() << "decode: " << s.to_string();
  const tools::RoundTripReport r = tools::check_round_trip(mesh, file);
  if (!r.faces_equal) return ::testing::AssertionFailure() << r.face_mismatch;
  if (!r.positions_within_bound) return ::testing::AssertionFailure() << r.position_mismatch;
  return ::testing::AssertionSuccess();
}

TEST(PolygonSymbols, QuadTypesAreTheirGapShapes) {
  // 5.4.3: Q12 is "y free, x adjacent": x an anchor reached by an edge gap,
  // then one detour through y to g0; its class is B.
  uint8_t status[2], gaps[3];
  uint32_t count = 0;
  EXPECT_EQ(symbol_shape(11, status, gaps, &count), 4u);
  EXPECT_EQ(status[0], 1);
  EXPECT_EQ(status[1], 0);
  ASSERT_EQ(count, 2u);
  EXPECT_EQ(gaps[0], 1);
  EXPECT_EQ(gaps[1], 0);
  // Q1 is a whole loop: two anchors, three edge gaps, class A.
  symbol_shape(0, status, gaps, &count);
  ASSERT_EQ(count, 3u);
  EXPECT_TRUE(gaps[0] && gaps[1] && gaps[2]);
}

TEST(PolygonSymbols, EveryShapeOfDegreeThreeAndFourHasItsOwnSymbol) {
  FaceShapes shapes;
  for (int symbol = 0; symbol < 18; ++symbol) {
    uint8_t status[2], gaps[3];
    uint32_t count = 0;
    const uint32_t d = symbol_shape(symbol, status, gaps, &count);
    shapes.add(d, status, gaps, count);
    EXPECT_EQ(face_symbol(shapes, shapes.size() - 1), symbol);
  }
  const uint8_t status[3] = {0, 1, 0}, gaps[2] = {0, 0};
  shapes.add(5, status, gaps, 2);
  EXPECT_EQ(face_symbol(shapes, shapes.size() - 1), kPolygonOtherSymbol);
}

// The pillow of the conformance vectors: two quads on four vertices, the
// first cut open, the second coded as Q1 in the plain coding.
std::vector<uint8_t> pillow_payload(uint32_t vertices, uint32_t faces) {
  std::vector<uint8_t> p{uint8_t(ConnectivityMethod::kPolygon)};
  put_varint(&p, vertices);
  put_varint(&p, faces);
  p.push_back(0);
  p.push_back(0);
  BitWriter b;
  b.write_exp_golomb(1);
  b.write_exp_golomb(0);
  b.write_exp_golomb(1);
  b.write_bits(0, 4);
  for (int i = 0; i < 4; ++i) b.write_exp_golomb(0);
  const std::vector<uint8_t> raw = b.finish();
  p.insert(p.end(), raw.begin(), raw.end());
  return p;
}

// Spec 5.4.10's counted probability: P moves by 1/(n + 2) of the distance
// to the coded bit (with floor(65536 / d) in 16-bit fixed point), then by
// 1/32 from n = 30 on, and stays within 31 .. 2017.
TEST(CodingSeven, CountedProbabilityFollowsTheSpecArithmetic) {
  CountedProbability m;
  counted_adapt(&m, 0);  // d = 2: 1024 + (1024 * 32768 >> 16)
  EXPECT_EQ(m.p, 1536);
  counted_adapt(&m, 0);  // d = 3: 1536 + (512 * 21845 >> 16) = 1536 + 170
  EXPECT_EQ(m.p, 1706);
  counted_adapt(&m, 1);  // d = 4: 1706 - (1706 * 16384 >> 16) = 1706 - 426
  EXPECT_EQ(m.p, 1280);
  EXPECT_EQ(m.n, 3);
  for (int i = 0; i < 200; ++i) counted_adapt(&m, 0);
  EXPECT_EQ(m.p, 2017);
  EXPECT_EQ(m.n, 30);
  for (int i = 0; i < 400; ++i) counted_adapt(&m, 1);
  EXPECT_EQ(m.p, 31);
}

// The gate context of 5.4.10 on a closed triangle mesh: each symbol 13 (a
// vertex made inner) is far cheaper where the gate's vertex already has
// most of its fan, so coding 7 beats coding 5 by a wide margin on a regular
// torus, whose vertices all have six triangles.
TEST(CodingSeven, RegularTriangleMeshCostsFarLessThanUnderCodingFive) {
  const Mesh torus = tools::triangulated(tools::make_torus(24, 16));
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  ASSERT_TRUE(encode(torus, EncodeOptions{}, &bytes, &stats).ok());
  ASSERT_EQ(stats.method, ConnectivityMethod::kPolygon);
  EXPECT_EQ(stats.polygon.coding, kPolygonContextCoded);
  EXPECT_LT(stats.polygon.coding_bits[kPolygonContextCoded] * 4, stats.polygon.coding_bits[kPolygonMixedHuffman]);
  EXPECT_EQ(stats.polygon.coding_bits[kPolygonUnassignedCoding], -1);
}

// Spec 5.4.10's worked example of coding 8: the cube's CONN payload and the
// faces it decodes to.
TEST(CodingEight, CubeDecodesAsTheSpecExample) {
  const std::vector<uint8_t> p{0x02, 0x08, 0x06, 0x00, 0x08, 0x02, 0x02, 0x05, 0xBC, 0x45, 0x5E};
  Mesh mesh;
  uint32_t vertices = 0;
  ConnectivityMethod method;
  ASSERT_TRUE(decode_connectivity(p.data(), p.size(), &vertices, &method, &mesh).ok());
  EXPECT_EQ(vertices, 8u);
  EXPECT_EQ(mesh.face_sizes, std::vector<uint32_t>(6, 4));
  EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{1, 0, 3, 2, 0, 1, 4, 5, 4, 1, 2, 6, 6, 2, 3, 7, 7, 3, 0, 5, 7, 5, 4, 6}));
  // The same bytes under coding 7 read other symbols from the same stream.
  std::vector<uint8_t> seven = p;
  seven[4] = 0x07;
  Mesh other;
  const Status s = decode_connectivity(seven.data(), seven.size(), &vertices, &method, &other);
  EXPECT_TRUE(!s.ok() || other.corners != mesh.corners);
}

// The example's table: x = 8 a + max(b, c) of each coded face of the cube
// as Spirale Reversi applies it, and coding 7's a alone.
TEST(CodingEight, CubeContextsAreTheSpecTable) {
  EXPECT_EQ(quad_context(GateContext{2, 1, 2}, true), 18u);
  EXPECT_EQ(quad_context(GateContext{2, 1, 2}, false), 2u);
  EXPECT_EQ(quad_context(GateContext{7, 7, 3}, true), 63u);
  PolygonSurfaceModel model;
  ASSERT_EQ(build_polygon_surface(tools::make_cube(), &model), "");
  PolygonTraversal t;
  ASSERT_EQ(traverse_polygon_surface(model, &t), "");
  class Contexts : public FaceSymbolSource {
   public:
    explicit Contexts(const FaceShapes& shapes) : shapes_(shapes) {}
    Status face(const GateContext& gate, size_t f, const FaceShapes** shapes, size_t* index) override {
      x.push_back(quad_context(gate, true));
      *shapes = &shapes_;
      *index = f;
      return Status::Ok();
    }
    std::vector<uint32_t> x;

   private:
    const FaceShapes& shapes_;
  } contexts(t.shapes);
  ASSERT_TRUE(polygon_spirale_contexts(t.component_faces, t.first_degree, &contexts).ok());
  EXPECT_EQ(contexts.x, (std::vector<uint32_t>{0, 9, 17, 17, 18}));
}

// On regular quads the neighbours' counts pay: the encoder writes coding 8
// (format 1.18), and without it (--format 1.17) coding 7 in a 1.17 file.
TEST(CodingEight, RegularQuadTorusTakesCodingEight) {
  const Mesh torus = tools::make_torus(32, 20);
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  EncodeOptions options;
  options.connectivity = ConnectivityChoice::kPolygon;
  ASSERT_TRUE(encode(torus, options, &bytes, &stats).ok());
  EXPECT_EQ(stats.polygon.coding, kPolygonQuadContextCoded);
  EXPECT_LT(stats.polygon.coding_bits[kPolygonQuadContextCoded] * 5,
            stats.polygon.coding_bits[kPolygonContextCoded] * 4);  // at least a fifth smaller
  EXPECT_EQ(bytes[8 + 8 + 1], 18);                                 // QHDR's minor (4.1)
  EXPECT_TRUE(polygon_round_trip(torus));
  options.polygon_quad_contexts = false;
  ASSERT_TRUE(encode(torus, options, &bytes, &stats).ok());
  EXPECT_EQ(stats.polygon.coding, kPolygonContextCoded);
  EXPECT_EQ(stats.polygon.coding_bits[kPolygonQuadContextCoded], -1);
  EXPECT_LE(bytes[8 + 8 + 1], 17);  // what its POSN method needs (16: method 12, 14.13), 1.17 decoders read it
}

// Coding 8 differs from 7 in the quads alone: a mesh of triangles keeps
// coding 7, whose bytes 1.6 decoders read, and forcing 8 costs nothing.
TEST(CodingEight, TrianglesKeepCodingSeven) {
  const Mesh sphere = tools::triangulated(tools::make_refined_sphere(2));
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  ASSERT_TRUE(encode(sphere, EncodeOptions{}, &bytes, &stats).ok());
  EXPECT_EQ(stats.polygon.coding, kPolygonContextCoded);
  EXPECT_EQ(stats.polygon.coding_bits[kPolygonQuadContextCoded], -1);
  EncodeOptions forced;
  forced.polygon_coding = kPolygonQuadContextCoded;
  EncodeStats forced_stats;
  ASSERT_TRUE(encode(sphere, forced, &bytes, &forced_stats).ok());
  EXPECT_EQ(forced_stats.polygon.coding, kPolygonQuadContextCoded);
  EXPECT_EQ(forced_stats.polygon.coding_bits[kPolygonQuadContextCoded],
            forced_stats.polygon.coding_bits[kPolygonContextCoded]);
}

TEST(PolygonDecoder, PillowIsTwoQuadsOnFourVertices) {
  const std::vector<uint8_t> p = pillow_payload(4, 2);
  Mesh mesh;
  uint32_t vertices = 0;
  ConnectivityMethod method;
  ASSERT_TRUE(decode_connectivity(p.data(), p.size(), &vertices, &method, &mesh).ok());
  EXPECT_EQ(method, ConnectivityMethod::kPolygon);
  // First face (1, 0, 3, 2) per 5.4.5; Q1 makes the loop 0 -> 1 -> 2 -> 3
  // from the gate, the reverse of the first face's cycle.
  EXPECT_EQ(mesh.corners, (std::vector<uint32_t>{1, 0, 3, 2, 0, 1, 2, 3}));
}

TEST(PolygonDecoder, PillowRejectsAWrongFaceCount) {
  const std::vector<uint8_t> p = pillow_payload(4, 3);
  Mesh mesh;
  uint32_t vertices = 0;
  ConnectivityMethod method;
  EXPECT_EQ(decode_connectivity(p.data(), p.size(), &vertices, &method, &mesh).code(), ErrorCode::kBadSymbol);
}

// Hands out a traversal's coded faces (5.4.2) and records the gate context
// (5.4.10) each one is applied at.
class RecordedGates : public FaceSymbolSource {
 public:
  explicit RecordedGates(const PolygonTraversal& t) : shapes_(t.shapes) {}
  Status face(const GateContext& gate, size_t f, const FaceShapes** shapes, size_t* index) override {
    gates.push_back((gate.gate * 8 + gate.next) * 8 + gate.prev);
    *shapes = &shapes_;
    *index = f;
    return Status::Ok();
  }
  std::vector<uint32_t> gates;

 private:
  const FaceShapes& shapes_;
};

// The encoder's context run (coding 7) skips the labels but must meet every
// face at the gate the decoder's full run meets it at.
TEST(PolygonSpiraleReversi, ContextRunSeesTheDecodersGates) {
  for (const Mesh& mesh : {tools::triangulated(tools::make_refined_sphere(1)), tools::make_prism(9), tools::make_torus(8, 5)}) {
    PolygonSurfaceModel model;
    ASSERT_EQ(build_polygon_surface(mesh, &model), "");
    PolygonTraversal t;
    ASSERT_EQ(traverse_polygon_surface(model, &t), "");
    RecordedGates full(t), contexts(t);
    PolygonSurface surface;
    ASSERT_TRUE(polygon_spirale_reversi(t.component_faces, t.first_degree, &full, 0, &surface).ok());
    ASSERT_TRUE(polygon_spirale_contexts(t.component_faces, t.first_degree, &contexts).ok());
    EXPECT_EQ(contexts.gates, full.gates);
    EXPECT_EQ(full.gates.size(), t.shapes.size());
    EXPECT_TRUE(std::any_of(full.gates.begin(), full.gates.end(), [](uint32_t g) { return g != 0; }));
  }
}

TEST(PolygonSpiraleReversi, ContextRunRejectsAComponentThatDoesNotClose) {
  PolygonSurfaceModel model;
  ASSERT_EQ(build_polygon_surface(tools::make_refined_sphere(1), &model), "");
  PolygonTraversal t;
  ASSERT_EQ(traverse_polygon_surface(model, &t), "");
  RecordedGates source(t);
  std::vector<uint32_t> wrong_degree = t.first_degree;
  ++wrong_degree[0];
  EXPECT_EQ(polygon_spirale_contexts(t.component_faces, wrong_degree, &source).code(), ErrorCode::kBadSymbol);
}

// Section 5.4.5 for the triangle symbols, undone in the reverse of stream
// order: 14 makes a loop of 3 edges, each 13 takes one edge off it, so a
// second 13 would leave a loop of 1 (rejected); 17 needs a loop on the
// stack; any symbol but 14 needs a loop to attach to.
Status undo_triangle_symbols(const std::vector<int>& stream_order, uint32_t first_degree = 3) {
  FaceShapes shapes;
  for (const int symbol : stream_order) {
    uint8_t status[2], gaps[3];
    uint32_t gap_count = 0;
    const uint32_t degree = symbol_shape(symbol, status, gaps, &gap_count);
    shapes.add(degree, status, gaps, gap_count);
  }
  PolygonSurface surface;
  return polygon_spirale_reversi({uint32_t(stream_order.size() + 1)}, {first_degree}, shapes, &surface);
}

TEST(PolygonSpiraleReversi, TriangleSymbolsNeedTheLoopsTheyUndo) {
  const Status short_loop = undo_triangle_symbols({13, 13, 14});
  EXPECT_EQ(short_loop.code(), ErrorCode::kBadSymbol);
  EXPECT_EQ(short_loop.message(), "CONN: polygon face symbol 0 has a detour of 1 free vertices on a loop of only 2 edges");
  const Status no_stack = undo_triangle_symbols({17, 14});
  EXPECT_EQ(no_stack.message(), "CONN: polygon face symbol 0 needs 1 loops from a stack of 0");
  for (const int symbol : {13, 15, 16, 17}) {
    const Status no_loop = undo_triangle_symbols({symbol});
    EXPECT_EQ(no_loop.message(), "CONN: polygon face symbol 0 has a detour but there is no boundary to attach to")
        << "symbol " << symbol;
  }
  // One 13 is undone (a loop of 2 edges, which no first face of 3 closes);
  // 15 after 14 leaves a loop of 4 that a quad closes: two triangles and a
  // quad on four vertices.
  EXPECT_EQ(undo_triangle_symbols({13, 14}).message(),
            "CONN: component ending at face symbol 0 does not close on its first face of degree 3");
  EXPECT_TRUE(undo_triangle_symbols({15, 14}, 4).ok());
  EXPECT_TRUE(undo_triangle_symbols({16, 14}, 4).ok());
}

TEST(PolygonCoder, GeneratedShapes) {
  using namespace tools;
  EncodeStats stats;
  EXPECT_TRUE(polygon_round_trip(make_tetrahedron(), &stats));
  EXPECT_EQ(stats.polygon.handles, 0u);
  EXPECT_TRUE(polygon_round_trip(make_torus(8, 5), &stats));
  EXPECT_EQ(stats.polygon.handles, 1u);
  EXPECT_TRUE(polygon_round_trip(make_prism(9), &stats));
  EXPECT_EQ(stats.polygon.non_quad_faces, 2u);
  EXPECT_TRUE(polygon_round_trip(make_grid(5, 4), &stats));
  EXPECT_EQ(stats.polygon.holes, 1u);
  EXPECT_TRUE(polygon_round_trip(make_quad_sphere(4), &stats));
}

// 5.4.2 leaves each component's first face and its corner c0 to the
// encoder. EncodeOptions::start_faces codes the file from several: each
// decodes to the input, the decoder's vertices 0 and 1 are the c1 and c0 that
// first_labels names, the kept file is the smallest, and qmc verify's check
// (check_round_trip without a correspondence) finds the start it came from.
TEST(PolygonCoder, EveryStartRoundTrips) {
  constexpr uint32_t kStarts = 6;
  int smaller = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    RandomPolygonMeshOptions o;
    o.seed = seed * 31;
    o.components = 1 + int(seed % 3);
    o.genus = int(seed % 3);
    o.holes = int((seed / 3) % 3);
    o.target_faces = 30 + int(seed % 40);
    o.non_manifold = seed % 4 == 0;
    const Mesh mesh = make_random_polygon_mesh(o);
    PolygonSurfaceModel surface;
    ASSERT_EQ(build_polygon_surface(mesh, &surface), "") << "seed " << seed;
    for (uint32_t t = 0; t < kStarts; ++t) {
      PolygonEncoding enc;
      ASSERT_EQ(encode_polygon_connectivity(mesh, -1, true, true, true, &enc, {t}), "") << "seed " << seed;
      uint32_t vertices = 0;
      ConnectivityMethod method;
      Mesh decoded;
      ASSERT_TRUE(decode_connectivity(enc.payload.data(), enc.payload.size(), &vertices, &method, &decoded).ok());
      ASSERT_EQ(decoded.face_sizes.size(), enc.face_source.size());
      size_t k = 0;
      for (size_t f = 0; f < decoded.face_sizes.size(); ++f) {
        std::vector<uint32_t> got, want;
        for (uint32_t i = 0; i < decoded.face_sizes[f]; ++i) got.push_back(enc.file_vertex[decoded.corners[k + i]]);
        k += decoded.face_sizes[f];
        uint32_t src = enc.face_source[f], begin = 0;
        for (uint32_t g = 0; g < src; ++g) begin += mesh.face_sizes[g];
        want.assign(mesh.corners.begin() + begin, mesh.corners.begin() + begin + mesh.face_sizes[src]);
        ASSERT_TRUE(std::is_permutation(got.begin(), got.end(), want.begin(), want.end()))
            << "seed " << seed << " start " << t << " face " << f;
      }
      const std::array<uint32_t, 2> first = first_labels(surface, kStarts)[t];
      EXPECT_EQ(enc.file_vertex[0], surface.original[first[0]]) << "seed " << seed << " start " << t;
      EXPECT_EQ(enc.file_vertex[1], surface.original[first[1]]) << "seed " << seed << " start " << t;
    }
    EncodeOptions options;
    std::vector<uint8_t> usual, searched;
    ASSERT_TRUE(encode(mesh, options, &usual).ok());
    options.start_faces = kStarts;
    EncodeStats stats;
    ASSERT_TRUE(encode(mesh, options, &searched, &stats).ok());
    ASSERT_EQ(stats.method, ConnectivityMethod::kPolygon);
    EXPECT_EQ(stats.polygon.usual_start_bytes, usual.size());
    EXPECT_LE(searched.size(), usual.size());
    EXPECT_EQ(stats.polygon.start_kept == 0, searched == usual) << "seed " << seed;
    smaller += searched.size() < usual.size();
    DecodedFile file;
    ASSERT_TRUE(decode(searched.data(), searched.size(), &file).ok());
    const tools::RoundTripReport r = tools::check_round_trip(mesh, file);
    EXPECT_TRUE(r.ok()) << "seed " << seed << ": " << r.face_mismatch << r.position_mismatch;
  }
  // Most of these small meshes code smaller from some other start.
  EXPECT_GT(smaller, 30);
}

TEST(PolygonCoder, EmptyAndVertexOnlyMeshes) {
  Mesh empty;
  EXPECT_TRUE(polygon_round_trip(empty));
  Mesh points;
  points.positions = {0, 0, 0, 1, 2, 3};
  EXPECT_TRUE(polygon_round_trip(points));
}

TEST(PolygonCoder, DegenerateFacesAreKept) {
  Mesh m = tools::make_tetrahedron();
  m.face_sizes.push_back(4);  // repeats vertex 0: a loose face (5.4.8)
  m.corners.insert(m.corners.end(), {0, 1, 0, 2});
  m.face_sizes.push_back(3);  // a duplicate of face 0
  m.corners.insert(m.corners.end(), m.corners.begin(), m.corners.begin() + 3);
  m.positions.insert(m.positions.end(), {5, 5, 5});  // unreferenced
  EncodeStats stats;
  EXPECT_TRUE(polygon_round_trip(m, &stats));
  EXPECT_EQ(stats.polygon.loose_faces, 1u);
}

TEST(PolygonCoder, RandomManifoldMeshesRoundTrip) {
  int meshes = 0;
  for (uint64_t seed = 1; seed <= 1500; ++seed) {
    RandomPolygonMeshOptions o;
    o.seed = seed;
    o.components = 1 + int(seed % 3);
    o.genus = int(seed % 4);
    o.holes = int((seed / 4) % 4);
    o.min_degree = 3;
    o.max_degree = 3 + int(seed % 6);
    o.target_faces = 20 + int(seed % 60);
    o.valence_two = seed % 2 == 0;
    o.isolated_vertices = int(seed % 3);
    RandomPolygonMeshInfo info;
    const Mesh mesh = make_random_polygon_mesh(o, &info);
    EncodeStats stats;
    ASSERT_TRUE(polygon_round_trip(mesh, &stats)) << "seed " << seed;
    ASSERT_EQ(stats.polygon.handles, uint32_t(info.genus_per_component * info.components)) << "seed " << seed;
    ASSERT_EQ(stats.polygon.holes, uint32_t(info.boundary_loops)) << "seed " << seed;
    ASSERT_EQ(stats.polygon.identifications, 0u) << "seed " << seed;
    ++meshes;
  }
  EXPECT_EQ(meshes, 1500);
}

TEST(PolygonCoder, RandomNonManifoldMeshesRoundTrip) {
  for (uint64_t seed = 1; seed <= 1500; ++seed) {
    RandomPolygonMeshOptions o;
    o.seed = seed * 7919;
    o.components = 1 + int(seed % 3);
    o.genus = int(seed % 3);
    o.holes = int(seed % 3);
    o.target_faces = 20 + int(seed % 50);
    o.non_manifold = true;
    RandomPolygonMeshInfo info;
    const Mesh mesh = make_random_polygon_mesh(o, &info);
    ASSERT_GT(info.non_manifold_defects, 0);
    ASSERT_TRUE(polygon_round_trip(mesh)) << "seed " << seed;
    // The default choice takes them too, never the indexed fallback.
    EncodeStats stats;
    ASSERT_TRUE(polygon_round_trip(mesh, &stats, ConnectivityChoice::kAuto)) << "seed " << seed;
    ASSERT_NE(stats.method, ConnectivityMethod::kIndexed) << stats.polygon_fallback_reason;
  }
}

TEST(PolygonCoder, EveryCorpusMeshGoesThroughAStructuredCoder) {
  const fs::path root = testing::corpus_dir();
  if (!fs::is_directory(root)) GTEST_SKIP() << "corpus not found at " << root;
  int seen = 0;
  for (const char* sub : {"quad", "tri"})
    for (const auto& entry : fs::directory_iterator(root / sub)) {
      Mesh mesh;
      std::vector<std::string> warnings;
      ASSERT_TRUE(tools::read_mesh(entry.path().string(), &mesh, &warnings).ok()) << entry.path();
      EncodeStats stats;
      ASSERT_TRUE(polygon_round_trip(mesh, &stats, ConnectivityChoice::kAuto)) << entry.path();
      EXPECT_NE(stats.method, ConnectivityMethod::kIndexed) << entry.path() << ": " << stats.fallback_reason;
      ++seen;
    }
  EXPECT_GE(seen, 21);
}

}  // namespace
}  // namespace qmc
