// Geometry-image files, spec section 13: the mesh of 13.9, the chunk rules of
// 13.1-13.8, and round trips through the writer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <utility>

#include "chunk_list.h"
#include "decoder/gim_mesh_builder.h"
#include "encoder/gim_writer.h"
#include "gim_test_images.h"
#include "qmc/decoder.h"

namespace qmc {
namespace {

GimSamples torus_image(uint32_t n) { return tools::make_torus_geometry_image(n); }

// Every undirected edge in exactly two faces, crossed in opposite directions.
bool closed_and_oriented(const Mesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  size_t c = 0;
  for (uint32_t size : m.face_sizes) {
    for (uint32_t i = 0; i < size; ++i) ++directed[{m.corners[c + i], m.corners[c + (i + 1) % size]}];
    c += size;
  }
  for (const auto& [edge, count] : directed)
    if (count != 1 || directed.count({edge.second, edge.first}) != 1) return false;
  return true;
}

Status write(const GimSamples& s, const GeometryImageOptions& o, std::vector<uint8_t>* file) {
  EncodeStats stats;
  return write_geometry_image(s, {}, o, {}, file, &stats);
}

TEST(GimMeshBuilder, GridOfQuadsAndItsTriangles) {
  GimTopologyInput in;
  in.width = 4;
  in.height = 3;
  GimTopology t;
  ASSERT_TRUE(build_gim_topology(in, &t).ok());
  EXPECT_EQ(t.pixel_of_vertex.size(), 12u);
  EXPECT_EQ(t.face_sizes, std::vector<uint32_t>(6, 4));
  // Block (0, 0): (0,0) (1,0) (1,1) (0,1) counter-clockwise in (x, y).
  EXPECT_EQ(std::vector<uint32_t>(t.corners.begin(), t.corners.begin() + 4), (std::vector<uint32_t>{0, 1, 5, 4}));
}

TEST(GimMeshBuilder, ShorterDiagonalSplitsEachBlock) {
  // Pixel (1, 1) is lifted: diagonal (0,0)-(1,1) is longer than (1,0)-(0,1).
  std::vector<double> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 5};
  GimTopologyInput in;
  in.width = in.height = 2;
  in.mode = GimFaceMode::kGridTriangles;
  in.xyz = xyz.data();
  GimTopology t;
  ASSERT_TRUE(build_gim_topology(in, &t).ok());
  EXPECT_EQ(t.corners, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  xyz[11] = 0;
  xyz[2] = 0;
  xyz[5] = 7;  // now (1,0) is lifted: the other diagonal
  ASSERT_TRUE(build_gim_topology(in, &t).ok());
  EXPECT_EQ(t.corners, (std::vector<uint32_t>{0, 1, 3, 0, 3, 2}));
}

TEST(GimMeshBuilder, BlankPixelLeavesATriangleAndSeamsMergeVertices) {
  std::vector<uint8_t> occupied = {1, 1, 1, 0};
  std::vector<SeamPair> seams = {{0, 2}};
  GimTopologyInput in;
  in.width = in.height = 2;
  in.occupied = &occupied;
  GimTopology t;
  ASSERT_TRUE(build_gim_topology(in, &t).ok());
  EXPECT_EQ(t.face_sizes, std::vector<uint32_t>{3});
  EXPECT_EQ(t.corners, (std::vector<uint32_t>{2, 0, 1}));  // cyclic order, starting after the blank
  in.seams = &seams;  // (0,0) = (0,1): the triangle collapses and is dropped
  ASSERT_TRUE(build_gim_topology(in, &t).ok());
  EXPECT_EQ(t.pixel_of_vertex, (std::vector<uint32_t>{0, 1}));
  EXPECT_TRUE(t.face_sizes.empty());
}

TEST(GimMeshBuilder, RejectsSeamsAndTrianglesOnBlankPixels) {
  std::vector<uint8_t> occupied = {1, 1, 1, 0};
  std::vector<SeamPair> seams = {{0, 3}};
  std::vector<uint32_t> triangles = {0, 1, 3};
  GimTopologyInput in;
  in.width = in.height = 2;
  in.occupied = &occupied;
  in.seams = &seams;
  GimTopology t;
  Status s = build_gim_topology(in, &t);
  EXPECT_EQ(s.code(), ErrorCode::kBadChunkPayload);
  EXPECT_NE(s.message().find("blank pixel"), std::string::npos) << s.message();
  in.seams = nullptr;
  in.mode = GimFaceMode::kExplicitTriangles;
  in.triangles = &triangles;
  s = build_gim_topology(in, &t);
  EXPECT_EQ(s.code(), ErrorCode::kBadChunkPayload);
  EXPECT_NE(s.message().find("blank pixel (1, 1)"), std::string::npos) << s.message();
}

TEST(GimFile, TorusImageDecodesToAClosedTorus) {
  for (bool quads : {true, false}) {
    GeometryImageOptions o;
    o.quads = quads;
    std::vector<uint8_t> file;
    ASSERT_TRUE(write(torus_image(17), o, &file).ok());
    DecodedFile d;
    ASSERT_TRUE(decode(file.data(), file.size(), &d).ok());
    EXPECT_EQ(d.mesh.vertex_count(), 16u * 16u);
    EXPECT_EQ(d.mesh.face_count(), quads ? 256u : 512u);
    EXPECT_TRUE(closed_and_oriented(d.mesh));
    // 16-bit samples: within half a step of the surface point.
    const double step = d.gim.planes[0].step;
    for (size_t v = 0; v < d.mesh.vertex_count(); ++v) {
      const double r = std::hypot(d.mesh.positions[3 * v], d.mesh.positions[3 * v + 1]) - 2;
      EXPECT_NEAR(r * r + d.mesh.positions[3 * v + 2] * d.mesh.positions[3 * v + 2], 1.0, 8 * step);
    }
  }
}

TEST(GimFile, FloatSamplesAreBitExact) {
  GimSamples s = torus_image(9);
  s.xyz[3 * 40] = -0.0;
  s.xyz[3 * 41] = 1e-40;  // a binary32 subnormal
  GeometryImageOptions o;
  o.float_samples = true;
  std::vector<uint8_t> file;
  ASSERT_TRUE(write(s, o, &file).ok());
  DecodedFile d;
  ASSERT_TRUE(decode(file.data(), file.size(), &d).ok());
  for (uint32_t p = 0; p < 81; ++p)
    for (int a = 0; a < 3; ++a) {
      const float want = float(s.xyz[3 * p + size_t(a)]);
      uint32_t bits;
      std::memcpy(&bits, &want, 4);
      EXPECT_EQ(d.gim.planes[size_t(a)].samples[p], bits);
    }
  EXPECT_TRUE(std::signbit(d.gim.value(0, 40)));
}

TEST(GimFile, StreamingByteByByteGivesTheSameResult) {
  GimSamples s = torus_image(8);
  s.occupied.assign(64, 1);
  s.occupied[27] = 0;
  s.occupied[28] = 0;
  std::vector<uint8_t> file;
  ASSERT_TRUE(write(s, GeometryImageOptions{}, &file).ok());
  DecodedFile whole;
  ASSERT_TRUE(decode(file.data(), file.size(), &whole).ok());
  StreamDecoder stream;
  bool mesh_before_end = false;
  for (size_t i = 0; i < file.size(); ++i) {
    ASSERT_TRUE(stream.feed(&file[i], 1).ok());
    if (!stream.complete() && stream.has_positions()) mesh_before_end = true;
  }
  ASSERT_TRUE(stream.finish().ok());
  EXPECT_TRUE(mesh_before_end);
  EXPECT_EQ(canonical_output(stream.file()), canonical_output(whole));
}

// Rewrites chunk `type` of `file` (CRC recomputed).
std::vector<uint8_t> with_chunk(const std::vector<uint8_t>& file, uint32_t type, const std::vector<uint8_t>& payload) {
  std::vector<tools::Chunk> chunks = tools::split_chunks(file);
  for (tools::Chunk& c : chunks)
    if (c.type == type) c.payload = payload;
  return tools::join_chunks(chunks);
}

ErrorCode decode_error(const std::vector<uint8_t>& file, std::string* message = nullptr) {
  DecodedFile d;
  const Status s = decode(file.data(), file.size(), &d);
  if (message) *message = s.message();
  return s.code();
}

TEST(GimFile, RejectsOversizedAndInconsistentImages) {
  std::vector<uint8_t> file;
  ASSERT_TRUE(write(torus_image(8), GeometryImageOptions{}, &file).ok());
  std::vector<tools::Chunk> chunks = tools::split_chunks(file);
  const std::vector<uint8_t> gimg = chunks[tools::find_chunk(chunks, kChunkGeometryImage)].payload;
  // 65535 x 65535 > 2^24 pixels.
  std::vector<uint8_t> big = {0xFF, 0xFF, 0x03, 0xFF, 0xFF, 0x03};
  big.insert(big.end(), gimg.begin() + 2, gimg.end());
  EXPECT_EQ(decode_error(with_chunk(file, kChunkGeometryImage, big)), ErrorCode::kLimitExceeded);
  // 4096 x 4096 fits the limit, but an 8-byte plane cannot justify it (13.3).
  std::vector<uint8_t> wide = {0x80, 0x20, 0x80, 0x20};
  wide.insert(wide.end(), gimg.begin() + 2, gimg.end());
  std::string message;
  EXPECT_EQ(decode_error(with_chunk(file, kChunkGeometryImage, wide), &message), ErrorCode::kLimitExceeded);
  EXPECT_NE(message.find("13.3"), std::string::npos) << message;
  // A seam pair that joins a pixel with itself.
  EXPECT_EQ(decode_error(with_chunk(file, kChunkGimSeams, {1, 3, 3, 1, 0, 0})), ErrorCode::kBadChunkPayload);
  // QEND right after the first plane.
  std::vector<tools::Chunk> short_file;
  for (const tools::Chunk& c : chunks)
    if (c.type != kChunkGimPlane || short_file.back().type != kChunkGimPlane) short_file.push_back(c);
  EXPECT_EQ(decode_error(tools::join_chunks(short_file), &message), ErrorCode::kChunkOrder);
  EXPECT_NE(message.find("planes"), std::string::npos) << message;
}

TEST(GimFile, TrianglesOverPixelsRoundTripAndMustNotPointAtBlankPixels) {
  // A 3 x 3 image with its centre blank: a fan of 4 triangles around (1, 1)
  // would need it, so the file lists triangles over the corners instead.
  GimSamples s;
  s.width = s.height = 3;
  s.xyz.resize(27);
  for (uint32_t p = 0; p < 9; ++p) s.xyz[3 * p] = p % 3, s.xyz[3 * p + 1] = p / 3, s.xyz[3 * p + 2] = 0.25 * p;
  s.occupied = {1, 1, 1, 1, 0, 1, 1, 1, 1};
  s.triangles = {0, 2, 8, 0, 8, 6, 1, 5, 7};
  GeometryImageOptions o;
  o.float_samples = true;
  std::vector<uint8_t> file;
  ASSERT_TRUE(write(s, o, &file).ok());
  DecodedFile d;
  ASSERT_TRUE(decode(file.data(), file.size(), &d).ok());
  EXPECT_EQ(d.gim.triangles, s.triangles);
  EXPECT_EQ(d.mesh.face_count(), 3u);
  // Triangle 1 with its corner 1 on the blank centre: coded over an all-occupied
  // image, then put into the file whose mask has the centre blank.
  GimSamples bad = s;
  bad.triangles[4] = 4;
  bad.occupied[4] = 1;  // write it with the centre occupied, then blank the mask again
  std::vector<uint8_t> bad_file;
  ASSERT_TRUE(write(bad, o, &bad_file).ok());
  std::vector<tools::Chunk> chunks = tools::split_chunks(bad_file);
  const std::vector<uint8_t> gfac = chunks[tools::find_chunk(chunks, kChunkGimFaces)].payload;
  std::string message;
  EXPECT_EQ(decode_error(with_chunk(file, kChunkGimFaces, gfac), &message), ErrorCode::kBadChunkPayload);
  EXPECT_NE(message.find("blank pixel (1, 1)"), std::string::npos) << message;
}

}  // namespace
}  // namespace qmc
