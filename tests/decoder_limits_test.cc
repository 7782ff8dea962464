// Spec section 8: files whose counts no bits justify are rejected before
// memory is reserved for them, and the embedder's limits (8.1) hold for valid
// files too. The crafted files are those of issue 12 (items 1-3, 5).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/byte_io.h"
#include "chunk_list.h"
#include "polygon_payloads.h"
#include "decoder/output_budget.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc {
namespace {

using tools::Chunk;
using tools::Chunks;

std::vector<uint8_t> read_vector(const char* name) {
  std::ifstream in(std::filesystem::path(QMC_SOURCE_DIR) / "conformance/vectors" / name, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<uint8_t> varints(std::initializer_list<uint64_t> values) {
  std::vector<uint8_t> out;
  for (uint64_t v : values) put_varint(&out, v);
  return out;
}

// A one-triangle CONN of method 0 (5.2) whose vertex_count says `vertices`.
Chunk indexed_triangle_claiming(uint64_t vertices) {
  Mesh triangle;
  triangle.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  triangle.face_sizes = {3};
  triangle.corners = {0, 1, 2};
  EncodeOptions options;
  options.connectivity = ConnectivityChoice::kIndexed;
  std::vector<uint8_t> file;
  EXPECT_TRUE(encode(triangle, options, &file).ok());
  const Chunks chunks = tools::split_chunks(file);
  std::vector<uint8_t> conn = chunks[tools::find_chunk(chunks, kChunkConnectivity)].payload;
  // method (0), vertex_count 3, face_count 1: one byte each.
  EXPECT_EQ(conn[0], 0);
  EXPECT_EQ(conn[1], 3);
  std::vector<uint8_t> payload{0};
  const std::vector<uint8_t> v = varints({vertices});
  payload.insert(payload.end(), v.begin(), v.end());
  payload.insert(payload.end(), conn.begin() + 2, conn.end());
  return Chunk{kChunkConnectivity, payload};
}

// Issue 12 item 1: LOOP, then a CONN claiming `vertices` for one triangle.
std::vector<uint8_t> progressive_file_claiming(uint64_t vertices) {
  return tools::join_chunks({Chunk{kChunkHeader, {1, 3}}, Chunk{kChunkLoop, {1, 0}},
                             indexed_triangle_claiming(vertices), Chunk{kChunkEnd, {}}});
}

// Runs `decode` in a child process whose address space is capped at
// `megabytes`, and returns the child's exit code: the error code, or 100 + the
// code if decode() let an exception out or the child died.
int decode_code_within(const std::vector<uint8_t>& file, size_t megabytes, const DecoderLimits& limits) {
  const pid_t child = fork();
  if (child == 0) {
    rlimit cap{megabytes << 20, megabytes << 20};
    setrlimit(RLIMIT_AS, &cap);
    DecodedFile decoded;
    const Status s = decode(file.data(), file.size(), &decoded, limits);
    _exit(int(s.code()));
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 200;
}

TEST(DecoderLimits, ProgressiveBaseClaimingMoreVerticesThanCornersIsRejectedBeforeAllocating) {
  // 2^32 - 1, 200 M and 20 M vertices once made the decoder reserve 3 V
  // binary64 positions (up to 103 GB) before rule 12.2-4 was checked.
  for (uint64_t claimed : {uint64_t(UINT32_MAX), uint64_t(200000000), uint64_t(20000000), uint64_t(4)}) {
    const std::vector<uint8_t> file = progressive_file_claiming(claimed);
    EXPECT_LT(file.size(), 130u);
    EXPECT_EQ(decode_code_within(file, 256, DecoderLimits::unlimited()), int(ErrorCode::kBadChunkPayload))
        << claimed << " vertices";
    DecodedFile decoded;
    const Status s = decode(file.data(), file.size(), &decoded, DecoderLimits::unlimited());
    EXPECT_NE(s.message().find("rule 4"), std::string::npos) << s.to_string();
  }
}

TEST(DecoderLimits, DefaultLimitsRejectAClaimOfTwentyMillionVertices) {
  const std::vector<uint8_t> file = progressive_file_claiming(20000000);
  DecodedFile decoded;
  const Status s = decode(file.data(), file.size(), &decoded);
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded) << s.to_string();
  EXPECT_NE(s.message().find("max_vertices"), std::string::npos) << s.to_string();
}

// In a 32-bit build (WebAssembly) DecoderLimits::unlimited() must not let a
// count reach sizes a size_t cannot hold; a 64-bit build's bound is the same
// rule at 2^58.
TEST(DecoderLimits, CountsAboveWhatThisBuildCanAddressAreRejectedEvenWithoutLimits) {
  EXPECT_TRUE(check_limit("CONN: vertices", kAddressableCount, UINT64_MAX, "max_vertices").ok());
  const Status s = check_limit("CONN: vertices", kAddressableCount + 1, UINT64_MAX, "max_vertices");
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded);
  EXPECT_NE(s.message().find("this build can address"), std::string::npos) << s.to_string();
  // Over both, the caller's limit is the one named.
  const Status both = check_limit("CONN: vertices", kAddressableCount + 1, 10, "max_vertices");
  EXPECT_NE(both.message().find("max_vertices"), std::string::npos) << both.to_string();
  EXPECT_EQ(kAddressableCount, uint64_t(SIZE_MAX) / 64);
}

TEST(DecoderLimits, EveryLimitIsReportedByName) {
  const std::vector<uint8_t> file = read_vector("valid_loop_octahedron_sphere_3_levels.qmc");
  DecodedFile decoded;
  ASSERT_TRUE(decode(file.data(), file.size(), &decoded).ok());
  const LoopLevel& finest = decoded.levels.back();
  struct Case {
    const char* field;
    DecoderLimits limits;
  };
  std::vector<Case> cases(4);
  cases[0] = {"max_vertices", {}};
  cases[0].limits.max_vertices = finest.vertex_count() - 1;
  cases[1] = {"max_faces", {}};
  cases[1].limits.max_faces = finest.face_count() - 1;
  cases[2] = {"max_levels", {}};
  cases[2].limits.max_levels = 2;
  cases[3] = {"max_output_bytes", {}};
  cases[3].limits.max_output_bytes = canonical_output(decoded).size() - 1;
  for (const Case& c : cases) {
    const Status s = decode(file.data(), file.size(), &decoded, c.limits);
    EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded) << c.field;
    EXPECT_NE(s.message().find(c.field), std::string::npos) << s.to_string();
  }
  // At the limit exactly, the file decodes.
  DecoderLimits exact;
  exact.max_vertices = finest.vertex_count();
  exact.max_faces = finest.face_count();
  exact.max_levels = 3;
  exact.max_output_bytes = canonical_output(decoded).size();
  EXPECT_TRUE(decode(file.data(), file.size(), &decoded, exact).ok());
}

TEST(DecoderLimits, LevelsBeforeTheLevelLimitStayAvailableToAStreamingViewer) {
  const std::vector<uint8_t> file = read_vector("valid_loop_octahedron_sphere_3_levels.qmc");
  DecoderLimits limits;
  limits.max_levels = 2;
  StreamDecoder stream(limits);
  EXPECT_EQ(stream.feed(file.data(), file.size()).code(), ErrorCode::kLimitExceeded);
  EXPECT_EQ(stream.complete_level(), 2);
  EXPECT_EQ(stream.file().levels.size(), 3u);
}

// The edges of a level cost more than its output, so level j + 1 must fit
// before level j's edges are numbered (8.1): the refusal comes with level j
// decoded and shown, and never after the edges were built.
TEST(DecoderLimits, NextLevelIsCheckedBeforeTheEdgesItNeedsAreNumbered) {
  const std::vector<uint8_t> file = read_vector("valid_loop_octahedron_sphere_3_levels.qmc");
  DecodedFile whole;
  ASSERT_TRUE(decode(file.data(), file.size(), &whole).ok());
  DecoderLimits limits;
  limits.max_output_bytes = canonical_output(whole).size() - 1;
  StreamDecoder stream(limits);
  const Status s = stream.feed(file.data(), file.size());
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded);
  EXPECT_NE(s.message().find("level 2: the next level"), std::string::npos) << s.to_string();
  EXPECT_EQ(stream.complete_level(), 2);
}

// Issue 12 item 3: a valid image of 4096 x 4096 pixels and 16 planes outputs
// 16 * 4 bytes a pixel (13.10); the default limits refuse it at GIMG.
TEST(DecoderLimits, GeometryImageOutputIsChargedAtGimg) {
  std::vector<uint8_t> gimg = varints({4096, 4096});
  const uint8_t format_f32 = 1, face_mode = 0, mask_flag = 1, planes = 16;
  gimg.insert(gimg.end(), {format_f32, face_mode, mask_flag, planes});
  for (uint8_t i = 0; i < planes; ++i) gimg.push_back(i < 3 ? i : 8);
  const std::vector<uint8_t> file = tools::join_chunks({Chunk{kChunkHeader, {1, 4}}, Chunk{kChunkGeometryImage, gimg}});
  DecodedFile decoded;
  const Status s = decode(file.data(), file.size(), &decoded);
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded) << s.to_string();
  EXPECT_NE(s.message().find("max_output_bytes"), std::string::npos) << s.to_string();
  DecoderLimits small_images;
  small_images.max_output_bytes = kNoLimit;
  small_images.max_pixels = 1 << 20;
  EXPECT_NE(decode(file.data(), file.size(), &decoded, small_images).message().find("max_pixels"), std::string::npos);

  FileSummary summary;
  ASSERT_TRUE(peek(file.data(), file.size(), &summary).ok());
  EXPECT_TRUE(summary.has_geometry_image);
  EXPECT_EQ(summary.gim_width, 4096u);
  EXPECT_EQ(summary.gim_plane_count, 16);
  EXPECT_GT(summary.min_output_bytes, uint64_t(1) << 30);
}

// The geometry-image chunks before the first plane, for items 2's files.
Chunks unmasked_topology_image(uint64_t width, uint64_t height) {
  std::vector<uint8_t> gimg = varints({width, height});
  gimg.insert(gimg.end(), {1, 2, 0, 3, 0, 1, 2});  // binary32, GFAC triangles, no mask, X Y Z
  return {Chunk{kChunkHeader, {1, 4}}, Chunk{kChunkGeometryImage, gimg}};
}

// Issue 12 item 2: without a mask nothing has justified W H when GSEM and
// GFAC arrive (13.3); their counts are bounded by their own bytes.
TEST(DecoderLimits, UnmaskedSeamRunsAreBoundedByTheirBytes) {
  Chunks c = unmasked_topology_image(4096, 4096);
  // One run joining pixel k to pixel 2^23 + k, for k below 2^23 (legal: both
  // inside the image): 8 M pairs in 11 bytes.
  c.push_back(Chunk{kChunkGimSeams, varints({1, 0, uint64_t(1) << 23, uint64_t(1) << 23, 2, 2})});
  const std::vector<uint8_t> file = tools::join_chunks(c);
  EXPECT_LT(file.size(), 100u);
  EXPECT_EQ(decode_code_within(file, 128, DecoderLimits::unlimited()), int(ErrorCode::kLimitExceeded));
  // The same run of 4096 pairs (a row's worth) stays within the bound.
  Chunks row = unmasked_topology_image(4096, 4096);
  row.push_back(Chunk{kChunkGimSeams, varints({1, 0, 4096 * 4095, 4096, 2, 2})});
  const std::vector<uint8_t> row_file = tools::join_chunks(row);
  DecodedFile decoded;
  EXPECT_EQ(decode(row_file.data(), row_file.size(), &decoded).code(), ErrorCode::kTruncated);
}

TEST(DecoderLimits, TrianglesOverPixelsAreBoundedByTheirBytes) {
  Chunks c = unmasked_topology_image(4096, 4096);
  c.push_back(Chunk{kChunkGimSeams, varints({0})});
  std::vector<uint8_t> gfac = varints({uint64_t(1) << 25});  // 33 M triangles...
  gfac.insert(gfac.end(), 40, 0);                            // ...in 40 bytes
  c.push_back(Chunk{kChunkGimFaces, gfac});
  const std::vector<uint8_t> file = tools::join_chunks(c);
  EXPECT_LT(file.size(), 130u);
  EXPECT_EQ(decode_code_within(file, 128, DecoderLimits::unlimited()), int(ErrorCode::kLimitExceeded));
  DecodedFile decoded;
  const Status s = decode(file.data(), file.size(), &decoded, DecoderLimits::unlimited());
  EXPECT_NE(s.message().find("cannot fit"), std::string::npos) << s.to_string();
}

TEST(DecoderLimits, PeekReadsTheCountsOfAProgressiveFileWithoutDecoding) {
  const std::vector<uint8_t> file = read_vector("valid_loop_octahedron_sphere_3_levels.qmc");
  DecodedFile decoded;
  ASSERT_TRUE(decode(file.data(), file.size(), &decoded).ok());
  FileSummary summary;
  ASSERT_TRUE(peek(file.data(), file.size(), &summary).ok());
  EXPECT_EQ(summary.version_major, 1);
  EXPECT_EQ(summary.loop_level_count, 3);
  EXPECT_TRUE(summary.has_connectivity);
  EXPECT_EQ(summary.vertex_count, decoded.levels[0].vertex_count());
  EXPECT_EQ(summary.face_count, decoded.levels[0].face_count());
  EXPECT_EQ(summary.finest_face_count, decoded.levels.back().face_count());
  EXPECT_LE(summary.min_output_bytes, canonical_output(decoded).size());
  // Cut inside CONN: more bytes are needed.
  EXPECT_EQ(peek(file.data(), 30, &summary).code(), ErrorCode::kTruncated);
  EXPECT_EQ(peek(file.data(), 0, &summary).code(), ErrorCode::kTruncated);
  std::vector<uint8_t> bad = file;
  bad[0] ^= 1;
  EXPECT_EQ(peek(bad.data(), bad.size(), &summary).code(), ErrorCode::kBadSignature);
}

// A file of QHDR 1.18, a CONN of polygon coding 7 (5.4.10) and QEND: the
// face symbols `code_symbols` codes, then the Exp-Golomb fields of the
// stream (components, then the records H, S, I, L and the loose faces).
std::vector<uint8_t> coding7_file(uint8_t groups, uint32_t faces,
                                  const std::function<void(RangeEncoder*, PolygonSymbolModel*)>& code_symbols,
                                  const std::vector<uint32_t>& stream_fields) {
  const std::vector<uint8_t> conn =
      tools::coding7_conn(8, faces, groups, tools::coding7_symbols(groups, code_symbols), [&](BitWriter* b) {
        for (uint32_t v : stream_fields) b->write_exp_golomb(v);
      });
  return tools::join_chunks({Chunk{kChunkHeader, {1, 18}}, Chunk{kChunkConnectivity, conn}, Chunk{kChunkEnd, {}}});
}

// One component of two faces, a pentagon first, then one symbol 18 (the
// only group) of degree `d` whose shape `code_shape` codes.
std::vector<uint8_t> coding7_file_with_other_face(uint64_t d, const std::function<void(RangeEncoder*, PolygonSymbolModel*)>& code_shape) {
  return coding7_file(kGroupOther, 2, [&](RangeEncoder* r, PolygonSymbolModel* m) {
    uint32_t extra = uint32_t(d - 5);
    EXPECT_TRUE(code_other_degree(r, &extra));
    code_shape(r, m);
  }, {1, 0, 2, 0, 0, 0, 0});  // C = 1, n - 2, d - 3, H, S, I, L
}

// 5.4.3, 5.4.10: d - 5 may code up to 2^32 - 2, but no face has more than
// 2^32 - 1 corners (10.2 writes a degree as u32). Checked before the stream
// is asked to justify d - 2 statuses, so a few bytes show it.
TEST(DecoderLimits, AFaceOfSymbol18AboveTwoToThe32IsRefusedBeforeItsStatuses) {
  const auto nothing = [](RangeEncoder*, PolygonSymbolModel*) {};
  DecodedFile decoded;
  const std::vector<uint8_t> above = coding7_file_with_other_face(uint64_t(UINT32_MAX) + 1, nothing);
  const Status s = decode(above.data(), above.size(), &decoded, DecoderLimits::unlimited());
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded);
  EXPECT_NE(s.message().find("above 2^32 - 1"), std::string::npos) << s.to_string();
  const std::vector<uint8_t> at = coding7_file_with_other_face(UINT32_MAX, nothing);
  const Status t = decode(at.data(), at.size(), &decoded, DecoderLimits::unlimited());
  EXPECT_EQ(t.code(), ErrorCode::kLimitExceeded);
  EXPECT_NE(t.message().find("cannot fit"), std::string::npos) << t.to_string();
}

// 5.4.8: the same for a loose face, whose d - 3 may code up to 2^32 - 2.
TEST(DecoderLimits, ALooseFaceAboveTwoToThe32IsRefusedBeforeItsLabels) {
  const auto pillow = [](RangeEncoder* r, PolygonSymbolModel* m) { code_face_symbol(r, m, GateContext{}, 0); };
  DecodedFile decoded;
  for (uint32_t extra : {UINT32_MAX - 1, UINT32_MAX - 3}) {
    // The pillow (two quads), then L = 1 loose face of degree extra + 3.
    const std::vector<uint8_t> file = coding7_file(kGroupQuads, 3, pillow, {1, 0, 1, 0, 0, 0, 1, extra});
    const Status s = decode(file.data(), file.size(), &decoded, DecoderLimits::unlimited());
    EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded);
    const bool above = uint64_t(extra) + 3 > UINT32_MAX;
    EXPECT_EQ(s.message().find("above 2^32 - 1") != std::string::npos, above) << s.to_string();
    EXPECT_EQ(s.message().find("cannot fit") != std::string::npos, !above) << s.to_string();
  }
}

// 8.1: a face of symbol 18 whose statuses are all anchors and gaps all edges
// codes some 180 corners a byte; its corners beyond 3 are checked against
// what is left of max_output_bytes when its degree is read, before Spirale
// Reversi reserves some 24 bytes for each.
TEST(DecoderLimits, TheCornersOfSymbol18AreCheckedAgainstTheOutputLimitBeforeTheFaceIsBuilt) {
  const uint64_t d = 300000;
  const std::vector<uint8_t> file = coding7_file_with_other_face(d, [&](RangeEncoder* r, PolygonSymbolModel* m) {
    std::vector<uint8_t> anchors(d - 2, 1), edges(d - 1, 1);
    code_other_shape(r, m, uint32_t(d - 2), anchors.data(), edges.data());
  });
  EXPECT_LT(file.size(), 2000u);
  DecoderLimits limits;
  limits.max_output_bytes = 1 << 20;  // 262,084 corners once CONN's header is charged
  DecodedFile decoded;
  const Status s = decode(file.data(), file.size(), &decoded, limits);
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded);
  EXPECT_NE(s.message().find("DecoderLimits::max_output_bytes"), std::string::npos) << s.to_string();
  EXPECT_NE(s.message().find("degree 300000"), std::string::npos) << s.to_string();
  // With room for its corners the face gets to Spirale Reversi, which finds
  // the anchors that are not there.
  limits.max_output_bytes = 2 << 20;
  const Status t = decode(file.data(), file.size(), &decoded, limits);
  EXPECT_FALSE(t.ok());
  EXPECT_EQ(t.message().find("max_output_bytes"), std::string::npos) << t.to_string();
}

// 8.1: a table of fLBL (16.1) reserves a string (32 bytes) per count before
// the strings are read; each count is checked at 4 bytes a string against
// what is left of max_output_bytes first. A million references whose first
// length is malformed: refused by the limit, not read.
TEST(DecoderLimits, FaceLabelTablesAreCheckedAgainstTheOutputLimitBeforeTheyAreReserved) {
  Chunks c = tools::split_chunks(read_vector("valid_flbl_hand_made.qmc"));
  const size_t labels = tools::find_chunk(c, kChunkFaceLabels);
  ByteReader old(c[labels].payload.data(), c[labels].payload.size());
  uint64_t face_count = 0;
  ASSERT_TRUE(old.get_varint(&face_count));
  std::vector<uint8_t> payload = varints({face_count});
  payload.insert(payload.end(), {1, 'g'});
  const std::vector<uint8_t> count = varints({1000000});
  payload.insert(payload.end(), count.begin(), count.end());
  payload.insert(payload.end(), 1000000, 0xFF);
  c[labels].payload = payload;
  const std::vector<uint8_t> file = tools::join_chunks(c);
  DecoderLimits limits;
  limits.max_output_bytes = 1 << 20;
  DecodedFile decoded;
  const Status s = decode(file.data(), file.size(), &decoded, limits);
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded) << s.to_string();
  EXPECT_NE(s.message().find("max_output_bytes"), std::string::npos) << s.to_string();
  // Within the limit the table is read, and its first string is cut short.
  limits.max_output_bytes = 8 << 20;
  EXPECT_EQ(decode(file.data(), file.size(), &decoded, limits).code(), ErrorCode::kBadChunkPayload);
}

// Issue 12 item 5: an empty input is truncated, with no null pointer handed
// to memcmp (UBSan flags that).
TEST(DecoderLimits, EmptyInputIsTruncated) {
  DecodedFile decoded;
  EXPECT_EQ(decode(nullptr, 0, &decoded).code(), ErrorCode::kTruncated);
  StreamDecoder stream;
  EXPECT_TRUE(stream.feed(nullptr, 0).ok());
  EXPECT_EQ(stream.finish().code(), ErrorCode::kTruncated);
}

}  // namespace
}  // namespace qmc
