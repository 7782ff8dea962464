// The mapping of spec section 15.11 (aTTR mapping 3): the decisions of the
// spec's example, the face rule on flat-shaded quads, and round trips of
// random tables over random polygon soups (vertices twice in a face, values
// shared between vertices), whatever the encoder calls single.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/predicted_mapping.h"
#include "common/range_coder.h"
#include "mesh_generators.h"
#include "splitmix64.h"
#include "qmc/mesh.h"

namespace qmc {
namespace {

constexpr uint32_t kNoValue = UINT32_MAX;

struct Coded {
  std::vector<uint8_t> stream;
  PredictedMappingModel model;  // after the last corner
  uint32_t met = 0;
};

Coded encode_mapping(const std::vector<uint32_t>& face_sizes, const std::vector<uint32_t>& corners,
                     uint32_t vertex_count, uint64_t value_count, const std::vector<uint32_t>& m,
                     const std::vector<uint8_t>& single) {
  RangeEncoder rc;
  Coded out;
  PredictedMapping mapping;
  mapping.reset(vertex_count, face_sizes, corners);
  for (size_t k = 0; k < m.size(); ++k) {
    MappingFault fault = MappingFault::kNone;
    EXPECT_EQ(mapping.code(&rc, &out.model, k, value_count, &out.met, m.data(), &single, &fault), m[k]) << k;
    EXPECT_EQ(fault, MappingFault::kNone);
  }
  out.stream = rc.finish();
  return out;
}

std::vector<uint32_t> decode_mapping(const std::vector<uint32_t>& face_sizes, const std::vector<uint32_t>& corners,
                                     uint32_t vertex_count, uint64_t value_count, const std::vector<uint8_t>& stream,
                                     uint32_t* met) {
  RangeDecoder rc(stream.data(), stream.size());
  PredictedMappingModel model;
  PredictedMapping mapping;
  mapping.reset(vertex_count, face_sizes, corners);
  std::vector<uint32_t> m;
  for (size_t k = 0; k < corners.size(); ++k) {
    MappingFault fault = MappingFault::kNone;
    m.push_back(mapping.code(&rc, &model, k, value_count, met, nullptr, nullptr, &fault));
    EXPECT_EQ(fault, MappingFault::kNone) << k;
    EXPECT_FALSE(rc.overrun()) << k;
  }
  EXPECT_EQ(rc.unread(), 0u);
  return m;
}

// 15.11's example: faces (0, 1, 2) and (2, 1, 3), m = 0 1 2 | 2 3 4, a seam
// at vertex 1 (values 1 and 3). The decisions: SINGLE[0][0] = 1 (vertex 0),
// SINGLE[1][0] = 0 then NEW[0] = 1 (vertex 1: no FACE, as vertex 0 is
// single), SINGLE[2][1] = 1 (vertex 2); corner 3 none (vertex 2 single);
// corner 4: the reference is corner 1 (x = 1), whose face has w- = 2 next
// to vertex 1 and agrees with corner 3 at vertex 2, so e = 1: SAME[0][1] = 0,
// then NEW[1] = 1; corner 5: SINGLE[2][1] = 1 (vertex 3).
TEST(PredictedMapping, DecisionsOfTheSpecExample) {
  const std::vector<uint32_t> sizes = {3, 3}, corners = {0, 1, 2, 2, 1, 3}, m = {0, 1, 2, 2, 3, 4};
  const std::vector<uint8_t> single = single_value_vertices(corners, m, 4);
  EXPECT_EQ(single, (std::vector<uint8_t>{1, 0, 1, 1}));
  const Coded coded = encode_mapping(sizes, corners, 4, 5, m, single);
  EXPECT_EQ(coded.met, 5u);
  // Each probability that a decision touched moved, the others stayed at 1024.
  const PredictedMappingModel& p = coded.model;
  EXPECT_LT(p.single[0][0], 1024);  // one 1
  EXPECT_GT(p.single[1][0], 1024);  // one 0
  EXPECT_EQ(p.single[2][1], 1024 - (1024 >> 5) - ((1024 - (1024 >> 5)) >> 5));  // two 1s
  EXPECT_GT(p.same[0][1], 1024);    // one 0
  EXPECT_LT(p.fallback.fresh[0], 1024);
  EXPECT_LT(p.fallback.fresh[1], 1024);
  EXPECT_EQ(p.fallback.fresh[2], 1024);
  EXPECT_EQ(p.fallback.own, 1024);
  EXPECT_EQ(p.face[0], 1024);
  EXPECT_EQ(p.face[1], 1024);
  for (int b = 0; b < 2; ++b)
    for (int e = 0; e < 4; ++e)
      if (b != 0 || e != 1) {
        EXPECT_EQ(p.same[b][e], 1024) << b << " " << e;
      }
  uint32_t met = 0;
  EXPECT_EQ(decode_mapping(sizes, corners, 4, 5, coded.stream, &met), m);
  EXPECT_EQ(met, 5u);
}

// 15.3's stream of the same choices, for comparison.
std::vector<uint8_t> mapping_1_stream(const std::vector<uint32_t>& corners, uint32_t vertex_count,
                                      uint64_t value_count, const std::vector<uint32_t>& m) {
  RangeEncoder rc;
  AttributeMappingModel model;
  VertexValueLists lists;
  lists.reset(vertex_count, corners);
  uint32_t met = 0;
  for (size_t k = 0; k < m.size(); ++k) {
    MappingFault fault = MappingFault::kNone;
    code_corner_value(&rc, &model, &lists, corners[k], value_count, &met,
                      fallback_choice(lists, corners[k], m[k], met), &fault);
  }
  return rc.finish();
}

// Flat shading on a strip of 200 quads: every corner of face f refers to
// value f. After each face's first corner the face rule gives the value
// (FACE = 1 three times a face), where 15.3 codes "any value met before" in
// 8 direct bits twice a face.
TEST(PredictedMapping, FaceRuleCarriesValuesGivenPerFace) {
  const uint32_t quads = 200;
  std::vector<uint32_t> sizes(quads, 4), corners, m;
  for (uint32_t f = 0; f < quads; ++f) {
    for (uint32_t v : {2 * f, 2 * f + 2, 2 * f + 3, 2 * f + 1}) corners.push_back(v);
    for (int i = 0; i < 4; ++i) m.push_back(f);
  }
  const uint32_t vertex_count = 2 * quads + 2;
  const Coded coded = encode_mapping(sizes, corners, vertex_count, quads, m, single_value_vertices(corners, m, vertex_count));
  EXPECT_LT(coded.model.face[0], 100);  // FACE = 1 near certain, from the first corner of a vertex
  EXPECT_LT(coded.model.face[1], 100);  // and from a later one
  EXPECT_LT(coded.stream.size(), 40u);
  EXPECT_GT(mapping_1_stream(corners, vertex_count, quads, m).size(), 300u);
  uint32_t met = 0;
  EXPECT_EQ(decode_mapping(sizes, corners, vertex_count, quads, coded.stream, &met), m);
}

// Random tables over random polygon soups (faces with a vertex twice,
// values shared between vertices, values no corner uses), coded with the
// encoder's single vertices and with none called single: the decoder gives
// back every m_k.
TEST(PredictedMapping, RandomTablesRoundTrip) {
  int checked = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 10 + uint32_t(seed % 9) * 7;
    o.faces = 12 + uint32_t(seed % 7) * 9;
    o.repeated_corners = seed % 2 == 0;
    const Mesh soup = tools::make_random_soup(seed, o);
    tools::SplitMix64 random(seed * 7919);
    // Values by first reference: a corner takes a new value, its vertex's
    // previous one, or any value met so far.
    std::vector<uint32_t> m(soup.corners.size()), last(soup.vertex_count(), kNoValue);
    uint32_t met = 0;
    for (size_t k = 0; k < m.size(); ++k) {
      const uint32_t v = soup.corners[k], pick = uint32_t(random.below(10));
      m[k] = pick < 3 || met == 0 ? met++ : pick < 8 && last[v] != kNoValue ? last[v] : uint32_t(random.below(met));
      last[v] = m[k];
    }
    const uint64_t value_count = met + seed % 3;  // some values no corner uses
    const uint32_t vertex_count = uint32_t(soup.vertex_count());
    for (bool encoders_single : {true, false}) {
      const std::vector<uint8_t> single =
          encoders_single ? single_value_vertices(soup.corners, m, vertex_count) : std::vector<uint8_t>(vertex_count, 0);
      const Coded coded = encode_mapping(soup.face_sizes, soup.corners, vertex_count, value_count, m, single);
      uint32_t decoded_met = 0;
      EXPECT_EQ(decode_mapping(soup.face_sizes, soup.corners, vertex_count, value_count, coded.stream, &decoded_met), m)
          << "seed " << seed;
      EXPECT_EQ(decoded_met, met);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 120);
}

}  // namespace
}  // namespace qmc
