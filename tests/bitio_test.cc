// Bit I/O, varints and CRC-32 (spec sections 2.1, 3.4, 7.1, 7.2).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "common/bit_reader.h"
#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/crc32.h"

namespace qmc {
namespace {

TEST(BitWriter, WritesMostSignificantBitFirst) {
  BitWriter w;
  w.write_bits(0b101, 3);
  w.write_bits(0b1, 1);
  w.write_bits(0xA, 4);
  w.write_bits(0b11, 2);
  EXPECT_EQ(w.bit_count(), 10u);
  const std::vector<uint8_t> bytes = w.finish();
  ASSERT_EQ(bytes.size(), 2u);
  EXPECT_EQ(bytes[0], 0b10111010);
  EXPECT_EQ(bytes[1], 0b11000000);  // zero padding (7.1)
}

TEST(BitWriter, CapacityLimitIsReportedNotExceeded) {
  BitWriter w(1);
  w.write_bits(0xFF, 8);
  EXPECT_FALSE(w.overflowed());
  w.write_bits(1, 1);
  EXPECT_TRUE(w.overflowed());
  EXPECT_EQ(w.finish().size(), 1u);
}

TEST(BitReader, RoundTripsRandomFieldWidths) {
  std::mt19937 rng(1);
  std::vector<std::pair<uint32_t, int>> fields;
  BitWriter w;
  for (int i = 0; i < 5000; ++i) {
    const int width = int(rng() % 33);
    const uint32_t value = width == 32 ? rng() : (rng() & ((1u << width) - 1));
    fields.push_back({value, width});
    w.write_bits(value, width);
  }
  const std::vector<uint8_t> bytes = w.finish();
  BitReader r(bytes.data(), bytes.size());
  for (auto [value, width] : fields) ASSERT_EQ(r.read_bits(width), value);
  EXPECT_FALSE(r.overrun());
  EXPECT_TRUE(r.at_clean_end());
}

TEST(BitReader, ReadingPastTheEndIsStickyAndReturnsZeros) {
  const uint8_t data[1] = {0xFF};
  BitReader r(data, 1);
  EXPECT_EQ(r.peek_bits(12), 0xFF0u);  // peeking past the end sees zeros, no error
  EXPECT_FALSE(r.overrun());
  EXPECT_EQ(r.read_bits(6), 0x3Fu);
  EXPECT_EQ(r.read_bits(4), 0xCu);  // two real bits, two zeros
  EXPECT_TRUE(r.overrun());
  EXPECT_EQ(r.read_bits(8), 0u);
  EXPECT_TRUE(r.overrun());
  EXPECT_EQ(r.bits_remaining(), 0u);
}

TEST(BitReader, EmptyBufferNeverDereferences) {
  BitReader r(nullptr, 0);
  EXPECT_EQ(r.peek_bits(32), 0u);
  EXPECT_EQ(r.read_bits(1), 0u);
  EXPECT_TRUE(r.overrun());
}

TEST(BitReader, CleanEndRequiresZeroPaddingAndNoExtraByte) {
  const uint8_t padded[1] = {0b10100000};
  BitReader a(padded, 1);
  a.read_bits(3);
  EXPECT_TRUE(a.at_clean_end());
  const uint8_t dirty[1] = {0b10100001};
  BitReader b(dirty, 1);
  b.read_bits(3);
  EXPECT_FALSE(b.at_clean_end());
  const uint8_t extra[2] = {0b10100000, 0};
  BitReader c(extra, 2);
  c.read_bits(3);
  EXPECT_FALSE(c.at_clean_end());
}

TEST(ExpGolomb, MatchesTheSpecExamplesAndExtremes) {
  // 0 -> "1", 1 -> "010", 2 -> "011", 3 -> "00100" (spec 7.2)
  BitWriter w;
  for (uint32_t v : {0u, 1u, 2u, 3u}) w.write_exp_golomb(v);
  const std::vector<uint8_t> bytes = w.finish();
  EXPECT_EQ(bytes[0], 0b10100110);
  EXPECT_EQ(bytes[1], 0b01000000);

  BitWriter big;
  const uint32_t values[] = {0, 7, 65535, 65536, 0x7FFFFFFF, 0xFFFFFFFE};
  for (uint32_t v : values) big.write_exp_golomb(v);
  const std::vector<uint8_t> b2 = big.finish();
  BitReader r(b2.data(), b2.size());
  for (uint32_t v : values) EXPECT_EQ(r.read_exp_golomb(), v);
  EXPECT_FALSE(r.invalid());
  EXPECT_FALSE(r.overrun());
}

TEST(ExpGolomb, RejectsTooManyLeadingZerosAndTooLargeValues) {
  std::vector<uint8_t> zeros(6, 0);  // 48 zero bits
  BitReader r(zeros.data(), zeros.size());
  r.read_exp_golomb();
  EXPECT_TRUE(r.invalid());

  // The 32nd zero is rejected at once, even if the stream ends right after it.
  const uint8_t four_zero_bytes[4] = {0, 0, 0, 0};
  BitReader r2(four_zero_bytes, 4);
  r2.read_exp_golomb();
  EXPECT_TRUE(r2.invalid());
  EXPECT_FALSE(r2.overrun());
  // 31 zeros is the longest prefix: 2^32 - 2 is the largest value.
  BitWriter w;
  w.write_bits(0, 31);
  w.write_bits(0xFFFFFFFF, 32);
  const std::vector<uint8_t> bytes = w.finish();
  BitReader r3(bytes.data(), bytes.size());
  EXPECT_EQ(r3.read_exp_golomb(), 0xFFFFFFFEu);
  EXPECT_FALSE(r3.invalid());
}

TEST(Varint, RoundTripsShortestForm) {
  for (uint64_t v : {0ull, 1ull, 127ull, 128ull, 300ull, 0xFFFFFFFFull, ~0ull}) {
    std::vector<uint8_t> bytes;
    put_varint(&bytes, v);
    ByteReader r(bytes.data(), bytes.size());
    uint64_t back = 0;
    ASSERT_TRUE(r.get_varint(&back));
    EXPECT_EQ(back, v);
    EXPECT_EQ(r.remaining(), 0u);
  }
  std::vector<uint8_t> bytes;
  put_varint(&bytes, 300);
  EXPECT_EQ(bytes, (std::vector<uint8_t>{0xAC, 0x02}));
}

TEST(Varint, RejectsMalformedEncodings) {
  uint64_t v = 0;
  const uint8_t not_shortest[] = {0x81, 0x00};
  EXPECT_FALSE(ByteReader(not_shortest, 2).get_varint(&v));
  const uint8_t unterminated[] = {0x80, 0x80};
  EXPECT_FALSE(ByteReader(unterminated, 2).get_varint(&v));
  const uint8_t too_long[11] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x81, 0x00};
  EXPECT_FALSE(ByteReader(too_long, 11).get_varint(&v));
  const uint8_t overflow[10] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x02};
  EXPECT_FALSE(ByteReader(overflow, 10).get_varint(&v));
  const uint8_t max[10] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x01};
  ASSERT_TRUE(ByteReader(max, 10).get_varint(&v));
  EXPECT_EQ(v, ~0ull);
  const uint8_t zero[] = {0x00};
  ASSERT_TRUE(ByteReader(zero, 1).get_varint(&v));
  EXPECT_EQ(v, 0u);
}

TEST(ByteReader, FixedWidthFieldsAreLittleEndianAndBounded) {
  const uint8_t data[] = {0x01, 0x02, 0x03, 0x04, 0x05};
  ByteReader r(data, sizeof data);
  uint32_t v = 0;
  ASSERT_TRUE(r.get_u32le(&v));
  EXPECT_EQ(v, 0x04030201u);
  EXPECT_FALSE(r.get_u32le(&v));
  EXPECT_EQ(r.position(), 4u);  // a failed read leaves the cursor
}

TEST(Crc32, MatchesTheCheckValue) {
  const char* text = "123456789";
  EXPECT_EQ(crc32(reinterpret_cast<const uint8_t*>(text), 9), 0xCBF43926u);
  EXPECT_EQ(crc32(nullptr, 0), 0u);
  // Incremental = one shot.
  const uint8_t* p = reinterpret_cast<const uint8_t*>(text);
  EXPECT_EQ(crc32_update(crc32(p, 4), p + 4, 5), 0xCBF43926u);
}

}  // namespace
}  // namespace qmc
