// Unit normals with the faces weighted by angle, spec section 15.13 (aTTR
// coding 8): the integer angle of the spec's example and of known angles,
// and normals weighted so coded smaller than with 15.7's area weights.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/octahedral_normal.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "roundtrip_check.h"
#include "splitmix64.h"

namespace qmc {
namespace {

// 15.13's example, a right angle: 32,767 units of pi / 2^16 (pi / 2 is 32,768).
TEST(AngleWeightedNormals, AngleOfTheSpec) {
  EXPECT_EQ(integer_angle(0, 5), 32767);
  // Within 4 units (0.011 degree) of the true angle over the half turn, whatever the lengths.
  for (double degrees : {0.5, 10.0, 45.0, 89.0, 91.0, 135.0, 179.5})
    for (double length : {3.0, 1000.0, 5e8}) {
      const double radians = degrees * M_PI / 180;
      const int64_t x = std::llround(length * std::cos(radians)), y = std::llround(length * std::sin(radians));
      if (y <= 0) continue;
      EXPECT_NEAR(double(integer_angle(x, y)), std::atan2(double(y), double(x)) / M_PI * 65536, 4.0)
          << degrees << " degrees, length " << length;
    }
}

// 15.13's steps written as the spec words them (doubling one step at a time,
// floor division by 2^i, a branch per step, 64-bit integers): the decoder's
// integer_angles, which shifts once, shifts arithmetically and turns without
// branches in 32 bits, any number of corners at a time, gives the same angles.
int64_t angle_as_the_spec_words_it(int64_t x, int64_t y) {
  int64_t z = 0;
  if (x < 0) {
    const int64_t t = x;
    x = y;
    y = -t;
    z = 1 << 15;
  }
  while (std::max(x, y) < (int64_t(1) << 24)) x *= 2, y *= 2;
  const auto floor_div_pow2 = [](int64_t v, int i) {
    const int64_t d = int64_t(1) << i, q = v / d;
    return (v % d != 0 && v < 0) ? q - 1 : q;
  };
  for (int i = 0; i < 16; ++i) {
    const int64_t dx = floor_div_pow2(y, i), dy = floor_div_pow2(x, i);
    if (y > 0) {
      x += dx, y -= dy, z += kCordicAngle[i];
    } else {
      x -= dx, y += dy, z -= kCordicAngle[i];
    }
  }
  return z;
}

TEST(AngleWeightedNormals, FastAnglesAreTheSpecsSteps) {
  tools::SplitMix64 random(15);
  int64_t x[5], y[5], angle[5];
  for (int round = 0; round < 100000; ++round) {
    const int count = 1 + round % 5;
    for (int j = 0; j < count; ++j) {
      // Dot products and cross-product lengths of 15-bit vectors: x^2 + y^2 <= (3 2^28)^2.
      const int bits = int(random.next() % 30);
      const int64_t range = (int64_t(1) << bits) + 1;
      x[j] = int64_t(random.next() % uint64_t(2 * range)) - range;
      y[j] = 1 + int64_t(random.next() % uint64_t(range));
    }
    integer_angles(count, x, y, angle);
    for (int j = 0; j < count; ++j) ASSERT_EQ(angle[j], angle_as_the_spec_words_it(x[j], y[j])) << x[j] << ", " << y[j];
  }
  // The longest vectors 15.13 makes, 3 2^28, all the way round: the 32-bit steps do not overflow.
  for (int degrees = 1; degrees < 180; ++degrees) {
    const double radians = degrees * M_PI / 180, longest = 3.0 * double(int64_t(1) << 28);
    const int64_t lx = std::llround(longest * std::cos(radians)), ly = std::llround(longest * std::sin(radians));
    EXPECT_EQ(integer_angle(lx, ly), angle_as_the_spec_words_it(lx, ly)) << degrees << " degrees";
  }
  for (int64_t v : {int64_t(-1), int64_t(-2), int64_t(-3), -(int64_t(1) << 40), (int64_t(1) << 40) + 3})
    for (int s = 0; s < 45; ++s) EXPECT_EQ(floor_shift(v, s), int64_t(std::floor(double(v) / std::ldexp(1.0, s))));
}

// Angle-weighted normals of an irregular bumpy grid: the encoder keeps
// coding 8, smaller than coding 3, and the decoded normals are as near the
// input as coding 3's (within one octahedral cell).
TEST(AngleWeightedNormals, CodingEightIsSmallerForAngleWeightedNormals) {
  Mesh m = tools::triangulated(tools::make_grid(24, 24));
  tools::SplitMix64 random(9);
  for (size_t v = 0; v < m.vertex_count(); ++v)
    for (int a = 0; a < 2; ++a) m.positions[3 * v + a] += 0.025f * (float(random.next() % 2001) / 1000.f - 1.f);
  std::vector<double> sum(3 * m.vertex_count(), 0.0);
  for (size_t f = 0; f < m.face_count(); ++f)
    for (int i = 0; i < 3; ++i) {
      const float* c = &m.positions[3 * size_t(m.corners[3 * f + i])];
      const float* a = &m.positions[3 * size_t(m.corners[3 * f + (i + 1) % 3])];
      const float* b = &m.positions[3 * size_t(m.corners[3 * f + (i + 2) % 3])];
      const double e[3] = {a[0] - c[0], a[1] - c[1], a[2] - c[2]}, g[3] = {b[0] - c[0], b[1] - c[1], b[2] - c[2]};
      const double n[3] = {e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2], e[0] * g[1] - e[1] * g[0]};
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double angle = std::atan2(length, e[0] * g[0] + e[1] * g[1] + e[2] * g[2]);
      for (int k = 0; k < 3; ++k) sum[3 * size_t(m.corners[3 * f + i]) + k] += angle * n[k] / length;
    }
  MeshAttribute normal{"normal", AttributeKind::kNormal, 3, {}, m.corners};
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    const double* s = &sum[3 * v];
    const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int k = 0; k < 3; ++k) normal.values.push_back(float(s[k] / length));
  }
  m.attributes.push_back(normal);
  std::vector<uint8_t> angle, area;
  EncodeOptions options;
  EncodeStats stats;
  ASSERT_TRUE(encode(m, options, &angle, &stats).ok());
  EXPECT_TRUE(stats.attributes[0].angle_weighted);
  const uint64_t angle_bytes = stats.attributes[0].chunk_bytes;
  options.angle_weighted_normals = false;
  ASSERT_TRUE(encode(m, options, &area, &stats).ok());
  EXPECT_FALSE(stats.attributes[0].angle_weighted);
  EXPECT_LT(angle_bytes, stats.attributes[0].chunk_bytes);
  DecodedFile a;
  ASSERT_TRUE(decode(angle.data(), angle.size(), &a).ok());
  EXPECT_EQ(a.attribute_codings[0].coding, 8);
  EXPECT_TRUE(tools::check_round_trip(m, a).ok());  // every corner within one octahedral cell
}

}  // namespace
}  // namespace qmc
