// The fuzz targets' structure-aware mutator (fuzz/chunk_mutator.h): it must
// frame chunks exactly as spec 3.2 and 3.4 do, find the header fields where
// the spec puts them, and produce files that get past `bad_crc`.
#include "chunk_mutator.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "qmc/decoder.h"
#include "qmc/format.h"

namespace qmc::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> read_vector(const std::string& name) {
  std::ifstream in(fs::path(QMC_SOURCE_DIR) / "conformance/vectors" / name, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

ErrorCode decode_error(const std::vector<uint8_t>& bytes) {
  DecodedFile file;
  return decode(bytes.data(), bytes.size(), &file).code();
}

Chunk* find(FramedInput* input, uint32_t type) {
  for (Chunk& c : input->chunks)
    if (c.type == type) return &c;
  return nullptr;
}

// A byte mutator standing in for LLVMFuzzerMutate: flips one byte.
size_t flip_one_byte(uint8_t* data, size_t size, size_t) {
  if (size > 0) data[size / 2] ^= 0x5A;
  return size;
}

// True when the bytes are the signature and chunks only, each with the
// length and CRC that frame_chunks would write.
bool framed_exactly(const std::vector<uint8_t>& bytes, size_t prefix_size) {
  const FramedInput input = split_chunks(bytes.data(), bytes.size(), prefix_size);
  return input.tail.empty() && frame_chunks(input) == bytes;
}

// One mutation of the vector per seed 0 .. count - 1, with 16 bytes to grow.
std::vector<std::vector<uint8_t>> mutants(const std::string& vector_name, unsigned count) {
  const std::vector<uint8_t> file = read_vector(vector_name);
  ChunkMutator mutator(0, flip_one_byte);
  std::vector<std::vector<uint8_t>> out;
  for (unsigned seed = 0; seed < count; ++seed) {
    std::vector<uint8_t> data(file);
    data.resize(data.size() + 16);
    data.resize(mutator.mutate(data.data(), file.size(), data.size(), seed));
    out.push_back(std::move(data));
  }
  return out;
}

TEST(ChunkMutator, SplitAndFrameGiveBackEveryValidVector) {
  size_t checked = 0;
  for (const auto& e : fs::directory_iterator(fs::path(QMC_SOURCE_DIR) / "conformance/vectors")) {
    const std::string name = e.path().filename().string();
    if (name.rfind("valid_", 0) != 0) continue;
    const std::vector<uint8_t> bytes = read_vector(name);
    EXPECT_EQ(frame_chunks(split_chunks(bytes.data(), bytes.size(), 0)), bytes) << name;
    ++checked;
  }
  EXPECT_GT(checked, 40u);
}

TEST(ChunkMutator, PrefixAndUnframedTailAreKeptAsTheyAre) {
  std::vector<uint8_t> bytes{0x07};  // stream_decoder's piece-size byte
  const std::vector<uint8_t> file = read_vector("valid_tetrahedron.qmc");
  bytes.insert(bytes.end(), file.begin(), file.end() - 3);  // QEND's CRC cut short
  const FramedInput input = split_chunks(bytes.data(), bytes.size(), 1);
  EXPECT_EQ(input.prefix, std::vector<uint8_t>{0x07});
  EXPECT_EQ(input.signature, std::vector<uint8_t>(kSignature, kSignature + 8));
  ASSERT_EQ(input.chunks.size(), 3u);  // QHDR CONN POSN
  EXPECT_EQ(input.chunks[2].type, kChunkPositions);
  EXPECT_EQ(input.tail.size(), 9u);  // QEND's type, length and one CRC byte
  EXPECT_EQ(frame_chunks(input), bytes);
}

TEST(ChunkMutator, RepairedCrcsLetAPayloadMutationReachThePayloadRules) {
  std::vector<uint8_t> bytes = read_vector("valid_tetrahedron.qmc");
  const std::vector<uint8_t> original = bytes;
  repair_crcs(bytes.data(), bytes.size(), 0);
  EXPECT_EQ(bytes, original);  // a valid file's CRCs are already right
  FramedInput input = split_chunks(bytes.data(), bytes.size(), 0);
  // POSN's bits field (spec 6.3) set to 0 in place, as a byte mutation would.
  const size_t bits_at = 8 + 12 + 2 + 12 + find(&input, kChunkConnectivity)->payload.size() + 8 + 1;
  ASSERT_EQ(bytes[bits_at], find(&input, kChunkPositions)->payload[1]);
  bytes[bits_at] = 0;
  EXPECT_EQ(decode_error(bytes), ErrorCode::kBadCrc);
  repair_crcs(bytes.data(), bytes.size(), 0);
  EXPECT_EQ(decode_error(bytes), ErrorCode::kBadChunkPayload);
}

TEST(ChunkMutator, ConnHeaderIsMethodVertexCountFaceCount) {
  const std::vector<uint8_t> bytes = read_vector("valid_tetrahedron.qmc");
  FramedInput input = split_chunks(bytes.data(), bytes.size(), 0);
  Chunk* conn = find(&input, kChunkConnectivity);
  ASSERT_NE(conn, nullptr);
  const std::vector<HeaderField> fields = header_fields(*conn);
  ASSERT_GE(fields.size(), 3u);
  EXPECT_EQ(fields[0].kind, FieldKind::kU8);
  EXPECT_EQ(fields[0].value, 0u);  // method 0
  EXPECT_EQ(fields[1].kind, FieldKind::kVarint);
  EXPECT_EQ(fields[1].offset, 1u);
  EXPECT_EQ(fields[1].value, 4u);  // V
  EXPECT_EQ(fields[2].value, 4u);  // F

  // Issue #12 item 1's rewrite: V = 2^32 - 1 takes five varint bytes.
  const size_t length = conn->payload.size();
  set_header_field(conn, fields[1], 0xFFFFFFFFu);
  EXPECT_EQ(conn->payload.size(), length + 4);
  EXPECT_EQ(std::vector<uint8_t>(conn->payload.begin() + 1, conn->payload.begin() + 6),
            (std::vector<uint8_t>{0xFF, 0xFF, 0xFF, 0xFF, 0x0F}));
  EXPECT_EQ(header_fields(*conn)[2].value, 4u);  // F unchanged after the longer V
  const std::vector<uint8_t> mutated = frame_chunks(input);
  EXPECT_NE(decode_error(mutated), ErrorCode::kBadCrc);
  EXPECT_NE(decode_error(mutated), ErrorCode::kOk);
}

TEST(ChunkMutator, GimgHeaderFollowsSpec13_2) {
  const std::vector<uint8_t> bytes = read_vector("valid_gim_one_pixel.qmc");
  FramedInput input = split_chunks(bytes.data(), bytes.size(), 0);
  const Chunk* gimg = find(&input, kChunkGeometryImage);
  ASSERT_NE(gimg, nullptr);
  const std::vector<HeaderField> fields = header_fields(*gimg);
  ASSERT_EQ(fields.size(), 9u);  // W H format face_mode flags P, plane 0's kind offset step
  EXPECT_EQ(fields[0].value, 1u);  // W
  EXPECT_EQ(fields[1].value, 1u);  // H
  EXPECT_EQ(fields[2].value, 0u);  // format 0: unorm16
  EXPECT_EQ(fields[5].value, 3u);  // P
  EXPECT_EQ(fields[8].kind, FieldKind::kF64);
  EXPECT_EQ(fields[8].offset, 6u + 1 + 8);
}

TEST(ChunkMutator, GsemFieldsAreRunCountThenFiveVarintsPerRun) {
  const std::vector<uint8_t> bytes = read_vector("valid_gim_u16_seams_collapse_quads.qmc");
  FramedInput input = split_chunks(bytes.data(), bytes.size(), 0);
  const std::vector<HeaderField> fields = header_fields(*find(&input, kChunkGimSeams));
  ASSERT_EQ(fields.size(), 6u);  // payload 01 00 01 02 08 0E: one run
  EXPECT_EQ(fields[0].value, 1u);  // R
  EXPECT_EQ(fields[3].value, 2u);  // count
  EXPECT_EQ(fields[5].value, 14u);  // zigzag step_b
}

TEST(ChunkMutator, MutationsFitMaxSizeAndMostKeepValidFraming) {
  const std::vector<uint8_t> file = read_vector("valid_gim_u16_mask.qmc");
  ChunkMutator mutator(0, flip_one_byte);
  size_t framed = 0, changed = 0, past_crc = 0;
  constexpr unsigned kSeeds = 2000;
  for (unsigned seed = 0; seed < kSeeds; ++seed) {
    const size_t max_size = file.size() + seed % 64;
    std::vector<uint8_t> data(file);
    data.resize(max_size);
    const size_t size = mutator.mutate(data.data(), file.size(), max_size, seed);
    ASSERT_LE(size, max_size) << "seed " << seed;
    data.resize(size);
    framed += framed_exactly(data, 0);
    changed += data != file;
    past_crc += decode_error(data) != ErrorCode::kBadCrc;
  }
  EXPECT_GT(changed, kSeeds * 9 / 10);
  EXPECT_GT(framed, kSeeds * 3 / 4);
  EXPECT_GT(past_crc, kSeeds * 3 / 4);
}

TEST(ChunkMutator, ReachesIssue12Item1VertexCountFromATetrahedron) {
  size_t huge_vertex_counts = 0;
  for (std::vector<uint8_t>& mutant : mutants("valid_tetrahedron.qmc", 5000)) {
    FramedInput input = split_chunks(mutant.data(), mutant.size(), 0);
    const Chunk* conn = find(&input, kChunkConnectivity);
    if (conn == nullptr) continue;
    const std::vector<HeaderField> fields = header_fields(*conn);
    huge_vertex_counts += fields.size() > 1 && fields[1].value >= 20'000'000 && framed_exactly(mutant, 0);
  }
  EXPECT_GT(huge_vertex_counts, 5u);
}

TEST(ChunkMutator, ReachesIssue12Item2ImageSizesThatGimgAccepts) {
  size_t large_images = 0;
  for (std::vector<uint8_t>& mutant : mutants("valid_gim_u16_torus_quads.qmc", 5000)) {  // 9 x 9, no mask
    FramedInput input = split_chunks(mutant.data(), mutant.size(), 0);
    const Chunk* gimg = find(&input, kChunkGeometryImage);
    if (gimg == nullptr) continue;
    const std::vector<HeaderField> fields = header_fields(*gimg);
    if (fields.size() < 2) continue;
    const uint64_t pixels = fields[0].value * fields[1].value;
    large_images += pixels >= (1u << 23) && pixels <= (1u << 24) && fields[0].value <= 65535 &&
                    fields[1].value <= 65535 && framed_exactly(mutant, 0);
  }
  EXPECT_GT(large_images, 5u);
}

TEST(ChunkMutator, CrossOverCombinesChunksOfBothInputs) {
  const std::vector<uint8_t> a = read_vector("valid_tetrahedron.qmc");
  const std::vector<uint8_t> b = read_vector("valid_loop_octahedron_sphere_1_levels.qmc");
  ChunkMutator mutator(0, flip_one_byte);
  size_t with_loop = 0;
  for (unsigned seed = 0; seed < 200; ++seed) {
    std::vector<uint8_t> out(a.size() + b.size());
    out.resize(mutator.cross_over(a.data(), a.size(), b.data(), b.size(), out.data(), out.size(), seed));
    ASSERT_FALSE(out.empty());
    EXPECT_TRUE(framed_exactly(out, 0)) << "seed " << seed;
    FramedInput input = split_chunks(out.data(), out.size(), 0);
    with_loop += find(&input, kChunkLoop) != nullptr;
  }
  EXPECT_GT(with_loop, 10u);
  std::vector<uint8_t> small(8);
  EXPECT_EQ(mutator.cross_over(a.data(), a.size(), b.data(), b.size(), small.data(), small.size(), 1), 0u);
}

}  // namespace
}  // namespace qmc::fuzz
