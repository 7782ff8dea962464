// The quad coder of seed 001 (spec/qmc-format.md section 5.3): the thesis's
// worked example, every interaction type through random valid sequences,
// the section 4.1 claim and the meshes that break it, and invalid streams.
#include <gtest/gtest.h>

#include <filesystem>

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/quad_codings.h"
#include "decoder/connectivity_decoder.h"
#include "decoder/spirale_reversi_decoder.h"
#include "encoder/opposite_edge_table.h"
#include "encoder/quad_traversal_encoder.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "quad_disk_generator.h"
#include "roundtrip_check.h"
#include "corpus_dir.h"

namespace qmc {
namespace {

// Seed 001 §3.4.1, figure 3-3: the code of a mesh with one boundary.
const std::vector<uint8_t> kThesisExample = {13, 6, 6, 5, 12, 12, 6, 6, 12, 12, 9, 1, 6, 1};

Mesh with_positions(Mesh m) {
  uint32_t n = 0;
  for (uint32_t v : m.corners) n = std::max(n, v + 1);
  m.positions.assign(3 * size_t(n), 0.f);
  for (uint32_t i = 0; i < n; ++i) m.positions[3 * i] = float(i);
  return m;
}

// Spec 5.3.1: what a method-1 stream decodes to.
std::string topology_problem(const Mesh& mesh) {
  OppositeEdgeTable t;
  if (std::string why = build_opposite_edge_table(mesh, &t); !why.empty()) return why;
  if (t.components != 1) return "components: " + std::to_string(t.components);
  if (t.boundary_loops > 1) return "boundary loops: " + std::to_string(t.boundary_loops);
  if (t.euler_characteristic != 2 - int64_t(t.boundary_loops)) return "not genus 0";
  return {};
}

std::vector<uint8_t> traverse(const Mesh& mesh) {
  QuadTraversal t;
  EXPECT_EQ(encode_quad_traversal(mesh, &t), "");
  return t.types;
}

// The quad coder itself, not the smaller of it and polygon coding 7.
EncodeOptions quad_coder_options() {
  EncodeOptions options;
  options.connectivity = ConnectivityChoice::kQuad;
  return options;
}

TEST(ThesisExample, DecodesToA14QuadDiskAndReencodesToTheSameCode) {
  Mesh m;
  ASSERT_TRUE(spirale_reversi_decode(kThesisExample, false, 1000, &m).ok());
  m = with_positions(m);
  EXPECT_EQ(m.face_count(), 14u);
  EXPECT_EQ(m.vertex_count(), 23u);
  EXPECT_EQ(topology_problem(m), "");
  // Spec 5.3.7: the Q13's free vertices are 16 and 17; the boundary has 16 vertices.
  EXPECT_EQ(std::vector<uint32_t>(m.corners.begin(), m.corners.begin() + 8),
            (std::vector<uint32_t>{0, 1, 16, 17, 16, 1, 2, 3}));
  OppositeEdgeTable t;
  ASSERT_EQ(build_opposite_edge_table(m, &t), "");
  size_t boundary_edges = 0;
  for (uint32_t e : t.across) boundary_edges += e == kNoEdge;
  EXPECT_EQ(boundary_edges, 16u);
  EXPECT_EQ(traverse(m), kThesisExample);
}

TEST(ThesisExample, CodingSizesMatchTheTables) {
  // Coding I: class bit, then Q13(0) Q6(1011) Q6(1010) Q5(111) Q12(100)x2 Q6(1011,1011) Q12(100)x2
  // Q9(111110) Q1(01) Q6(1010) Q1(01): 47 bits (spec 5.3.7).
  EXPECT_EQ(quad_stream_bits(QuadCoding::kCodingI, kThesisExample), 47);
  EXPECT_EQ(quad_stream_bits(QuadCoding::kPlain4, kThesisExample), 4 * 14);
  EXPECT_GT(quad_stream_bits(QuadCoding::kCodingIII, kThesisExample), 0);
}

TEST(QuadCodings, EveryFixedTableIsAPrefixCodePerClass) {
  for (QuadCoding coding : {QuadCoding::kCodingI, QuadCoding::kCodingII, QuadCoding::kCodingIII}) {
    for (int type = 1; type <= 13; ++type)
      for (QuadClass next : {QuadClass::kA, QuadClass::kB}) {
        const QuadCodeWord w = fixed_code_word(coding, type, next);
        const bool claimed = type == 5 || type == 10 || type == 12 || type == 13;
        EXPECT_EQ(w.length == 0, claimed && next == QuadClass::kA) << int(coding) << " Q" << type;
        if (w.length == 0) continue;
        BitWriter bits;
        bits.write_bits(w.bits, w.length);
        const std::vector<uint8_t> bytes = bits.finish();
        BitReader r(bytes.data(), bytes.size());
        QuadClass back;
        EXPECT_EQ(read_fixed_code_word(coding, quad_class(type), &r, &back), type);
        EXPECT_EQ(back, next);
        EXPECT_EQ(r.position(), w.length);
      }
  }
}

TEST(RandomSequences, EveryValidSequenceDecodesAndReencodesExactly) {
  std::array<size_t, 14> seen{};
  for (uint64_t seed = 1; seed <= 3000; ++seed) {
    const uint32_t ops = uint32_t(1 + seed % 157);
    const std::vector<uint8_t> types = tools::random_quad_sequence(seed, ops);
    for (uint8_t t : types) ++seen[t];
    Mesh m;
    const Status s = spirale_reversi_decode(types, false, UINT32_MAX, &m);
    ASSERT_TRUE(s.ok()) << "seed " << seed << ": " << s.to_string();
    m = with_positions(m);
    ASSERT_EQ(topology_problem(m), "") << "seed " << seed;
    ASSERT_EQ(traverse(m), types) << "seed " << seed;
  }
  for (int t = 1; t <= 13; ++t) EXPECT_GT(seen[t], 100u) << "Q" << t;
}

TEST(RandomSequences, ClaimRespectingSequencesFitCodingsOneToThree) {
  for (uint64_t seed = 1; seed <= 500; ++seed) {
    const std::vector<uint8_t> types = tools::random_quad_sequence(seed, uint32_t(1 + seed % 211), true);
    for (QuadCoding c : {QuadCoding::kCodingI, QuadCoding::kCodingII, QuadCoding::kCodingIII})
      ASSERT_GT(quad_stream_bits(c, types), 0) << "seed " << seed;
    Mesh m;
    ASSERT_TRUE(spirale_reversi_decode(types, false, UINT32_MAX, &m).ok());
    QuadTraversal t;
    ASSERT_EQ(encode_quad_traversal(with_positions(m), &t), "");
    EXPECT_EQ(t.types, types);
    EXPECT_EQ(t.claim_violations, 0u);
  }
}

TEST(RandomSequences, RoundTripThroughTheFileWithEveryCoding) {
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    const Mesh m = tools::make_random_quad_disk(seed, uint32_t(1 + seed % 97));
    for (int coding = -1; coding < kQuadCodingCount; ++coding) {
      EncodeOptions o;
      o.connectivity = ConnectivityChoice::kQuad;
      o.quad_coding = coding;
      std::vector<uint8_t> bytes;
      EncodeStats stats;
      const Status s = encode(m, o, &bytes, &stats);
      const bool fixed = coding >= 1 && coding <= 3;
      if (!s.ok()) {
        // Only Codings I-III may refuse, and only where the seed's claim fails.
        ASSERT_TRUE(fixed) << s.to_string();
        continue;
      }
      ASSERT_EQ(stats.method, ConnectivityMethod::kQuad);
      DecodedFile d;
      ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d).ok());
      tools::Correspondence c{stats.file_vertex, stats.face_source};
      const tools::RoundTripReport r = tools::check_round_trip(m, d, c);
      ASSERT_TRUE(r.ok()) << "seed " << seed << " coding " << coding << ": " << r.face_mismatch;
      EXPECT_TRUE(tools::check_round_trip(m, d).ok());  // the spec's own correspondence
    }
  }
}

// A grid in which the middle quad is split into two that share two edges,
// leaving a vertex of valence 2 inside: the seed's §4.1 claim fails around it.
Mesh grid_with_doublet(int n) { return tools::split_quad_with_doublet(tools::make_grid(n, n), size_t(n / 2) * n + n / 2); }

TEST(SeedClaim, HoldsOnGeneratedSpheresAndGrids) {
  for (const Mesh& m : {tools::make_refined_sphere(3), tools::make_quad_sphere(12), tools::make_grid(30, 20),
                        tools::make_cube(), tools::make_grid(1, 200)}) {
    QuadTraversal t;
    ASSERT_EQ(encode_quad_traversal(m, &t), "");
    EXPECT_EQ(t.claim_violations, 0u);
  }
}

TEST(SeedClaim, ValenceTwoVerticesBreakItAndTheFileStaysCorrect) {
  uint32_t violations = 0;
  for (int n = 3; n <= 12; ++n) {
    const Mesh m = grid_with_doublet(n);
    ASSERT_EQ(topology_problem(m), "");
    QuadTraversal t;
    ASSERT_EQ(encode_quad_traversal(m, &t), "");
    violations += t.claim_violations;
    std::vector<uint8_t> bytes;
    EncodeStats stats;
    ASSERT_TRUE(encode(m, quad_coder_options(), &bytes, &stats).ok());
    EXPECT_EQ(stats.method, ConnectivityMethod::kQuad);
    if (t.claim_violations) {
      EXPECT_LT(stats.quad.coding_bits[1], 0);  // Coding I cannot express it
      EXPECT_TRUE(stats.quad.coding == 0 || stats.quad.coding == 4);
    }
    DecodedFile d;
    ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d).ok());
    EXPECT_TRUE(tools::check_round_trip(m, d).ok()) << n;
  }
  EXPECT_GT(violations, 0u);
}

TEST(QuadCoder, TinyClosedMeshesAndStrips) {
  Mesh pillow;  // two quads glued along all four edges: closed, genus 0
  pillow.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  pillow.face_sizes = {4, 4};
  pillow.corners = {0, 1, 2, 3, 3, 2, 1, 0};
  for (const Mesh& m : {pillow, tools::make_cube(), tools::make_deltoidal_hexecontahedron(), tools::make_grid(1, 1),
                        tools::make_grid(1, 300), tools::make_grid(2, 2)}) {
    std::vector<uint8_t> bytes;
    EncodeStats stats;
    ASSERT_TRUE(encode(m, quad_coder_options(), &bytes, &stats).ok());
    EXPECT_EQ(stats.method, ConnectivityMethod::kQuad) << stats.fallback_reason;
    DecodedFile d;
    ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d).ok());
    EXPECT_TRUE(tools::check_round_trip(m, d).ok());
  }
}

TEST(QuadCoder, OutOfScopeMeshesGoToThePolygonCoderWithAReason) {
  struct Case {
    Mesh mesh;
    const char* reason;
  };
  Mesh two = tools::make_cube();
  const Mesh cube = tools::make_cube();
  for (uint32_t v : cube.corners) two.corners.push_back(v + 8);
  two.face_sizes.insert(two.face_sizes.end(), cube.face_sizes.begin(), cube.face_sizes.end());
  two.positions.insert(two.positions.end(), cube.positions.begin(), cube.positions.end());
  for (const Case& c : {Case{tools::make_torus(12, 8), "genus 1"}, Case{tools::make_prism(5), "not quads"},
                        Case{two, "2 connected components"}, Case{tools::make_tetrahedron(), "not quads"}}) {
    std::vector<uint8_t> bytes;
    EncodeStats stats;
    ASSERT_TRUE(encode(c.mesh, EncodeOptions{}, &bytes, &stats).ok());
    EXPECT_EQ(stats.method, ConnectivityMethod::kPolygon);
    EXPECT_NE(stats.fallback_reason.find(c.reason), std::string::npos) << stats.fallback_reason;
    EncodeOptions strict;
    strict.connectivity = ConnectivityChoice::kQuad;
    EXPECT_EQ(encode(c.mesh, strict, &bytes).code(), ErrorCode::kInvalidArgument);
  }
}

// Method-1 CONN payloads with hand-made streams (spec 5.3.2, 5.3.6).
std::vector<uint8_t> quad_payload(uint32_t vertices, uint32_t faces, uint8_t flags, uint8_t coding,
                                  const std::vector<uint8_t>& types) {
  std::vector<uint8_t> p{1};
  put_varint(&p, vertices);
  put_varint(&p, faces);
  p.push_back(flags);
  p.push_back(coding);
  BitWriter bits;
  for (uint8_t t : types) bits.write_bits(uint32_t(t - 1), 4);
  const std::vector<uint8_t> stream = bits.finish();
  p.insert(p.end(), stream.begin(), stream.end());
  return p;
}

Status decode_payload(const std::vector<uint8_t>& p) {
  Mesh m;
  uint32_t v = 0;
  ConnectivityMethod method;
  return decode_connectivity(p.data(), p.size(), &v, &method, &m);
}

TEST(SpiraleReversi, RejectsImpossibleOperationSequences) {
  EXPECT_TRUE(decode_payload(quad_payload(100, 2, 0, 0, {6, 1})).ok());
  EXPECT_EQ(decode_payload(quad_payload(100, 2, 0, 0, {1, 5})).code(), ErrorCode::kBadSymbol);   // Q5 first: no loop
  EXPECT_EQ(decode_payload(quad_payload(100, 2, 0, 0, {3, 1})).code(), ErrorCode::kBadSymbol);   // pop from empty stack
  EXPECT_EQ(decode_payload(quad_payload(100, 3, 0, 0, {8, 1, 1})).code(), ErrorCode::kBadSymbol);  // Q8 needs two loops
  EXPECT_EQ(decode_payload(quad_payload(100, 2, 0, 0, {13, 1})).code(), ErrorCode::kBadSymbol);  // Q13 on 4 edges
  EXPECT_EQ(decode_payload(quad_payload(100, 2, 0, 0, {1, 1})).code(), ErrorCode::kBadSymbol);   // a loop left over
  EXPECT_EQ(decode_payload(quad_payload(100, 3, 1, 0, {2, 1})).code(), ErrorCode::kBadSymbol);   // closed, 6 edges left
  EXPECT_EQ(decode_payload(quad_payload(5, 2, 0, 0, {6, 1})).code(), ErrorCode::kBadSymbol);     // 6 vertices > 5
  EXPECT_EQ(decode_payload(quad_payload(100, 1, 2, 0, {1})).code(), ErrorCode::kBadChunkPayload);  // reserved flag
  EXPECT_EQ(decode_payload(quad_payload(100, 1, 0, 5, {1})).code(), ErrorCode::kUnsupportedFeature);
  EXPECT_EQ(decode_payload(quad_payload(100, 1, 1, 0, {})).code(), ErrorCode::kBadChunkPayload);  // closed, 1 face
  EXPECT_EQ(decode_payload(quad_payload(100, 0, 0, 0, {})).code(), ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> p = quad_payload(100, 1, 0, 0, {1});
  p.back() = 0xD0;  // plain value 13
  EXPECT_EQ(decode_payload(p).code(), ErrorCode::kBadSymbol);
  EXPECT_EQ(decode_payload(quad_payload(100, 40, 0, 0, {1})).code(), ErrorCode::kLimitExceeded);
  EXPECT_EQ(decode_payload(quad_payload(100, 3, 0, 0, {6, 1})).code(), ErrorCode::kTruncated);
}

TEST(SpiraleReversi, FixedCodingsRejectBadWords) {
  // Coding III, class B context: 11110 is no code word.
  std::vector<uint8_t> p = {1, 100, 1, 0, 3, 0b11111000};
  EXPECT_EQ(decode_payload(p).code(), ErrorCode::kBadSymbol);
  // Coding I: Q1 announcing a following class-A quad as the last word.
  p = {1, 100, 1, 0, 1, 0b00000000};
  EXPECT_EQ(decode_payload(p).code(), ErrorCode::kBadSymbol);
  p = {1, 100, 1, 0, 1, 0b00100000};  // class bit 0, then Q1 "01" (next B): valid
  EXPECT_TRUE(decode_payload(p).ok());
}

// The quad coder can take every closed all-quad corpus mesh; by default
// the encoder keeps it unless polygon coding 7's CONN is smaller (5.4.10),
// and says so.
TEST(QuadCorpus, EveryInScopeCorpusQuadMeshGoesThroughTheQuadCoder) {
  namespace fs = std::filesystem;
  const fs::path dir = testing::corpus_dir() / "quad";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "corpus not found at " << dir;
  size_t quad_coded = 0;
  for (const char* name : {"cube.off", "fandisk_quads.off", "horse_quad.obj"}) {
    Mesh m;
    std::vector<std::string> warnings;
    ASSERT_TRUE(tools::read_mesh((dir / name).string(), &m, &warnings).ok());
    std::vector<uint8_t> bytes;
    EncodeStats stats;
    ASSERT_TRUE(encode(m, quad_coder_options(), &bytes, &stats).ok());
    quad_coded += stats.method == ConnectivityMethod::kQuad;
    EXPECT_EQ(stats.quad.claim_violations, 0u) << name;
    const uint64_t quad_conn = stats.chunks[1].bytes;
    EncodeStats automatic;
    ASSERT_TRUE(encode(m, EncodeOptions{}, &bytes, &automatic).ok());
    if (automatic.method == ConnectivityMethod::kPolygon) {
      EXPECT_LT(automatic.chunks[1].bytes, quad_conn) << name;
      EXPECT_NE(automatic.fallback_reason.find("smaller"), std::string::npos) << name;
    } else {
      EXPECT_EQ(automatic.method, ConnectivityMethod::kQuad) << name;
    }
  }
  EXPECT_EQ(quad_coded, 3u);
}

}  // namespace
}  // namespace qmc
