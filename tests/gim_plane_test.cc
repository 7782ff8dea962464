// Lossless plane and mask coding of geometry images (spec 13.5, 13.6):
// the range coder, round trips of every predictor and sample format, the
// blank-pixel rule, rejection of damaged payloads, and known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "common/plane_prediction.h"
#include "common/range_coder.h"
#include "decoder/plane_decoder.h"
#include "encoder/plane_encoder.h"

namespace qmc {
namespace {

std::vector<uint32_t> random_samples(size_t n, uint32_t mask, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<uint32_t> s(n);
  for (uint32_t& v : s) v = rng() & mask;
  return s;
}

// A quantized sphere coordinate sampled on a latitude-longitude grid.
std::vector<uint32_t> sphere_plane(uint32_t w, uint32_t h, int axis) {
  std::vector<uint32_t> s(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const double th = M_PI * y / (h - 1), ph = 2 * M_PI * x / (w - 1);
      const double p[3] = {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      s[size_t(y) * w + x] = uint32_t(std::lround((p[axis] + 1) / 2 * 65535));
    }
  return s;
}

uint32_t float_bits(float f) {
  uint32_t b;
  std::memcpy(&b, &f, 4);
  return b;
}

PlaneLayout layout(uint32_t w, uint32_t h, GimSampleFormat f = GimSampleFormat::kUnorm16) {
  PlaneLayout l;
  l.width = w;
  l.height = h;
  l.format = f;
  return l;
}

// Every predictor and the encoder's choice decode back to the input.
void expect_round_trip(const std::vector<uint32_t>& samples, const PlaneLayout& l) {
  for (int p = 0; p < kPlanePredictorCount; ++p) {
    const std::vector<uint8_t> bytes = encode_plane_with(samples, l, p);
    std::vector<uint32_t> back;
    const Status s = decode_plane(bytes.data(), bytes.size(), l, &back);
    ASSERT_TRUE(s.ok()) << "predictor " << p << ": " << s.to_string();
    ASSERT_EQ(back, samples) << "predictor " << p << " " << l.width << "x" << l.height;
  }
  PlaneEncodeStats stats;
  const std::vector<uint8_t> best = encode_plane(samples, l, &stats);
  EXPECT_EQ(stats.bytes, best.size());
  ASSERT_EQ(stats.bytes_per_predictor.size(), size_t(kPlanePredictorCount));
  for (size_t b : stats.bytes_per_predictor) EXPECT_LE(best.size(), b);
}

TEST(GimRangeCoder, RoundTripOfSkewedBitsNearEntropy) {
  std::mt19937 rng(7);
  for (double p1 : {0.5, 0.2, 0.03, 0.001}) {
    const int n = 200000;
    std::vector<int> bits(n);
    std::bernoulli_distribution d(p1);
    for (int& b : bits) b = d(rng);
    RangeEncoder enc;
    uint16_t probs[3] = {1024, 1024, 1024};
    for (int i = 0; i < n; ++i) {
      enc.code(bits[i], &probs[i % 2]);
      if (i % 97 == 0) enc.code_direct(i & 1);
    }
    const std::vector<uint8_t> bytes = enc.finish();
    RangeDecoder dec(bytes.data(), bytes.size());
    uint16_t dprobs[3] = {1024, 1024, 1024};
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(dec.code(0, &dprobs[i % 2]), bits[i]) << "bit " << i << " p1 " << p1;
      if (i % 97 == 0) {
        ASSERT_EQ(dec.code_direct(0), i & 1);
      }
    }
    EXPECT_FALSE(dec.overrun());
    EXPECT_FALSE(dec.bad_start());
    EXPECT_EQ(dec.unread(), 0u);
    EXPECT_LE(dec.invented(), kRangeMaxInventedBytes);
    const double entropy = p1 <= 0 ? 0 : -n * (p1 * std::log2(p1) + (1 - p1) * std::log2(1 - p1));
    // Adaptation costs a little over the entropy, bounded by the 11-bit floor.
    EXPECT_LE(bytes.size() * 8.0, entropy * 1.06 + n * 0.025 + n / 97 + 64) << "p1 " << p1;
  }
}

TEST(GimRangeCoder, CarriesThroughRunsOfFF) {
  // Bits of probability near 1 for the coded value drive low to runs of 0xFF
  // bytes that a later carry must ripple through.
  std::mt19937 rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    RangeEncoder enc;
    std::vector<int> bits;
    uint16_t p = 1024;
    const int n = 50 + int(rng() % 3000);
    for (int i = 0; i < n; ++i) bits.push_back(rng() % 50 != 0);
    for (int b : bits) enc.code(b, &p);
    const std::vector<uint8_t> bytes = enc.finish();
    RangeDecoder dec(bytes.data(), bytes.size());
    uint16_t q = 1024;
    for (int i = 0; i < n; ++i) ASSERT_EQ(dec.code(0, &q), bits[i]) << "trial " << trial << " bit " << i;
    EXPECT_FALSE(dec.overrun());
    EXPECT_EQ(dec.unread(), 0u);
  }
}

TEST(GimRangeCoder, EmptyStreamHasNoBytes) {
  RangeEncoder enc;
  EXPECT_TRUE(enc.finish().empty());
  RangeDecoder dec(nullptr, 0);
  EXPECT_FALSE(dec.overrun());
  EXPECT_EQ(dec.invented(), 4u);
  EXPECT_EQ(dec.unread(), 0u);
}

// 13.5.2: an empty stream is zero bytes. Bytes given to a stream in which
// nothing is decoded are unread, i.e. trailing data (bad_chunk_payload),
// even though the decoder's initial 4 bytes would have covered them.
TEST(GimRangeCoder, EmptyStreamWithBytesLeavesThemUnread) {
  const uint8_t four_zeros[4] = {0, 0, 0, 0};
  for (size_t size = 1; size <= 4; ++size) {
    RangeDecoder dec(four_zeros, size);
    EXPECT_FALSE(dec.bad_start());
    EXPECT_FALSE(dec.overrun());
    EXPECT_EQ(dec.unread(), size) << size << " bytes";
  }
  RangeDecoder one_decision(four_zeros, 4);
  uint16_t p = 1024;
  EXPECT_EQ(one_decision.code(0, &p), 0);
  EXPECT_EQ(one_decision.unread(), 0u) << "once a decision is decoded the 4 bytes are read";
}

TEST(GimPlane, RoundTripShapesAndContents) {
  for (auto [w, h] : {std::pair<uint32_t, uint32_t>{1, 1}, {1, 37}, {41, 1}, {2, 2}, {7, 5}, {33, 19}}) {
    const size_t n = size_t(w) * h;
    expect_round_trip(random_samples(n, 0xFFFF, w * 100 + h), layout(w, h));
    expect_round_trip(std::vector<uint32_t>(n, 12345), layout(w, h));
    std::vector<uint32_t> extremes(n);
    for (size_t i = 0; i < n; ++i) extremes[i] = (i * 7 + i / w) % 3 == 0 ? 0 : 0xFFFF;
    expect_round_trip(extremes, layout(w, h));
    expect_round_trip(random_samples(n, 0xFFFFFFFF, uint32_t(n)), layout(w, h, GimSampleFormat::kFloat32));
    std::vector<uint32_t> float_extremes(n);
    for (size_t i = 0; i < n; ++i) float_extremes[i] = (i % 2) ? 0xFFFFFFFFu : 0u;
    expect_round_trip(float_extremes, layout(w, h, GimSampleFormat::kFloat32));
  }
  for (int axis = 0; axis < 3; ++axis) expect_round_trip(sphere_plane(40, 30, axis), layout(40, 30));
}

TEST(GimPlane, FloatBitPatternsSurviveExactly) {
  const uint32_t specials[] = {
      0x00000000u, 0x80000000u,                     // +0, -0
      0x7F800000u, 0xFF800000u,                     // +inf, -inf
      0x7FC00000u, 0xFFC00000u, 0x7F800001u,        // quiet NaNs, a signalling NaN
      0x7FBFFFFFu, 0xFFFFFFFFu, 0x7FFFFFFFu,        // NaN payloads
      0x00000001u, 0x807FFFFFu, 0x00400000u,        // denormals
      0x7F7FFFFFu, 0xFF7FFFFFu, 0x3F800000u,        // +-max, 1
  };
  std::vector<uint32_t> s;
  for (int rep = 0; rep < 4; ++rep)
    for (uint32_t b : specials) s.push_back(b);
  for (int i = 0; i < 36; ++i) s.push_back(float_bits(std::sin(0.1f * i) * 1e-3f));
  expect_round_trip(s, layout(10, 10, GimSampleFormat::kFloat32));
  // The ordered mapping is a bijection that keeps the order of numbers.
  for (uint32_t b : specials) EXPECT_EQ(ordered_to_float_bits(float_bits_to_ordered(b)), b);
  EXPECT_LT(float_bits_to_ordered(float_bits(-1.0f)), float_bits_to_ordered(0x80000000u));
  EXPECT_LT(float_bits_to_ordered(0x80000000u), float_bits_to_ordered(0u));
  EXPECT_LT(float_bits_to_ordered(0u), float_bits_to_ordered(1u));
  EXPECT_LT(float_bits_to_ordered(float_bits(2.0f)), float_bits_to_ordered(0x7F800000u));
}

std::vector<uint8_t> blob_mask(uint32_t w, uint32_t h) {
  std::vector<uint8_t> m(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const double dx = x - w * 0.4, dy = y - h * 0.6;
      m[size_t(y) * w + x] = dx * dx + dy * dy < 0.2 * w * h;
    }
  return m;
}

TEST(GimPlane, BlankPixelsAreTheirPredictions) {
  for (auto format : {GimSampleFormat::kUnorm16, GimSampleFormat::kFloat32}) {
    const uint32_t w = 23, h = 17;
    const std::vector<uint8_t> mask = blob_mask(w, h);
    const std::vector<uint32_t> samples =
        random_samples(size_t(w) * h, format == GimSampleFormat::kFloat32 ? 0xFFFFFFFFu : 0xFFFFu, 11);
    PlaneLayout l = layout(w, h, format);
    l.occupied = &mask;
    l.blank_stored = true;
    expect_round_trip(samples, l);  // stored blank pixels come back too
    l.blank_stored = false;
    const bool is_float = format == GimSampleFormat::kFloat32;
    const uint32_t top = is_float ? 0xFFFFFFFFu : 0xFFFFu;
    for (int p = 0; p < kPlanePredictorCount; ++p) {
      const std::vector<uint8_t> bytes = encode_plane_with(samples, l, p);
      EXPECT_LT(bytes.size(), encode_plane_with(samples, layout(w, h, format), p).size());
      std::vector<uint32_t> back;
      ASSERT_TRUE(decode_plane(bytes.data(), bytes.size(), l, &back).ok());
      std::vector<uint32_t> ordered(back.size());
      for (size_t i = 0; i < back.size(); ++i) ordered[i] = is_float ? float_bits_to_ordered(back[i]) : back[i];
      for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
          const size_t i = size_t(y) * w + x;
          if (mask[i])
            EXPECT_EQ(back[i], samples[i]);
          else
            EXPECT_EQ(ordered[i], predict_sample(ordered.data(), w, x, y, p, top)) << x << "," << y;
        }
    }
  }
}

TEST(GimPlane, AllBlankPlaneIsOneByte) {
  const std::vector<uint8_t> mask(12, 0);
  PlaneLayout l = layout(4, 3);
  l.occupied = &mask;
  l.blank_stored = false;
  const std::vector<uint8_t> bytes = encode_plane_with(random_samples(12, 0xFFFF, 1), l, kPredictParallelogram);
  EXPECT_EQ(bytes, std::vector<uint8_t>{kPredictParallelogram});
  std::vector<uint32_t> back;
  ASSERT_TRUE(decode_plane(bytes.data(), bytes.size(), l, &back).ok());
  EXPECT_EQ(back, std::vector<uint32_t>(12, 0x8000));  // (0, 0) predicts 2^15; the rest copy it
}

TEST(GimMask, RoundTrip) {
  std::mt19937 rng(5);
  for (auto [w, h] : {std::pair<uint32_t, uint32_t>{1, 1}, {1, 50}, {50, 1}, {64, 48}, {9, 9}}) {
    std::vector<uint8_t> random(size_t(w) * h);
    for (uint8_t& o : random) o = rng() % 3 == 0;
    for (const std::vector<uint8_t>& mask : {random, blob_mask(w, h), std::vector<uint8_t>(size_t(w) * h, 1)}) {
      const std::vector<uint8_t> bytes = encode_mask(mask, w, h);
      std::vector<uint8_t> back;
      const Status s = decode_mask(bytes.data(), bytes.size(), w, h, &back);
      ASSERT_TRUE(s.ok()) << s.to_string();
      EXPECT_EQ(back, mask);
    }
  }
  const std::vector<uint8_t> blob = blob_mask(180, 180);
  EXPECT_LT(encode_mask(blob, 180, 180).size(), 180u * 180 / 8 / 20);  // a smooth outline is cheap
}

TEST(GimPlane, SmoothSurfaceCompresses) {
  // The quadratic predictor is exact on quadratic surfaces up to rounding;
  // a 16-bit sphere costs a little over 2 bits per sample.
  for (int axis = 0; axis < 2; ++axis) {
    PlaneEncodeStats stats;
    const std::vector<uint8_t> bytes = encode_plane(sphere_plane(180, 180, axis), layout(180, 180), &stats);
    EXPECT_EQ(stats.predictor, kPredictQuadratic);
    EXPECT_LT(bytes.size() * 8.0 / (180 * 180), 2.5);
  }
}

TEST(GimPlane, DamagedPayloadsAreRejectedWithoutCrashing) {
  const PlaneLayout l = layout(20, 20);
  const std::vector<uint8_t> good = encode_plane(sphere_plane(20, 20, 0), l);
  std::vector<uint32_t> back;
  // Cut short by more than the four bytes a decoder may invent: truncated.
  for (size_t cut = 1; cut + 4 < good.size(); ++cut) {
    const Status s = decode_plane(good.data(), cut, l, &back);
    EXPECT_FALSE(s.ok()) << "cut at " << cut;
  }
  EXPECT_EQ(decode_plane(good.data(), 0, l, &back).code(), ErrorCode::kTruncated);
  // The encoder leaves out up to four trailing zero bytes, so five zero bytes
  // appended are at least one byte after the end of the coded data.
  std::vector<uint8_t> longer = good;
  longer.insert(longer.end(), 5, 0);
  EXPECT_EQ(decode_plane(longer.data(), longer.size(), l, &back).code(), ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> bad_predictor = good;
  bad_predictor[0] = kPlanePredictorCount;
  EXPECT_EQ(decode_plane(bad_predictor.data(), bad_predictor.size(), l, &back).code(),
            ErrorCode::kUnsupportedFeature);
  const std::vector<uint8_t> ff = {3, 0xFF, 0xFF, 0xFF, 0xFF, 0x10};
  EXPECT_EQ(decode_plane(ff.data(), ff.size(), l, &back).code(), ErrorCode::kBadChunkPayload);
  // A huge image from a few bytes is refused before anything is allocated.
  const std::vector<uint8_t> tiny = {3, 1, 2, 3};
  EXPECT_EQ(decode_plane(tiny.data(), tiny.size(), layout(65535, 1024), &back).code(), ErrorCode::kLimitExceeded);
  std::vector<uint8_t> occupied;
  EXPECT_EQ(decode_mask(tiny.data(), tiny.size(), 8192, 8192, &occupied).code(), ErrorCode::kLimitExceeded);
  // Random corruption: any verdict, but no crash (the fuzzer covers more).
  std::mt19937 rng(9);
  int rejected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<uint8_t> bytes = good;
    bytes[1 + rng() % (bytes.size() - 1)] ^= uint8_t(1 + rng() % 255);
    const Status s = decode_plane(bytes.data(), bytes.size(), layout(20, 20, GimSampleFormat(trial % 2)), &back);
    rejected += !s.ok();
    if (s.ok()) {
      EXPECT_EQ(back.size(), 400u);
    }
  }
  EXPECT_GT(rejected, 150);
}

TEST(GimPlane, OverflowingResidualIsBadSymbol) {
  // Craft a stream: pixel (0, 0) predicted 2^15 with residual +2^15, which
  // the u16 range cannot hold (class 16, positive).
  RangeEncoder enc;
  PlaneResidualModel model;
  SignedResidual r;
  r.magnitude = 0x8000;
  r.negative = false;
  code_residual(&enc, &model, 0, 16, r);
  std::vector<uint8_t> bytes{kPredictLeft};
  for (uint8_t b : enc.finish()) bytes.push_back(b);
  std::vector<uint32_t> back;
  const Status s = decode_plane(bytes.data(), bytes.size(), layout(1, 1), &back);
  EXPECT_EQ(s.code(), ErrorCode::kBadSymbol) << s.to_string();
  EXPECT_NE(s.message().find("(0, 0)"), std::string::npos);
  r.negative = true;  // -2^15 is fine
  RangeEncoder enc2;
  PlaneResidualModel model2;
  code_residual(&enc2, &model2, 0, 16, r);
  bytes = {kPredictLeft};
  for (uint8_t b : enc2.finish()) bytes.push_back(b);
  ASSERT_TRUE(decode_plane(bytes.data(), bytes.size(), layout(1, 1), &back).ok());
  EXPECT_EQ(back, std::vector<uint32_t>{0});
}

// Fixed inputs and their exact bytes, so that the specification and the code
// cannot drift apart unnoticed (spec 13.6.1, examples).
TEST(GimPlane, KnownAnswers) {
  const std::vector<uint32_t> u16 = {100, 102, 104, 101, 103, 106};  // 3 x 2
  const std::vector<uint8_t> plane = encode_plane_with(u16, layout(3, 2), kPredictParallelogram);
  const std::vector<uint8_t> expected_plane = {0x03, 0xFF, 0xFE, 0xFF, 0x2D, 0x86, 0x11};
  EXPECT_EQ(plane, expected_plane);
  const std::vector<uint32_t> f32 = {float_bits(1.0f), float_bits(-0.0f), 0x7FC00001u};  // 3 x 1
  const std::vector<uint8_t> fplane = encode_plane_with(f32, layout(3, 1, GimSampleFormat::kFloat32), kPredictLeft);
  const std::vector<uint8_t> expected_fplane = {0x01, 0xFF, 0xFF, 0xFF, 0xFB, 0xFB, 0xCF, 0xC0, 0x08, 0x00, 0x7F, 0xFF,
                                                 0xEF, 0xDC, 0xF5, 0x40, 0x88, 0x27, 0xFF, 0xFF, 0x04, 0x01, 0x22, 0x03};
  EXPECT_EQ(fplane, expected_fplane);
  const std::vector<uint8_t> mask = {0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0};  // 4 x 3
  const std::vector<uint8_t> expected_mask = {0x6F, 0x6E};
  EXPECT_EQ(encode_mask(mask, 4, 3), expected_mask);
  std::vector<uint32_t> back;
  ASSERT_TRUE(decode_plane(expected_plane.data(), expected_plane.size(), layout(3, 2), &back).ok());
  EXPECT_EQ(back, u16);
  ASSERT_TRUE(decode_plane(expected_fplane.data(), expected_fplane.size(), layout(3, 1, GimSampleFormat::kFloat32),
                           &back)
                  .ok());
  EXPECT_EQ(back, f32);
  std::vector<uint8_t> occupied;
  ASSERT_TRUE(decode_mask(expected_mask.data(), expected_mask.size(), 4, 3, &occupied).ok());
  EXPECT_EQ(occupied, mask);

  // 4 x 4, quadratic predictor, corners blank and not stored: they decode to
  // 2^15 at (0, 0), edge extrapolations at (3, 0) and (0, 3), and the
  // quadratic prediction at (3, 3).
  const std::vector<uint8_t> corners = {0, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 0};
  PlaneLayout l = layout(4, 4);
  l.occupied = &corners;
  l.blank_stored = false;
  const std::vector<uint32_t> quad = {1000, 1003, 1012, 1027, 1007, 1017, 1029, 1049,
                                      1028, 1041, 1062, 1085, 1063, 1081, 1105, 1135};
  const std::vector<uint8_t> expected_quad = {0x04, 0xFF, 0xFE, 0xF8, 0x1F, 0xC0, 0xFF, 0x4C, 0xFA,
                                              0x6F, 0x79, 0xBF, 0x1F, 0x97, 0x4C, 0x41, 0xC1, 0x4C,
                                              0x26, 0xA9, 0xA6, 0x4A, 0x12, 0x31, 0xB9, 0x73, 0xCE};
  EXPECT_EQ(encode_plane_with(quad, l, kPredictQuadratic), expected_quad);
  ASSERT_TRUE(decode_plane(expected_quad.data(), expected_quad.size(), l, &back).ok());
  const std::vector<uint32_t> decoded_quad = {32768, 1003, 1012, 1021, 1007, 1017, 1029, 1049,
                                              1028,  1041, 1062, 1085, 1049, 1081, 1105, 1131};
  EXPECT_EQ(back, decoded_quad);
}

}  // namespace
}  // namespace qmc
