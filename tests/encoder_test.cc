// Encoder behaviour: input validation (never a silent drop), the vertex
// relabelling of spec 5.2.1, and the quantization bound of spec 6.2.
#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <limits>

#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "roundtrip_check.h"

namespace qmc {
namespace {

Mesh triangle_pair() {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 5, 5, 5};
  m.face_sizes = {3, 3};
  m.corners = {2, 0, 1, 0, 2, 3};  // vertex 4 unreferenced
  return m;
}

// Method 0 (spec 5.2), whose order rules these tests check.
DecodedFile round_trip(const Mesh& m, int bits = 12) {
  EncodeOptions o;
  o.position_bits = bits;
  o.connectivity = ConnectivityChoice::kIndexed;
  std::vector<uint8_t> bytes;
  EXPECT_TRUE(encode(m, o, &bytes).ok());
  DecodedFile d;
  EXPECT_TRUE(decode(bytes.data(), bytes.size(), &d).ok());
  return d;
}

TEST(Encoder, RelabelsVerticesByFirstReference) {
  // Spec 5.2.1: faces (2 0 1) (0 2 3) -> labels 2->0, 0->1, 1->2, 3->3, unreferenced 4->4.
  const DecodedFile d = round_trip(triangle_pair());
  EXPECT_EQ(d.mesh.corners, (std::vector<uint32_t>{0, 1, 2, 1, 0, 3}));
  EXPECT_EQ(d.mesh.face_sizes, (std::vector<uint32_t>{3, 3}));
  ASSERT_EQ(d.mesh.vertex_count(), 5u);
  EXPECT_FLOAT_EQ(d.mesh.positions[0], 1.f);  // old vertex 2 = (1, 1, 0)
  EXPECT_FLOAT_EQ(d.mesh.positions[1], 1.f);
  EXPECT_FLOAT_EQ(d.mesh.positions[12], 5.f);  // unreferenced vertex last
}

// The polygon coder's vertices no face uses get the last labels in the
// encoder's order (spec 5.4.9), each predicted from the vertex before: by
// default along a Z-order curve, so points on a line come out sorted along
// it; or in the input's order.
TEST(Encoder, VerticesOfNoFaceFollowACurve) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.face_sizes = {3};
  m.corners = {0, 1, 2};
  constexpr uint32_t kPoints = 40;
  for (uint32_t i = 0; i < kPoints; ++i) {
    const float x = float((i * 17) % kPoints);  // a shuffle of 0 .. 39
    m.positions.insert(m.positions.end(), {x, 7, 7});
  }
  for (bool along_curve : {true, false}) {
    EncodeOptions o;
    o.connectivity = ConnectivityChoice::kPolygon;
    o.unused_vertices_along_curve = along_curve;
    std::vector<uint8_t> bytes;
    EncodeStats stats;
    ASSERT_TRUE(encode(m, o, &bytes, &stats).ok());
    ASSERT_EQ(stats.file_vertex.size(), 3 + kPoints);
    for (uint32_t k = 0; k < kPoints; ++k)
      if (along_curve)
        EXPECT_EQ(m.positions[3 * size_t(stats.file_vertex[3 + k])], float(k)) << "label " << 3 + k;
      else
        EXPECT_EQ(stats.file_vertex[3 + k], 3 + k) << "label " << 3 + k;
    DecodedFile d;
    ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d).ok());
    EXPECT_TRUE(tools::check_round_trip(m, d, tools::Correspondence{stats.file_vertex, stats.face_source}).ok());
  }
}

TEST(Encoder, StatsNameTheFileVertexOrder) {
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  EncodeOptions indexed;
  indexed.connectivity = ConnectivityChoice::kIndexed;
  ASSERT_TRUE(encode(triangle_pair(), indexed, &bytes, &stats).ok());
  EXPECT_EQ(stats.file_vertex, (std::vector<uint32_t>{2, 0, 1, 3, 4}));
  EXPECT_EQ(stats.total_bytes, bytes.size());
  uint64_t sum = 8;
  for (const ChunkStats& c : stats.chunks) sum += c.bytes;
  EXPECT_EQ(sum, bytes.size());
}

TEST(Encoder, RejectsWhatItCannotRepresent) {
  std::vector<uint8_t> out;
  Mesh m = triangle_pair();
  m.positions[4] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(encode(m, {}, &out).code(), ErrorCode::kInvalidArgument);
  m = triangle_pair();
  m.positions[4] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(encode(m, {}, &out).code(), ErrorCode::kInvalidArgument);
  m = triangle_pair();
  m.face_sizes = {2, 4};
  EXPECT_EQ(encode(m, {}, &out).code(), ErrorCode::kInvalidArgument);
  m = triangle_pair();
  m.corners[3] = 5;
  EXPECT_EQ(encode(m, {}, &out).code(), ErrorCode::kInvalidArgument);
  m = triangle_pair();
  m.corners.pop_back();
  EXPECT_EQ(encode(m, {}, &out).code(), ErrorCode::kInvalidArgument);
  m = triangle_pair();
  m.positions.pop_back();
  EXPECT_EQ(encode(m, {}, &out).code(), ErrorCode::kInvalidArgument);
  for (int bits : {0, 31, -1}) {
    EncodeOptions o;
    o.position_bits = bits;
    EXPECT_EQ(encode(triangle_pair(), o, &out).code(), ErrorCode::kInvalidArgument) << bits;
  }
}

TEST(Encoder, KeepsDegenerateFacesExactly) {
  Mesh m = triangle_pair();
  m.face_sizes = {3, 3, 4};
  m.corners = {2, 0, 1, 0, 2, 3, 1, 1, 1, 1};  // a face repeating one vertex
  const DecodedFile d = round_trip(m);
  EXPECT_TRUE(tools::check_round_trip(m, d).ok());
}

TEST(Encoder, EveryBitDepthStaysWithinHalfAStep) {
  const Mesh sphere = tools::make_quad_sphere(6);
  for (int bits = kMinPositionBits; bits <= kMaxPositionBits; ++bits) {
    const DecodedFile d = round_trip(sphere, bits);
    const tools::RoundTripReport r = tools::check_round_trip(sphere, d);
    EXPECT_TRUE(r.ok()) << bits << " bits: " << r.position_mismatch;
  }
}

TEST(Encoder, DefaultBitsKeepErrorBelowOne4096thOfTheLargestSide) {
  tools::RandomSoupOptions o;
  o.vertices = 3000;
  o.faces = 2000;
  const Mesh m = tools::make_random_soup(11, o);
  const tools::RoundTripReport r = tools::check_round_trip(m, round_trip(m));
  ASSERT_TRUE(r.ok());
  EXPECT_LT(r.max_error, r.max_bbox_side / 4096);
}

TEST(Encoder, DequantizationFollowsSection64) {
  // 2 bits over [0, 1]: steps of 1/3, computed in binary64 and rounded once.
  Mesh m;
  m.positions = {0, 0, 0, 1.f / 3, 0, 0, 2.f / 3, 0, 0, 1, 0, 0};
  const DecodedFile d = round_trip(m, 2);
  EXPECT_EQ(d.quantized[3], 1u);
  EXPECT_EQ(d.mesh.positions[3], float(0.0 + 1.0 * (1.0 / 3.0)));
  EXPECT_EQ(d.mesh.positions[6], float(0.0 + 2.0 * (1.0 / 3.0)));
  EXPECT_EQ(d.mesh.positions[9], 1.f);
}

TEST(Encoder, EmptyMeshAndPointCloud) {
  EXPECT_EQ(round_trip(Mesh{}).mesh.vertex_count(), 0u);
  Mesh points;
  points.positions = {1, 2, 3, 4, 5, 6};
  const DecodedFile d = round_trip(points);
  EXPECT_EQ(d.mesh.vertex_count(), 2u);
  EXPECT_EQ(d.mesh.face_count(), 0u);
  EXPECT_TRUE(tools::check_round_trip(points, d).ok());
}

TEST(Encoder, OutputIsDeterministic) {
  const Mesh m = tools::make_torus(20, 10);
  std::vector<uint8_t> a, b;
  ASSERT_TRUE(encode(m, {}, &a).ok());
  ASSERT_TRUE(encode(m, {}, &b).ok());
  EXPECT_EQ(a, b);
}

// ---------------------------------------------------------------------------
// Issue #12 item 6: every encoder stage near-linear on degenerate inputs. Each
// case below takes about a second; the bound is 10 s of this process's CPU
// time (not wall time, so a loaded machine cannot fail it), where the
// quadratic paths it guards against took 33 s (300k faces on one edge) to
// hours (a face of a million corners).

constexpr double kGenerousCpuSeconds = 10;

struct TimedRoundTrip {
  double encode_cpu_seconds = 0;
  tools::RoundTripReport check;
};

// Encodes with the default choice of coder (the polygon coder for all of
// these) and checks the decoded file against the input.
TimedRoundTrip timed_round_trip(const Mesh& m, bool keep_order = false) {
  EncodeOptions o;
  o.keep_order = keep_order;
  std::vector<uint8_t> bytes;
  EncodeStats stats;
  const std::clock_t start = std::clock();
  const Status encoded = encode(m, o, &bytes, &stats);
  TimedRoundTrip r;
  r.encode_cpu_seconds = double(std::clock() - start) / CLOCKS_PER_SEC;
  EXPECT_TRUE(encoded.ok()) << encoded.to_string();
  DecodedFile d;
  EXPECT_TRUE(decode(bytes.data(), bytes.size(), &d).ok());
  r.check = keep_order ? tools::check_round_trip(m, d, tools::identity_correspondence(m))
                       : tools::check_round_trip(m, d, tools::Correspondence{stats.file_vertex, stats.face_source});
  return r;
}

TEST(EncoderComplexity, OneFaceOfAMillionCorners) {
  const TimedRoundTrip r = timed_round_trip(tools::make_polygon(1000000));
  EXPECT_TRUE(r.check.ok()) << r.check.face_mismatch << r.check.position_mismatch;
  EXPECT_LT(r.encode_cpu_seconds, kGenerousCpuSeconds);
}

TEST(EncoderComplexity, ThreeHundredThousandTrianglesOnOneEdge) {
  const TimedRoundTrip r = timed_round_trip(tools::make_book(300000));
  EXPECT_TRUE(r.check.ok()) << r.check.face_mismatch << r.check.position_mismatch;
  EXPECT_LT(r.encode_cpu_seconds, kGenerousCpuSeconds);
}

TEST(EncoderComplexity, ThreeHundredThousandTrianglesOnOneVertex) {
  const TimedRoundTrip r = timed_round_trip(tools::make_vertex_star(300000));
  EXPECT_TRUE(r.check.ok()) << r.check.face_mismatch << r.check.position_mismatch;
  EXPECT_LT(r.encode_cpu_seconds, kGenerousCpuSeconds);
}

// Handle cutting (spec 5.4.9) on a great many components, each with a handle:
// 100000 disjoint 3 x 3 tori.
TEST(EncoderComplexity, AHundredThousandComponentsWithAHandleEach) {
  const Mesh torus = tools::make_torus(3, 3);
  Mesh m;
  for (uint32_t copy = 0; copy < 100000; ++copy) {
    const uint32_t first = uint32_t(m.vertex_count());
    m.positions.insert(m.positions.end(), torus.positions.begin(), torus.positions.end());
    m.face_sizes.insert(m.face_sizes.end(), torus.face_sizes.begin(), torus.face_sizes.end());
    for (uint32_t v : torus.corners) m.corners.push_back(first + v);
  }
  const TimedRoundTrip r = timed_round_trip(m);
  EXPECT_TRUE(r.check.ok()) << r.check.face_mismatch << r.check.position_mismatch;
  EXPECT_LT(r.encode_cpu_seconds, kGenerousCpuSeconds);
}

// Spec 4.5 rotations of a face that repeats a vertex: (1^k 0 1^k) starts k
// corners after its smallest vertex, and every rotation in between agrees
// with it for about k corners before differing (k^2 / 2 comparisons when
// tried one by one).
TEST(EncoderComplexity, KeepOrderOfAMillionCornerFaceRepeatingAVertex) {
  const uint32_t k = 500000;
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0};
  m.face_sizes = {2 * k + 1};
  m.corners.assign(2 * k + 1, 1);
  m.corners[k] = 0;
  const TimedRoundTrip r = timed_round_trip(m, /*keep_order=*/true);
  EXPECT_TRUE(r.check.ok()) << r.check.face_mismatch << r.check.position_mismatch;
  EXPECT_LT(r.encode_cpu_seconds, kGenerousCpuSeconds);
}

}  // namespace
}  // namespace qmc
