// Tests for tools/lib/mesh_io: round trips through every writer, each reader
// on small hand-written inputs, and the error messages for malformed files.
#include "mesh_io.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "atomic_file.h"
#include "mesh_generators.h"
#include "splitmix64.h"

namespace qmc::tools {
namespace {

using qmc::ErrorCode;
using qmc::Mesh;
using qmc::Status;

Mesh make_mesh(std::vector<float> positions, std::vector<std::vector<uint32_t>> faces) {
  Mesh mesh;
  mesh.positions = std::move(positions);
  for (const auto& face : faces) {
    mesh.face_sizes.push_back(static_cast<uint32_t>(face.size()));
    mesh.corners.insert(mesh.corners.end(), face.begin(), face.end());
  }
  return mesh;
}

uint32_t float_bits(float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// Bit-exact comparison: -0.0 and 0.0 differ, as they must for the codec.
void expect_same_mesh(const Mesh& expected, const Mesh& actual) {
  ASSERT_EQ(expected.positions.size(), actual.positions.size());
  for (size_t i = 0; i < expected.positions.size(); ++i) {
    EXPECT_EQ(float_bits(expected.positions[i]), float_bits(actual.positions[i])) << "coordinate " << i;
  }
  EXPECT_EQ(expected.face_sizes, actual.face_sizes);
  EXPECT_EQ(expected.corners, actual.corners);
}

// A soup with everything a reader must not "fix": awkward floats, a face
// with a repeated vertex, two faces on the same three vertices, an edge with
// three faces, an unreferenced vertex, and a 300-gon (PLY needs a wide count).
Mesh awkward_mesh() {
  std::vector<float> positions = {
      -0.0f,       0.0f,           0.1f,         FLT_MAX,     -FLT_MAX,       FLT_MIN,
      FLT_TRUE_MIN, 1.0f / 3.0f,   -123456.789f, 16777217.0f, 1e-30f,         -2.5e30f,
      0.5f,        0.25f,          0.125f,       7.0f,        8.0f,           9.0f,
  };
  std::vector<std::vector<uint32_t>> faces = {{0, 1, 2}, {0, 0, 1, 2}, {2, 1, 0}, {0, 1, 3}, {3, 2, 1, 0, 1}};
  const uint32_t ring_start = 6;
  std::vector<uint32_t> big_face;
  for (uint32_t i = 0; i < 300; ++i) {
    positions.push_back(static_cast<float>(i) * 0.01f);
    positions.push_back(static_cast<float>(i) * -0.02f);
    positions.push_back(static_cast<float>(i % 7));
    big_face.push_back(ring_start + i);
  }
  faces.push_back(big_face);
  return make_mesh(positions, faces);  // vertex 4 and 5 are unreferenced
}

std::string temp_path(const std::string& file) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info->name();  // "ThroughFile/0" for parameterised tests
  for (char& c : name) {
    if (c == '/') c = '_';
  }
  return ::testing::TempDir() + "qmc_mesh_io_" + name + "_" + file;
}

Status read_text(const std::string& text, const char* format, Mesh* mesh, std::vector<std::string>* warnings = nullptr) {
  return read_mesh_from_memory(text, format, mesh, warnings);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool has_warning(const std::vector<std::string>& warnings, const std::string& part) {
  for (const std::string& w : warnings) {
    if (contains(w, part)) return true;
  }
  return false;
}

std::string joined(const std::vector<std::string>& warnings) {
  std::string all;
  for (const std::string& w : warnings) all += w + "\n";
  return all;
}

// Expects kInvalidArgument whose message names `location` (e.g. "line 7").
void expect_invalid(const Status& status, const std::string& location, const std::string& problem) {
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument) << status.message();
  EXPECT_TRUE(contains(status.message(), location)) << status.message();
  EXPECT_TRUE(contains(status.message(), problem)) << status.message();
}

// ---------------------------------------------------------------------------
// Round trips

class RoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(RoundTrip, ThroughFileIsBitExact) {
  const Mesh mesh = awkward_mesh();
  const std::string path = temp_path(std::string("mesh.") + GetParam());
  ASSERT_TRUE(write_mesh(path, mesh).ok());
  Mesh read;
  std::vector<std::string> warnings;
  Status status = read_mesh(path, &read, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(mesh, read);
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
  std::remove(path.c_str());
}

TEST_P(RoundTrip, ThroughMemoryIsBitExact) {
  const Mesh mesh = awkward_mesh();
  std::string text;
  ASSERT_TRUE(write_mesh_to_memory(mesh, GetParam(), &text).ok());
  Mesh read;
  ASSERT_TRUE(read_mesh_from_memory(text, GetParam(), &read, nullptr).ok());
  expect_same_mesh(mesh, read);
}

TEST_P(RoundTrip, EmptyMesh) {
  std::string text;
  ASSERT_TRUE(write_mesh_to_memory(Mesh(), GetParam(), &text).ok());
  Mesh read = make_mesh({1, 2, 3}, {});
  ASSERT_TRUE(read_mesh_from_memory(text, GetParam(), &read, nullptr).ok());
  EXPECT_EQ(read.vertex_count(), 0u);
  EXPECT_EQ(read.face_count(), 0u);
}

INSTANTIATE_TEST_SUITE_P(MeshIo, RoundTrip, ::testing::Values("obj", "off", "ply"));

TEST(MeshIo, ExtensionIsCaseInsensitive) {
  const Mesh mesh = make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}});
  const std::string path = temp_path("MESH.ObJ");
  ASSERT_TRUE(write_mesh(path, mesh).ok());
  Mesh read;
  ASSERT_TRUE(read_mesh(path, &read, nullptr).ok());
  expect_same_mesh(mesh, read);
  std::remove(path.c_str());
}

TEST(MeshIo, WrittenTextIsPlain) {
  std::string text;
  ASSERT_TRUE(write_mesh_to_memory(make_mesh({0.5f, -0.0f, 1e20f, 1, 2, 3, 4, 5, 6}, {{0, 1, 2}}), "obj", &text).ok());
  EXPECT_EQ(text, "v 0.5 -0 1.00000002e+20\nv 1 2 3\nv 4 5 6\nf 1 2 3\n");
  ASSERT_TRUE(write_mesh_to_memory(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}}), "off", &text).ok());
  EXPECT_EQ(text, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
}

// ---------------------------------------------------------------------------
// OBJ

TEST(MeshIo, ObjReadsAllFaceFormsAndWarns) {
  const std::string obj =
      "# a comment\n"
      "mtllib x.mtl\n"
      "o thing\n"
      "v 0 0 0\n"
      "v 1.5 0 0 1.0\n"          // w
      "v 0 +2 0 0.1 0.2 0.3\n"   // colour
      "v 0 0 -3e0  # trailing comment\n"
      "vt 0 0\nvt 1 0\n"
      "vn 0 0 1\n"
      "g group\nusemtl m\ns 1\n"
      "f 1 2 3\n"
      "f 1/1 2/2 4/1\n"
      "f 1/1/1 3/2/1 4/1/1\n"
      "f 2//1 3//1 4//1\n"
      "f -4 -3 -1\n"             // relative: 1 2 4
      "f 1 2 \\\n 3 4\n"         // continuation
      "l 1 2\n"
      "p 1\n"
      "curv 0 1 1 2\n";
  Mesh mesh;
  std::vector<std::string> warnings;
  Status status = read_text(obj, "obj", &mesh, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(make_mesh({0, 0, 0, 1.5f, 0, 0, 0, 2, 0, 0, 0, -3},
                             {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}, {0, 1, 3}, {0, 1, 2, 3}}),
                   mesh);
  // Spec 15 carries an attribute on every corner or none: 6 of 19 is neither.
  EXPECT_TRUE(has_warning(warnings, "texture coordinate (vt) values: only 6 of 19 face corners")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "normal (vn) values: only 6 of 19 face corners")) << joined(warnings);
  EXPECT_TRUE(mesh.attributes.empty());
  EXPECT_TRUE(has_warning(warnings, "w (homogeneous weight) values on v lines: 1")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "colours on v lines: only 1 of 4 vertices have one")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "(l) elements: 1")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "(p) elements: 1")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "unknown keyword 'curv': 1")) << joined(warnings);
  EXPECT_EQ(mesh.face_labels.size(), 4u);  // o, g, usemtl (with mtllib), s: spec 16
  EXPECT_EQ(warnings.size(), 7u) << joined(warnings);
}

// Spec 16: groups, objects, materials (with their libraries) and smoothing
// groups become face labels, each face with the value its statements set.
TEST(MeshIo, ObjGroupsObjectsAndMaterialsAreFaceLabels) {
  const std::string obj =
      "mtllib a.mtl b.mtl\no box\ng left\nusemtl red\ns 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "f 1 2 3\ng right\nusemtl blue\ns off\nf 2 4 3\nusemtl red\nf 1 4 2\n";
  Mesh mesh;
  std::vector<std::string> warnings;
  ASSERT_TRUE(read_text(obj, "obj", &mesh, &warnings).ok());
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
  ASSERT_EQ(mesh.face_labels.size(), 4u);
  const FaceLabels& object = mesh.face_labels[0];
  const FaceLabels& group = mesh.face_labels[1];
  const FaceLabels& material = mesh.face_labels[2];
  const FaceLabels& smoothing = mesh.face_labels[3];
  EXPECT_EQ(object.name, "object");
  EXPECT_EQ(object.face_values, (std::vector<uint32_t>{0, 0, 0}));
  EXPECT_EQ(group.values, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(group.face_values, (std::vector<uint32_t>{0, 1, 1}));
  EXPECT_EQ(material.references, (std::vector<std::string>{"a.mtl", "b.mtl"}));
  EXPECT_EQ(material.values, (std::vector<std::string>{"red", "blue"}));
  EXPECT_EQ(material.face_values, (std::vector<uint32_t>{0, 1, 0}));
  EXPECT_EQ(smoothing.values, (std::vector<std::string>{"1", "off"}));
  std::string written;
  ASSERT_TRUE(write_mesh_to_memory(mesh, "obj", &written).ok());
  Mesh again;
  ASSERT_TRUE(read_text(written, "obj", &again, nullptr).ok());
  for (size_t j = 0; j < 4; ++j) {
    EXPECT_EQ(again.face_labels[j].values, mesh.face_labels[j].values) << j;
    EXPECT_EQ(again.face_labels[j].face_values, mesh.face_labels[j].face_values) << j;
    EXPECT_EQ(again.face_labels[j].references, mesh.face_labels[j].references) << j;
  }
}

// Issue #12 item 8: a file named .obj that is not an OBJ mesh is an error
// naming where, never an empty mesh.
TEST(MeshIo, ObjWithBinaryDataIsAnError) {
  Mesh mesh;
  expect_invalid(read_text(std::string("v 0 0 0\nv 1\0\xff", 13), "obj", &mesh), "<obj data> byte 11:", "NUL byte");
  std::string random(4096, ' ');
  SplitMix64 rng(12);
  for (char& c : random) c = static_cast<char>(rng.next() & 0xff);
  const Status status = read_text(random, "obj", &mesh);
  expect_invalid(status, "<obj data> byte ", "NUL byte");
  EXPECT_EQ(mesh.vertex_count(), 0u);
}

TEST(MeshIo, ObjWithoutVertexOrFaceLinesIsAnError) {
  Mesh mesh;
  expect_invalid(read_text("# exported\n\nmtllib scene.mtl\no empty\n", "obj", &mesh), "line 3:",
                 "no vertex (v) or face (f) line in the whole file, which starts 'mtllib scene.mtl'");
  expect_invalid(read_text("vt 0 0\nvn 0 0 1\n", "obj", &mesh), "line 1:", "no vertex (v) or face (f) line");
  // Printable garbage: words and newlines, but no NUL byte.
  std::string text;
  SplitMix64 rng(7);
  for (int i = 0; i < 2000; ++i) text += rng.below(8) == 0 ? '\n' : static_cast<char>('!' + rng.below(94));
  const Status status = read_text(text, "obj", &mesh);
  EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument);
  EXPECT_TRUE(contains(status.message(), "<obj data> line ")) << status.message();
}

TEST(MeshIo, ObjOfOnlyCommentsAndBlankLinesIsAnEmptyMesh) {
  for (const char* text : {"", "\n\n", "# nothing here\n   \n# at all\n"}) {
    Mesh mesh = make_mesh({1, 2, 3}, {});
    ASSERT_TRUE(read_text(text, "obj", &mesh).ok()) << text;
    EXPECT_EQ(mesh.vertex_count(), 0u);
    EXPECT_EQ(mesh.face_count(), 0u);
  }
  Mesh points;  // vertices alone are a point cloud, not garbage
  ASSERT_TRUE(read_text("v 0 0 0\nv 1 1 1\n", "obj", &points).ok());
  EXPECT_EQ(points.vertex_count(), 2u);
}

TEST(MeshIo, ObjKeepsSoupExactly) {
  // Repeated corner, duplicate face, unreferenced vertex, forward reference.
  const std::string obj = "f 1 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\nf 1 2 3\r\n";
  Mesh mesh;
  Status status = read_text(obj, "obj", &mesh);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5}, {{0, 0, 1, 2}, {0, 1, 2}, {0, 1, 2}}), mesh);
}

TEST(MeshIo, ObjErrorsNameTheLine) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  Mesh mesh;
  expect_invalid(read_text(vertices + "\nf 1 2 9\n", "obj", &mesh), "line 5:", "vertex index 9 is out of range");
  expect_invalid(read_text(vertices + "f 1 2\n", "obj", &mesh), "line 4:", "at least 3");
  expect_invalid(read_text(vertices + "f 0 1 2\n", "obj", &mesh), "line 4:", "index 0");
  expect_invalid(read_text(vertices + "f -4 1 2\n", "obj", &mesh), "line 4:", "before the first vertex");
  expect_invalid(read_text(vertices + "f 1 2 x\n", "obj", &mesh), "line 4:", "unparsable vertex index 'x'");
  expect_invalid(read_text(vertices + "f 1 2 3/\n", "obj", &mesh), "line 4:", "malformed face corner");
  expect_invalid(read_text("v 0 0\n", "obj", &mesh), "line 1:", "3 are needed");
  expect_invalid(read_text("v 0 0 1.2.3\n", "obj", &mesh), "line 1:", "unparsable number '1.2.3'");
  expect_invalid(read_text("\n\nv 0 nan 0\n", "obj", &mesh), "line 3:", "non-finite");
  expect_invalid(read_text("v 0 inf 0\n", "obj", &mesh), "line 1:", "non-finite");
  expect_invalid(read_text("v 0 1e39 0\n", "obj", &mesh), "line 1:", "outside the float range");
  expect_invalid(read_text("v 0 0 0 0x\n", "obj", &mesh), "line 1:", "unparsable number");
  EXPECT_EQ(mesh.vertex_count(), 0u);  // failed reads leave the mesh alone
}

TEST(MeshIo, ObjReadsTinyNumbersAsFloatsRound) {
  Mesh mesh;
  ASSERT_TRUE(read_text("v 1e-50 -7e-46 0.1\n", "obj", &mesh).ok());
  EXPECT_EQ(float_bits(mesh.positions[0]), float_bits(0.0f));
  EXPECT_EQ(float_bits(mesh.positions[1]), float_bits(-0.0f));
  EXPECT_EQ(float_bits(mesh.positions[2]), float_bits(0.1f));
}

// ---------------------------------------------------------------------------
// OFF

TEST(MeshIo, OffWithCommentsCountsOnHeaderLine) {
  const std::string off =
      "# leading comment\n"
      "OFF 4 2 5 # counts on the header line\n"
      "\n"
      "0 0 0\n"
      "# between vertices\n"
      "1 0 0 # after a vertex\n"
      "0 1 0\n"
      "0 0 1\n"
      "3 0 1 2\n"
      "4 0 2 3 3\n";  // a repeated corner stays
  Mesh mesh;
  std::vector<std::string> warnings;
  Status status = read_text(off, "off", &mesh, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, {{0, 1, 2}, {0, 2, 3, 3}}), mesh);
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
}

TEST(MeshIo, OffColourNormalAndTextureVariants) {
  const std::string coff =
      "COFF\n3 1 0\n"
      "0 0 0 255 0 0 255\n"
      "1 0 0 0 255 0 255\n"
      "0 1 0 0 0 255 255\n"
      "3 0 1 2 0.5 0.5 0.5\n";
  Mesh mesh;
  std::vector<std::string> warnings;
  Status status = read_text(coff, "off", &mesh, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}}), mesh);
  EXPECT_TRUE(has_warning(warnings, "colours (COFF): 3")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "face colours (OFF): 1")) << joined(warnings);

  warnings.clear();
  const std::string stcnoff = "STCNOFF\n3 1 0\n0 0 0 0 0 1 1 1 1 1 0 0\n1 0 0 0 0 1 1 1 1 1 1 0\n0 1 0 0 0 1 1 1 1 1 0 1\n3 2 1 0\n";
  status = read_text(stcnoff, "off", &mesh, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{2, 1, 0}}), mesh);
  EXPECT_TRUE(has_warning(warnings, "normals (NOFF): 3")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "texture coordinates (STOFF): 3")) << joined(warnings);

  // No keyword at all is allowed by the OFF description.
  ASSERT_TRUE(read_text("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off", &mesh).ok());
  EXPECT_EQ(mesh.face_count(), 1u);
}

TEST(MeshIo, OffErrorsNameTheLine) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  Mesh mesh;
  expect_invalid(read_text(head + "3 0 1 3\n", "off", &mesh), "line 6:", "vertex index 3 is out of range");
  expect_invalid(read_text(head + "2 0 1\n", "off", &mesh), "line 6:", "at least 3");
  expect_invalid(read_text(head + "4 0 1 2\n", "off", &mesh), "line 6:", "declares 4 corners");
  expect_invalid(read_text("OFF\n3 1 0\n0 0 0\n1 zero 0\n", "off", &mesh), "line 4:", "unparsable number 'zero'");
  expect_invalid(read_text("OFF\n3 1 0\n0 0 0\n1 0 0\n", "off", &mesh), "line 4:", "2 of 3 vertices");
  expect_invalid(read_text("OFF BINARY\n", "off", &mesh), "line 1:", "binary OFF is not supported");
  expect_invalid(read_text("OFF\n3 x 0\n", "off", &mesh), "line 2:", "count");
  expect_invalid(read_text("PLY\n", "off", &mesh), "line 1:", "expected an OFF header");
}

TEST(MeshIo, OffHugeCountDoesNotAllocate) {
  Mesh mesh;
  expect_invalid(read_text("OFF\n4000000000 1099511627776 0\n0 0 0\n", "off", &mesh), "line 3:", "1 of 4000000000");
}

// ---------------------------------------------------------------------------
// PLY

// Little- or big-endian bytes of typed values, for binary PLY in memory.
class Bytes {
 public:
  // The value's bits as an unsigned integer of the same size (or 0 if the
  // sizes differ, for the branches put() does not take).
  template <class U, class T>
  static uint64_t as_unsigned(T value) {
    U bits = 0;
    if (sizeof bits == sizeof value) std::memcpy(&bits, &value, sizeof bits);
    return bits;
  }
  explicit Bytes(bool big_endian) : big_endian_(big_endian) {}
  template <class T>
  Bytes& put(T value) {
    const uint64_t bits = sizeof value == 1   ? as_unsigned<uint8_t>(value)
                          : sizeof value == 2 ? as_unsigned<uint16_t>(value)
                          : sizeof value == 4 ? as_unsigned<uint32_t>(value)
                                              : as_unsigned<uint64_t>(value);
    for (size_t i = 0; i < sizeof value; ++i) {
      size_t shift = big_endian_ ? sizeof value - 1 - i : i;
      text_.push_back(static_cast<char>((bits >> (8 * shift)) & 0xff));
    }
    return *this;
  }
  const std::string& text() const { return text_; }

 private:
  bool big_endian_;
  std::string text_;
};

TEST(MeshIo, PlyAsciiSkipsOtherPropertiesAndElements) {
  const std::string ply =
      "ply\n"
      "format ascii 1.0\n"
      "comment made by hand\n"
      "element vertex 4\n"
      "property float32 x\n"
      "property uchar red\n"
      "property double y\n"
      "property list uchar int something\n"
      "property short z\n"
      "element face 2\n"
      "property list uint8 int32 vertex_index\n"
      "property int flags\n"
      "element edge 1\n"
      "property int vertex1\n"
      "property int vertex2\n"
      "end_header\n"
      "0.1 255 0.5 2 7 8 -3\n"
      "1 0 0 0 0\n"
      "0 0 1 1 9 0\n"
      "-0 1 0 0 32767\n"
      "3 0 1 2 7\n"
      "4 0 1 3 3 -1\n"
      "0 1\n";
  Mesh mesh;
  std::vector<std::string> warnings;
  Status status = read_text(ply, "ply", &mesh, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(make_mesh({0.1f, 0.5f, -3, 1, 0, 0, 0, 1, 0, -0.0f, 0, 32767}, {{0, 1, 2}, {0, 1, 3, 3}}), mesh);
  EXPECT_TRUE(has_warning(warnings, "ignored PLY vertex properties (red, something) on 4 vertices")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "ignored PLY face properties (flags) on 2 faces")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "ignored PLY element 'edge' (1 items)")) << joined(warnings);
}

std::string binary_ply(bool big_endian, uint32_t faces_claimed = 2) {
  std::string header = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                       " 1.0\n"
                       "element vertex 4\n"
                       "property double x\nproperty float y\nproperty int16 z\nproperty list uchar float normal\n"
                       "element material 2\nproperty uchar kind\n"
                       "element face " + std::to_string(faces_claimed) + "\n"
                       "property list ushort uint vertex_indices\nproperty float quality\n"
                       "end_header\n";
  Bytes data(big_endian);
  const double xs[4] = {0.1, 1, 0, 0};
  const float ys[4] = {-0.0f, 0, 1, 0};
  const int16_t zs[4] = {0, -2, 0, 300};
  for (int v = 0; v < 4; ++v) {
    data.put(xs[v]).put(ys[v]).put(zs[v]).put(uint8_t{1}).put(0.5f);
  }
  data.put(uint8_t{1}).put(uint8_t{2});
  data.put(uint16_t{3}).put(uint32_t{0}).put(uint32_t{1}).put(uint32_t{2}).put(1.0f);
  data.put(uint16_t{5}).put(uint32_t{3}).put(uint32_t{2}).put(uint32_t{1}).put(uint32_t{0}).put(uint32_t{3}).put(2.0f);
  return header + data.text();
}

Mesh binary_ply_mesh() {
  return make_mesh({static_cast<float>(0.1), -0.0f, 0, 1, 0, -2, 0, 1, 0, 0, 0, 300}, {{0, 1, 2}, {3, 2, 1, 0, 3}});
}

TEST(MeshIo, PlyBinaryLittleEndian) {
  Mesh mesh;
  std::vector<std::string> warnings;
  Status status = read_text(binary_ply(false), "ply", &mesh, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(binary_ply_mesh(), mesh);
  EXPECT_TRUE(has_warning(warnings, "ignored PLY vertex properties (normal) on 4 vertices")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "ignored PLY element 'material' (2 items)")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "ignored PLY face properties (quality) on 2 faces")) << joined(warnings);
}

TEST(MeshIo, PlyBinaryBigEndian) {
  Mesh mesh;
  Status status = read_text(binary_ply(true), "ply", &mesh);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(binary_ply_mesh(), mesh);
}

TEST(MeshIo, PlyBinaryTruncatedAnywhere) {
  const std::string full = binary_ply(false);
  const size_t header_size = full.find("end_header\n") + 11;
  Mesh mesh;
  for (size_t size = header_size; size < full.size(); ++size) {
    Status status = read_text(full.substr(0, size), "ply", &mesh);
    EXPECT_EQ(status.code(), ErrorCode::kInvalidArgument) << size;
    EXPECT_TRUE(contains(status.message(), "truncated binary data")) << status.message();
    EXPECT_TRUE(contains(status.message(), " byte ")) << status.message();
  }
  EXPECT_EQ(mesh.vertex_count(), 0u);
}

TEST(MeshIo, PlyHugeClaimedCountsFailWithoutAllocating) {
  Mesh mesh;
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1099511627776\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  Status status = read_text(header + std::string(24, '\0'), "ply", &mesh);
  EXPECT_TRUE(contains(status.message(), "item 2")) << status.message();
  const std::string skipped =
      "ply\nformat binary_little_endian 1.0\nelement junk 18446744073709551615\nproperty double a\n"
      "element vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  expect_invalid(read_text(skipped + "12345678", "ply", &mesh), "byte", "element 'junk' item 1");
  const std::string list = std::string(
      "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uint uint vertex_indices\nend_header\n") + "\xff\xff\xff\xff" + "1234";
  expect_invalid(read_text(list, "ply", &mesh), "byte", "truncated binary data in element 'face' item 0");
}

TEST(MeshIo, PlyAsciiErrorsNameTheLine) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  Mesh mesh;
  expect_invalid(read_text(header + vertices + "3 0 1 5\n", "ply", &mesh), "line 13:", "vertex index 5");
  expect_invalid(read_text(header + vertices + "2 0 1\n", "ply", &mesh), "line 13:", "at least 3");
  expect_invalid(read_text(header + vertices + "3 0 1\n", "ply", &mesh), "line 13:", "data ends inside element 'face'");
  expect_invalid(read_text(header + "0 0 0\n1 0 zero\n", "ply", &mesh), "line 11:", "'zero'");
  expect_invalid(read_text(header + "0 0 0\n1 0 nan\n", "ply", &mesh), "line 11:", "non-finite");
  expect_invalid(read_text(header + vertices + "256 0 1 2\n", "ply", &mesh), "line 13:", "out-of-range value '256'");
  expect_invalid(read_text("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", "ply", &mesh),
                 "line 3:", "no scalar property 'y'");
  expect_invalid(read_text("ply\nformat ascii 2.0\n", "ply", &mesh), "line 2:", "unsupported PLY version");
  expect_invalid(read_text("ply\nformat ascii 1.0\nproperty float x\n", "ply", &mesh), "line 3:", "before any element");
  expect_invalid(read_text("ply\nformat ascii 1.0\nelement vertex 1\n", "ply", &mesh), "<ply data>", "no end_header");
  expect_invalid(read_text("solid\n", "ply", &mesh), "line 1:", "'ply' magic");
}

TEST(MeshIo, PlyFacesBeforeVertices) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar uint vertex_indices\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
      "3 2 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  Mesh mesh;
  Status status = read_text(ply, "ply", &mesh);
  ASSERT_TRUE(status.ok()) << status.message();
  expect_same_mesh(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{2, 1, 0}}), mesh);
  std::string bad = ply;
  bad.replace(bad.find("3 2 1 0"), 7, "3 2 1 3");
  expect_invalid(read_text(bad, "ply", &mesh), "<ply data>", "index 3 is out of range");
}

// ---------------------------------------------------------------------------
// STL

TEST(MeshIo, StlAsciiMergesCorners) {
  const std::string stl =
      "solid two triangles\n"
      "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n      vertex 0 1 0\n"
      "    endloop\n  endfacet\n"
      "  FACET NORMAL nan 0 1\n    OUTER LOOP\n      vertex 1 0 0\n      vertex 1 1 0\n      vertex 0 1 0\n"
      "    ENDLOOP\n  ENDFACET\n"
      "  facet normal 0 0 1\n    outer loop\n      vertex -0 0 0\n      vertex 1 0 0\n      vertex 1 0 0\n"
      "    endloop\n  endfacet\n"
      "endsolid two triangles\n";
  Mesh mesh;
  std::vector<std::string> warnings;
  Status status = read_text(stl, "stl", &mesh, &warnings);
  ASSERT_TRUE(status.ok()) << status.message();
  // -0 and 0 are different bits, so not merged; the degenerate facet stays.
  expect_same_mesh(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, -0.0f, 0, 0}, {{0, 1, 2}, {1, 3, 2}, {4, 1, 1}}),
                   mesh);
  EXPECT_TRUE(has_warning(warnings, "merged 9 STL corners into 5 vertices")) << joined(warnings);
  EXPECT_TRUE(has_warning(warnings, "ignored STL facet normals: 3")) << joined(warnings);
}

std::string binary_stl(const std::string& header_text, const std::vector<std::vector<float>>& triangles) {
  Bytes data(false);
  std::string header = header_text;
  header.resize(80, ' ');
  std::string bytes = header;
  data.put(static_cast<uint32_t>(triangles.size()));
  for (const auto& triangle : triangles) {
    data.put(0.0f).put(0.0f).put(1.0f);
    for (float value : triangle) data.put(value);
    data.put(uint16_t{0});
  }
  return bytes + data.text();
}

TEST(MeshIo, StlBinaryEvenWithSolidHeader) {
  const std::vector<std::vector<float>> triangles = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}};
  const Mesh expected = make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, {{0, 1, 2}, {1, 3, 2}});
  for (const char* header : {"binary stl", "solid but actually binary"}) {
    Mesh mesh;
    std::vector<std::string> warnings;
    Status status = read_text(binary_stl(header, triangles), "stl", &mesh, &warnings);
    ASSERT_TRUE(status.ok()) << status.message();
    expect_same_mesh(expected, mesh);
    EXPECT_TRUE(has_warning(warnings, "merged 6 STL corners into 4 vertices")) << joined(warnings);
  }
}

// Issue #12 item 8: the count field (bytes 80-83) must agree with the file
// size; a count of 0 or too small would otherwise drop triangles silently.
TEST(MeshIo, StlBinaryCountDisagreeingWithTheSizeIsAnError) {
  const std::string two = binary_stl("binary", {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}});
  for (const char* header : {"binary", "solid but actually binary"}) {
    for (char count : {0, 1}) {
      std::string data = two;
      data.replace(0, std::strlen(header), header);
      data[80] = count;
      Mesh mesh;
      expect_invalid(read_text(data, "stl", &mesh), "<stl data> byte 80:",
                     "header says " + std::to_string(count) + " triangles but the file's 184 bytes hold 2");
      EXPECT_EQ(mesh.face_count(), 0u);
    }
  }
}

TEST(MeshIo, StlBinaryPaddingShorterThanATriangleIsANote) {
  const std::string two = binary_stl("binary", {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}});
  Mesh mesh;
  std::vector<std::string> warnings;
  ASSERT_TRUE(read_text(two + std::string(49, '\0'), "stl", &mesh, &warnings).ok());
  EXPECT_EQ(mesh.face_count(), 2u);
  EXPECT_TRUE(has_warning(warnings, "ignored trailing bytes after the STL triangles: 49")) << joined(warnings);
}

TEST(MeshIo, StlErrors) {
  const std::string full = binary_stl("binary", {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}});
  Mesh mesh;
  expect_invalid(read_text(full.substr(0, full.size() - 1), "stl", &mesh), "<stl data>", "truncated binary STL");
  expect_invalid(read_text(full.substr(0, 50), "stl", &mesh), "<stl data>", "truncated binary STL");
  const std::string nan_stl = binary_stl("x", {{0, 0, 0, 1, 0, 0, 0, NAN, 0}});
  expect_invalid(read_text(nan_stl, "stl", &mesh), "byte 84", "non-finite");
  const std::string facet = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n";
  expect_invalid(read_text(facet + "vertex 0 one 0\nendloop\nendfacet\nendsolid\n", "stl", &mesh), "line 6:",
                 "unparsable number 'one'");
  expect_invalid(read_text(facet + "endloop\nendfacet\nendsolid\n", "stl", &mesh), "line 6:", "at least 3");
  expect_invalid(read_text(facet, "stl", &mesh), "line 5:", "endloop");
  expect_invalid(read_text("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "stl", &mesh), "line 4:",
                 "endloop");
}

// ---------------------------------------------------------------------------
// Files and arguments

TEST(MeshIo, FileErrors) {
  Mesh mesh;
  Status status = read_mesh("/nonexistent/dir/mesh.obj", &mesh, nullptr);
  EXPECT_EQ(status.code(), ErrorCode::kIo);
  EXPECT_TRUE(contains(status.message(), "/nonexistent/dir/mesh.obj")) << status.message();
  EXPECT_EQ(read_mesh(::testing::TempDir(), &mesh, nullptr).code(), ErrorCode::kInvalidArgument);  // no extension
  EXPECT_EQ(read_mesh("mesh.3ds", &mesh, nullptr).code(), ErrorCode::kInvalidArgument);
  EXPECT_EQ(read_mesh_from_memory("", "dae", &mesh, nullptr).code(), ErrorCode::kInvalidArgument);

  const Mesh triangle = make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}});
  EXPECT_EQ(write_mesh("/nonexistent/dir/mesh.obj", triangle).code(), ErrorCode::kIo);
  EXPECT_EQ(write_mesh(temp_path("mesh.stl"), triangle).code(), ErrorCode::kInvalidArgument);

  const std::string directory = temp_path("directory.obj");
  std::filesystem::create_directory(directory);
  EXPECT_EQ(read_mesh(directory, &mesh, nullptr).code(), ErrorCode::kIo);
  std::filesystem::remove(directory);
}

// ---------------------------------------------------------------------------
// Writing in one step (issue #12 item 7)

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Names in `directory` other than `keep`: a left-over temporary file shows here.
std::vector<std::string> other_files(const std::string& directory, const std::string& keep) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    if (entry.path().filename() != keep) names.push_back(entry.path().filename().string());
  return names;
}

TEST(MeshIo, WriteMeshReplacesTheFileKeepingItsPermissions) {
  const std::string directory = temp_path("replace");
  std::filesystem::create_directories(directory);
  const std::string path = directory + "/mesh.obj";
  ASSERT_TRUE(write_mesh(path, make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}})).ok());
  struct stat st;
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  const mode_t umask_now = umask(0);
  umask(umask_now);
  EXPECT_EQ(st.st_mode & 0777, 0666u & ~umask_now);  // a new file, as any other (not 0600)
  ASSERT_EQ(chmod(path.c_str(), 0640), 0);
  ASSERT_TRUE(write_mesh(path, make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{2, 1, 0}})).ok());
  EXPECT_EQ(file_text(path), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 3 2 1\n");
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  EXPECT_TRUE(other_files(directory, "mesh.obj").empty());
  std::filesystem::remove_all(directory);
}

// A write that fails midway (here: past a file-size limit, as `ulimit -f`
// sets) leaves the old file whole and no temporary behind, and names errno.
TEST(MeshIo, WriteMeshFailingMidwayLeavesTheOldFile) {
  const std::string directory = temp_path("limit");
  std::filesystem::create_directories(directory);
  const std::string path = directory + "/mesh.obj";
  { std::ofstream(path) << "old content\n"; }
  const Mesh big = make_quad_sphere(20);  // about 100 KB of OBJ text
  rlimit saved;
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  rlimit small = saved;
  small.rlim_cur = 16384;
  auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  const Status status = write_mesh(path, big);
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previous_handler);
  EXPECT_EQ(status.code(), ErrorCode::kIo);
  EXPECT_EQ(status.message(), "cannot write " + path + ": " + std::strerror(EFBIG));
  EXPECT_EQ(file_text(path), "old content\n");
  EXPECT_TRUE(other_files(directory, "mesh.obj").empty());
  std::filesystem::remove_all(directory);
}

TEST(MeshIo, WriteFailuresNameTheReason) {
  const Status missing = write_mesh("/nonexistent/dir/mesh.obj", make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}}));
  EXPECT_EQ(missing.message(), std::string("cannot write /nonexistent/dir/mesh.obj: ") + std::strerror(ENOENT));
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  // A device is written in place (never replaced), and a full disk is named.
  const Status full = write_file_atomically("/dev/full", "x", 1);
  EXPECT_EQ(full.code(), ErrorCode::kIo);
  EXPECT_EQ(full.message(), std::string("cannot write /dev/full: ") + std::strerror(ENOSPC));
}

TEST(MeshIo, SameFileComparesDeviceAndInodeNotNames) {
  const std::string directory = temp_path("same");
  std::filesystem::create_directories(directory);
  const std::string a = directory + "/a.obj", b = directory + "/b.obj", link = directory + "/link.obj";
  { std::ofstream(a) << "v 0 0 0\n"; }
  { std::ofstream(b) << "v 0 0 0\n"; }
  std::filesystem::create_hard_link(a, link);
  EXPECT_TRUE(same_file(a, a));
  EXPECT_TRUE(same_file(a, directory + "/./a.obj"));
  EXPECT_TRUE(same_file(a, link));
  EXPECT_FALSE(same_file(a, b));  // same content, another file
  EXPECT_FALSE(same_file(a, directory + "/missing.obj"));
  std::filesystem::remove_all(directory);
}

TEST(MeshIo, WriterRejectsBrokenMeshes) {
  std::string text;
  EXPECT_EQ(write_mesh_to_memory(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 3}}), "obj", &text).code(),
            ErrorCode::kInvalidArgument);
  EXPECT_EQ(write_mesh_to_memory(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1}}), "obj", &text).code(),
            ErrorCode::kInvalidArgument);
  EXPECT_EQ(write_mesh_to_memory(make_mesh({0, 0, 0, 1, 0, 0, 0, 1, NAN}, {{0, 1, 2}}), "ply", &text).code(),
            ErrorCode::kInvalidArgument);
  Mesh mismatched = make_mesh({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}});
  mismatched.corners.push_back(0);
  EXPECT_EQ(write_mesh_to_memory(mismatched, "off", &text).code(), ErrorCode::kInvalidArgument);
}

}  // namespace
}  // namespace qmc::tools
