// Tests for tools/lib/image_io (16-bit PNG planes, 8-bit pictures, PFM) and
// tools/lib/mesh_render (the software rasterizer and the plane pictures):
// round trips, bit exactness, row order, rejection of unsuitable or broken
// files, and rendered coverage against the analytic projected area.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "image_io.h"
#include "mesh_generators.h"
#include "mesh_render.h"

namespace qmc::tools {
namespace {

using qmc::ErrorCode;
using qmc::Status;

std::string temp_path(const std::string& file) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "qmc_image_io_" + info->name() + "_" + file;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<uint8_t> file_bytes(const std::string& path) {
  std::vector<uint8_t> bytes;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return bytes;
  int c = 0;
  while ((c = std::fgetc(file)) != EOF) bytes.push_back(static_cast<uint8_t>(c));
  std::fclose(file);
  return bytes;
}

void put_file(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  if (!bytes.empty()) {
    ASSERT_EQ(std::fwrite(bytes.data(), 1, bytes.size(), file), bytes.size());
  }
  std::fclose(file);
}

void put_text(const std::string& path, const std::string& text) {
  put_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

// Deterministic 16-bit samples with both extremes present.
std::vector<uint16_t> test_samples(uint32_t width, uint32_t height) {
  std::vector<uint16_t> samples(size_t{width} * height);
  uint32_t state = 12345;
  for (size_t i = 0; i < samples.size(); ++i) {
    state = state * 1664525u + 1013904223u;
    samples[i] = static_cast<uint16_t>(state >> 16);
  }
  samples.front() = 0;
  samples.back() = 65535;
  return samples;
}

float from_bits(uint32_t bits) {
  float value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

uint32_t to_bits(float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// ---------------------------------------------------------------------------
// 16-bit PNG

TEST(GimImageIo, Png16RoundTripsEverySize) {
  const uint32_t sizes[][2] = {{1, 1}, {300, 7}, {7, 300}, {64, 64}};
  for (const auto& size : sizes) {
    const std::vector<uint16_t> samples = test_samples(size[0], size[1]);
    const std::string path = temp_path(std::to_string(size[0]) + "x" + std::to_string(size[1]) + ".png");
    ASSERT_TRUE(write_png_gray16(path, size[0], size[1], samples).ok());
    uint32_t width = 0, height = 0;
    std::vector<uint16_t> read;
    Status status = read_png_gray16(path, &width, &height, &read);
    ASSERT_TRUE(status.ok()) << status.to_string();
    EXPECT_EQ(width, size[0]);
    EXPECT_EQ(height, size[1]);
    EXPECT_EQ(read, samples);
    std::remove(path.c_str());
  }
}

TEST(GimImageIo, Png16SinglePixelExtremes) {
  for (uint16_t value : {uint16_t{0}, uint16_t{1}, uint16_t{256}, uint16_t{65535}}) {
    const std::string path = temp_path("pixel.png");
    ASSERT_TRUE(write_png_gray16(path, 1, 1, {value}).ok());
    uint32_t width = 0, height = 0;
    std::vector<uint16_t> read;
    ASSERT_TRUE(read_png_gray16(path, &width, &height, &read).ok());
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(read[0], value);
    std::remove(path.c_str());
  }
}

// Our writer never interlaces; other tools may. A 5x3 Adam7 16-bit gray PNG
// (made with Python's zlib) whose samples hit every pass that has pixels.
TEST(GimImageIo, Png16ReadsInterlacedFiles) {
  static const char kPng[] =
      "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x05\x00\x00\x00\x03"
      "\x10\x00\x00\x00\x01\x59\xca\x76\xf1\x00\x00\x00\x2e\x49\x44\x41\x54\x78\xda\x63\x60\x60\x60\x38"
      "\x73\x86\x21\x2d\x8d\x61\xd5\x2a\x41\x81\xff\xff\x19\x8c\x8d\x67\xce\x64\xb8\x7b\xd7\xc5\x99\x21"
      "\x34\xb4\xa3\x63\xf7\xee\x77\xef\x94\x14\x01\xf8\x29\x0f\x00\x2f\xa2\x51\x17\x00\x00\x00\x00\x49"
      "\x45\x4e\x44\xae\x42\x60\x82";
  const std::string path = temp_path("adam7.png");
  put_file(path, std::vector<uint8_t>(kPng, kPng + sizeof kPng - 1));
  uint32_t width = 0, height = 0;
  std::vector<uint16_t> samples;
  Status status = read_png_gray16(path, &width, &height, &samples);
  ASSERT_TRUE(status.ok()) << status.to_string();
  EXPECT_EQ(width, 5u);
  EXPECT_EQ(height, 3u);
  EXPECT_EQ(samples, (std::vector<uint16_t>{0, 13107, 26214, 39321, 52428, 21845, 34952, 48059, 61166, 8737, 43690,
                                            56797, 4368, 17475, 65535}));
  std::remove(path.c_str());
}

TEST(GimImageIo, Png16MemoryEncodingEqualsFile) {
  const std::vector<uint16_t> samples = test_samples(300, 7);
  const std::string path = temp_path("plane.png");
  ASSERT_TRUE(write_png_gray16(path, 300, 7, samples).ok());
  const std::vector<uint8_t> memory = encode_png_gray16_to_memory(300, 7, samples);
  EXPECT_EQ(memory, file_bytes(path));
  ASSERT_GE(memory.size(), 8u);
  EXPECT_EQ(std::memcmp(memory.data(), "\x89PNG\r\n\x1a\n", 8), 0);
  EXPECT_TRUE(encode_png_gray16_to_memory(300, 7, {1, 2, 3}).empty());
  EXPECT_TRUE(encode_png_gray16_to_memory(0, 7, {}).empty());
  std::remove(path.c_str());
}

TEST(GimImageIo, Png16CompressesASmoothPlane) {
  const uint32_t side = 256;
  std::vector<uint16_t> ramp(side * side);
  for (uint32_t y = 0; y < side; ++y) {
    for (uint32_t x = 0; x < side; ++x) ramp[y * side + x] = static_cast<uint16_t>(x * 200 + y * 50);
  }
  const std::vector<uint8_t> png = encode_png_gray16_to_memory(side, side, ramp);
  ASSERT_FALSE(png.empty());
  EXPECT_LT(png.size(), ramp.size() * 2 / 20) << "row filters + zlib 9 should shrink a linear ramp";
}

TEST(GimImageIo, Png16WriteRejectsBadSizes) {
  const std::string path = temp_path("bad.png");
  Status status = write_png_gray16(path, 3, 3, std::vector<uint16_t>(8));
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "8 values given for a 3x3 image")) << status.message();
  EXPECT_EQ(write_png_gray16(path, 0, 3, {}).code(), ErrorCode::kInvalidArgument);
  status = write_png_gray16(path, 1u << 14, 1u << 13, {});
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "2^26")) << status.message();
}

TEST(GimImageIo, Png16ReaderRejects8BitPng) {
  const std::string path = temp_path("gray8.png");
  ASSERT_TRUE(write_png_gray8(path, 4, 2, std::vector<uint8_t>(8, 7)).ok());
  uint32_t width = 99, height = 99;
  std::vector<uint16_t> samples = {42};
  Status status = read_png_gray16(path, &width, &height, &samples);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_EQ(status.message(), path + ": 8-bit gray PNG; a geometry-image plane must be 16-bit gray");
  EXPECT_EQ(width, 99u);
  EXPECT_EQ(samples, std::vector<uint16_t>{42});

  ASSERT_TRUE(write_png_rgb8(path, 2, 2, std::vector<uint8_t>(12, 200)).ok());
  status = read_png_gray16(path, &width, &height, &samples);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "8-bit RGB PNG")) << status.message();
  std::remove(path.c_str());
}

TEST(GimImageIo, Png16ReaderRejectsBrokenFiles) {
  const std::string path = temp_path("broken.png");
  uint32_t width = 0, height = 0;
  std::vector<uint16_t> samples;

  put_text(path, "this is not a picture");
  Status status = read_png_gray16(path, &width, &height, &samples);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "not a PNG file")) << status.message();

  // Every truncation of a valid file is an error, never a crash or a partial image.
  const std::vector<uint8_t> good = encode_png_gray16_to_memory(300, 7, test_samples(300, 7));
  for (size_t keep : {size_t{8}, size_t{20}, size_t{40}, good.size() / 2, good.size() - 13, good.size() - 1}) {
    put_file(path, std::vector<uint8_t>(good.begin(), good.begin() + static_cast<long>(keep)));
    status = read_png_gray16(path, &width, &height, &samples);
    EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument) << "kept " << keep << " bytes";
    EXPECT_TRUE(samples.empty());
  }

  // A flipped byte inside IDAT breaks its CRC.
  std::vector<uint8_t> corrupt = good;
  corrupt[good.size() / 2] ^= 0x40;
  put_file(path, corrupt);
  status = read_png_gray16(path, &width, &height, &samples);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(samples.empty());

  std::remove(path.c_str());
  EXPECT_EQ(read_png_gray16(path, &width, &height, &samples).code(), ErrorCode::kIo);
}

// ---------------------------------------------------------------------------
// PFM

TEST(GimImageIo, PfmRoundTripIsBitExact) {
  const std::vector<uint32_t> bits = {
      0x7fc00001u,  // quiet NaN with a payload
      0x7f800001u,  // signalling NaN with a payload
      0xffc12345u,  // negative NaN
      0x80000000u,  // -0
      0x7f800000u,  // +inf
      0xff800000u,  // -inf
      0x00000001u,  // smallest subnormal
      to_bits(FLT_MAX), to_bits(-1.5f), to_bits(1.0f / 3.0f), 0x00000000u, to_bits(42.0f),
  };
  std::vector<float> samples;
  for (uint32_t b : bits) samples.push_back(from_bits(b));
  const std::string path = temp_path("plane.pfm");
  ASSERT_TRUE(write_pfm_gray(path, 4, 3, samples).ok());
  uint32_t width = 0, height = 0;
  std::vector<float> read;
  Status status = read_pfm_gray(path, &width, &height, &read);
  ASSERT_TRUE(status.ok()) << status.to_string();
  EXPECT_EQ(width, 4u);
  EXPECT_EQ(height, 3u);
  ASSERT_EQ(read.size(), bits.size());
  for (size_t i = 0; i < bits.size(); ++i) EXPECT_EQ(to_bits(read[i]), bits[i]) << "sample " << i;
  std::remove(path.c_str());
}

TEST(GimImageIo, PfmStoresBottomRowFirstLittleEndian) {
  const std::string path = temp_path("rows.pfm");
  ASSERT_TRUE(write_pfm_gray(path, 2, 2, {1.0f, 2.0f, 3.0f, 4.0f}).ok());  // top row 1 2, bottom row 3 4
  const std::vector<uint8_t> bytes = file_bytes(path);
  const std::string header = "Pf\n2 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 16);
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + static_cast<long>(header.size())), header);
  const uint8_t* data = bytes.data() + header.size();
  const uint32_t first = uint32_t{data[0]} | uint32_t{data[1]} << 8 | uint32_t{data[2]} << 16 | uint32_t{data[3]} << 24;
  EXPECT_EQ(first, to_bits(3.0f));
  std::remove(path.c_str());
}

TEST(GimImageIo, PfmReadsBigEndian) {
  const std::string path = temp_path("big.pfm");
  std::vector<uint8_t> bytes;
  const std::string header = "Pf\n2 1\n1.0\n";
  bytes.assign(header.begin(), header.end());
  for (float value : {0.5f, -7.25f}) {
    const uint32_t b = to_bits(value);
    for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<uint8_t>(b >> shift));
  }
  put_file(path, bytes);
  uint32_t width = 0, height = 0;
  std::vector<float> read;
  Status status = read_pfm_gray(path, &width, &height, &read);
  ASSERT_TRUE(status.ok()) << status.to_string();
  EXPECT_EQ(read, (std::vector<float>{0.5f, -7.25f}));
  std::remove(path.c_str());
}

TEST(GimImageIo, PfmRejectsTruncatedAndPaddedFiles) {
  const std::string path = temp_path("short.pfm");
  ASSERT_TRUE(write_pfm_gray(path, 3, 2, std::vector<float>(6, 1.0f)).ok());
  std::vector<uint8_t> bytes = file_bytes(path);
  uint32_t width = 0, height = 0;
  std::vector<float> read;

  put_file(path, std::vector<uint8_t>(bytes.begin(), bytes.end() - 1));
  Status status = read_pfm_gray(path, &width, &height, &read);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "truncated PFM: 23 bytes of float data, 24 needed for 3x2"))
      << status.message();
  EXPECT_TRUE(read.empty());

  bytes.push_back(0);
  put_file(path, bytes);
  status = read_pfm_gray(path, &width, &height, &read);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "1 extra bytes")) << status.message();
  EXPECT_TRUE(read.empty());
  std::remove(path.c_str());
}

TEST(GimImageIo, PfmRejectsMalformedHeaders) {
  const std::string path = temp_path("header.pfm");
  const std::string data(16, '\0');
  const struct {
    std::string text;
    const char* expected;
  } cases[] = {
      {"", "not a PFM file"},
      {"P5\n2 2\n255\n" + data, "not a PFM file"},
      {"PF\n2 2\n-1.0\n" + data, "colour PFM"},
      {"Pf\n2 2\n", "header ends early"},
      {"Pf2 2\n-1.0\n" + data, "header ends early or is malformed"},
      {"Pf\n0 2\n-1.0\n" + data, "width '0'"},
      {"Pf\n-2 2\n-1.0\n" + data, "width '-2'"},
      {"Pf\n2 x\n-1.0\n" + data, "height 'x'"},
      {"Pf\n99999999999 2\n-1.0\n" + data, "width '99999999999'"},
      {"Pf\n65536 65536\n-1.0\n" + data, "over the limit of 2^26 pixels"},
      {"Pf\n2 2\n0\n" + data, "scale '0'"},
      {"Pf\n2 2\nabc\n" + data, "scale 'abc'"},
      {"Pf\n2 2\nnan\n" + data, "scale 'nan'"},
      {"Pf\n2 2\n-1.0", "header ends early"},
  };
  for (const auto& c : cases) {
    put_text(path, c.text);
    uint32_t width = 5, height = 5;
    std::vector<float> read = {9.0f};
    Status status = read_pfm_gray(path, &width, &height, &read);
    EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument) << c.text;
    EXPECT_TRUE(contains(status.message(), c.expected)) << status.message();
    EXPECT_EQ(width, 5u);
    EXPECT_EQ(read, std::vector<float>{9.0f});
  }
  std::remove(path.c_str());
}

// ---------------------------------------------------------------------------
// Rendering

size_t non_background_pixels(const RgbImage& image) {
  size_t count = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3) {
    if (image.rgb[i] != 255 || image.rgb[i + 1] != 255 || image.rgb[i + 2] != 255) ++count;
  }
  return count;
}

TEST(GimRender, CubeCoverageMatchesProjectedArea) {
  RenderOptions options;  // orthographic 512x512, yaw 30, pitch 20
  RgbImage image;
  ASSERT_TRUE(render_mesh(make_cube(), options, &image).ok());
  ASSERT_EQ(image.rgb.size(), 512u * 512u * 3u);
  // An orthographic cube [-1,1]^3 covers 4 (|dx| + |dy| + |dz|) square units
  // for view direction d; the bounding sphere (radius sqrt 3) spans 0.9 * 512.
  const double pi = 3.14159265358979323846;
  const double yaw = 30 * pi / 180, pitch = 20 * pi / 180;
  const double units = 4 * (std::cos(pitch) * std::sin(yaw) + std::sin(pitch) + std::cos(pitch) * std::cos(yaw));
  const double scale = 0.45 * 512 / std::sqrt(3.0);
  const double expected = units * scale * scale;
  const double covered = static_cast<double>(non_background_pixels(image));
  EXPECT_NEAR(covered, expected, 0.01 * expected);
}

TEST(GimRender, PerspectiveStaysInsideTheBoundingDisc) {
  RenderOptions options;
  options.perspective = true;
  RgbImage image;
  ASSERT_TRUE(render_mesh(make_cube(), options, &image).ok());
  const double disc = 3.14159265358979323846 * (0.45 * 512) * (0.45 * 512);
  const size_t covered = non_background_pixels(image);
  EXPECT_GT(covered, static_cast<size_t>(0.4 * disc));
  EXPECT_LT(covered, static_cast<size_t>(disc));
}

TEST(GimRender, SameMeshSameBytes) {
  RenderOptions options;
  options.wireframe = true;
  options.width = 320;
  options.height = 200;
  const qmc::Mesh sphere = make_quad_sphere(6);
  const std::string first = temp_path("a.png"), second = temp_path("b.png");
  ASSERT_TRUE(render_mesh_png(sphere, options, first).ok());
  ASSERT_TRUE(render_mesh_png(sphere, options, second).ok());
  const std::vector<uint8_t> a = file_bytes(first);
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, file_bytes(second));
  std::remove(first.c_str());
  std::remove(second.c_str());
}

TEST(GimRender, WireframeDarkensPolygonEdgesOnly) {
  RenderOptions options;
  RgbImage plain, wired;
  ASSERT_TRUE(render_mesh(make_cube(), options, &plain).ok());
  options.wireframe = true;
  ASSERT_TRUE(render_mesh(make_cube(), options, &wired).ok());
  EXPECT_EQ(non_background_pixels(plain), non_background_pixels(wired));
  size_t darker = 0;
  for (size_t i = 0; i < plain.rgb.size(); ++i) {
    EXPECT_LE(wired.rgb[i], plain.rgb[i]);
    if (wired.rgb[i] < plain.rgb[i]) ++darker;
  }
  darker /= 3;
  // Nine visible edges of about 200-270 pixels, lines about 1.2 pixels wide.
  EXPECT_GT(darker, 1000u);
  EXPECT_LT(darker, 6000u);

  // One square facing the camera: its centre lies on the fan diagonal, which
  // is not a polygon edge and stays undarkened; its border is darkened.
  qmc::Mesh square;
  square.positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  square.face_sizes = {4};
  square.corners = {0, 1, 2, 3};
  options.yaw_degrees = 0;
  options.pitch_degrees = 0;
  options.width = options.height = 101;
  RgbImage image;
  ASSERT_TRUE(render_mesh(square, options, &image).ok());
  const auto grey = [&](uint32_t x, uint32_t y) { return image.rgb[3 * (size_t{y} * 101 + x)]; };
  EXPECT_EQ(grey(50, 50), grey(30, 60));
  EXPECT_EQ(grey(60, 40), grey(30, 60));  // also on the diagonal x + y = 101 (pixel centres)
  // The square spans 50.5 -+ 0.45 * 101 / sqrt 2 ~ 18.36..82.64 on both axes.
  EXPECT_LT(grey(50, 18), grey(50, 50));
  EXPECT_LT(grey(82, 50), grey(50, 50));
  EXPECT_EQ(grey(50, 2), 255);
}

TEST(GimRender, RejectsInconsistentMesh) {
  qmc::Mesh mesh = make_cube();
  mesh.corners[5] = 8;
  RgbImage image;
  Status status = render_mesh(mesh, RenderOptions{}, &image);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "corner 5 names vertex 8 of 8")) << status.message();
  EXPECT_TRUE(image.rgb.empty());
}

TEST(GimRender, FalseColourPlaneNormalisesUsedPixels) {
  const std::vector<double> values = {10, 30, 1000, NAN, 20};
  const std::vector<uint8_t> mask = {1, 1, 0, 1, 1};
  RgbImage image;
  ASSERT_TRUE(false_colour_plane(values, 5, 1, &mask, &image).ok());
  EXPECT_EQ(std::vector<uint8_t>(image.rgb.begin(), image.rgb.begin() + 6),
            (std::vector<uint8_t>{68, 1, 84, 253, 231, 37}));  // minimum, maximum
  EXPECT_EQ(std::vector<uint8_t>(image.rgb.begin() + 6, image.rgb.begin() + 12), std::vector<uint8_t>(6, 0));
  EXPECT_EQ(std::vector<uint8_t>(image.rgb.begin() + 12, image.rgb.end()), (std::vector<uint8_t>{33, 145, 140}));
  EXPECT_EQ(false_colour_plane(values, 2, 2, &mask, &image).code(), ErrorCode::kInvalidArgument);

  const std::string path = temp_path("plane.png");
  ASSERT_TRUE(render_false_colour_plane(values, 5, 1, nullptr, path).ok());
  EXPECT_GT(file_bytes(path).size(), 8u);
  std::remove(path.c_str());
}

TEST(GimRender, RgbGeometryImageMapsAxesToChannels) {
  const std::vector<double> x = {0, 2, 9}, y = {5, 5, 9}, z = {1, 0, 9};
  const std::vector<uint8_t> mask = {1, 1, 0};
  RgbImage image;
  ASSERT_TRUE(rgb_geometry_image(x, y, z, 3, 1, &mask, &image).ok());
  EXPECT_EQ(image.rgb, (std::vector<uint8_t>{0, 128, 255, 255, 128, 0, 0, 0, 0}));
  const std::string path = temp_path("gim.png");
  ASSERT_TRUE(render_rgb_geometry_image(x, y, z, 3, 1, &mask, path).ok());
  EXPECT_GT(file_bytes(path).size(), 8u);
  EXPECT_EQ(render_rgb_geometry_image(x, y, {1, 2}, 3, 1, &mask, path).code(), ErrorCode::kInvalidArgument);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace qmc::tools
