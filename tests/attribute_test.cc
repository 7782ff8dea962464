// Attributes of the corners, spec section 15: the mapping decisions of
// 15.3, round trips of random seamed tables through every coder, with and
// without oRDR, the encoder's refusals, and OBJ's vt / vn.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "attribute_generators.h"
#include "common/attribute_mapping.h"
#include "common/octahedral_normal.h"
#include "common/range_coder.h"
#include "chunk_list.h"
#include "corpus_dir.h"
#include "mesh_generators.h"
#include "mesh_io.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "roundtrip_check.h"

namespace qmc {
namespace {

std::vector<uint8_t> encode_or_fail(const Mesh& mesh, const EncodeOptions& options) {
  std::vector<uint8_t> out;
  const Status s = encode(mesh, options, &out);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return out;
}

DecodedFile decode_or_fail(const std::vector<uint8_t>& file) {
  DecodedFile d;
  const Status s = decode(file.data(), file.size(), &d);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return d;
}

// 15.3 on two triangles (0, 1, 2) and (2, 1, 3), a seam through vertices 1
// and 2: corners 3 and 4 (vertices 2 and 1 in the second face) get new
// values, corner 5 (vertex 3) too. Decoding the coded choices gives back
// m = 0 1 2 3 4 5 and U = 6; own and met choices give the listed values.
TEST(AttributeMapping, DecisionsOfTheSpecExample) {
  const std::vector<uint32_t> corners = {0, 1, 2, 2, 1, 3};
  using C = MappingChoice;
  const std::vector<C> choices = {C{}, C{}, C{}, C{C::kOwn, 0}, C{}, C{C::kMet, 1}};
  RangeEncoder enc;
  AttributeMappingModel model;
  VertexValueLists lists;
  lists.reset(4, corners);
  uint32_t met = 0;
  MappingFault fault = MappingFault::kNone;
  std::vector<uint32_t> coded;
  for (size_t k = 0; k < corners.size(); ++k)
    coded.push_back(code_corner_value(&enc, &model, &lists, corners[k], 8, &met, choices[k], &fault));
  // Corner 3 (vertex 2) reuses vertex 2's value 2; corner 4 (vertex 1) is
  // new (3); corner 5 (vertex 3) takes value 1, met at vertex 1.
  EXPECT_EQ(coded, (std::vector<uint32_t>{0, 1, 2, 2, 3, 1}));
  EXPECT_EQ(met, 4u);
  const std::vector<uint8_t> stream = enc.finish();
  RangeDecoder dec(stream.data(), stream.size());
  AttributeMappingModel model2;
  lists.reset(4, corners);
  uint32_t met2 = 0;
  std::vector<uint32_t> decoded;
  for (size_t k = 0; k < corners.size(); ++k)
    decoded.push_back(code_corner_value(&dec, &model2, &lists, corners[k], 8, &met2, MappingChoice{}, &fault));
  EXPECT_EQ(fault, MappingFault::kNone);
  EXPECT_EQ(decoded, coded);
  EXPECT_EQ(dec.unread(), 0u);
}

// With N values met already (U = N), a corner cannot be new: no NEW
// decision is coded, and an all-zero stream reads "met, j = 0".
TEST(AttributeMapping, NoNewValueOnceTheTableIsFull) {
  const std::vector<uint32_t> corners = {0, 1, 2};
  const std::vector<uint8_t> zeros(8, 0);
  RangeDecoder dec(zeros.data(), zeros.size());
  AttributeMappingModel model;
  VertexValueLists lists;
  lists.reset(3, corners);
  uint32_t met = 1;  // as if value 0 had been met
  MappingFault fault = MappingFault::kNone;
  EXPECT_EQ(code_corner_value(&dec, &model, &lists, 0, 1, &met, MappingChoice{}, &fault), 0u);
  EXPECT_EQ(fault, MappingFault::kNone);
  EXPECT_EQ(met, 1u);
}

// 15.7 on one counter-clockwise triangle (0,0,0), (1,0,0), (0,1,0): every
// corner predicts +z (t = 2, sigma = +1, X = Y = 0, L = 1), the grid point
// floor(((0 + 1) M + 1) / 2) = 512 of M = 1023 on both axes; its output is
// (1/1023, 1/1023, 1 - 2/1023) normalized.
TEST(OctahedralNormals, PredictionOfTheSpecExample) {
  const std::vector<uint32_t> corners = {0, 1, 2};
  const std::vector<uint32_t> q = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  CornerCycle cycle;
  cycle.build({3}, 3);
  ValueCorners value_corners;
  value_corners.build(corners, 3);
  for (uint32_t i = 0; i < 3; ++i) {
    OctahedralFrame frame;
    uint32_t pu = 0, pv = 0;
    predict_octahedral(value_corners.begin(i), value_corners.end(i), corners, cycle, q.data(), 1023, &frame, &pu, &pv);
    EXPECT_EQ(frame.t, 2);
    EXPECT_EQ(frame.sigma, 1);
    EXPECT_EQ(pu, 512u);
    EXPECT_EQ(pv, 512u);
  }
  float n[3];
  octahedral_output(512, 512, 1023, OctahedralFrame{}, n);
  const double u = 1.0 / 1023, w = 1 - 2.0 / 1023, l = std::sqrt(2 * u * u + w * w);
  EXPECT_EQ(n[0], float(u / l));
  EXPECT_EQ(n[2], float(w / l));
  // Facing -x: the frame puts axis 0 up with sigma -1, and (y, z) become (u, v).
  const std::vector<uint32_t> q_x = {0, 0, 0, 0, 0, 1, 0, 1, 0};  // (0,0,0), (0,0,1), (0,1,0): normal -x
  OctahedralFrame frame;
  uint32_t pu = 0, pv = 0;
  predict_octahedral(value_corners.begin(0), value_corners.end(0), corners, cycle, q_x.data(), 1023, &frame, &pu, &pv);
  EXPECT_EQ(frame.t, 0);
  EXPECT_EQ(frame.sigma, -1);
  octahedral_output(pu, pv, 1023, frame, n);
  EXPECT_LT(n[0], -0.99f);
}

// Unit normals of every direction come back within their octahedral cell,
// with the positions' frames (15.7; 15.13 where the encoder finds it
// smaller), in coder order and with oRDR.
TEST(OctahedralNormals, RoundTripAtEveryBitCount) {
  Mesh m = tools::make_scrambled(tools::triangulated(tools::make_refined_sphere(2)), 3);
  tools::add_vertex_normals(&m);
  for (bool angle_weighted : {false, true})
    for (int bits : {2, 5, 10, 16}) {
      EncodeOptions options;
      options.normal_bits = bits;
      options.keep_order = bits == 5;
      options.angle_weighted_normals = angle_weighted;
      const DecodedFile d = decode_or_fail(encode_or_fail(m, options));
      ASSERT_EQ(d.attribute_codings.size(), 1u);
      if (!angle_weighted) {
        EXPECT_EQ(d.attribute_codings[0].coding, 3) << bits;
      }
      EXPECT_TRUE(d.attribute_codings[0].octahedral()) << bits;
      EXPECT_TRUE(tools::check_round_trip(m, d).ok()) << bits << (angle_weighted ? " (angle weights allowed)" : "");
    }
}

void expect_round_trip(const Mesh& mesh, const EncodeOptions& options, const std::string& what) {
  const std::vector<uint8_t> file = encode_or_fail(mesh, options);
  const DecodedFile d = decode_or_fail(file);
  const tools::RoundTripReport r = tools::check_round_trip(mesh, d);
  EXPECT_TRUE(r.ok()) << what << ": " << r.face_mismatch << r.position_mismatch;
  ASSERT_EQ(d.mesh.attributes.size(), mesh.attributes.size()) << what;
}

// Property: random tables (own values, other vertices' values, values no
// corner uses) on soups with non-manifold edges, loose faces, repeated
// corners, and on closed quad and triangle meshes, through the quad,
// polygon and indexed coders, in coder order and with oRDR, quantized and
// exact.
TEST(AttributeRoundTrip, RandomTablesOnEveryCoder) {
  int meshes = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 20 + uint32_t(seed % 7) * 9;
    o.faces = 30 + uint32_t(seed % 5) * 11;
    o.repeated_corners = seed % 3 == 0;
    Mesh soup = tools::make_random_soup(seed, o);
    Mesh torus = tools::make_scrambled(tools::make_torus(6 + int(seed % 4), 4), seed);
    Mesh sphere = tools::triangulated(tools::make_refined_sphere(1 + int(seed % 2)));
    for (Mesh* m : {&soup, &torus, &sphere}) {
      tools::add_random_corner_attribute(m, seed, "a", AttributeKind::kGeneric, 1 + uint32_t(seed % 3));
      tools::add_chart_texcoords(m);
      for (ConnectivityChoice c : {ConnectivityChoice::kAuto, ConnectivityChoice::kIndexed}) {
        EncodeOptions options;
        options.connectivity = c;
        options.generic_bits = 8 + int(seed % 10);
        options.keep_order = seed % 2 == 0;
        options.exact_attributes = seed % 4 == 1;
        expect_round_trip(*m, options, "seed " + std::to_string(seed));
        ++meshes;
      }
    }
  }
  EXPECT_EQ(meshes, 240);
}

// 15.9: coding 4 carries coding 0's integers in 14.6's order over the
// attribute mesh; the encoder keeps it where smaller, and keeps coding 0
// when asked to (files for decoders before coding 4).
TEST(AttributeEncoder, GeometryOrderCodingCarriesCodingZerosValues) {
  Mesh sphere = tools::triangulated(tools::make_refined_sphere(3));
  tools::add_chart_texcoords(&sphere);
  EncodeOptions options;
  options.attribute_graded_start = false;  // codings 5 and 6: the next test
  options.attribute_twins = false;         // coding 9 (the sphere is mirrored): attribute_twins_test.cc
  EncodeStats stats;
  std::vector<uint8_t> file;
  ASSERT_TRUE(encode(sphere, options, &file, &stats).ok());
  ASSERT_EQ(stats.attributes.size(), 1u);
  EXPECT_TRUE(stats.attributes[0].geometry_order);
  const DecodedFile four = decode_or_fail(file);
  EXPECT_EQ(four.attribute_codings[0].coding, 4);
  options.attribute_geometry_order = false;
  EncodeStats zero_stats;
  ASSERT_TRUE(encode(sphere, options, &file, &zero_stats).ok());
  EXPECT_FALSE(zero_stats.attributes[0].geometry_order);
  EXPECT_LT(stats.attributes[0].value_bytes, zero_stats.attributes[0].value_bytes);
  const DecodedFile zero = decode_or_fail(file);
  EXPECT_EQ(zero.attribute_codings[0].coding, 0);
  EXPECT_EQ(four.mesh.attributes[0].values, zero.mesh.attributes[0].values);
  EXPECT_EQ(four.mesh.attributes[0].corner_values, zero.mesh.attributes[0].corner_values);
}

// 15.10: codings 5 and 6 are codings 0 and 4 with 14.4.1's start of the
// class probabilities. Under 1,000 values the encoder keeps them where
// smaller, as here: the same values, fewer bytes; asked for codings 0 and 4
// only, or for the label order only, it keeps within them.
// The decoded file of mesh, with one attribute, coded with the options'
// attribute_geometry_order and attribute_graded_start; its stats in *stats.
DecodedFile coded_attribute(const Mesh& mesh, bool geometry_order, bool graded_start, AttributeStats* stats) {
  EncodeOptions options;
  options.attribute_geometry_order = geometry_order;
  options.attribute_graded_start = graded_start;
  options.attribute_twins = false;  // coding 9 (mirrored meshes): attribute_twins_test.cc
  EncodeStats st;
  std::vector<uint8_t> file;
  EXPECT_TRUE(encode(mesh, options, &file, &st).ok());
  EXPECT_EQ(st.attributes.size(), 1u);
  *stats = st.attributes.at(0);
  return decode_or_fail(file);
}

TEST(AttributeEncoder, GradedStartCodingsCarryTheSameValues) {
  Mesh torus = tools::triangulated(tools::make_torus(20, 8));  // 160 vertices
  tools::add_chart_texcoords(&torus);
  const auto coded = [&](bool geometry_order, bool graded_start, AttributeStats* stats) {
    return coded_attribute(torus, geometry_order, graded_start, stats);
  };
  AttributeStats six, four, five, zero;
  const DecodedFile with_six = coded(true, true, &six);
  const DecodedFile with_four = coded(true, false, &four);
  const DecodedFile with_five = coded(false, true, &five);
  const DecodedFile with_zero = coded(false, false, &zero);
  EXPECT_EQ(with_six.attribute_codings[0].coding, 6);
  EXPECT_EQ(with_four.attribute_codings[0].coding, 4);
  EXPECT_EQ(with_five.attribute_codings[0].coding, 5);
  EXPECT_EQ(with_zero.attribute_codings[0].coding, 0);
  EXPECT_TRUE(six.graded_start && six.geometry_order);
  EXPECT_TRUE(five.graded_start && !five.geometry_order);
  EXPECT_LT(six.value_bytes, four.value_bytes);
  EXPECT_LT(five.value_bytes, zero.value_bytes);
  for (const DecodedFile* other : {&with_four, &with_five, &with_zero}) {
    EXPECT_EQ(with_six.mesh.attributes[0].values, other->mesh.attributes[0].values);
    EXPECT_EQ(with_six.mesh.attributes[0].corner_values, other->mesh.attributes[0].corner_values);
  }
}

// From 1,000 values on the encoder tries only the graded start of the
// coding that won with the flat one, and keeps it where smaller, as on this
// sphere's 1,010 texture coordinates (15.10).
TEST(AttributeEncoder, LargeTablesTryTheWinnersGradedStart) {
  Mesh sphere = tools::triangulated(tools::make_refined_sphere(2));
  tools::add_chart_texcoords(&sphere);
  AttributeStats graded, flat;
  const DecodedFile with_graded = coded_attribute(sphere, true, true, &graded);
  const DecodedFile with_flat = coded_attribute(sphere, true, false, &flat);
  EXPECT_GE(with_graded.mesh.attributes[0].value_count(), 1000u);
  EXPECT_TRUE(graded.graded_start);
  EXPECT_FALSE(flat.graded_start);
  EXPECT_EQ(graded.geometry_order, flat.geometry_order);
  EXPECT_EQ(graded.guided, flat.guided);
  EXPECT_LT(graded.value_bytes, flat.value_bytes);
  EXPECT_EQ(with_graded.mesh.attributes[0].values, with_flat.mesh.attributes[0].values);
  EXPECT_EQ(with_graded.mesh.attributes[0].corner_values, with_flat.mesh.attributes[0].corner_values);
}

// Spec 16: labels in runs, unlabelled faces, through every coder, in coder
// order and with oRDR; the encoder refuses a label past its table.
TEST(FaceLabels, RoundTripThroughEveryCoder) {
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    tools::RandomSoupOptions o;
    o.vertices = 30;
    o.faces = 50;
    Mesh soup = tools::make_random_soup(seed, o);
    Mesh torus = tools::make_scrambled(tools::make_torus(7, 5), seed);
    for (Mesh* m : {&soup, &torus}) {
      tools::add_face_labels(m, seed, 1 + uint32_t(seed % 5));
      EncodeOptions options;
      options.keep_order = seed % 2 == 0;
      options.connectivity = seed % 3 == 0 ? ConnectivityChoice::kIndexed : ConnectivityChoice::kAuto;
      const DecodedFile d = decode_or_fail(encode_or_fail(*m, options));
      ASSERT_EQ(d.mesh.face_labels.size(), 2u);
      EXPECT_EQ(d.mesh.face_labels[0].references, (std::vector<std::string>{"m.mtl"}));
      const tools::RoundTripReport r = tools::check_round_trip(*m, d);
      EXPECT_TRUE(r.ok()) << seed << ": " << r.face_mismatch;
    }
  }
  Mesh bad = tools::make_cube();
  tools::add_face_labels(&bad, 1, 2);
  bad.face_labels[0].face_values[2] = 4;  // a table of 3 values: 3 is none, 4 nothing
  std::vector<uint8_t> out;
  EXPECT_EQ(encode(bad, EncodeOptions{}, &out).code(), ErrorCode::kInvalidArgument);
}

// Issue 16: every corpus mesh with attributes or labels round-trips with all
// of them, in coder order and with oRDR (qmc verify's check).
TEST(AttributeCorpus, EveryMeshKeepsItsAttributesAndLabels) {
  int checked = 0;
  for (const char* sub : {"attr", "quad", "tri"}) {
    const std::filesystem::path dir = testing::corpus_dir() / sub;
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      Mesh m;
      std::vector<std::string> notes;
      ASSERT_TRUE(tools::read_mesh(entry.path().string(), &m, &notes).ok()) << entry.path();
      EXPECT_TRUE(notes.empty()) << entry.path() << ": " << notes.front();
      if (m.attributes.empty() && m.face_labels.empty()) continue;
      for (bool keep : {false, true}) {
        EncodeOptions options;
        options.keep_order = keep;
        const DecodedFile d = decode_or_fail(encode_or_fail(m, options));
        const tools::RoundTripReport r = tools::check_round_trip(m, d);
        EXPECT_TRUE(r.ok()) << entry.path() << (keep ? " kept order: " : ": ") << r.face_mismatch << r.position_mismatch;
      }
      ++checked;
    }
  }
  if (checked == 0) GTEST_SKIP() << "corpus not found at " << testing::corpus_dir() << " (set QMC_CORPUS_DIR)";
  EXPECT_GE(checked, 8);  // attr/ 3, quad/ 4 with texture coordinates, normals or labels, tri/cathead
}

// 15.8: per-vertex normals use mapping 0; texture coordinates with seams
// mapping 3 (15.11), or mapping 1 when asked for files earlier decoders read.
TEST(AttributeEncoder, ChoosesPerVertexMappingWhenItFits) {
  Mesh m = tools::triangulated(tools::make_refined_sphere(2));
  tools::add_vertex_normals(&m);
  tools::add_chart_texcoords(&m);
  const DecodedFile d = decode_or_fail(encode_or_fail(m, EncodeOptions{}));
  ASSERT_EQ(d.attribute_codings.size(), 2u);
  EXPECT_EQ(d.attribute_codings[0].mapping, 0);
  EXPECT_EQ(d.attribute_codings[1].mapping, 3);
  EncodeOptions earlier;
  earlier.attribute_predicted_mapping = false;
  EXPECT_EQ(decode_or_fail(encode_or_fail(m, earlier)).attribute_codings[1].mapping, 1);
  EXPECT_EQ(d.mesh.attributes[0].kind, AttributeKind::kNormal);
  EXPECT_EQ(d.mesh.attributes[1].name, "texcoord");
}

// 3.3: aTTR is ancillary and adds to the mesh without changing it: the file
// without its aTTR chunks decodes to the same faces and positions.
TEST(AttributeContainer, TheMeshIsTheSameWithoutTheChunks) {
  Mesh m = tools::make_torus(8, 5);
  tools::add_chart_texcoords(&m);
  const std::vector<uint8_t> file = encode_or_fail(m, EncodeOptions{});
  tools::Chunks chunks = tools::split_chunks(file), without;
  for (const tools::Chunk& c : chunks)
    if (c.type != kChunkAttribute) without.push_back(c);
  ASSERT_EQ(without.size() + 1, chunks.size());
  const DecodedFile a = decode_or_fail(file), b = decode_or_fail(tools::join_chunks(without));
  EXPECT_EQ(a.mesh.positions, b.mesh.positions);
  EXPECT_EQ(a.mesh.corners, b.mesh.corners);
  EXPECT_TRUE(b.mesh.attributes.empty());
}

TEST(AttributeEncoder, RefusesWhatTheFormatCannotCarry) {
  Mesh m = tools::triangulated(tools::make_refined_sphere(1));
  tools::add_chart_texcoords(&m);
  std::vector<uint8_t> out;
  EncodeOptions progressive;
  progressive.progressive_levels = 2;
  EXPECT_EQ(encode(m, progressive, &out).code(), ErrorCode::kInvalidArgument);
  Mesh bad = m;
  bad.attributes[0].corner_values[5] = uint32_t(bad.attributes[0].value_count());
  EXPECT_EQ(encode(bad, EncodeOptions{}, &out).code(), ErrorCode::kInvalidArgument);
  Mesh infinite = m;
  infinite.attributes[0].values[3] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(encode(infinite, EncodeOptions{}, &out).code(), ErrorCode::kInvalidArgument);
  EncodeOptions exact;
  exact.exact_attributes = true;
  EXPECT_TRUE(encode(infinite, exact, &out).ok());
  Mesh twice = m;
  twice.attributes.push_back(twice.attributes[0]);
  EXPECT_EQ(encode(twice, EncodeOptions{}, &out).code(), ErrorCode::kInvalidArgument);
}

// 8.1: an attribute's output is charged before its memory is reserved.
TEST(AttributeLimits, OutputChargedBeforeDecoding) {
  Mesh m = tools::make_torus(20, 12);
  tools::add_random_corner_attribute(&m, 5, "big", AttributeKind::kGeneric, 3);
  EncodeOptions exact;
  exact.exact_attributes = true;
  const std::vector<uint8_t> file = encode_or_fail(m, exact);
  DecoderLimits limits;
  limits.max_output_bytes = 20000;  // the mesh fits, the attribute's 12 bytes a value do not
  DecodedFile d;
  const Status s = decode(file.data(), file.size(), &d, limits);
  EXPECT_EQ(s.code(), ErrorCode::kLimitExceeded) << s.to_string();
  EXPECT_NE(s.message().find("aTTR"), std::string::npos) << s.message();
}

TEST(AttributeObj, ReadsAndWritesTextureCoordinatesAndNormals) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
      "vn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\nf 3/5/1 2/2/1 4/4/1\n";
  Mesh m;
  std::vector<std::string> notes;
  ASSERT_TRUE(tools::read_mesh_from_memory(text, "obj", &m, &notes).ok());
  EXPECT_TRUE(notes.empty());
  ASSERT_EQ(m.attributes.size(), 2u);
  EXPECT_EQ(m.attributes[0].name, "texcoord");
  EXPECT_EQ(m.attributes[0].components, 2u);
  EXPECT_EQ(m.attributes[0].corner_values, (std::vector<uint32_t>{0, 1, 2, 4, 1, 3}));
  EXPECT_EQ(m.attributes[1].corner_values, std::vector<uint32_t>(6, 0));
  std::string written;
  ASSERT_TRUE(tools::write_mesh_to_memory(m, "obj", &written).ok());
  Mesh again;
  ASSERT_TRUE(tools::read_mesh_from_memory(written, "obj", &again, nullptr).ok());
  EXPECT_EQ(again.attributes[0].values, m.attributes[0].values);
  EXPECT_EQ(again.attributes[0].corner_values, m.attributes[0].corner_values);
  EXPECT_EQ(again.attributes[1].values, m.attributes[1].values);
  // OFF cannot hold them: an error, never a silent loss.
  EXPECT_EQ(tools::write_mesh_to_memory(m, "off", &written).code(), ErrorCode::kInvalidArgument);
}

// Binary PLY: the header's format line, then each value in its declared
// type's bytes, least significant first. One triangle, known bytes.
TEST(AttributePly, BinaryLittleEndianHasTheDeclaredBytes) {
  Mesh m;
  m.positions = {1.0f, 0.0f, 0.0f, 0.0f, -2.0f, 0.0f, 0.0f, 0.0f, 0.5f};
  m.face_sizes = {3};
  m.corners = {0, 2, 1};
  std::string written;
  tools::MeshWriteOptions binary;
  binary.binary_ply = true;
  ASSERT_TRUE(tools::write_mesh_to_memory(m, "ply", &written, binary).ok());
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  ASSERT_EQ(written.substr(0, header.size()), header);
  const std::string body = written.substr(header.size());
  const std::string one("\x00\x00\x80\x3f", 4), zero(4, '\0'), minus_two("\x00\x00\x00\xc0", 4),
      half("\x00\x00\x00\x3f", 4);
  const std::string face = std::string("\x03", 1) + std::string("\x00\x00\x00\x00", 4) +
                           std::string("\x02\x00\x00\x00", 4) + std::string("\x01\x00\x00\x00", 4);
  EXPECT_EQ(body, one + zero + zero + zero + minus_two + zero + zero + zero + half + face);
}

// The same mesh, attributes and all, reads back from binary as from ASCII.
TEST(AttributePly, BinaryReadsBackAsAscii) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
      "0 0 0 0 0 1 255 0 0\n1 0 0 0 0 1 0 255 0\n0 1 0 0 0 1 0 0 255\n1 1 0.1 0 0 1 10 20 30\n"
      "3 0 1 2 6 0 0 1 0 0 1\n4 2 1 3 0 8 0.5 0.5 1 0 1 1 0.25 0.75\n";
  Mesh m;
  ASSERT_TRUE(tools::read_mesh_from_memory(text, "ply", &m, nullptr).ok());
  tools::MeshWriteOptions binary;
  binary.binary_ply = true;
  std::string ascii_text, binary_text;
  ASSERT_TRUE(tools::write_mesh_to_memory(m, "ply", &ascii_text).ok());
  ASSERT_TRUE(tools::write_mesh_to_memory(m, "ply", &binary_text, binary).ok());
  Mesh from_ascii, from_binary;
  ASSERT_TRUE(tools::read_mesh_from_memory(ascii_text, "ply", &from_ascii, nullptr).ok());
  ASSERT_TRUE(tools::read_mesh_from_memory(binary_text, "ply", &from_binary, nullptr).ok());
  EXPECT_EQ(from_binary.positions, from_ascii.positions);
  EXPECT_EQ(from_binary.face_sizes, from_ascii.face_sizes);
  EXPECT_EQ(from_binary.corners, from_ascii.corners);
  ASSERT_EQ(from_binary.attributes.size(), 3u);
  ASSERT_EQ(from_ascii.attributes.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(from_binary.attributes[i].name, from_ascii.attributes[i].name);
    EXPECT_EQ(from_binary.attributes[i].values, from_ascii.attributes[i].values) << i;
    EXPECT_EQ(from_binary.attributes[i].corner_values, from_ascii.attributes[i].corner_values) << i;
  }
  EXPECT_EQ(from_binary.positions, m.positions);
}

// What a format cannot hold, by name: what `qmc decode --drop-unsupported`
// leaves out. The normal here has one value for all corners, so PLY holds it
// per vertex; a normal that differs between two corners of a vertex it
// cannot, nor the face labels.
TEST(AttributeFormats, UnwritablePartsNameWhatEachFormatCannotHold) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
      "vn 0 0 1\nvn 0 1 0\n"
      "g left\nf 1/1/1 2/2/1 3/3/1\ng right\nf 3/5/2 2/2/1 4/4/1\n";
  Mesh m;
  ASSERT_TRUE(tools::read_mesh_from_memory(text, "obj", &m, nullptr).ok());
  ASSERT_EQ(m.face_labels.size(), 1u);
  const auto names = [&](const char* format) {
    std::vector<std::string> out;
    for (const tools::UnwritablePart& part : tools::unwritable_parts(m, format)) out.push_back(part.name);
    return out;
  };
  EXPECT_EQ(names("obj"), std::vector<std::string>{});
  EXPECT_EQ(names("OFF"), (std::vector<std::string>{"texcoord", "normal", "group"}));
  EXPECT_EQ(names("ply"), (std::vector<std::string>{"normal", "group"}));
  EXPECT_EQ(names("stl"), std::vector<std::string>{});  // write_mesh refuses the format itself
  // Each reason is write_mesh's own refusal, and without them the mesh writes.
  std::string written;
  const Status refused = tools::write_mesh_to_memory(m, "ply", &written);
  ASSERT_EQ(refused.code(), ErrorCode::kInvalidArgument);
  EXPECT_EQ(refused.message(), tools::unwritable_parts(m, "ply").front().reason);
  m.attributes.erase(m.attributes.begin() + 1);
  m.face_labels.clear();
  EXPECT_TRUE(tools::unwritable_parts(m, "ply").empty());
  EXPECT_TRUE(tools::write_mesh_to_memory(m, "ply", &written).ok());
}

// PLY: per-vertex normals and uchar colours, texture coordinates per corner
// (a face texcoord list), through a .qmc file and back in the same form.
TEST(AttributePly, NormalsColoursAndFaceTexcoordsRoundTrip) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
      "0 0 0 0 0 1 255 0 0\n1 0 0 0 0 1 0 255 0\n0 1 0 0 0 1 0 0 255\n1 1 0 0 0 1 10 20 30\n"
      "3 0 1 2 6 0 0 1 0 0 1\n3 2 1 3 6 0.5 0.5 1 0 1 1\n";
  Mesh m;
  std::vector<std::string> notes;
  ASSERT_TRUE(tools::read_mesh_from_memory(text, "ply", &m, &notes).ok());
  EXPECT_TRUE(notes.empty()) << notes.front();
  ASSERT_EQ(m.attributes.size(), 3u);
  EXPECT_EQ(m.attributes[0].name, "normal");
  EXPECT_EQ(m.attributes[1].name, "colour");
  EXPECT_EQ(m.attributes[1].values[9], 10.f);
  EXPECT_EQ(m.attributes[2].name, "texcoord");
  EXPECT_EQ(m.attributes[2].corner_values, (std::vector<uint32_t>{0, 1, 2, 3, 1, 4}));
  const DecodedFile d = decode_or_fail(encode_or_fail(m, EncodeOptions{}));
  EXPECT_TRUE(tools::check_round_trip(m, d).ok());
  std::string written;
  ASSERT_TRUE(tools::write_mesh_to_memory(d.mesh, "ply", &written).ok());
  EXPECT_NE(written.find("property uchar red"), std::string::npos) << written;
  EXPECT_NE(written.find("property list uchar float texcoord"), std::string::npos) << written;
  Mesh again;
  ASSERT_TRUE(tools::read_mesh_from_memory(written, "ply", &again, nullptr).ok());
  ASSERT_EQ(again.attributes.size(), 3u);
  // Written in the decoded mesh's order, the colours are the decoded ones
  // rounded: the input's integers (check_round_trip kept them within 1/8).
  const MeshAttribute& decoded = d.mesh.attributes[1];
  const MeshAttribute& back = again.attributes[1];
  for (size_t k = 0; k < again.corners.size(); ++k)
    for (uint32_t c = 0; c < 3; ++c)
      EXPECT_EQ(back.values[3 * size_t(back.corner_values[k]) + c],
                std::round(decoded.values[3 * size_t(decoded.corner_values[k]) + c]));
}

// `v x y z r g b`: a colour per vertex, through a .qmc file and back onto
// the v lines; on only some vertices, or as 7 numbers, kept out with a note.
TEST(AttributeObj, VertexColoursRoundTrip) {
  const std::string text = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0 0.25 0.5 0.75\nf 1 2 3\nf 3 2 4\n";
  Mesh m;
  std::vector<std::string> notes;
  ASSERT_TRUE(tools::read_mesh_from_memory(text, "obj", &m, &notes).ok());
  EXPECT_TRUE(notes.empty()) << notes.front();
  ASSERT_EQ(m.attributes.size(), 1u);
  EXPECT_EQ(m.attributes[0].name, "colour");
  EXPECT_EQ(m.attributes[0].kind, AttributeKind::kColour);
  EXPECT_EQ(m.attributes[0].values, (std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 1, 0.25f, 0.5f, 0.75f}));
  EXPECT_EQ(m.attributes[0].corner_values, m.corners);
  const DecodedFile d = decode_or_fail(encode_or_fail(m, EncodeOptions{}));
  EXPECT_TRUE(tools::check_round_trip(m, d).ok());
  std::string written;
  ASSERT_TRUE(tools::write_mesh_to_memory(m, "obj", &written).ok());
  EXPECT_EQ(written, "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0 0.25 0.5 0.75\nf 1 2 3\nf 3 2 4\n");
  for (const std::string partial : {"v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n",
                                    "v 0 0 0 1 0 0 1\nv 1 0 0 0 1 0 1\nv 0 1 0 0 0 1 1\nf 1 2 3\n"}) {
    Mesh p;
    notes.clear();
    ASSERT_TRUE(tools::read_mesh_from_memory(partial, "obj", &p, &notes).ok());
    EXPECT_TRUE(p.attributes.empty());
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].rfind("ignored per-vertex colours on v lines", 0), 0u) << notes[0];
  }
}

// A coloured vertex no face uses keeps its colour: a value per vertex
// travels with mapping 0 (spec 15.6), which ties value l to vertex l, and
// verify checks it, as no corner does. Exact colours, so the v lines read
// back as they were written.
TEST(AttributeObj, VertexColourOfAVertexInNoFaceTravels) {
  const std::string text = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 5 5 5 0.25 0.75 0.125\nf 1 2 3\n";
  Mesh m;
  std::vector<std::string> notes;
  ASSERT_TRUE(tools::read_mesh_from_memory(text, "obj", &m, &notes).ok());
  EncodeOptions exact;
  exact.exact_attributes = true;
  DecodedFile d = decode_or_fail(encode_or_fail(m, exact));
  ASSERT_EQ(d.attribute_codings.size(), 1u);
  EXPECT_EQ(d.attribute_codings[0].mapping, 0);
  EXPECT_TRUE(tools::check_round_trip(m, d).ok());
  std::string written;
  ASSERT_TRUE(tools::write_mesh_to_memory(d.mesh, "obj", &written).ok());
  EXPECT_NE(written.find("v 5 5 5 0.25 0.75 0.125\n"), std::string::npos) << written;
  // The check fails when that value is not the vertex's.
  d.mesh.attributes[0].values[3 * 3 + 1] = 0.5f;
  const tools::RoundTripReport r = tools::check_round_trip(m, d);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.face_mismatch.find("vertex 3, in no face"), std::string::npos) << r.face_mismatch;
}

TEST(AttributeObj, CornersWithoutAnIndexLeaveTheValuesOutWithANote) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3\n";
  Mesh m;
  std::vector<std::string> notes;
  ASSERT_TRUE(tools::read_mesh_from_memory(text, "obj", &m, &notes).ok());
  EXPECT_TRUE(m.attributes.empty());
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("only 2 of 3 face corners"), std::string::npos) << notes[0];
}

}  // namespace
}  // namespace qmc
