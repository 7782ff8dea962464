// Canonical length-limited Huffman coding (spec section 7.3).
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

#include "common/huffman.h"

namespace qmc {
namespace {

uint64_t kraft_sum(const std::vector<uint8_t>& lengths) {
  uint64_t k = 0;
  for (uint8_t l : lengths)
    if (l) k += uint64_t(1) << (kMaxHuffmanLength - l);
  return k;
}

std::vector<uint8_t> round_trip_table(const std::vector<uint8_t>& lengths, uint32_t alphabet, Status* status) {
  BitWriter w;
  write_code_lengths(&w, lengths);
  const std::vector<uint8_t> bytes = w.finish();
  BitReader r(bytes.data(), bytes.size());
  std::vector<uint8_t> back;
  *status = read_code_lengths(&r, alphabet, &back);
  return back;
}

TEST(HuffmanLengths, NoSymbolOneSymbolTwoSymbols) {
  EXPECT_EQ(huffman_code_lengths({0, 0, 0}), (std::vector<uint8_t>{0, 0, 0}));
  EXPECT_EQ(huffman_code_lengths({0, 9, 0}), (std::vector<uint8_t>{0, 1, 0}));
  EXPECT_EQ(huffman_code_lengths({5, 0, 1}), (std::vector<uint8_t>{1, 0, 1}));
}

TEST(HuffmanLengths, EqualFrequenciesGiveEqualLengths) {
  EXPECT_EQ(huffman_code_lengths(std::vector<uint64_t>(256, 7)), std::vector<uint8_t>(256, 8));
  const std::vector<uint8_t> five = huffman_code_lengths(std::vector<uint64_t>(5, 1));
  EXPECT_EQ(kraft_sum(five), 1u << 15);  // 2,2,2,3,3 in some order
}

TEST(HuffmanLengths, MatchesTextbookExample) {
  // Frequencies 45, 13, 12, 16, 9, 5 (CLRS): lengths 1, 3, 3, 3, 4, 4.
  EXPECT_EQ(huffman_code_lengths({45, 13, 12, 16, 9, 5}), (std::vector<uint8_t>{1, 3, 3, 3, 4, 4}));
}

TEST(HuffmanLengths, FibonacciFrequenciesRespectTheLimit) {
  // Unlimited Huffman would need 39 bits for 40 Fibonacci weights.
  std::vector<uint64_t> f(40);
  f[0] = f[1] = 1;
  for (size_t i = 2; i < f.size(); ++i) f[i] = f[i - 1] + f[i - 2];
  for (int limit : {6, 10, 15}) {
    const std::vector<uint8_t> l = huffman_code_lengths(f, limit);
    for (uint8_t x : l) {
      EXPECT_GE(x, 1);
      EXPECT_LE(x, limit);
    }
    EXPECT_EQ(kraft_sum(l), 1u << 15) << "limit " << limit;
  }
  // With limit 6 and 40 symbols the code is nearly flat; the most frequent symbol is shortest.
  const std::vector<uint8_t> l6 = huffman_code_lengths(f, 6);
  EXPECT_LE(l6.back(), l6.front());
}

// The cost sum f_s l_s of an unlimited Huffman code, by merging the two
// lightest weights n - 1 times: each merge adds its weight once per bit.
uint64_t unlimited_huffman_cost(const std::vector<uint64_t>& frequencies) {
  std::vector<uint64_t> w;
  for (uint64_t f : frequencies)
    if (f > 0) w.push_back(f);
  if (w.size() < 2) return w.empty() ? 0 : w[0];
  uint64_t cost = 0;
  while (w.size() > 1) {
    std::sort(w.begin(), w.end(), std::greater<uint64_t>());
    const uint64_t merged = w[w.size() - 1] + w[w.size() - 2];
    w.resize(w.size() - 2);
    w.push_back(merged);
    cost += merged;
  }
  return cost;
}

// A limit of n - 1 bits or more never binds for n symbols (huffman_code_lengths
// stops its levels there): the code is then an optimal unlimited one, whatever
// the limit, ties included.
TEST(HuffmanLengths, NoLimitBindsFromNMinusOneBits) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<uint64_t> f(2 + rng() % 14);
    const uint64_t spread = trial % 3 == 0 ? 3 : trial % 3 == 1 ? 100 : 1u << 20;
    for (uint64_t& x : f) x = rng() % spread;
    size_t used = 0;
    for (uint64_t x : f) used += x > 0;
    if (used < 2) continue;
    const std::vector<uint8_t> tight = huffman_code_lengths(f, int(used) - 1);
    EXPECT_EQ(huffman_code_lengths(f, kMaxHuffmanLength), tight) << "trial " << trial;
    uint64_t cost = 0, kraft = 0;
    for (size_t s = 0; s < f.size(); ++s) {
      cost += f[s] * tight[s];
      if (tight[s]) kraft += uint64_t(1) << (kMaxHuffmanLength - tight[s]);
    }
    EXPECT_EQ(cost, unlimited_huffman_cost(f)) << "trial " << trial;
    EXPECT_EQ(kraft, uint64_t(1) << kMaxHuffmanLength) << "trial " << trial;
  }
}

TEST(HuffmanCode, RoundTripsRandomSymbolsWithMaximumLengthCodes) {
  std::vector<uint64_t> f(20);
  f[0] = f[1] = 1;
  for (size_t i = 2; i < f.size(); ++i) f[i] = f[i - 1] + f[i - 2];
  const std::vector<uint8_t> lengths = huffman_code_lengths(f, 15);
  EXPECT_EQ(*std::max_element(lengths.begin(), lengths.end()), 15);
  HuffmanEncoder enc(lengths);
  HuffmanDecoder dec;
  ASSERT_TRUE(dec.init(lengths).ok());
  std::mt19937 rng(3);
  std::vector<uint32_t> symbols;
  BitWriter w;
  for (int i = 0; i < 20000; ++i) {
    const uint32_t s = rng() % 20;
    symbols.push_back(s);
    enc.write(&w, s);
  }
  const std::vector<uint8_t> bytes = w.finish();
  BitReader r(bytes.data(), bytes.size());
  for (uint32_t s : symbols) ASSERT_EQ(dec.decode(&r), int(s));
  EXPECT_FALSE(r.overrun());
}

TEST(HuffmanCode, CanonicalCodesFollowRfc1951Example) {
  // RFC 1951 3.2.2: lengths (3,3,3,3,3,2,4,4) give F=00, A=010 ... G=1110, H=1111.
  const std::vector<uint8_t> lengths = {3, 3, 3, 3, 3, 2, 4, 4};
  HuffmanEncoder enc(lengths);
  BitWriter w;
  enc.write(&w, 5);  // F: 00
  enc.write(&w, 0);  // A: 010
  enc.write(&w, 7);  // H: 1111
  const std::vector<uint8_t> bytes = w.finish();
  EXPECT_EQ(bytes[0], 0b00010111);
  EXPECT_EQ(bytes[1], 0b10000000);
}

TEST(HuffmanCode, SingleSymbolUsesOneBitAndRejectsTheOtherBit) {
  const std::vector<uint8_t> lengths = {0, 0, 1};
  HuffmanDecoder dec;
  ASSERT_TRUE(dec.init(lengths).ok());
  const uint8_t bits[1] = {0b01000000};
  BitReader r(bits, 1);
  EXPECT_EQ(dec.decode(&r), 2);
  EXPECT_EQ(dec.decode(&r), -1);
}

TEST(HuffmanTable, RoundTripsWithZeroRuns) {
  std::vector<uint8_t> lengths(65, 0);
  lengths[0] = 1;
  lengths[40] = 2;
  lengths[64] = 2;
  Status s;
  EXPECT_EQ(round_trip_table(lengths, 65, &s), lengths);
  EXPECT_TRUE(s.ok());
  // Trailing unused symbols are implied by a larger alphabet.
  std::vector<uint8_t> expected = lengths;
  expected.resize(70, 0);
  EXPECT_EQ(round_trip_table(lengths, 70, &s), expected);
}

TEST(HuffmanTable, RejectsSymbolsOutsideTheAlphabet) {
  std::vector<uint8_t> lengths(10, 0);
  lengths[9] = 1;
  Status s;
  round_trip_table(lengths, 9, &s);
  EXPECT_EQ(s.code(), ErrorCode::kBadHuffmanTable);
}

TEST(HuffmanTable, RejectsATruncatedTable) {
  BitWriter w;
  w.write_exp_golomb(20);
  w.write_bits(3, 4);
  const std::vector<uint8_t> bytes = w.finish();
  BitReader r(bytes.data(), bytes.size());
  std::vector<uint8_t> lengths;
  EXPECT_EQ(read_code_lengths(&r, 33, &lengths).code(), ErrorCode::kTruncated);
}

TEST(HuffmanTable, ValidityRulesOfSection732) {
  HuffmanDecoder dec;
  EXPECT_EQ(dec.init({0, 0, 0}).code(), ErrorCode::kBadHuffmanTable);        // no symbol
  EXPECT_EQ(dec.init({0, 2, 0}).code(), ErrorCode::kBadHuffmanTable);        // single, length 2
  EXPECT_EQ(dec.init({1, 1, 1}).code(), ErrorCode::kBadHuffmanTable);        // over-subscribed
  EXPECT_EQ(dec.init({1, 2, 0}).code(), ErrorCode::kBadHuffmanTable);        // incomplete
  EXPECT_EQ(dec.init({1, 2, 16}).code(), ErrorCode::kBadHuffmanTable);       // too long
  EXPECT_TRUE(dec.init({1, 2, 2}).ok());
  EXPECT_TRUE(dec.init({0, 1, 0}).ok());
}

}  // namespace
}  // namespace qmc
