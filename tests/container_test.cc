// The container of spec sections 3 and 4: framing, CRC, order, streaming.
#include <gtest/gtest.h>

#include "common/byte_io.h"
#include "encoder/chunk_writer.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"

namespace qmc {
namespace {

std::vector<uint8_t> encoded_cube() {
  std::vector<uint8_t> out;
  EXPECT_TRUE(encode(tools::make_cube(), EncodeOptions{}, &out).ok());
  return out;
}

ErrorCode decode_code(const std::vector<uint8_t>& bytes) {
  DecodedFile f;
  return decode(bytes.data(), bytes.size(), &f).code();
}

// Offsets of the chunks of a file we wrote ourselves.
std::vector<size_t> chunk_offsets(const std::vector<uint8_t>& file) {
  std::vector<size_t> out;
  for (size_t pos = 8; pos + 12 <= file.size(); pos += 12 + load_u32le(&file[pos + 4])) out.push_back(pos);
  return out;
}

TEST(Container, FileStartsWithSignatureThenQhdr) {
  const std::vector<uint8_t> f = encoded_cube();
  ASSERT_GE(f.size(), 22u);
  EXPECT_TRUE(std::equal(kSignature, kSignature + 8, f.begin()));
  EXPECT_EQ(load_u32be(&f[8]), kChunkHeader);
  EXPECT_EQ(load_u32le(&f[12]), 2u);
  EXPECT_EQ(f[16], kFormatMajor);
  EXPECT_EQ(f[17], 7u);  // the cube's positions are predicted, method 3 (spec 14.4.1, 14.5), defined by 1.7
}

TEST(Container, ChunkListIsQhdrConnPosnQend) {
  const std::vector<uint8_t> f = encoded_cube();
  DecodedFile d;
  ASSERT_TRUE(decode(f.data(), f.size(), &d).ok());
  ASSERT_EQ(d.chunks.size(), 4u);
  EXPECT_EQ(d.chunks[0].type, kChunkHeader);
  EXPECT_EQ(d.chunks[1].type, kChunkConnectivity);
  EXPECT_EQ(d.chunks[2].type, kChunkPositions);
  EXPECT_EQ(d.chunks[3].type, kChunkEnd);
  for (const ChunkInfo& c : d.chunks) EXPECT_TRUE(c.critical);
}

TEST(Container, EveryProperPrefixIsTruncated) {
  const std::vector<uint8_t> f = encoded_cube();
  for (size_t n = 0; n < f.size(); ++n)
    EXPECT_EQ(decode_code({f.begin(), f.begin() + long(n)}), ErrorCode::kTruncated) << "prefix " << n;
}

TEST(Container, EveryFlippedBitIsRejected) {
  const std::vector<uint8_t> f = encoded_cube();
  for (size_t i = 0; i < f.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::vector<uint8_t> g = f;
      g[i] ^= uint8_t(1 << bit);
      EXPECT_NE(decode_code(g), ErrorCode::kOk) << "byte " << i << " bit " << bit;
    }
}

TEST(Container, PayloadCorruptionIsACrcError) {
  std::vector<uint8_t> f = encoded_cube();
  const size_t conn = chunk_offsets(f)[1];
  f[conn + 8] ^= 0x40;
  EXPECT_EQ(decode_code(f), ErrorCode::kBadCrc);
}

TEST(Container, UnknownAncillaryChunksAreSkippedUnknownCriticalRejected) {
  const std::vector<uint8_t> f = encoded_cube();
  const size_t conn = chunk_offsets(f)[1];
  std::vector<uint8_t> extra;
  write_chunk(&extra, chunk_type('v', 'e', 'N', 'd'), {9, 9, 9});
  std::vector<uint8_t> g = f;
  g.insert(g.begin() + long(conn), extra.begin(), extra.end());
  DecodedFile d;
  ASSERT_TRUE(decode(g.data(), g.size(), &d).ok());
  ASSERT_EQ(d.chunks.size(), 5u);
  EXPECT_FALSE(d.chunks[1].known);
  EXPECT_FALSE(d.chunks[1].critical);
  DecodedFile plain;
  ASSERT_TRUE(decode(f.data(), f.size(), &plain).ok());
  EXPECT_EQ(canonical_output(d), canonical_output(plain));

  std::vector<uint8_t> critical;
  write_chunk(&critical, chunk_type('V', 'e', 'N', 'd'), {});
  std::vector<uint8_t> h = f;
  h.insert(h.begin() + long(conn), critical.begin(), critical.end());
  EXPECT_EQ(decode_code(h), ErrorCode::kUnknownCriticalChunk);
}

TEST(Container, LengthAboveTheLimitIsRejectedBeforeThePayloadArrives) {
  std::vector<uint8_t> f = encoded_cube();
  const size_t conn = chunk_offsets(f)[1];
  f.resize(conn + 8);
  f[conn + 7] = 0x80;  // length >= 2^31
  StreamDecoder s;
  EXPECT_EQ(s.feed(f.data(), f.size()).code(), ErrorCode::kBadChunkLength);

  DecoderLimits limits;
  limits.max_chunk_length = 16;
  std::vector<uint8_t> g = encoded_cube();
  StreamDecoder limited(limits);
  EXPECT_EQ(limited.feed(g.data(), g.size()).code(), ErrorCode::kLimitExceeded);
}

TEST(Container, TextChunksAreReturned) {
  EncodeOptions o;
  o.texts = {"author=qmc tests", ""};
  std::vector<uint8_t> f;
  ASSERT_TRUE(encode(tools::make_cube(), o, &f).ok());
  DecodedFile d;
  ASSERT_TRUE(decode(f.data(), f.size(), &d).ok());
  EXPECT_EQ(d.texts, o.texts);
}

TEST(StreamDecoder, EverySplitPointGivesTheSameResult) {
  const std::vector<uint8_t> f = encoded_cube();
  DecodedFile whole;
  ASSERT_TRUE(decode(f.data(), f.size(), &whole).ok());
  const std::vector<uint8_t> expected = canonical_output(whole);
  for (size_t cut = 0; cut <= f.size(); ++cut) {
    StreamDecoder s;
    ASSERT_TRUE(s.feed(f.data(), cut).ok());
    EXPECT_FALSE(s.complete() && cut < f.size());
    ASSERT_TRUE(s.feed(f.data() + cut, f.size() - cut).ok());
    ASSERT_TRUE(s.finish().ok());
    EXPECT_EQ(canonical_output(s.file()), expected) << "cut at " << cut;
  }
}

TEST(StreamDecoder, FacesAreAvailableBeforePositionsArrive) {
  const std::vector<uint8_t> f = encoded_cube();
  const std::vector<size_t> at = chunk_offsets(f);
  StreamDecoder s;
  ASSERT_TRUE(s.feed(f.data(), at[2]).ok());  // up to the end of CONN
  EXPECT_TRUE(s.has_connectivity());
  EXPECT_FALSE(s.has_positions());
  EXPECT_EQ(s.file().mesh.face_count(), 6u);
  ASSERT_TRUE(s.feed(f.data() + at[2], f.size() - at[2]).ok());
  EXPECT_TRUE(s.has_positions());
  EXPECT_TRUE(s.complete());
}

TEST(StreamDecoder, ErrorsAreStickyAndFinishReportsTruncation) {
  const std::vector<uint8_t> f = encoded_cube();
  StreamDecoder s;
  ASSERT_TRUE(s.feed(f.data(), 20).ok());
  EXPECT_EQ(s.finish().code(), ErrorCode::kTruncated);
  EXPECT_EQ(s.feed(f.data() + 20, f.size() - 20).code(), ErrorCode::kTruncated);

  StreamDecoder t;
  const uint8_t junk[3] = {'x', 'y', 'z'};
  EXPECT_EQ(t.feed(junk, 3).code(), ErrorCode::kBadSignature);
  EXPECT_EQ(t.feed(f.data(), f.size()).code(), ErrorCode::kBadSignature);
}

TEST(StreamDecoder, DataAfterQendIsRejected) {
  std::vector<uint8_t> f = encoded_cube();
  StreamDecoder s;
  ASSERT_TRUE(s.feed(f.data(), f.size()).ok());
  EXPECT_TRUE(s.complete());
  const uint8_t more = 0;
  EXPECT_EQ(s.feed(&more, 1).code(), ErrorCode::kTrailingData);
}

}  // namespace
}  // namespace qmc
