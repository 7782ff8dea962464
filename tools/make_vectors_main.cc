// qmc-make-vectors: writes the conformance vectors and MANIFEST
// (spec/qmc-format.md section 10) into a directory.
//
// Published vectors are frozen: this program exists to show how each was
// made and to add new ones. Re-running it over conformance/ leaves the
// existing files byte-identical as long as the encoder's output does not
// change; `git diff conformance/` shows if it did, and such a change must
// not be committed over existing vectors (give new vectors new names).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"
#include "common/polygon_symbol_coding.h"
#include "common/polygon_symbols.h"
#include "common/range_coder.h"
#include "common/splitmix64_mix.h"
#include "common/quad_codings.h"
#include "analytic_loop_files.h"
#include "attribute_generators.h"
#include "common/attribute_mapping.h"
#include "common/predicted_mapping.h"
#include "common/face_label_coding.h"
#include "common/octahedral_normal.h"
#include "encoder/position_encoder.h"
#include "chunk_list.h"
#include "mesh_generators.h"
#include "polygon_payloads.h"
#include "quad_disk_generator.h"
#include "random_polygon_mesh.h"
#include "decoder/connectivity_decoder.h"
#include "decoder/position_decoder.h"
#include "decoder/loop_level_decoder.h"
#include "encoder/loop_level_encoder.h"
#include "decoder/spirale_reversi_decoder.h"
#include "encoder/gim_writer.h"
#include "encoder/polygon_connectivity_encoder.h"
#include "gim_test_images.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "roundtrip_check.h"
#include "sha256.h"
#include "splitmix64.h"

namespace {

// The vectors published up to format 1.6 were written with POSN method 1
// where they predict positions (format 1.7's method 3 and 1.8's method 4
// came later); they stay so.
// POSN method 11 (14.12) came after every vector but the posn11 ones, which
// ask encode_posn_method for it, method 12 (14.13) after those and method
// 13 (14.14) after the posn12 ones: the others keep the encoder's choices of
// before.
qmc::EncodeOptions without_shear(qmc::EncodeOptions options) {
  options.shear = false;
  options.edge_extrapolation = false;
  options.axis_class_probabilities = false;
  options.polygon_quad_contexts = false;  // CONN coding 8 (5.4.10) came after every one of these vectors
  return options;
}

qmc::EncodeOptions format_1_6_options() {
  qmc::EncodeOptions options;
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.graded_class_start = false;
  options.geometry_order = false;
  options.quad_twist = false;
  options.attribute_geometry_order = false;
  options.attribute_graded_start = false;
  options.attribute_predicted_mapping = false;  // mapping 3 (15.11) came after these vectors
  options.attribute_guided = false;             // and coding 7 (15.12)
  options.angle_weighted_normals = false;       // and coding 8 (15.13)
  return options;
}

// The vectors published up to format 1.4 were written with method 0 on the
// per-axis grid (section 6), then the encoder's only choice; they stay so.
qmc::EncodeOptions format_1_4_options() {
  qmc::EncodeOptions options = format_1_6_options();
  options.position_grid = qmc::PositionGrid::kPerAxis;
  options.position_method = qmc::PositionMethod::kDeltas;
  options.polygon_context_coding = false;
  options.unused_vertices_along_curve = false;
  return options;
}


using qmc::Mesh;
using qmc::FaceLabels;
using qmc::MeshAttribute;

using qmc::tools::Chunk;
using qmc::tools::Chunks;
using qmc::tools::find_chunk;
using qmc::tools::join_chunks;
using qmc::tools::split_chunks;

// Vectors of format 1.0 use the indexed coding, whatever the encoder would
// choose by itself today: they are frozen (see the top of this file).
std::vector<uint8_t> encode(const Mesh& mesh, int bits, std::vector<std::string> texts = {},
                            qmc::ConnectivityChoice connectivity = qmc::ConnectivityChoice::kIndexed) {
  qmc::EncodeOptions options = format_1_4_options();
  options.position_bits = bits;
  options.connectivity = connectivity;
  options.texts = std::move(texts);
  std::vector<uint8_t> out;
  if (qmc::Status s = qmc::encode(mesh, without_shear(options), &out); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

// A valid file with one chunk's payload replaced (the CONN chunk unless
// told), for invalid streams.
class ChunkReplacer {
 public:
  explicit ChunkReplacer(const std::vector<uint8_t>& file, uint32_t type = qmc::kChunkConnectivity)
      : base_(split_chunks(file)), at_(find_chunk(base_, type)) {}
  std::vector<uint8_t> operator()(std::vector<uint8_t> payload) const {
    Chunks c = base_;
    c[at_].payload = std::move(payload);
    return join_chunks(c);
  }
  const std::vector<uint8_t>& payload() const { return base_[at_].payload; }

 private:
  Chunks base_;
  size_t at_;
};

class VectorWriter {
 public:
  explicit VectorWriter(std::string dir) : dir_(std::move(dir)) {}

  // A valid vector; `source` (if given) is checked against the decoded mesh.
  void valid(const std::string& name, const std::vector<uint8_t>& bytes, const Mesh* source) {
    qmc::DecodedFile file;
    if (qmc::Status s = qmc::decode(bytes.data(), bytes.size(), &file); !s.ok()) die(name, s.to_string());
    if (source && !qmc::tools::check_round_trip(*source, file).ok()) die(name, "does not reproduce its source");
    const std::vector<uint8_t> out = qmc::canonical_output(file);
    write(name, bytes, "valid", qmc::tools::sha256_hex(out.data(), out.size()));
  }

  void invalid(const std::string& name, const std::vector<uint8_t>& bytes, qmc::ErrorCode expected) {
    qmc::DecodedFile file;
    const qmc::Status s = qmc::decode(bytes.data(), bytes.size(), &file);
    if (s.code() != expected) die(name, "decodes as " + s.to_string());
    write(name, bytes, "invalid", qmc::error_code_name(expected));
  }

  void finish() {
    std::ofstream out(dir_ + "/MANIFEST");
    out << "# qmc conformance vectors (spec/qmc-format.md section 10).\n"
           "# valid PATH SHA256-of-canonical-output | invalid PATH ERROR\n";
    for (const std::string& line : manifest_) out << line << "\n";
  }

 private:
  void write(const std::string& name, const std::vector<uint8_t>& bytes, const char* kind, const std::string& expect) {
    const std::string path = "vectors/" + name + ".qmc";
    std::ofstream f(dir_ + "/" + path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!f) die(name, "cannot write");
    char line[512];
    std::snprintf(line, sizeof line, "%-7s %-44s %s", kind, path.c_str(), expect.c_str());
    manifest_.push_back(line);
  }
  [[noreturn]] static void die(const std::string& name, const std::string& why) {
    std::fprintf(stderr, "qmc-make-vectors: %s: %s\n", name.c_str(), why.c_str());
    std::exit(3);
  }
  std::string dir_;
  std::vector<std::string> manifest_;
};

Mesh planar_square_grid() {
  Mesh m;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) m.positions.insert(m.positions.end(), {float(x), float(y), 0.f});
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 2; ++x) {
      m.face_sizes.push_back(4);
      m.corners.insert(m.corners.end(), {3 * y + x, 3 * y + x + 1, 3 * y + x + 4, 3 * y + x + 3});
    }
  return m;
}

Mesh points_only() {
  Mesh m;
  for (int i = 0; i < 5; ++i) m.positions.insert(m.positions.end(), {float(i), float(i * i), -float(i)});
  return m;
}

// CONN payload of method 0 with a hand-made bit stream (invalid streams).
std::vector<uint8_t> conn_payload(uint64_t vertices, uint64_t faces, const std::function<void(qmc::BitWriter*)>& body) {
  std::vector<uint8_t> p{0};
  qmc::put_varint(&p, vertices);
  qmc::put_varint(&p, faces);
  qmc::BitWriter bits;
  body(&bits);
  const std::vector<uint8_t> stream = bits.finish();
  p.insert(p.end(), stream.begin(), stream.end());
  return p;
}

std::vector<uint8_t> lengths_of(std::initializer_list<std::pair<uint32_t, uint8_t>> set, size_t alphabet) {
  std::vector<uint8_t> l(alphabet, 0);
  for (auto [symbol, length] : set) l[symbol] = length;
  return l;
}

// A POSN payload for one vertex with a hand-made stream.
std::vector<uint8_t> posn_payload(uint64_t vertices, uint8_t bits, const float min[3], const float max[3],
                                  const std::function<void(qmc::BitWriter*)>& body) {
  std::vector<uint8_t> p;
  qmc::put_varint(&p, vertices);
  p.push_back(bits);
  for (int a = 0; a < 3; ++a) qmc::put_f32le(&p, min[a]);
  for (int a = 0; a < 3; ++a) qmc::put_f32le(&p, max[a]);
  qmc::BitWriter w;
  body(&w);
  const std::vector<uint8_t> stream = w.finish();
  p.insert(p.end(), stream.begin(), stream.end());
  return p;
}

void write_valid(VectorWriter* w) {
  using namespace qmc::tools;
  const Mesh empty;
  w->valid("valid_empty_mesh", encode(empty, 12), &empty);
  const Mesh tetra = make_tetrahedron();
  w->valid("valid_tetrahedron", encode(tetra, 12), &tetra);
  const Mesh cube = make_cube();
  w->valid("valid_cube_8bit", encode(cube, 8), &cube);
  const Mesh sphere = make_quad_sphere(4);
  w->valid("valid_quad_sphere", encode(sphere, 12), &sphere);
  const Mesh torus = make_torus(12, 8);
  w->valid("valid_torus_quads", encode(torus, 14), &torus);
  const Mesh prism = make_prism(40);
  w->valid("valid_prism_40gon_caps", encode(prism, 12), &prism);
  RandomSoupOptions soup_options;
  soup_options.vertices = 400;
  soup_options.faces = 500;
  const Mesh soup = make_random_soup(7, soup_options);
  w->valid("valid_random_soup", encode(soup, 16), &soup);
  const Mesh points = points_only();
  w->valid("valid_unreferenced_vertices_only", encode(points, 10), &points);
  w->valid("valid_1bit_positions", encode(sphere, 1), &sphere);
  w->valid("valid_30bit_positions", encode(sphere, 30), &sphere);
  const Mesh flat = planar_square_grid();
  w->valid("valid_flat_axis", encode(flat, 12), &flat);
  w->valid("valid_text_chunk", encode(cube, 12, {"generator=qmc conformance", "units=m"}), &cube);

  // Awkward bounds and fine steps, so that reconstruction arithmetic other
  // than spec 6.4's (another operation order, binary32, FMA) changes bits.
  RandomSoupOptions dense;
  dense.vertices = 3000;
  dense.faces = 200;
  Mesh odd = make_random_soup(21, dense);
  for (size_t i = 0; i < odd.positions.size(); i += 3) {
    odd.positions[i] = odd.positions[i] * 4321.123f - 1234.567f;
    odd.positions[i + 1] = odd.positions[i + 1] * 1.3e-3f + 1e-3f;
    odd.positions[i + 2] = odd.positions[i + 2] * 3.7f - 7.1f;
  }
  w->valid("valid_dequantization_24bit", encode(odd, 24), &odd);
  w->valid("valid_dequantization_17bit", encode(odd, 17), &odd);

  // Flat axes at -0.0: spec 6.4's formula gives +0.0, a shortcut would give -0.0.
  Mesh negative_zero;
  for (int i = 0; i < 4; ++i) negative_zero.positions.insert(negative_zero.positions.end(), {-0.f, float(i), -0.f});
  negative_zero.face_sizes = {4};
  negative_zero.corners = {0, 1, 2, 3};
  w->valid("valid_negative_zero_bounds", encode(negative_zero, 12), &negative_zero);

  Chunks c = split_chunks(encode(cube, 12));
  c.insert(c.begin() + 1, Chunk{qmc::chunk_type('e', 'x', 'T', 'n'), {1, 2, 3, 4, 5}});
  c.insert(c.end() - 1, Chunk{qmc::chunk_type('z', 'z', 'z', 'z'), {}});
  w->valid("valid_unknown_ancillary_chunks", join_chunks(c), &cube);
  c = split_chunks(encode(cube, 12));
  c[0].payload[1] = 7;
  w->valid("valid_future_minor_version", join_chunks(c), &cube);
}

void write_container_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const std::vector<uint8_t> cube = encode(qmc::tools::make_cube(), 12);
  std::vector<uint8_t> b = cube;
  b[1] = 'q';
  w->invalid("invalid_signature", b, ErrorCode::kBadSignature);
  w->invalid("invalid_truncated_signature", {cube.begin(), cube.begin() + 5}, ErrorCode::kTruncated);
  w->invalid("invalid_truncated_in_chunk", {cube.begin(), cube.end() - 20}, ErrorCode::kTruncated);
  w->invalid("invalid_missing_qend", {cube.begin(), cube.end() - 12}, ErrorCode::kTruncated);
  b = cube;
  b[8 + 12 + 2 + 12] ^= 0x01;  // a byte inside CONN's payload
  w->invalid("invalid_crc", b, ErrorCode::kBadCrc);
  b = cube;
  b.push_back(0);
  w->invalid("invalid_trailing_data", b, ErrorCode::kTrailingData);

  Chunks c = split_chunks(cube);
  c[1].type = qmc::chunk_type('C', 'O', '1', 'N');
  w->invalid("invalid_chunk_type_not_letters", join_chunks(c), ErrorCode::kBadChunkType);
  b = cube;
  b[8 + 4 + 3] = 0x80;  // QHDR length = 2^31 + 2
  w->invalid("invalid_chunk_length", b, ErrorCode::kBadChunkLength);
  c = split_chunks(cube);
  c.insert(c.begin() + 1, Chunk{qmc::chunk_type('Z', 'Z', 'Z', 'Z'), {}});
  w->invalid("invalid_unknown_critical_chunk", join_chunks(c), ErrorCode::kUnknownCriticalChunk);
  c = split_chunks(cube);
  c[0].payload[0] = 2;
  w->invalid("invalid_major_version", join_chunks(c), ErrorCode::kUnsupportedVersion);
  c = split_chunks(cube);
  c[0].payload.push_back(0);
  w->invalid("invalid_qhdr_length", join_chunks(c), ErrorCode::kBadChunkPayload);
  c = split_chunks(cube);
  c.back().payload.push_back(0);
  w->invalid("invalid_qend_not_empty", join_chunks(c), ErrorCode::kBadChunkPayload);
}

void write_order_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Chunks base = split_chunks(encode(qmc::tools::make_cube(), 12));  // QHDR CONN POSN QEND
  w->invalid("invalid_order_conn_first", join_chunks({base[1], base[0], base[2], base[3]}), ErrorCode::kChunkOrder);
  w->invalid("invalid_order_posn_before_conn", join_chunks({base[0], base[2], base[1], base[3]}), ErrorCode::kChunkOrder);
  w->invalid("invalid_order_qend_early", join_chunks({base[0], base[1], base[3]}), ErrorCode::kChunkOrder);
  w->invalid("invalid_order_second_conn", join_chunks({base[0], base[1], base[1], base[2], base[3]}), ErrorCode::kChunkOrder);
  // Spec 3.6: order rules come before unknown types and before payload checks.
  w->invalid("invalid_order_unknown_critical_first",
             join_chunks({{qmc::chunk_type('Z', 'Z', 'Z', 'Z'), {}}, base[0], base[1], base[2], base[3]}), ErrorCode::kChunkOrder);
  w->invalid("invalid_order_qend_early_not_empty", join_chunks({base[0], base[1], {qmc::kChunkEnd, {0}}}),
             ErrorCode::kChunkOrder);
  w->invalid("invalid_order_second_qhdr", join_chunks({base[0], base[0], base[1], base[2], base[3]}), ErrorCode::kChunkOrder);
}

void write_connectivity_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Mesh tetra = qmc::tools::make_tetrahedron();
  const ChunkReplacer with_conn(encode(tetra, 12));
  std::vector<uint8_t> p = with_conn.payload();
  p[0] = 9;
  w->invalid("invalid_conn_unknown_method", with_conn(p), ErrorCode::kUnsupportedFeature);
  p = with_conn.payload();
  p[1] = 3;  // vertex_count 3: the fourth vertex cannot be introduced
  w->invalid("invalid_conn_vertex_beyond_count", with_conn(p), ErrorCode::kBadSymbol);
  p = with_conn.payload();
  p.insert(p.begin() + 1, 0x84);  // vertex_count 4 written as 84 00: not shortest form
  p[2] = 0x00;
  w->invalid("invalid_conn_varint_not_shortest", with_conn(p), ErrorCode::kBadChunkPayload);
  p = with_conn.payload();
  p.push_back(0);
  w->invalid("invalid_conn_trailing_byte", with_conn(p), ErrorCode::kBadChunkPayload);
  p = {0, 4, 0xFF, 0xFF, 0xFF, 0xFF, 0x0F};
  p.insert(p.end(), with_conn.payload().begin() + 3, with_conn.payload().end());
  w->invalid("invalid_conn_face_count_unjustified", with_conn(p), ErrorCode::kLimitExceeded);

  const size_t A = 65;
  auto deg3 = [](qmc::BitWriter* b) { qmc::write_code_lengths(b, lengths_of({{0, 1}}, 33)); };
  w->invalid("invalid_conn_unknown_method_no_counts", with_conn({9}), ErrorCode::kUnsupportedFeature);
  w->invalid("invalid_huffman_exp_golomb_32_zeros", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               b->write_bits(0, 32);  // rejected at the 32nd zero, before the stream ends
             })), ErrorCode::kBadHuffmanTable);
  w->invalid("invalid_huffman_oversubscribed", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               qmc::write_code_lengths(b, lengths_of({{0, 1}, {1, 1}, {2, 1}}, 33));
             })), ErrorCode::kBadHuffmanTable);
  w->invalid("invalid_huffman_incomplete", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               qmc::write_code_lengths(b, lengths_of({{0, 1}, {1, 2}}, 33));
             })), ErrorCode::kBadHuffmanTable);
  w->invalid("invalid_huffman_single_symbol_length_2", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               qmc::write_code_lengths(b, lengths_of({{0, 2}}, 33));
             })), ErrorCode::kBadHuffmanTable);
  w->invalid("invalid_huffman_symbol_outside_alphabet", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               qmc::write_code_lengths(b, lengths_of({{40, 1}}, 41));
             })), ErrorCode::kBadHuffmanTable);
  w->invalid("invalid_conn_recent_slot_empty_list", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               deg3(b);
               qmc::write_code_lengths(b, lengths_of({{0, 1}, {5, 1}}, A));
               b->write_bits(0, 1);  // degree 3
               b->write_bits(1, 1);  // corner symbol 5: slot 4 of an empty list
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_conn_back_distance_too_far", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               deg3(b);
               qmc::write_code_lengths(b, lengths_of({{0, 1}, {34, 1}}, A));
               b->write_bits(0, 1);  // degree 3
               b->write_bits(0, 1);  // new vertex 0
               b->write_bits(1, 1);  // class 2 distance ...
               b->write_bits(1, 1);  // ... d = 3 > next_label = 1
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_conn_single_code_bad_word", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               deg3(b);
               qmc::write_code_lengths(b, lengths_of({{0, 1}}, A));
               b->write_bits(0, 1);  // degree 3
               b->write_bits(1, 1);  // '1' is no code word of a one-symbol code
               b->write_bits(0xFF, 8);
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_conn_degree_unjustified", with_conn(conn_payload(4, 1, [&](qmc::BitWriter* b) {
               qmc::write_code_lengths(b, lengths_of({{32, 1}}, 33));
               qmc::write_code_lengths(b, lengths_of({{0, 1}}, A));
               b->write_bits(0, 1);           // class 32
               b->write_bits(0x7FFFFFFF, 31);  // degree 3 + 2^32 - 1
             })), ErrorCode::kLimitExceeded);
  w->invalid("invalid_conn_truncated_stream", with_conn(conn_payload(100, 3, [&](qmc::BitWriter* b) {
               deg3(b);
               qmc::write_code_lengths(b, lengths_of({{0, 1}, {1, 1}}, A));
               // 19 bits so far; with the padding, the stream holds two faces, not three.
               b->write_bits(0, 1);
               b->write_bits(0, 2);
             })), ErrorCode::kTruncated);
}

void write_position_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Chunks base = split_chunks(encode(qmc::tools::make_tetrahedron(), 12));
  const size_t posn = find_chunk(base, qmc::kChunkPositions);
  auto with_posn = [&](std::vector<uint8_t> payload) {
    Chunks c = base;
    c[posn].payload = std::move(payload);
    return join_chunks(c);
  };
  std::vector<uint8_t> p = base[posn].payload;
  p[0] = 5;
  w->invalid("invalid_posn_count_mismatch", with_posn(p), ErrorCode::kBadChunkPayload);
  p = base[posn].payload;
  p[1] = 0;
  w->invalid("invalid_posn_zero_bits", with_posn(p), ErrorCode::kBadChunkPayload);
  p[1] = 31;
  w->invalid("invalid_posn_31_bits", with_posn(p), ErrorCode::kBadChunkPayload);
  p = base[posn].payload;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<uint8_t> nan_bytes;
  qmc::put_f32le(&nan_bytes, nan);
  std::copy(nan_bytes.begin(), nan_bytes.end(), p.begin() + 2);
  w->invalid("invalid_posn_nan_bound", with_posn(p), ErrorCode::kBadChunkPayload);
  p = base[posn].payload;
  std::swap_ranges(p.begin() + 2, p.begin() + 6, p.begin() + 14);  // swap min.x and max.x
  w->invalid("invalid_posn_min_above_max", with_posn(p), ErrorCode::kBadChunkPayload);
  p = base[posn].payload;
  p.push_back(0);
  w->invalid("invalid_posn_trailing_byte", with_posn(p), ErrorCode::kBadChunkPayload);
  p = base[posn].payload;
  p.resize(p.size() - 1);
  w->invalid("invalid_posn_truncated_stream", with_posn(p), ErrorCode::kTruncated);

  // One vertex, no faces: CONN says V = 1.
  const std::vector<uint8_t> conn_v1 = {0, 1, 0};
  const float lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, flat_hi[3] = {0, 1, 1};
  auto one_vertex = [&](const float* max, bool negative) {
    return posn_payload(1, 4, lo, max, [&](qmc::BitWriter* b) {
      qmc::write_code_lengths(b, lengths_of({{1, 1}}, 5));  // x: class 1 only
      qmc::write_code_lengths(b, lengths_of({{0, 1}}, 5));
      qmc::write_code_lengths(b, lengths_of({{0, 1}}, 5));
      b->write_bits(0, 1);              // x class 1
      b->write_bits(negative ? 1 : 0, 1);  // sign
      b->write_bits(0, 2);              // y, z class 0
    });
  };
  w->invalid("invalid_posn_negative_value", join_chunks({base[0], {qmc::kChunkConnectivity, conn_v1},
                                                  {qmc::kChunkPositions, one_vertex(hi, true)}, base.back()}),
             ErrorCode::kBadSymbol);
  w->invalid("invalid_posn_flat_axis_nonzero", join_chunks({base[0], {qmc::kChunkConnectivity, conn_v1},
                                                     {qmc::kChunkPositions, one_vertex(flat_hi, false)}, base.back()}),
             ErrorCode::kBadSymbol);
  const std::vector<uint8_t> conn_huge = {0, 0xFF, 0xFF, 0xFF, 0xFF, 0x0F, 0};
  w->invalid("invalid_posn_vertex_count_unjustified",
             join_chunks({base[0], {qmc::kChunkConnectivity, conn_huge},
                   {qmc::kChunkPositions, posn_payload(0xFFFFFFFFu, 12, lo, hi, [](qmc::BitWriter* b) {
                      b->write_bits(0xABCD, 16);
                    })}, base.back()}),
             ErrorCode::kLimitExceeded);
}

// Structured connectivity (methods 1 and 2) with a forced coding or -1.
std::vector<uint8_t> encode_structured(const Mesh& mesh, qmc::ConnectivityChoice choice, int coding) {
  qmc::EncodeOptions options = format_1_4_options();
  options.connectivity = choice;
  options.quad_coding = choice == qmc::ConnectivityChoice::kQuad ? coding : -1;
  options.polygon_coding = choice == qmc::ConnectivityChoice::kPolygon ? coding : -1;
  std::vector<uint8_t> out;
  if (qmc::Status s = qmc::encode(mesh, without_shear(options), &out); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

// Format 1.1: connectivity method 1, the quad coder (spec 5.3).
std::vector<uint8_t> encode_quads(const Mesh& mesh, int coding = -1) {
  return encode_structured(mesh, qmc::ConnectivityChoice::kQuad, coding);
}

Mesh decoded_disk(const std::vector<uint8_t>& types) {
  Mesh m;
  if (qmc::Status s = qmc::spirale_reversi_decode(types, false, UINT32_MAX, &m); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: a generated disk does not decode: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  uint32_t n = 0;
  for (uint32_t v : m.corners) n = std::max(n, v + 1);
  for (uint32_t i = 0; i < n; ++i) m.positions.insert(m.positions.end(), {float(i % 7), float(i / 7), float(i % 3)});
  return m;
}

// A random disk in which all thirteen interaction types occur.
Mesh all_types_disk() {
  for (uint64_t seed = 1;; ++seed) {
    const std::vector<uint8_t> types = qmc::tools::random_quad_sequence(seed, 80);
    bool seen[14] = {};
    for (uint8_t t : types) seen[t] = true;
    bool all = true;
    for (int t = 1; t <= 13; ++t) all = all && seen[t];
    if (all) return decoded_disk(types);
  }
}

// A disk whose sequence keeps the seed's claim and uses every code word of
// Codings I-III: all 22 pairs (type, class of the next type) they define.
Mesh every_code_word_disk() {
  for (uint64_t seed = 1;; ++seed) {
    const std::vector<uint8_t> types = qmc::tools::random_quad_sequence(seed, 300, true);
    bool pair[14][2] = {};
    for (size_t i = 0; i < types.size(); ++i)
      pair[types[i]][i + 1 < types.size() ? (types[i + 1] >= 6) : 1] = true;
    int covered = 0;
    for (int t = 1; t <= 13; ++t)
      for (int n = 0; n < 2; ++n)
        covered += pair[t][n] && qmc::fixed_code_word(qmc::QuadCoding::kCodingI, t, qmc::QuadClass(n)).length > 0;
    if (covered == 22) return decoded_disk(types);
  }
}

void write_quad_valid(VectorWriter* w) {
  using namespace qmc::tools;
  const Mesh sphere = make_refined_sphere(1);  // 240 quads, closed
  const char* names[] = {"plain", "coding_i", "coding_ii", "coding_iii", "huffman"};
  for (int c = 0; c < qmc::kQuadCodingCount; ++c)
    w->valid(std::string("valid_quad_sphere240_") + names[c], encode_quads(sphere, c), &sphere);
  const Mesh thesis = decoded_disk({13, 6, 6, 5, 12, 12, 6, 6, 12, 12, 9, 1, 6, 1});
  w->valid("valid_quad_thesis_example_coding_i", encode_quads(thesis, 1), &thesis);
  const Mesh all = all_types_disk();
  w->valid("valid_quad_all_thirteen_types", encode_quads(all), &all);
  const Mesh grid = make_grid(6, 4);
  w->valid("valid_quad_grid_one_boundary", encode_quads(grid), &grid);
  const Mesh doublet = split_quad_with_doublet(make_grid(4, 4), 5);
  w->valid("valid_quad_valence_two_vertex", encode_quads(doublet), &doublet);
  const Mesh every = every_code_word_disk();
  w->valid("valid_quad_every_code_word_coding_i", encode_quads(every, 1), &every);
  w->valid("valid_quad_every_code_word_coding_ii", encode_quads(every, 2), &every);
  w->valid("valid_quad_every_code_word_coding_iii", encode_quads(every, 3), &every);
  Mesh cube = make_cube();
  cube.positions.insert(cube.positions.end(), {9, 9, 9, -9, 9, 9, 9, -9, 9});
  w->valid("valid_quad_cube_unreferenced_vertices", encode_quads(cube), &cube);
  Mesh pillow;
  pillow.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  pillow.face_sizes = {4, 4};
  pillow.corners = {0, 1, 2, 3, 3, 2, 1, 0};
  w->valid("valid_quad_two_quad_pillow", encode_quads(pillow), &pillow);
}

// Method-1 CONN payload with types in the plain 4-bit coding, or raw stream bytes.
std::vector<uint8_t> quad_conn(uint64_t vertices, uint64_t faces, uint8_t flags, uint8_t coding,
                               const std::vector<uint8_t>& plain_types, std::vector<uint8_t> raw = {}) {
  std::vector<uint8_t> p{1};
  qmc::put_varint(&p, vertices);
  qmc::put_varint(&p, faces);
  p.push_back(flags);
  p.push_back(coding);
  if (raw.empty()) {
    qmc::BitWriter bits;
    for (uint8_t t : plain_types) bits.write_bits(uint32_t(t - 1), 4);
    raw = bits.finish();
  }
  p.insert(p.end(), raw.begin(), raw.end());
  return p;
}

void write_quad_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const ChunkReplacer with_conn(encode_quads(qmc::tools::make_cube()));
  // Types are listed in stream (encoder) order; the decoder applies them last to first.
  w->invalid("invalid_quad_no_boundary_for_q5", with_conn(quad_conn(8, 2, 0, 0, {1, 5})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_empty_loop_stack", with_conn(quad_conn(8, 2, 0, 0, {3, 1})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_q8_one_loop", with_conn(quad_conn(8, 3, 0, 0, {8, 1, 1})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_q13_on_four_edges", with_conn(quad_conn(8, 2, 0, 0, {13, 1})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_loop_left_over", with_conn(quad_conn(8, 2, 0, 0, {1, 1})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_closed_six_edges_left", with_conn(quad_conn(8, 3, 1, 0, {2, 1})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_labels_beyond_vertex_count", with_conn(quad_conn(5, 2, 0, 0, {6, 1})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_edge_used_twice", with_conn(quad_conn(8, 3, 0, 0, {13, 2, 1})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_reserved_flags", with_conn(quad_conn(8, 1, 2, 0, {1})), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_quad_unknown_coding", with_conn(quad_conn(8, 1, 0, 5, {1})), ErrorCode::kUnsupportedFeature);
  w->invalid("invalid_quad_closed_one_face", with_conn(quad_conn(8, 1, 1, 0, {})), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_quad_plain_value_13", with_conn(quad_conn(8, 1, 0, 0, {}, {0xD0})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_coding_iii_unused_word", with_conn(quad_conn(8, 1, 0, 3, {}, {0xF8})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_last_announces_class_a", with_conn(quad_conn(8, 1, 0, 1, {}, {0x00})), ErrorCode::kBadSymbol);
  w->invalid("invalid_quad_count_unjustified", with_conn(quad_conn(8, 40, 0, 0, {1})), ErrorCode::kLimitExceeded);
  w->invalid("invalid_quad_truncated_codes", with_conn(quad_conn(8, 3, 0, 0, {6, 1})), ErrorCode::kTruncated);
  w->invalid("invalid_quad_trailing_byte", with_conn(quad_conn(8, 1, 0, 0, {}, {0x00, 0x00})), ErrorCode::kBadChunkPayload);
}

// Format 1.2: connectivity method 2, the polygon coder (spec 5.4).
std::vector<uint8_t> encode_polygons(const Mesh& mesh, int coding = -1) {
  return encode_structured(mesh, qmc::ConnectivityChoice::kPolygon, coding);
}

// Appends `b`'s faces and vertices to `a` (vertex indices shifted), then
// optionally identifies vertex `glue_b` of b with vertex `glue_a` of a.
Mesh combined(Mesh a, const Mesh& b, int glue_a = -1, int glue_b = -1) {
  const uint32_t shift = uint32_t(a.vertex_count());
  a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
  a.face_sizes.insert(a.face_sizes.end(), b.face_sizes.begin(), b.face_sizes.end());
  for (uint32_t v : b.corners) a.corners.push_back(glue_b >= 0 && v == uint32_t(glue_b) ? uint32_t(glue_a) : v + shift);
  return a;
}

Mesh shifted(Mesh m, float dx) {
  for (size_t i = 0; i < m.positions.size(); i += 3) m.positions[i] += dx;
  return m;
}

void write_polygon_valid(VectorWriter* w) {
  using namespace qmc::tools;
  const Mesh tet = make_tetrahedron();
  w->valid("polygon_tetrahedron", encode_polygons(tet), &tet);
  const Mesh torus = make_torus(6, 4);
  w->valid("polygon_torus_handle", encode_polygons(torus), &torus);
  w->valid("polygon_torus_mixed_huffman", encode_polygons(torus, qmc::kPolygonMixedHuffman), &torus);
  w->valid("polygon_torus_coding_plain", encode_polygons(torus, 0), &torus);
  const Mesh prism = make_prism(7);
  w->valid("polygon_prism_heptagons", encode_polygons(prism), &prism);
  const Mesh grid = make_grid(3, 2);
  w->valid("polygon_grid_hole", encode_polygons(grid), &grid);
  Mesh two = combined(tet, shifted(make_cube(), 3.f));
  two.positions.insert(two.positions.end(), {9.f, 9.f, 9.f});  // an isolated vertex
  w->valid("polygon_two_components_isolated_vertex", encode_polygons(two), &two);
  const Mesh pinched = combined(tet, shifted(tet, 2.f), 0, 0);  // two tetrahedra sharing vertex 0
  w->valid("polygon_pinched_vertex", encode_polygons(pinched), &pinched);
  Mesh book = tet;  // a fourth face on edge 0-1 makes it non-manifold
  book.positions.insert(book.positions.end(), {0.5f, -1.f, 0.5f});
  book.face_sizes.push_back(3);
  book.corners.insert(book.corners.end(), {0, 1, 4});
  w->valid("polygon_book_edge", encode_polygons(book), &book);
  Mesh loose = tet;  // a face that repeats a vertex
  loose.face_sizes.push_back(4);
  loose.corners.insert(loose.corners.end(), {0, 1, 0, 2});
  w->valid("polygon_loose_face", encode_polygons(loose), &loose);
  Mesh flipped = make_cube();  // one face turned over: its four edges disagree with their neighbours
  std::swap(flipped.corners[1], flipped.corners[3]);
  w->valid("polygon_flipped_face", encode_polygons(flipped), &flipped);
}

// A method-2 CONN payload written field by field.
std::vector<uint8_t> polygon_conn(uint32_t vertices, uint32_t faces, uint8_t flags, uint8_t coding,
                                  const std::function<void(qmc::BitWriter*)>& stream) {
  std::vector<uint8_t> p{uint8_t(qmc::ConnectivityMethod::kPolygon)};
  qmc::put_varint(&p, vertices);
  qmc::put_varint(&p, faces);
  p.push_back(flags);
  p.push_back(coding);
  qmc::BitWriter bits;
  stream(&bits);
  const std::vector<uint8_t> raw = bits.finish();
  p.insert(p.end(), raw.begin(), raw.end());
  return p;
}

// The pillow: two quads on the same four vertices, one component whose
// first face is cut open and whose other face is Q1. Records are appended
// by `tail` (default: none).
void pillow(qmc::BitWriter* b, int first_degree_minus_3 = 1, int type = 1,
            const std::function<void(qmc::BitWriter*)>& tail = nullptr) {
  b->write_exp_golomb(1);  // C
  b->write_exp_golomb(0);  // n - 2
  b->write_exp_golomb(uint32_t(first_degree_minus_3));
  b->write_bits(uint32_t(type - 1), 4);  // plain 4-bit coding
  if (tail) {
    tail(b);
  } else {
    for (int i = 0; i < 4; ++i) b->write_exp_golomb(0);  // H, S, I, L
  }
}

void write_polygon_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const ChunkReplacer with_conn(encode_polygons(qmc::tools::make_cube()));
  auto ok = [](qmc::BitWriter* b) { pillow(b); };
  // The pillow itself decodes (vertex_count 8: four of the cube's vertices are used by no face).
  w->valid("polygon_pillow_plain", with_conn(polygon_conn(8, 2, 0, 0, ok)), nullptr);
  w->invalid("invalid_polygon_reserved_flags", with_conn(polygon_conn(8, 2, 1, 0, ok)), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_polygon_unknown_coding", with_conn(polygon_conn(8, 2, 0, 6, ok)), ErrorCode::kUnsupportedFeature);
  w->invalid("invalid_polygon_components_unjustified", with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) {
               b->write_exp_golomb(5000);
             })), ErrorCode::kLimitExceeded);
  w->invalid("invalid_polygon_exp_golomb_32_zeros", with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) {
               for (int i = 0; i < 4; ++i) b->write_bits(0, 8);
               b->write_bits(0xFF, 8);
             })), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_polygon_quad_coding_no_symbols", with_conn(polygon_conn(8, 0, 0, 0, [](qmc::BitWriter* b) {
               b->write_exp_golomb(0);
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_first_face_not_closed",
             with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) { pillow(b, 2); })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_detour_without_loop",
             with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) { pillow(b, 1, 5); })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_edge_used_twice", with_conn(polygon_conn(8, 4, 0, 0, [](qmc::BitWriter* b) {
               b->write_exp_golomb(1);
               b->write_exp_golomb(2);  // four faces: the first and Q13 Q2 Q1
               b->write_exp_golomb(1);
               for (int t : {13, 2, 1}) b->write_bits(uint32_t(t - 1), 4);
               for (int i = 0; i < 4; ++i) b->write_exp_golomb(0);
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_virtual_index_past_end",
             with_conn(polygon_conn(8, 1, 0, 0, [](qmc::BitWriter* b) {
               pillow(b, 1, 1, [](qmc::BitWriter* t) {
                 t->write_exp_golomb(1);
                 t->write_exp_golomb(2);
                 for (int i = 0; i < 3; ++i) t->write_exp_golomb(0);
               });
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_seam_rotation", with_conn(polygon_conn(8, 0, 0, 0, [](qmc::BitWriter* b) {
               pillow(b, 1, 1, [](qmc::BitWriter* t) {
                 t->write_exp_golomb(2);  // faces 0 and 1 virtual
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(1);  // one seam (0, 1) with rotation 4 of degree 4
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(4);
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(0);
               });
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_seam_face_not_virtual", with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) {
               pillow(b, 1, 1, [](qmc::BitWriter* t) {
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(1);  // a seam although no face is virtual
                 for (int i = 0; i < 5; ++i) t->write_exp_golomb(0);
               });
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_identification_same_vertex", with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) {
               pillow(b, 1, 1, [](qmc::BitWriter* t) {
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(0);
                 t->write_exp_golomb(1);
                 t->write_bits(3, 2);  // N = 4 surface labels: 2 bits each
                 t->write_bits(3, 2);
                 t->write_exp_golomb(0);
               });
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_loose_label_past_vertex_count", with_conn(polygon_conn(6, 3, 0, 0, [](qmc::BitWriter* b) {
               pillow(b, 1, 1, [](qmc::BitWriter* t) {
                 for (int i = 0; i < 3; ++i) t->write_exp_golomb(0);
                 t->write_exp_golomb(1);  // one loose triangle naming vertex 7 of 6
                 t->write_exp_golomb(0);
                 for (uint32_t v : {0u, 1u, 7u}) t->write_bits(v, 3);
               });
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_face_count_mismatch", with_conn(polygon_conn(8, 3, 0, 0, ok)), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_vertex_count_too_small", with_conn(polygon_conn(3, 2, 0, 0, ok)), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_absent_context_table", with_conn(polygon_conn(8, 2, 0, 5, [](qmc::BitWriter* b) {
               b->write_exp_golomb(1);
               b->write_exp_golomb(0);
               b->write_exp_golomb(1);
               b->write_bit(false);  // no table for class A
               b->write_bit(false);  // nor for class B, where the first symbol is read
               for (int i = 0; i < 4; ++i) b->write_exp_golomb(0);
             })), ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_other_degree_unjustified", with_conn(polygon_conn(8, 2, 0, 5, [](qmc::BitWriter* b) {
               b->write_exp_golomb(1);
               b->write_exp_golomb(0);
               b->write_exp_golomb(1);
               b->write_bit(false);
               b->write_bit(true);  // class B table: only symbol 18, length 1
               std::vector<uint8_t> lengths(qmc::kPolygonSymbolCount, 0);
               lengths[qmc::kPolygonOtherSymbol] = 1;
               qmc::write_code_lengths(b, lengths);
               b->write_bit(false);             // symbol 18
               b->write_exp_golomb(1000000);    // degree 1000005 with a handful of bits left
             })), ErrorCode::kLimitExceeded);
  w->invalid("invalid_polygon_truncated", with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) {
               b->write_exp_golomb(1);
               b->write_exp_golomb(0);
               b->write_exp_golomb(1);
               b->write_bits(0, 4);
               b->write_exp_golomb(0);  // H, then the stream ends
             })), ErrorCode::kTruncated);
  std::vector<uint8_t> trailing = polygon_conn(8, 2, 0, 0, ok);
  trailing.push_back(0);
  w->invalid("invalid_polygon_trailing_byte", with_conn(trailing), ErrorCode::kBadChunkPayload);
}

// Spec 4.5: the ancillary oRDR chunk, the input's order of vertices, faces
// and corners. Valid vectors decode to the input in its own order.
std::vector<uint8_t> encode_keeping_order(const Mesh& mesh, qmc::ConnectivityChoice connectivity) {
  qmc::EncodeOptions options = format_1_4_options();
  options.connectivity = connectivity;
  options.keep_order = true;
  std::vector<uint8_t> out;
  if (qmc::Status s = qmc::encode(mesh, without_shear(options), &out); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  return out;
}


std::vector<uint8_t> order_header(uint64_t vertices, uint64_t faces, uint8_t flags) {
  std::vector<uint8_t> p;
  qmc::put_varint(&p, vertices);
  qmc::put_varint(&p, faces);
  p.push_back(flags);
  return p;
}

// A map part of spec 4.5: its table, then each value as the difference from
// the previous value plus one (any values, to make invalid maps too).
void write_order_values(qmc::BitWriter* b, const std::vector<int64_t>& values) {
  auto magnitude = [](int64_t e) { return uint32_t(e < 0 ? -e : e); };
  std::vector<uint64_t> freq(33, 0);
  int64_t previous = -1;
  for (int64_t v : values) {
    ++freq[qmc::magnitude_class(magnitude(v - previous - 1))];
    previous = v;
  }
  const std::vector<uint8_t> lengths = qmc::huffman_code_lengths(freq);
  qmc::write_code_lengths(b, lengths);
  const qmc::HuffmanEncoder code(lengths);
  previous = -1;
  for (int64_t v : values) {
    const int64_t e = v - previous - 1;
    const int c = qmc::magnitude_class(magnitude(e));
    code.write(b, uint32_t(c));
    if (c > 0) b->write_bit(e < 0);
    qmc::write_magnitude_extra(b, magnitude(e), c);
    previous = v;
  }
}

void write_order_rotations(qmc::BitWriter* b, const std::vector<uint32_t>& offsets) {
  std::vector<uint64_t> freq(33, 0);
  for (uint32_t s : offsets) ++freq[qmc::magnitude_class(s)];
  const std::vector<uint8_t> lengths = qmc::huffman_code_lengths(freq);
  qmc::write_code_lengths(b, lengths);
  const qmc::HuffmanEncoder code(lengths);
  for (uint32_t s : offsets) {
    code.write(b, uint32_t(qmc::magnitude_class(s)));
    qmc::write_magnitude_extra(b, s, qmc::magnitude_class(s));
  }
}

std::vector<uint8_t> order_payload(std::vector<uint8_t> header, const std::function<void(qmc::BitWriter*)>& body) {
  qmc::BitWriter bits;
  body(&bits);
  const std::vector<uint8_t> stream = bits.finish();
  header.insert(header.end(), stream.begin(), stream.end());
  return header;
}

void write_input_order_vectors(VectorWriter* w) {
  using namespace qmc::tools;
  using qmc::ErrorCode;
  const Mesh sphere = qmc::tools::make_scrambled(make_quad_sphere(3), 1);  // all three maps
  w->valid("valid_ordr_quad_sphere_scrambled", encode_keeping_order(sphere, qmc::ConnectivityChoice::kQuad), &sphere);
  const Mesh grid = make_grid(5, 3);  // faces starting at their lowest vertex: rotation offsets 0
  w->valid("valid_ordr_quad_grid", encode_keeping_order(grid, qmc::ConnectivityChoice::kQuad), &grid);
  RandomSoupOptions soup_options;
  soup_options.vertices = 60;
  soup_options.faces = 40;
  const Mesh soup = make_random_soup(3, soup_options);  // indexed: the vertex map only
  w->valid("valid_ordr_indexed_soup", encode_keeping_order(soup, qmc::ConnectivityChoice::kIndexed), &soup);
  const Mesh tetra = make_tetrahedron();  // in first-reference order already: flags 0 is the identity
  Chunks c = split_chunks(encode(tetra, 12));
  c.insert(c.end() - 1, Chunk{qmc::kChunkOrder, order_header(4, 4, 0)});
  w->valid("valid_ordr_flags_zero", join_chunks(c), &tetra);

  // Invalid oRDR chunks in the quad-coded cube (8 vertices, 6 quads).
  const Chunks base = split_chunks(encode_quads(make_cube()));  // QHDR CONN POSN QEND
  auto with_order = [&](const std::vector<uint8_t>& payload) {
    Chunks chunks = base;
    chunks.insert(chunks.end() - 1, Chunk{qmc::kChunkOrder, payload});
    return join_chunks(chunks);
  };
  const uint8_t kFaces = 1, kVertices = 2, kRotations = 4;
  const std::vector<uint8_t> faces_reversed =
      order_payload(order_header(8, 6, kFaces), [](qmc::BitWriter* b) { write_order_values(b, {5, 4, 3, 2, 1, 0}); });
  w->invalid("invalid_ordr_not_permutation",
             with_order(order_payload(order_header(8, 6, kFaces),
                                      [](qmc::BitWriter* b) { write_order_values(b, {0, 1, 2, 2, 4, 5}); })),
             ErrorCode::kBadSymbol);
  w->invalid("invalid_ordr_vertex_out_of_range",
             with_order(order_payload(order_header(8, 6, kVertices),
                                      [](qmc::BitWriter* b) { write_order_values(b, {0, 1, 2, 3, 4, 5, 6, 8}); })),
             ErrorCode::kBadSymbol);
  w->invalid("invalid_ordr_rotation_out_of_range",
             with_order(order_payload(order_header(8, 6, kRotations),
                                      [](qmc::BitWriter* b) { write_order_rotations(b, {0, 1, 4, 0, 0, 0}); })),
             ErrorCode::kBadSymbol);
  w->invalid("invalid_ordr_face_count_mismatch", with_order(order_header(8, 7, 0)), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_ordr_reserved_flags", with_order(order_header(8, 6, 8)), ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> p = faces_reversed;
  p.push_back(0);
  w->invalid("invalid_ordr_trailing_byte", with_order(p), ErrorCode::kBadChunkPayload);
  p = order_header(8, 6, kFaces | kRotations);
  p.push_back(0xFF);  // 12 values cannot fit in 8 bits
  w->invalid("invalid_ordr_count_unjustified", with_order(p), ErrorCode::kLimitExceeded);
  w->invalid("invalid_ordr_truncated", with_order(order_payload(order_header(8, 6, kFaces), [](qmc::BitWriter* b) {
               qmc::write_code_lengths(b, lengths_of({{0, 1}, {3, 1}}, 4));  // class 0: '0', class 3: '1'
               while ((b->bit_count() + 3) % 8 != 0) b->write_bit(false);   // values 0, 1, ... (fewer than 6)
               b->write_bits(0b100, 3);  // class 3, '+', and one of its two extra bits: the stream ends
             })),
             ErrorCode::kTruncated);
  Chunks early = base;
  early.insert(early.begin() + 2, Chunk{qmc::kChunkOrder, faces_reversed});  // before POSN
  w->invalid("invalid_ordr_before_posn", join_chunks(early), ErrorCode::kChunkOrder);
  Chunks twice = base;
  twice.insert(twice.end() - 1, Chunk{qmc::kChunkOrder, faces_reversed});
  twice.insert(twice.end() - 1, Chunk{qmc::kChunkOrder, faces_reversed});
  w->invalid("invalid_ordr_twice", join_chunks(twice), ErrorCode::kChunkOrder);
}

// Added after the first polygon vectors: a seam that names a real face,
// which the earlier invalid_polygon_seam_face_not_virtual never reaches (its
// "2 S > H" check comes first). Two pillows; faces 0 and 2 are virtual.
void write_polygon_seam_vectors(VectorWriter* w) {
  const Chunks base = split_chunks(encode_polygons(qmc::tools::make_cube()));
  Chunks c = base;
  c[find_chunk(base, qmc::kChunkConnectivity)].payload = polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) {
    b->write_exp_golomb(2);  // C
    b->write_exp_golomb(0);
    b->write_exp_golomb(0);
    b->write_exp_golomb(1);
    b->write_exp_golomb(1);
    b->write_bits(0, 4);  // Q1
    b->write_bits(0, 4);  // Q1
    b->write_exp_golomb(2);  // H: faces 0 and 0 + 1 + 1 = 2
    b->write_exp_golomb(0);
    b->write_exp_golomb(1);
    b->write_exp_golomb(1);  // S: seam (0, 1, 0), face 1 is real
    for (int i = 0; i < 5; ++i) b->write_exp_golomb(0);
  });
  w->invalid("invalid_polygon_seam_names_real_face", join_chunks(c), qmc::ErrorCode::kBadSymbol);
}

// Section 12: progressive files aiming at analytic surfaces, then the ways a
// level can be wrong.
std::vector<uint8_t> loop_file(const Mesh& base, int levels, const qmc::LevelTargets& targets, int bits = 12,
                               qmc::PositionMethod base_positions = qmc::PositionMethod::kDeltas,
                               int displacement_code = 0, bool context_coded_faces = false) {
  std::vector<uint8_t> out;
  if (qmc::Status s = qmc::tools::make_loop_file(base, levels, targets, bits, &out, nullptr, base_positions,
                                                displacement_code, context_coded_faces);
      !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

void write_loop_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Mesh octahedron = qmc::tools::loop_octahedron();
  for (int levels = 1; levels <= 5; ++levels)
    w->valid("valid_loop_octahedron_sphere_" + std::to_string(levels) + "_levels",
             loop_file(octahedron, levels, qmc::tools::unit_sphere_targets(), 14), nullptr);
  w->valid("valid_loop_torus_genus1_3_levels",
           loop_file(qmc::tools::triangulated(qmc::tools::make_torus(9, 6)), 3, qmc::tools::torus_targets(1, 0.35)),
           nullptr);
  w->valid("valid_loop_grid_boundary_3_levels",
           loop_file(qmc::tools::triangulated(qmc::tools::make_grid(4, 3)), 3, qmc::tools::height_field_targets()),
           nullptr);

  const Chunks base = split_chunks(loop_file(octahedron, 2, qmc::tools::unit_sphere_targets()));
  const size_t loop = find_chunk(base, qmc::kChunkLoop), conn = find_chunk(base, qmc::kChunkConnectivity),
               posn = find_chunk(base, qmc::kChunkPositions), first = find_chunk(base, qmc::kChunkLevel, 0),
               second = find_chunk(base, qmc::kChunkLevel, 1);
  Chunks c = base;
  std::swap(c[posn], c[first]);
  w->invalid("invalid_loop_level_before_base", join_chunks(c), ErrorCode::kChunkOrder);
  c = base;
  c.erase(c.begin() + long(second));
  w->invalid("invalid_loop_level_missing", join_chunks(c), ErrorCode::kChunkOrder);
  c = base;
  c.insert(c.begin() + long(second) + 1, c[second]);
  w->invalid("invalid_loop_level_beyond_count", join_chunks(c), ErrorCode::kChunkOrder);
  c = base;
  std::swap(c[first], c[second]);
  w->invalid("invalid_loop_levels_swapped", join_chunks(c), ErrorCode::kBadChunkPayload);
  c = base;
  std::swap(c[loop], c[conn]);
  w->invalid("invalid_loop_after_conn", join_chunks(c), ErrorCode::kChunkOrder);
  c = base;
  c.erase(c.begin() + long(loop));
  w->invalid("invalid_loop_level_without_loop", join_chunks(c), ErrorCode::kChunkOrder);
  c = base;
  c[loop].payload = {0, 0};
  w->invalid("invalid_loop_zero_levels", join_chunks(c), ErrorCode::kBadChunkPayload);
  c[loop].payload = {2, 1};
  w->invalid("invalid_loop_unknown_scheme", join_chunks(c), ErrorCode::kUnsupportedFeature);
  c = base;
  c[first].payload[2] = 13;  // the octahedron has 12 edges
  w->invalid("invalid_loop_wrong_edge_count", join_chunks(c), ErrorCode::kBadChunkPayload);
  c = base;
  c[first].payload[1] = 1;
  w->invalid("invalid_loop_unknown_code", join_chunks(c), ErrorCode::kUnsupportedFeature);
  c = base;
  for (int i = 0; i < 8; ++i) c[first].payload[3 + i] = i == 7 ? 0x7F : i == 6 ? 0xF8 : 0;  // NaN
  w->invalid("invalid_loop_step_nan", join_chunks(c), ErrorCode::kBadChunkPayload);
  c = base;
  // The largest binary64 step, every edge point pushed by -127 steps of it.
  for (int i = 0; i < 8; ++i) c[first].payload[3 + i] = i == 7 ? 0x7F : i == 6 ? 0xEF : 0xFF;
  {
    qmc::BitWriter b;
    for (int e = 0; e < 12; ++e) b.write_bits(0x1FF, 9);
    const std::vector<uint8_t> stream = b.finish();
    c[first].payload.resize(11);
    c[first].payload.insert(c[first].payload.end(), stream.begin(), stream.end());
  }
  w->invalid("invalid_loop_positions_overflow", join_chunks(c), ErrorCode::kBadChunkPayload);
  c = base;
  c[second].payload.resize(c[second].payload.size() - 2);
  w->invalid("invalid_loop_codes_truncated", join_chunks(c), ErrorCode::kTruncated);
  c = base;
  {
    qmc::BitWriter b;
    b.write_bits(0x100, 9);  // flag 1, sign 0, magnitude 0
    for (int e = 1; e < 12; ++e) b.write_bit(false);
    const std::vector<uint8_t> stream = b.finish();
    c[first].payload.resize(11);
    c[first].payload.insert(c[first].payload.end(), stream.begin(), stream.end());
  }
  w->invalid("invalid_loop_zero_magnitude", join_chunks(c), ErrorCode::kBadSymbol);
  c = base;
  c.insert(c.begin() + long(first), Chunk{qmc::kChunkOrder, {0}});
  w->invalid("invalid_loop_with_ordr", join_chunks(c), ErrorCode::kChunkOrder);
  // Bases the levels cannot refine: quads, and two tetrahedra sharing a vertex.
  c = base;
  c[conn].payload = split_chunks(encode_polygons(qmc::tools::make_cube()))[1].payload;
  c[posn].payload = split_chunks(encode_polygons(qmc::tools::make_cube()))[2].payload;
  w->invalid("invalid_loop_quad_base", join_chunks(c), ErrorCode::kBadChunkPayload);
  Mesh pinched = qmc::tools::make_tetrahedron();
  const Mesh second_tetrahedron = qmc::tools::make_tetrahedron();
  for (size_t i = 3; i < second_tetrahedron.positions.size(); ++i)
    pinched.positions.push_back(second_tetrahedron.positions[i] + 3);
  for (size_t f = 0; f < 4; ++f) {
    pinched.face_sizes.push_back(3);
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = second_tetrahedron.corners[3 * f + size_t(k)];
      pinched.corners.push_back(v == 0 ? 0 : v + 3);
    }
  }
  const Chunks indexed = split_chunks(encode(pinched, 12));
  c = base;
  c[conn].payload = indexed[find_chunk(indexed, qmc::kChunkConnectivity)].payload;
  c[posn].payload = indexed[find_chunk(indexed, qmc::kChunkPositions)].payload;
  w->invalid("invalid_loop_pinched_base", join_chunks(c), ErrorCode::kBadChunkPayload);
}

// Section 13: geometry images, from formula images (gim_test_images.h).
[[noreturn]] void gim_die(const std::string& what, const std::string& why) {
  std::fprintf(stderr, "qmc-make-vectors: %s: %s\n", what.c_str(), why.c_str());
  std::exit(3);
}

std::vector<uint8_t> gim_file(const qmc::GimSamples& s, bool float_samples, bool quads = false, bool store_blank = false,
                              const std::vector<qmc::GimExtraPlane>& extra = {}) {
  qmc::GeometryImageOptions o;
  o.float_samples = float_samples;
  o.quads = quads;
  o.store_blank_pixels = store_blank;
  std::vector<uint8_t> bytes;
  qmc::EncodeStats stats;
  if (qmc::Status st = qmc::write_geometry_image(s, extra, o, {}, &bytes, &stats); !st.ok())
    gim_die("geometry image", st.to_string());
  return bytes;
}

// The bytes of a file the writer refuses to vouch for (its decode check
// fails): for vectors of samples no valid file holds.
std::vector<uint8_t> gim_file_unchecked(const qmc::GimSamples& s) {
  qmc::GeometryImageOptions o;
  o.float_samples = true;
  std::vector<uint8_t> bytes;
  qmc::EncodeStats stats;
  if (qmc::write_geometry_image(s, {}, o, {}, &bytes, &stats).ok()) gim_die("geometry image", "expected a refused file");
  return bytes;
}

std::vector<uint8_t> varints(std::initializer_list<uint64_t> values) {
  std::vector<uint8_t> p;
  for (uint64_t v : values) qmc::put_varint(&p, v);
  return p;
}

void write_gim_valid(VectorWriter* w) {
  const qmc::GimSamples torus = qmc::tools::make_torus_geometry_image(9);
  w->valid("valid_gim_u16_torus_quads", gim_file(torus, false, true), nullptr);
  w->valid("valid_gim_u16_torus_triangles", gim_file(torus, false), nullptr);
  w->valid("valid_gim_f32_torus_triangles", gim_file(torus, true), nullptr);
  const qmc::GimSamples disk = qmc::tools::make_disk_geometry_image(12);
  w->valid("valid_gim_u16_mask", gim_file(disk, false), nullptr);
  w->valid("valid_gim_u16_mask_blank_stored", gim_file(disk, false, false, true), nullptr);
  w->valid("valid_gim_f32_mask_quads", gim_file(disk, true, true), nullptr);
  // Normals and a curvature-like value as attribute planes (kinds 3..6).
  std::vector<qmc::GimExtraPlane> extra(4);
  for (int k = 0; k < 4; ++k) {
    extra[size_t(k)].kind = uint8_t(3 + k);
    for (size_t p = 0; p < 81; ++p) extra[size_t(k)].values.push_back(k < 3 ? torus.xyz[3 * p + size_t(k)] / 3 : 0.5 * p);
  }
  w->valid("valid_gim_u16_attributes", gim_file(torus, false, false, false, extra), nullptr);
  w->valid("valid_gim_f32_attributes", gim_file(torus, true, false, false, extra), nullptr);
  const qmc::GimSamples sparse = qmc::tools::make_sparse_triangle_image(9);
  w->valid("valid_gim_f32_topology", gim_file(sparse, true), nullptr);
  w->valid("valid_gim_u16_topology", gim_file(sparse, false), nullptr);
  w->valid("valid_gim_u16_topology_blank_stored", gim_file(sparse, false, false, true), nullptr);
  qmc::GimSamples tiny;
  tiny.width = tiny.height = 1;
  tiny.xyz = {1, 2, 3};
  w->valid("valid_gim_one_pixel", gim_file(tiny, false), nullptr);
}

void write_gim_header_errors(VectorWriter* w, const Chunks& base) {
  const size_t gimg = find_chunk(base, qmc::kChunkGeometryImage);
  const std::vector<uint8_t> fields(base[gimg].payload.begin() + 2, base[gimg].payload.end());  // after W, H (9, 9)
  auto with_header = [&](const std::vector<uint8_t>& size_and_fields) {
    Chunks c = base;
    c[gimg].payload = size_and_fields;
    return join_chunks(c);
  };
  auto sized = [&](uint64_t width, uint64_t height) {
    std::vector<uint8_t> p = varints({width, height});
    p.insert(p.end(), fields.begin(), fields.end());
    return p;
  };
  w->invalid("invalid_gim_size_overflow", with_header(sized(65535, 65535)), qmc::ErrorCode::kLimitExceeded);
  w->invalid("invalid_gim_size_unjustified", with_header(sized(4096, 4096)), qmc::ErrorCode::kLimitExceeded);
  w->invalid("invalid_gim_zero_width", with_header(sized(0, 9)), qmc::ErrorCode::kBadChunkPayload);
  w->invalid("invalid_gim_width_too_large", with_header(sized(65536, 1)), qmc::ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> p = sized(9, 9);
  p[2] = 2;  // format
  w->invalid("invalid_gim_unknown_format", with_header(p), qmc::ErrorCode::kUnsupportedFeature);
  p = sized(9, 9);
  p[3] = 3;  // face mode
  w->invalid("invalid_gim_unknown_face_mode", with_header(p), qmc::ErrorCode::kUnsupportedFeature);
  p = sized(9, 9);
  p[4] |= 4;  // a reserved flag
  w->invalid("invalid_gim_reserved_flag", with_header(p), qmc::ErrorCode::kBadChunkPayload);
  p = sized(9, 9);
  p[5] = 2;  // two planes
  w->invalid("invalid_gim_two_planes", with_header(p), qmc::ErrorCode::kBadChunkPayload);
  p = sized(9, 9);
  p[6] = 1;  // plane 0 says Y
  w->invalid("invalid_gim_plane_kind", with_header(p), qmc::ErrorCode::kBadChunkPayload);
  p = sized(9, 9);
  for (int i = 0; i < 8; ++i) p[size_t(15 + i)] = i == 7 ? 0xBF : 0;  // plane 0 step -1.0
  w->invalid("invalid_gim_negative_step", with_header(p), qmc::ErrorCode::kBadChunkPayload);
  p = sized(9, 9);
  p.push_back(0);
  w->invalid("invalid_gim_header_trailing_byte", with_header(p), qmc::ErrorCode::kBadChunkPayload);
}

void write_gim_order_errors(VectorWriter* w, const Chunks& torus, const Chunks& disk) {
  Chunks c = torus;
  c.erase(c.end() - 2);  // the last plane
  w->invalid("invalid_gim_qend_before_last_plane", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = torus;
  c.insert(c.end() - 1, c[c.size() - 2]);
  w->invalid("invalid_gim_extra_plane", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = torus;
  c.insert(c.begin() + 2, c[1]);
  w->invalid("invalid_gim_second_gimg", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = torus;
  const Chunks indexed = split_chunks(encode(qmc::tools::make_tetrahedron(), 12));
  c.insert(c.end() - 1, indexed[find_chunk(indexed, qmc::kChunkConnectivity)]);
  w->invalid("invalid_gim_with_conn", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = indexed;
  c.insert(c.begin() + 2, torus[find_chunk(torus, qmc::kChunkGeometryImage)]);
  w->invalid("invalid_gim_after_conn", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = disk;
  c.erase(c.begin() + long(find_chunk(c, qmc::kChunkGimMask)));
  w->invalid("invalid_gim_missing_mask", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = torus;
  c.insert(c.begin() + 2, disk[find_chunk(disk, qmc::kChunkGimMask)]);
  w->invalid("invalid_gim_mask_without_flag", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = torus;
  const size_t seams = find_chunk(c, qmc::kChunkGimSeams);
  std::swap(c[seams], c[seams + 1]);  // GSEM after the first plane
  w->invalid("invalid_gim_seams_after_plane", join_chunks(c), qmc::ErrorCode::kChunkOrder);
  c = torus;
  c.insert(c.begin() + 1, Chunk{qmc::kChunkGimPlane, c[c.size() - 2].payload});
  w->invalid("invalid_gim_plane_before_gimg", join_chunks(c), qmc::ErrorCode::kChunkOrder);
}

void write_gim_payload_errors(VectorWriter* w, const Chunks& torus, const Chunks& disk, const Chunks& sparse) {
  const size_t seams = find_chunk(torus, qmc::kChunkGimSeams);
  auto seams_file = [&](const std::vector<uint8_t>& payload) {
    Chunks c = torus;
    c[seams].payload = payload;
    return join_chunks(c);
  };
  w->invalid("invalid_gim_seam_self", seams_file(varints({1, 5, 5, 1, 0, 0})), qmc::ErrorCode::kBadChunkPayload);
  w->invalid("invalid_gim_seam_outside", seams_file(varints({1, 0, 81, 1, 0, 0})), qmc::ErrorCode::kBadChunkPayload);
  w->invalid("invalid_gim_seam_run_leaves_image", seams_file(varints({1, 0, 8, 10, 2, 18})), qmc::ErrorCode::kBadChunkPayload);
  w->invalid("invalid_gim_seam_count_overflow", seams_file(varints({1, 0, 8, 82, 2, 2})), qmc::ErrorCode::kLimitExceeded);
  w->invalid("invalid_gim_seam_runs_overflow", seams_file(varints({1000})), qmc::ErrorCode::kLimitExceeded);
  w->invalid("invalid_gim_seam_truncated", seams_file(varints({2, 0, 8, 1, 0, 0})), qmc::ErrorCode::kBadChunkPayload);
  // Masks that do not match: a seam on a blank pixel of the disk image
  // (pixel 0 is outside its inscribed disk).
  Chunks c = disk;
  c.insert(c.begin() + long(find_chunk(c, qmc::kChunkGimMask)) + 1, Chunk{qmc::kChunkGimSeams, varints({1, 0, 70, 1, 0, 0})});
  w->invalid("invalid_gim_seam_on_blank_pixel", join_chunks(c), qmc::ErrorCode::kBadChunkPayload);
  // The sparse image's mask with one vertex pixel cleared: a face points at it.
  const size_t mask = find_chunk(sparse, qmc::kChunkGimMask);
  qmc::GimSamples holed = qmc::tools::make_sparse_triangle_image(9);
  holed.occupied[2] = 0;  // pixel (2, 0), a corner of triangles 0 and 2
  holed.triangles.clear();
  const Chunks holed_chunks = split_chunks(gim_file(holed, true));
  c = sparse;
  c[mask].payload = holed_chunks[find_chunk(holed_chunks, qmc::kChunkGimMask)].payload;
  w->invalid("invalid_gim_face_on_blank_pixel", join_chunks(c), qmc::ErrorCode::kBadChunkPayload);
  // Faces whose corners leave the image, or collapse, or run out.
  const size_t faces = find_chunk(sparse, qmc::kChunkGimFaces);
  auto faces_file = [&](const std::vector<uint32_t>& triangles, uint64_t count) {
    const std::vector<uint8_t> payload = qmc::encode_gim_triangles(triangles, 9);
    Chunks out = sparse;
    out[faces].payload = varints({count});
    out[faces].payload.insert(out[faces].payload.end(), payload.begin() + 1, payload.end());
    return join_chunks(out);
  };
  w->invalid("invalid_gim_face_repeated_vertex", faces_file({0, 2, 2}, 1), qmc::ErrorCode::kBadChunkPayload);
  w->invalid("invalid_gim_face_count_overflow", faces_file({0, 2, 20}, 51), qmc::ErrorCode::kLimitExceeded);
  w->invalid("invalid_gim_face_stream_truncated", faces_file({0, 2, 20}, 40), qmc::ErrorCode::kTruncated);
  c = sparse;
  c[faces].payload.insert(c[faces].payload.end(), 8, 0x55);  // more than the 4 bytes a decoder looks ahead
  w->invalid("invalid_gim_face_trailing_bytes", join_chunks(c), qmc::ErrorCode::kBadChunkPayload);
  c = sparse;
  c[faces].payload = varints({1});
  c[faces].payload.insert(c[faces].payload.end(), {0xC0, 0, 0, 0, 0});  // dx0 = -1: left of the image
  w->invalid("invalid_gim_face_outside_image", join_chunks(c), qmc::ErrorCode::kBadSymbol);
  // Planes: truncated, and a non-finite binary32 sample on a vertex.
  c = torus;
  std::vector<uint8_t>& plane = c[c.size() - 2].payload;
  plane.resize(plane.size() / 2);
  w->invalid("invalid_gim_plane_truncated", join_chunks(c), qmc::ErrorCode::kTruncated);
  qmc::GimSamples infinite = qmc::tools::make_torus_geometry_image(9);
  infinite.xyz[3 * 40] = 1e300;  // rounds to +infinity in binary32
  w->invalid("invalid_gim_f32_infinite_vertex", gim_file_unchecked(infinite), qmc::ErrorCode::kBadChunkPayload);
}

void write_geometry_image_vectors(VectorWriter* w) {
  write_gim_valid(w);
  const Chunks torus = split_chunks(gim_file(qmc::tools::make_torus_geometry_image(9), false));
  const Chunks disk = split_chunks(gim_file(qmc::tools::make_disk_geometry_image(12), false));
  const Chunks sparse = split_chunks(gim_file(qmc::tools::make_sparse_triangle_image(9), true));
  write_gim_header_errors(w, torus);
  write_gim_order_errors(w, torus, disk);
  write_gim_payload_errors(w, torus, disk, sparse);
  // 13.9 step 3's cleaning: seams that join two corners of a block. Pixels
  // 0 and 1 are one vertex (block (0,0) keeps a triangle), 4 and 8 too
  // (block (1,1) repeats a vertex across the diagonal and is dropped).
  qmc::GimSamples joined;
  joined.width = joined.height = 3;
  for (uint32_t p = 0; p < 9; ++p) joined.xyz.insert(joined.xyz.end(), {double(p % 3), double(p / 3), 0.125 * (p % 4)});
  joined.seams = {{0, 1}, {4, 8}};
  joined.xyz[3] = joined.xyz[0], joined.xyz[4] = joined.xyz[1], joined.xyz[5] = joined.xyz[2];
  joined.xyz[24] = joined.xyz[12], joined.xyz[25] = joined.xyz[13], joined.xyz[26] = joined.xyz[14];
  w->valid("valid_gim_u16_seams_collapse_quads", gim_file(joined, false, true), nullptr);
  w->valid("valid_gim_u16_seams_collapse_triangles", gim_file(joined, false), nullptr);
  Chunks c = sparse;
  c.insert(c.begin() + long(find_chunk(c, qmc::kChunkGimFaces)) + 1, Chunk{qmc::kChunkGimSeams, varints({1, 0, 2, 1, 0, 0})});
  w->invalid("invalid_gim_seams_after_faces", join_chunks(c), qmc::ErrorCode::kChunkOrder);
}

// Issue #12 item 10: vectors for readings of the spec that could differ.
// Each settles one sentence of the spec; the comment names it.

// One component (first face a triangle) whose two coded faces, in the
// mixed Huffman coding (5.4.4), are Q13 then a pentagon of anchors only.
// Undone from the last: the pentagon makes a loop of 5 edges; Q13 cuts two
// of its vertices off (n = 5 >= fj + 2 = 4), leaving the triangle's loop.
// The surface has 5 vertices (N = 5) and 3 faces.
void q13_on_pentagon(qmc::BitWriter* b) {
  b->write_exp_golomb(1);  // C
  b->write_exp_golomb(1);  // n - 2: three faces
  b->write_exp_golomb(0);  // d - 3: the first face is a triangle
  b->write_bit(false);     // no table for class A
  b->write_bit(true);      // class B: symbols 12 (Q13) and 18, one bit each
  std::vector<uint8_t> lengths(qmc::kPolygonSymbolCount, 0);
  lengths[12] = lengths[qmc::kPolygonOtherSymbol] = 1;
  qmc::write_code_lengths(b, lengths);
  b->write_bit(false);      // Q13 (context B: the first symbol)
  b->write_bit(true);       // symbol 18 (context B: Q13's class)
  b->write_exp_golomb(0);   // d - 5: a pentagon
  b->write_bits(0x7, 3);    // w1..w3 anchors
  b->write_bits(0xF, 4);    // its four gaps are edge gaps: D = 0
}

void write_polygon_reading_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Chunks base = split_chunks(encode_polygons(qmc::tools::make_cube()));
  auto with_conn = [&](std::vector<uint8_t> payload) {
    Chunks c = base;
    c[find_chunk(base, qmc::kChunkConnectivity)].payload = std::move(payload);
    return join_chunks(c);
  };
  auto no_records = [](qmc::BitWriter* b) {
    for (int i = 0; i < 4; ++i) b->write_exp_golomb(0);  // H, S, I, L
  };
  // 5.4.5: method 1's "Q13 on a loop of fewer than 6 edges" (5.3.6) is not
  // a rule of method 2; here Q13 cuts a loop of 5 edges.
  w->valid("valid_polygon_q13_on_pentagon_loop", with_conn(polygon_conn(8, 3, 0, qmc::kPolygonMixedHuffman,
                                                                   [&](qmc::BitWriter* b) {
                                                                     q13_on_pentagon(b);
                                                                     no_records(b);
                                                                   })),
           nullptr);
  // 5.4.1: "bits remaining" are counted after the field just read, up to
  // the end of the payload, padding bits included. C = 3 in one byte
  // leaves 3 bits (limit_exceeded); C = 2 leaves 5 >= 4 (then truncated).
  w->invalid("invalid_polygon_components_count_after_field",
             with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) { b->write_exp_golomb(3); })),
             ErrorCode::kLimitExceeded);
  w->invalid("invalid_polygon_components_padding_counts",
             with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) { b->write_exp_golomb(2); })),
             ErrorCode::kTruncated);
  // 5.4.7: H above the number of surface faces is bad_symbol before any v_i
  // is read (the pillow has 2 faces; the stream ends after H = 3).
  w->invalid("invalid_polygon_virtual_faces_above_face_count",
             with_conn(polygon_conn(8, 2, 0, 0, [](qmc::BitWriter* b) {
               pillow(b, 1, 1, [](qmc::BitWriter* t) { t->write_exp_golomb(3); });
             })),
             ErrorCode::kBadSymbol);
  // 5.4.7: H greater than the bits remaining is limit_exceeded. Ten faces
  // (the first and nine Q1), H = 9, and the stream ends on a byte boundary.
  w->invalid("invalid_polygon_virtual_faces_unjustified", with_conn(polygon_conn(8, 10, 0, 0, [](qmc::BitWriter* b) {
               b->write_exp_golomb(1);
               b->write_exp_golomb(8);
               b->write_exp_golomb(1);
               for (int i = 0; i < 9; ++i) b->write_bits(0, 4);  // Q1
               b->write_exp_golomb(9);
             })),
             ErrorCode::kLimitExceeded);
  // 5.4.7: p and q are both read before either is checked. N = 5 (w = 3);
  // the last identification's p = 7 is complete and its q is cut by the
  // end of the stream: truncated, not bad_symbol. Valid identifications
  // (0, 1) in front place the end inside q.
  auto identifications = [](qmc::BitWriter* b, int valid_pairs) {
    q13_on_pentagon(b);
    b->write_exp_golomb(0);  // H
    b->write_exp_golomb(0);  // S
    b->write_exp_golomb(uint32_t(valid_pairs + 1));  // I
    for (int i = 0; i < valid_pairs; ++i) b->write_bits(0x01, 6);  // p = 0, q = 1
    b->write_bits(7, 3);  // p = 7, then the stream ends
  };
  int valid_pairs = 0;
  for (;; ++valid_pairs) {  // the padding after p must be shorter than q's 3 bits
    qmc::BitWriter probe;
    identifications(&probe, valid_pairs);
    if ((8 - probe.bit_count() % 8) % 8 < 3) break;
  }
  w->invalid("invalid_polygon_identification_cut_after_bad_label",
             with_conn(polygon_conn(8, 3, 0, qmc::kPolygonMixedHuffman,
                                    [&](qmc::BitWriter* b) { identifications(b, valid_pairs); })),
             ErrorCode::kTruncated);
  // 5.4.8: a loose face's d w' is checked against the bits remaining before
  // its first label: limit_exceeded although that label (7 >= V = 6) is bad.
  w->invalid("invalid_polygon_loose_face_unjustified_before_label",
             with_conn(polygon_conn(6, 3, 0, 0, [](qmc::BitWriter* b) {
               pillow(b, 1, 1, [](qmc::BitWriter* t) {
                 for (int i = 0; i < 3; ++i) t->write_exp_golomb(0);  // H, S, I
                 t->write_exp_golomb(1);   // L
                 t->write_exp_golomb(97);  // d = 100: 300 bits of labels
                 t->write_bits(7, 3);
               });
             })),
             ErrorCode::kLimitExceeded);
}

void write_gim_reading_vectors(VectorWriter* w) {
  // 13.9 step 3: when the repeated corners of a block wrap around (c3 and
  // c0 are one vertex), the copy at c0 is kept and the face starts there:
  // block (0, 0) becomes (v0 v1 v4), not (v1 v4 v0). Pixels 0 and 3 are
  // joined by a seam.
  qmc::GimSamples wrapped;
  wrapped.width = wrapped.height = 3;
  for (uint32_t p = 0; p < 9; ++p) wrapped.xyz.insert(wrapped.xyz.end(), {double(p % 3), double(p / 3), 0.25 * (p % 2)});
  wrapped.seams = {{0, 3}};
  for (int a = 0; a < 3; ++a) wrapped.xyz[size_t(9 + a)] = wrapped.xyz[size_t(a)];
  w->valid("valid_gim_u16_seam_wraps_quad", gim_file(wrapped, false, true), nullptr);
  // 13.7: a run whose count is 0 is bad_chunk_payload.
  Chunks c = split_chunks(gim_file(qmc::tools::make_torus_geometry_image(9), false));
  c[find_chunk(c, qmc::kChunkGimSeams)].payload = varints({1, 0, 8, 0, 0, 0});
  w->invalid("invalid_gim_seam_zero_count", join_chunks(c), qmc::ErrorCode::kBadChunkPayload);
  // 13.7: the running total of pairs is the exact sum: a second run of
  // 2^64 - 1 pairs after one pair must not wrap it to 0 (and pass W H).
  c[find_chunk(c, qmc::kChunkGimSeams)].payload = varints({2, 0, 8, 1, 0, 0, 0, 8, ~uint64_t(0), 0, 0});
  w->invalid("invalid_gim_seam_count_wraps", join_chunks(c), qmc::ErrorCode::kLimitExceeded);
  // 13.5.2: an empty stream is zero bytes. No triangle (T = 0) with the
  // empty stream decodes; with one byte after it, that byte is trailing data.
  const Chunks sparse = split_chunks(gim_file(qmc::tools::make_sparse_triangle_image(9), false));
  const size_t faces = find_chunk(sparse, qmc::kChunkGimFaces);
  c = sparse;
  c[faces].payload = varints({0});
  w->valid("valid_gim_u16_topology_no_triangles", join_chunks(c), nullptr);
  c[faces].payload.push_back(0);
  w->invalid("invalid_gim_empty_face_stream_with_byte", join_chunks(c), qmc::ErrorCode::kBadChunkPayload);
  // The same for a plane: every pixel of the mask blank and not stored
  // (N = 0), so plane 0 is its predictor byte alone; one more byte is
  // trailing data.
  qmc::GimSamples blank;
  blank.width = blank.height = 2;
  blank.xyz.assign(12, 0.5);
  blank.occupied.assign(4, 0);
  c = split_chunks(gim_file(blank, false));
  w->valid("valid_gim_u16_all_blank", join_chunks(c), nullptr);
  c[find_chunk(c, qmc::kChunkGimPlane)].payload.push_back(0);
  w->invalid("invalid_gim_empty_plane_stream_with_byte", join_chunks(c), qmc::ErrorCode::kBadChunkPayload);
}


// Issue 12: counts that no chunk had justified (spec 8, 12.2, 13.3, 13.7, 13.8).
void write_hardening_vectors(VectorWriter* w) {
  // 12.2: a base mesh of 4 triangles (12 corners) claiming 13 vertices.
  const Chunks tetrahedron = split_chunks(encode(qmc::tools::make_tetrahedron(), 12));
  std::vector<uint8_t> conn = tetrahedron[find_chunk(tetrahedron, qmc::kChunkConnectivity)].payload;
  conn[1] = 13;  // method 0, vertex_count 4 -> 13 (one byte either way), face_count 4
  w->invalid("invalid_loop_base_more_vertices_than_corners",
             join_chunks({Chunk{qmc::kChunkHeader, {1, 3}}, Chunk{qmc::kChunkLoop, {1, 0}},
                          Chunk{qmc::kChunkConnectivity, conn}, Chunk{qmc::kChunkEnd, {}}}),
             qmc::ErrorCode::kBadChunkPayload);
  // 13.7, 13.8: a 1024 x 1024 image without a mask (binary32, GFAC triangles, X Y Z).
  std::vector<uint8_t> gimg = varints({1024, 1024});
  gimg.insert(gimg.end(), {1, 2, 0, 3, 0, 1, 2});
  const Chunks image = {Chunk{qmc::kChunkHeader, {1, 4}}, Chunk{qmc::kChunkGeometryImage, gimg}};
  Chunks c = image;
  // One run of 2^19 pairs (k, 2^19 + k), all inside the image, in 12 bytes.
  c.push_back(Chunk{qmc::kChunkGimSeams, varints({1, 0, 1 << 19, 1 << 19, 2, 2})});
  c.push_back(Chunk{qmc::kChunkEnd, {}});
  w->invalid("invalid_gim_unmasked_seam_pairs_unjustified", join_chunks(c), qmc::ErrorCode::kLimitExceeded);
  // 2^21 triangles (twice the pixels) in a stream of 40 bytes.
  c = image;
  c.push_back(Chunk{qmc::kChunkGimSeams, varints({0})});
  std::vector<uint8_t> gfac = varints({1 << 21});
  gfac.insert(gfac.end(), 40, 0);
  c.push_back(Chunk{qmc::kChunkGimFaces, gfac});
  c.push_back(Chunk{qmc::kChunkEnd, {}});
  w->invalid("invalid_gim_faces_unjustified", join_chunks(c), qmc::ErrorCode::kLimitExceeded);
}

// Encodes with `options`, which must give the POSN method `method`.
// The options with the faces listed as given (indexed) and the positions on
// the grid of step 1 from their box's corner: the spec's examples, whose
// labels and integers the file must keep.
qmc::EncodeOptions on_unit_grid(qmc::EncodeOptions options) {
  options.connectivity = qmc::ConnectivityChoice::kIndexed;
  options.position_step = 1;
  return options;
}

std::vector<uint8_t> encode_posn_method(const Mesh& mesh, const qmc::EncodeOptions& options, int method) {
  std::vector<uint8_t> out;
  qmc::EncodeStats stats;
  qmc::EncodeOptions asked = method >= 11 ? options : without_shear(options);
  if (method == 11) asked.edge_extrapolation = false;
  if (method <= 12) asked.axis_class_probabilities = false;
  asked.polygon_quad_contexts = false;  // CONN coding 8 came after the POSN vectors
  if (qmc::Status s = qmc::encode(mesh, asked, &out, &stats); !s.ok() || stats.positions.method != method) {
    std::fprintf(stderr, "qmc-make-vectors: POSN method %d: %s\n", method, s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

// Section 14 (format 1.5): predicted positions, POSN method 1.
std::vector<uint8_t> encode_predicted(const Mesh& mesh, int bits,
                                      qmc::ConnectivityChoice connectivity = qmc::ConnectivityChoice::kAuto,
                                      qmc::PositionGrid grid = qmc::PositionGrid::kUniform) {
  qmc::EncodeOptions options = format_1_6_options();
  options.position_bits = bits;
  options.connectivity = connectivity;
  options.position_grid = grid;
  options.position_method = qmc::PositionMethod::kPredicted;
  options.candidate_choice = qmc::CandidateChoice::kNearest;  // the choice when these vectors were made
  options.polygon_context_coding = false;                      // format 1.5's codings
  return encode_posn_method(mesh, options, 1);
}

// A random walk on a sphere: positions a predictor cannot guess exactly.
Mesh perturbed(Mesh mesh, uint64_t seed, float amount) {
  qmc::tools::SplitMix64 random(seed);
  for (float& x : mesh.positions) x += amount * (float(random.next() % 2001) / 1000.f - 1.f);
  return mesh;
}

// Vertices a = 0, b = 1, t1 = 2, t2 = 3: `degenerate` faces (a, b, a), then
// (a, b, t1) and (b, a, t2), the parallelogram of t2 across (a, b) being t1's.
// With `own_face_first`, the triangle (t1, 4, 5) comes first, so that t1 is
// labelled before t2, and then (b, a, t2), so that its own corner is the
// first one 14.2's search for the edge examines.
Mesh search_cap_mesh(int degenerate, bool own_face_first = false) {
  Mesh m;
  m.positions = {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.5f, 1.f, 0.f, 0.5f, -1.f, 0.25f, 2.f, 2.f, 0.f, 2.f, 3.f, 1.f};
  auto triangle = [&](uint32_t x, uint32_t y, uint32_t z) {
    m.face_sizes.push_back(3);
    m.corners.insert(m.corners.end(), {x, y, z});
  };
  if (own_face_first) {
    triangle(2, 4, 5);
    triangle(1, 0, 3);
  }
  for (int i = 0; i < degenerate; ++i) triangle(0, 1, 0);
  triangle(0, 1, 2);
  if (!own_face_first) triangle(1, 0, 3);
  if (!own_face_first) m.positions.resize(12);
  return m;
}

// Disjoint prisms with caps of 9 .. 16 corners: c_9 .. c_12 and beyond.
Mesh large_polygon_prisms() {
  Mesh m;
  for (int n : {9, 10, 11, 12, 13, 16}) {
    Mesh prism = perturbed(qmc::tools::make_prism(n), uint64_t(n), 0.01f);
    const uint32_t first = uint32_t(m.vertex_count());
    for (size_t i = 0; i < prism.positions.size(); ++i)
      m.positions.push_back(prism.positions[i] + (i % 3 == 0 ? 3.f * float(n) : 0.f));
    m.face_sizes.insert(m.face_sizes.end(), prism.face_sizes.begin(), prism.face_sizes.end());
    for (uint32_t v : prism.corners) m.corners.push_back(first + v);
  }
  return m;
}

// Section 12.7.1 (format 1.5): LEVL displacement code 2, valid and invalid.
void write_displacement_code_2_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Mesh octahedron = qmc::tools::loop_octahedron();
  w->valid("valid_levl2_octahedron_sphere_4_levels",
           loop_file(octahedron, 4, qmc::tools::unit_sphere_targets(), 14, qmc::PositionMethod::kDeltas, 2), nullptr);
  w->valid("valid_levl2_torus_genus1_3_levels",
           loop_file(qmc::tools::triangulated(qmc::tools::make_torus(9, 6)), 3, qmc::tools::torus_targets(1, 0.35), 12,
                     qmc::PositionMethod::kDeltas, 2),
           nullptr);
  w->valid("valid_levl2_grid_boundary_3_levels",
           loop_file(qmc::tools::triangulated(qmc::tools::make_grid(4, 3)), 3, qmc::tools::height_field_targets(), 12,
                     qmc::PositionMethod::kDeltas, 2),
           nullptr);
  // The encoder's own choice: code 0 on the small first levels, code 2 on the larger ones.
  w->valid("valid_levl2_mixed_codes",
           loop_file(octahedron, 5, qmc::tools::unit_sphere_targets(), 14, qmc::PositionMethod::kDeltas, -1),
           nullptr);
  const Chunks base = split_chunks(loop_file(octahedron, 3, qmc::tools::unit_sphere_targets(), 14, qmc::PositionMethod::kDeltas, 2));
  const size_t last = find_chunk(base, qmc::kChunkLevel, 2);
  const std::vector<uint8_t> payload = base[last].payload;  // level, code, varint edge_count (192), step (8)
  const size_t stream = 2 + 2 + 8;
  auto with_level = [&](std::vector<uint8_t> p) {
    Chunks c = base;
    c[last].payload = std::move(p);
    return join_chunks(c);
  };
  std::vector<uint8_t> p = payload;
  p[1] = 3;
  w->invalid("invalid_levl_code_3", with_level(p), ErrorCode::kUnsupportedFeature);
  w->invalid("invalid_levl2_truncated", with_level({payload.begin(), payload.begin() + stream + 6}),
             ErrorCode::kTruncated);
  p = payload;
  p.insert(p.end(), {0x55, 0x55, 0x55, 0x55, 0x55, 0x55});
  w->invalid("invalid_levl2_bytes_after_stream", with_level(p), ErrorCode::kBadChunkPayload);
  p = payload;
  std::fill(p.begin() + stream, p.begin() + stream + 4, 0xFF);
  w->invalid("invalid_levl2_stream_start_ffffffff", with_level(p), ErrorCode::kBadChunkPayload);
  // 12.1: the 12288 edges of the octahedron's level 5 in one stream byte, above 512 (1 + 8).
  const Chunks deep = split_chunks(loop_file(octahedron, 6, qmc::tools::unit_sphere_targets(), 14, qmc::PositionMethod::kDeltas, 2));
  const size_t sixth = find_chunk(deep, qmc::kChunkLevel, 5);
  Chunks c = deep;
  c[sixth].payload.resize(2 + 2 + 8 + 1);  // level, code, varint 12288, step, one byte of stream
  w->invalid("invalid_levl2_edges_unjustified", join_chunks(c), ErrorCode::kLimitExceeded);
}

void write_predicted_position_valid(VectorWriter* w) {
  using namespace qmc::tools;
  const Mesh sphere = perturbed(triangulated(make_refined_sphere(2)), 1, 0.01f);  // parallelograms, flags
  w->valid("valid_posn1_triangles", encode_predicted(sphere, 12), &sphere);
  const Mesh torus = perturbed(make_torus(16, 10), 2, 0.005f);  // quad runs and strips
  w->valid("valid_posn1_quads", encode_predicted(torus, 14), &torus);
  const Mesh prism = perturbed(make_prism(7), 3, 0.01f);  // heptagon caps: c_7
  w->valid("valid_posn1_heptagon_caps", encode_predicted(prism, 12), &prism);
  const Mesh hexecontahedron = make_deltoidal_hexecontahedron();
  w->valid("valid_posn1_polygons", encode_predicted(hexecontahedron, 16), &hexecontahedron);
  w->valid("valid_posn1_per_axis_grid",
           encode_predicted(sphere, 10, qmc::ConnectivityChoice::kAuto, qmc::PositionGrid::kPerAxis), &sphere);
  RandomSoupOptions soup_options;  // non-manifold faces, unreferenced vertices: neighbours, previous
  soup_options.vertices = 300;
  soup_options.faces = 200;
  const Mesh soup = make_random_soup(11, soup_options);
  w->valid("valid_posn1_soup", encode_predicted(soup, 12, qmc::ConnectivityChoice::kIndexed), &soup);
  const Mesh points = points_only();
  w->valid("valid_posn1_points_only", encode_predicted(points, 20, qmc::ConnectivityChoice::kIndexed), &points);
  const Mesh flat = planar_square_grid();
  w->valid("valid_posn1_flat_axis", encode_predicted(flat, 12), &flat);
  const Mesh empty;
  w->valid("valid_posn1_empty_mesh", encode_predicted(empty, 12), &empty);
  w->valid("valid_posn1_30bit", encode_predicted(sphere, 30), &sphere);
  // 14.2's bounded search: nine degenerate triangles (a, b, a) fill the 8
  // corners examined for the edge (a, b), so vertex 3 finds no parallelogram
  // across it and takes the fallback; examining more would find face 9.
  const Mesh capped = search_cap_mesh(9);
  w->valid("valid_posn1_search_cap", encode_predicted(capped, 12, qmc::ConnectivityChoice::kIndexed), &capped);
  // Seven fill all but the 8th corner examined, which finds (a, b, t1);
  // eight fill all 8; and with t2's own face first its corner is the 1st.
  for (const auto& [name, mesh] : {std::pair{"valid_posn1_search_cap_eighth_examined", search_cap_mesh(7)},
                                   std::pair{"valid_posn1_search_cap_ninth_not_examined", search_cap_mesh(8)},
                                   std::pair{"valid_posn1_search_cap_own_face_counts", search_cap_mesh(7, true)}})
    w->valid(name, encode_predicted(mesh, 12, qmc::ConnectivityChoice::kIndexed), &mesh);
  // Section 12.2: a progressive file's base may use method 1 (on 6.1's grid).
  w->valid("valid_posn1_loop_base",
           loop_file(qmc::tools::triangulated(qmc::tools::make_torus(9, 6)), 2, qmc::tools::torus_targets(1, 0.35), 12,
                     qmc::PositionMethod::kPredicted),
           nullptr);
  write_displacement_code_2_vectors(w);
  const Mesh prisms = large_polygon_prisms();
  w->valid("valid_posn1_large_polygons", encode_predicted(prisms, 14, qmc::ConnectivityChoice::kPolygon), &prisms);
}

void write_predicted_position_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Mesh sphere = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(1)), 4, 0.01f);
  const Chunks base = split_chunks(encode_predicted(sphere, 12));
  const size_t posn = find_chunk(base, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = base[posn].payload;
  auto with_posn = [&](std::vector<uint8_t> p) {
    Chunks c = base;
    c[posn].payload = std::move(p);
    return join_chunks(c);
  };
  // The header: varint V, 0x81, grid, origin (12 bytes), step (8), 3 varint tops (2 bytes each at 12 bits).
  std::vector<uint8_t> count;
  qmc::put_varint(&count, sphere.vertex_count());
  const size_t selector = count.size(), grid = selector + 1, origin = grid + 1, step = origin + 12, tops = step + 8,
               stream = tops + 6;
  std::vector<uint8_t> p = payload;
  p[selector] = 0x82;
  w->invalid("invalid_posn1_unknown_method", with_posn(p), ErrorCode::kUnsupportedFeature);
  p = payload;
  p[grid] = 2;
  w->invalid("invalid_posn1_grid_value", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn1_header_cut", with_posn({payload.begin(), payload.begin() + tops + 1}),
             ErrorCode::kBadChunkPayload);
  p = payload;
  std::vector<uint8_t> bytes;
  qmc::put_f32le(&bytes, std::numeric_limits<float>::infinity());
  std::copy(bytes.begin(), bytes.end(), p.begin() + origin);
  w->invalid("invalid_posn1_infinite_origin", with_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  bytes.clear();
  qmc::put_f64le(&bytes, -1e-3);
  std::copy(bytes.begin(), bytes.end(), p.begin() + step);
  w->invalid("invalid_posn1_negative_step", with_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  bytes.clear();
  qmc::put_f64le(&bytes, 1e36);  // 4095 steps of 1e36 overflow binary32
  std::copy(bytes.begin(), bytes.end(), p.begin() + step);
  w->invalid("invalid_posn1_grid_overflows_binary32", with_posn(p), ErrorCode::kBadChunkPayload);
  p = {payload.begin(), payload.begin() + tops};
  qmc::put_varint(&p, uint64_t(1) << 30);
  p.insert(p.end(), payload.begin() + tops + 2, payload.end());
  w->invalid("invalid_posn1_top_above_2_30", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn1_truncated_stream", with_posn({payload.begin(), payload.end() - 8}), ErrorCode::kTruncated);
  // 14.4: the 5th invented byte and a value outside the grid come with the
  // same residual (vertex 153, z); the end is checked first. Found by a
  // decoder written from the spec alone, by random cuts.
  Chunks quads = split_chunks(encode_predicted(perturbed(qmc::tools::make_torus(16, 10), 2, 0.005f), 14));
  std::vector<uint8_t>& quad_posn = quads[find_chunk(quads, qmc::kChunkPositions)].payload;
  quad_posn.resize(681);
  w->invalid("invalid_posn1_truncated_before_bad_symbol", join_chunks(quads), ErrorCode::kTruncated);
  p = payload;
  p.insert(p.end(), {0x55, 0x55, 0x55, 0x55, 0x55, 0x55});
  w->invalid("invalid_posn1_bytes_after_stream", with_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  std::fill(p.begin() + stream, p.begin() + stream + 4, 0xFF);
  w->invalid("invalid_posn1_stream_start_ffffffff", with_posn(p), ErrorCode::kBadChunkPayload);
  // Tops of 1: a residual the grid cannot hold (the first vertex's x is coded
  // against a prediction of 0 with the data of a 4095-wide grid).
  p = {payload.begin(), payload.begin() + tops};
  qmc::put_varint(&p, 1);
  qmc::put_varint(&p, 1);
  qmc::put_varint(&p, 1);
  p.insert(p.end(), payload.begin() + stream, payload.end());
  w->invalid("invalid_posn1_value_outside_grid", with_posn(p), ErrorCode::kBadSymbol);
  // 14.1: 5000 unreferenced vertices on one point cost no decision: an empty
  // stream cannot justify them.
  std::vector<uint8_t> conn{0};
  qmc::put_varint(&conn, 5000);
  qmc::put_varint(&conn, 0);
  std::vector<uint8_t> free_points;
  qmc::put_varint(&free_points, 5000);
  free_points.insert(free_points.end(), {0x81, 0});
  for (int i = 0; i < 5; ++i) qmc::put_f32le(&free_points, 0.f);  // origin (3) and the step's 8 bytes
  free_points.insert(free_points.end(), {0, 0, 0});
  w->invalid("invalid_posn1_vertices_unjustified",
             join_chunks({Chunk{qmc::kChunkHeader, {1, 5}}, Chunk{qmc::kChunkConnectivity, conn},
                          Chunk{qmc::kChunkPositions, free_points}, Chunk{qmc::kChunkEnd, {}}}),
             ErrorCode::kLimitExceeded);
}


}  // namespace

// Section 5.4.10 (format 1.6): polygon coding 7, the face symbols range
// coded in the contexts of Spirale Reversi's gate.
using qmc::tools::coding7_conn;
using qmc::tools::coding7_symbols;

// One component of n - 2 = `faces_minus_2`, first degree d - 3, then the
// records H, S, I, L all 0.
std::function<void(qmc::BitWriter*)> one_component(uint32_t faces_minus_2, uint32_t first_degree_minus_3) {
  return [=](qmc::BitWriter* b) {
    b->write_exp_golomb(1);
    b->write_exp_golomb(faces_minus_2);
    b->write_exp_golomb(first_degree_minus_3);
    for (int i = 0; i < 4; ++i) b->write_exp_golomb(0);
  };
}

// The file with the first half of its `CONN` coding 7 or 8 symbols only
// (their length byte made to say so): the decoder runs out of stream.
std::vector<uint8_t> with_symbols_cut(const std::vector<uint8_t>& file, const char* what) {
  Chunks c = split_chunks(file);
  const size_t k = find_chunk(c, qmc::kChunkConnectivity);
  std::vector<uint8_t>& p = c[k].payload;
  qmc::ByteReader r(p.data(), p.size());
  uint8_t byte = 0;
  uint64_t skip = 0;
  r.get_u8(&byte);
  r.get_varint(&skip);
  r.get_varint(&skip);
  for (int i = 0; i < 3; ++i) r.get_u8(&byte);  // flags, coding, groups
  const size_t length_at = r.position();
  uint64_t length = 0;
  r.get_varint(&length);
  if (r.position() != length_at + 1 || length < 16 || length > 127) {
    std::fprintf(stderr, "qmc-make-vectors: %s: unexpected symbol length %llu\n", what,
                 static_cast<unsigned long long>(length));
    std::exit(3);
  }
  p.erase(p.begin() + std::ptrdiff_t(length_at + 1 + length / 2), p.begin() + std::ptrdiff_t(length_at + 1 + length));
  p[length_at] = uint8_t(length / 2);
  return join_chunks(c);
}

void write_context_coded_valid(VectorWriter* w) {
  using namespace qmc::tools;
  const Mesh sphere = perturbed(triangulated(make_refined_sphere(3)), 5, 0.01f);
  w->valid("valid_polygon_coding7_sphere", encode_polygons(sphere, qmc::kPolygonContextCoded), &sphere);
  const Mesh torus = triangulated(make_torus(12, 8));  // genus 1: a seam
  w->valid("valid_polygon_coding7_torus_triangles", encode_polygons(torus, qmc::kPolygonContextCoded), &torus);
  const Mesh grid = triangulated(make_grid(6, 5));  // one hole: a virtual face of degree 22, symbol 18
  w->valid("valid_polygon_coding7_grid_hole", encode_polygons(grid, qmc::kPolygonContextCoded), &grid);
  const Mesh quads = make_torus(16, 10);  // quads only: groups = 2
  w->valid("valid_polygon_coding7_quads", encode_polygons(quads, qmc::kPolygonContextCoded), &quads);
  // Triangles, quads and heptagons in three components: every group, both NT and OT.
  const Mesh mixed = combined(combined(make_prism(7), shifted(triangulated(make_refined_sphere(1)), 3.f)),
                              shifted(make_torus(6, 4), 6.f));
  w->valid("valid_polygon_coding7_all_groups", encode_polygons(mixed, qmc::kPolygonContextCoded), &mixed);
  RandomSoupOptions soup_options;  // non-manifold edges and vertices, loose faces, identifications
  soup_options.vertices = 120;
  soup_options.faces = 160;
  const Mesh soup = make_random_soup(21, soup_options);
  w->valid("valid_polygon_coding7_soup", encode_polygons(soup, qmc::kPolygonContextCoded), &soup);
  // What `qmc encode` writes by default: coding 7 with predicted positions (1.6).
  qmc::EncodeOptions options = format_1_6_options();
  options.position_method = qmc::PositionMethod::kPredicted;
  options.candidate_choice = qmc::CandidateChoice::kFewestBits;
  options.polygon_coding = qmc::kPolygonContextCoded;
  std::vector<uint8_t> bytes;
  if (qmc::Status s = qmc::encode(sphere, without_shear(options), &bytes); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: coding 7 with POSN 1: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  w->valid("valid_polygon_coding7_posn1", bytes, &sphere);
  w->valid("valid_polygon_coding7_loop_base",
           loop_file(triangulated(make_torus(9, 6)), 2, torus_targets(1, 0.35), 12, qmc::PositionMethod::kPredicted, 2,
                     true),
           nullptr);
  // A random quad disk whose traversal has a Q8 (symbol 7): three detours
  // in one face, so the two loops popped (5.4.5) must be taken in order.
  for (uint64_t seed = 1;; ++seed) {
    const Mesh disk = qmc::tools::make_random_quad_disk(seed, 60);
    qmc::PolygonEncoding encoding;
    if (!qmc::encode_polygon_connectivity(disk, qmc::kPolygonContextCoded, true, false, true, &encoding).empty()) continue;
    if (encoding.symbol_counts[7] == 0) continue;
    w->valid("valid_polygon_coding7_three_detours", encode_polygons(disk, qmc::kPolygonContextCoded), &disk);
    break;
  }
  // No component: K = 0, no decision, an empty `symbols` field.
  const Chunks base = split_chunks(encode_polygons(make_cube()));
  Chunks c = base;
  const size_t conn = find_chunk(c, qmc::kChunkConnectivity);
  c[conn].payload = coding7_conn(8, 0, 0, {}, [](qmc::BitWriter* b) {
    for (int i = 0; i < 5; ++i) b->write_exp_golomb(0);  // C, H, S, I, L
  });
  w->valid("valid_polygon_coding7_no_component", join_chunks(c), nullptr);
}

void write_context_coded_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  const ChunkReplacer with_conn(encode_polygons(qmc::tools::make_cube()));
  // The pillow of 5.4 (two quads on four vertices) with coding 7: Q1 applied with no loop.
  const std::vector<uint8_t> q1 = coding7_symbols(qmc::kGroupQuads, [](qmc::RangeEncoder* r, qmc::PolygonSymbolModel* m) {
    qmc::code_face_symbol(r, m, qmc::GateContext{}, 0);
  });
  w->valid("valid_polygon_coding7_pillow", with_conn(coding7_conn(8, 2, qmc::kGroupQuads, q1, one_component(0, 1))),
           nullptr);
  w->invalid("invalid_polygon_coding7_groups_above_7",
             with_conn(coding7_conn(8, 2, 8, q1, one_component(0, 1))), ErrorCode::kBadChunkPayload);
  {
    std::vector<uint8_t> p = coding7_conn(8, 2, qmc::kGroupQuads, q1, one_component(0, 1));
    p.resize(6);  // method, 8, 2, flags, coding, groups, then no symbol_bytes
    w->invalid("invalid_polygon_coding7_length_missing", with_conn(p), ErrorCode::kBadChunkPayload);
  }
  w->invalid("invalid_polygon_coding7_length_past_end",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, q1, one_component(0, 1), 100)), ErrorCode::kTruncated);
  // B = 2^32 + the real length: past the end, also where size_t has 32 bits (WebAssembly).
  w->invalid("invalid_polygon_coding7_length_above_4_gib",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, q1, one_component(0, 1), uint64_t(1) << 32)),
             ErrorCode::kTruncated);
  w->invalid("invalid_polygon_coding7_no_groups", with_conn(coding7_conn(8, 2, 0, q1, one_component(0, 1))),
             ErrorCode::kBadSymbol);
  // K = 4097 face symbols from 0 bytes: 512 (0 + 8) = 4096 at most.
  w->invalid("invalid_polygon_coding7_symbols_unjustified",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, {}, one_component(4096, 1))), ErrorCode::kLimitExceeded);
  // C + K = 101 surface faces for face_count 2 and 5 bits after the d_c fields: at most 7 (5.4.10).
  w->invalid("invalid_polygon_coding7_faces_beyond_count",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, {}, one_component(99, 1))), ErrorCode::kLimitExceeded);
  w->invalid("invalid_polygon_coding7_bad_start",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, {0xFF, 0xFF, 0xFF, 0xFF}, one_component(0, 1))),
             ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> trailing = q1;
  trailing.insert(trailing.end(), 8, 0);  // read as the invented zeros would be, then 4 never read
  w->invalid("invalid_polygon_coding7_bytes_after_coded_data",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, trailing, one_component(0, 1))), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_polygon_coding7_no_component_with_byte", with_conn(coding7_conn(8, 0, 0, {0}, [](qmc::BitWriter* b) {
               for (int i = 0; i < 5; ++i) b->write_exp_golomb(0);
             })),
             ErrorCode::kBadChunkPayload);
  // The quad tree's code 13 (node 29) is no symbol.
  const std::vector<uint8_t> code13 = coding7_symbols(qmc::kGroupQuads, [](qmc::RangeEncoder* r, qmc::PolygonSymbolModel* m) {
    qmc::code_face_symbol(r, m, qmc::GateContext{}, 13);
  });
  w->invalid("invalid_polygon_coding7_quad_code_13",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, code13, one_component(0, 1))), ErrorCode::kBadSymbol);
  // A triangle C (symbol 13) first: a detour with no current loop (5.4.5).
  const std::vector<uint8_t> c13 = coding7_symbols(qmc::kGroupTriangles, [](qmc::RangeEncoder* r, qmc::PolygonSymbolModel* m) {
    qmc::code_face_symbol(r, m, qmc::GateContext{}, 13);
  });
  w->invalid("invalid_polygon_coding7_detour_without_loop",
             with_conn(coding7_conn(8, 2, qmc::kGroupTriangles, c13, one_component(0, 0))), ErrorCode::kBadSymbol);
  // Symbol 18's degree: 32 zeros, then a degree the stream cannot justify.
  const std::vector<uint8_t> zeros = coding7_symbols(qmc::kGroupOther, [](qmc::RangeEncoder* r, qmc::PolygonSymbolModel*) {
    for (int i = 0; i < 40; ++i) r->code_direct(0);
  });
  // An empty stream reads as zeros: the degree's prefix runs past the 4
  // invented bytes before its 32nd zero.
  w->invalid("invalid_polygon_coding7_degree_prefix_truncated",
             with_conn(coding7_conn(8, 2, qmc::kGroupOther, {}, one_component(0, 2))), ErrorCode::kTruncated);
  w->invalid("invalid_polygon_coding7_degree_32_zeros",
             with_conn(coding7_conn(8, 2, qmc::kGroupOther, zeros, one_component(0, 2))), ErrorCode::kBadChunkPayload);
  const std::vector<uint8_t> huge = coding7_symbols(qmc::kGroupOther, [](qmc::RangeEncoder* r, qmc::PolygonSymbolModel*) {
    uint32_t extra = 1u << 20;
    qmc::code_other_degree(r, &extra);
  });
  w->invalid("invalid_polygon_coding7_degree_unjustified",
             with_conn(coding7_conn(8, 2, qmc::kGroupOther, huge, one_component(0, 2))), ErrorCode::kLimitExceeded);
  // The sphere's symbols cut in half: the decoder runs out of stream.
  const Mesh sphere = qmc::tools::triangulated(qmc::tools::make_refined_sphere(3));
  w->invalid("invalid_polygon_coding7_symbols_cut",
             with_symbols_cut(encode_polygons(sphere, qmc::kPolygonContextCoded), "coding 7 sphere"), ErrorCode::kTruncated);
}


// A disk of quads around a pole where `spokes` quads meet, in `rings`
// rings of 2 spokes vertices, one quad of the middle ring left out (a
// hole): the pole's count reaches 7 and b and c differ at many gates.
Mesh pole_disk(int spokes, int rings) {
  Mesh m;
  const int n = 2 * spokes;
  m.positions = {0.f, 0.f, 0.f};
  for (int r = 1; r <= rings; ++r)
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * 3.14159265358979 * i / n;
      m.positions.push_back(float(r * std::cos(angle)));
      m.positions.push_back(float(r * std::sin(angle)));
      m.positions.push_back(0.05f * float((i + r) % 3));
    }
  const auto ring = [n](int r, int i) { return uint32_t(1 + (r - 1) * n + i % n); };
  const auto quad = [&m](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    m.face_sizes.push_back(4);
    m.corners.insert(m.corners.end(), {a, b, c, d});
  };
  for (int i = 0; i < spokes; ++i) quad(0, ring(1, 2 * i), ring(1, 2 * i + 1), ring(1, 2 * i + 2));
  for (int r = 1; r < rings; ++r)
    for (int i = 0; i < n; ++i)
      if (r != rings / 2 || i != 0) quad(ring(r, i), ring(r + 1, i), ring(r + 1, i + 1), ring(r, i + 1));
  return m;
}

// Coding 8 symbols of one component: `q1` Q1 faces (each a new loop: the
// first at no loop, a = b = c = 0, the others at a = b = c = 1), then the
// quad code 13.
std::vector<uint8_t> q1s_then_code13(int q1) {
  return coding7_symbols(
      qmc::kGroupQuads,
      [q1](qmc::RangeEncoder* r, qmc::PolygonSymbolModel* m) {
        for (int i = 0; i <= q1; ++i)
          qmc::code_face_symbol(r, m, i == 0 ? qmc::GateContext{} : qmc::GateContext{1, 1, 1}, i < q1 ? 0 : 13);
      },
      true);
}

// Whether the decoder of 5.4.10 meets its fifth invented byte (truncated)
// in the very symbol that decodes to the quad code 13 (bad_symbol), the
// Q1s before it decoding as such: which check comes first then matters.
bool code13_meets_truncation(const std::vector<uint8_t>& symbols, int q1) {
  qmc::RangeDecoder r(symbols.data(), symbols.size());
  qmc::PolygonSymbolModel m;
  m.groups = qmc::kGroupQuads;
  m.quad_neighbours = true;
  for (int i = 0; i <= q1; ++i) {
    const int symbol = qmc::code_face_symbol(&r, &m, i == 0 ? qmc::GateContext{} : qmc::GateContext{1, 1, 1}, 0);
    if (i < q1 && (symbol != 0 || r.overrun())) return false;
    if (i == q1) return symbol < 0 && r.overrun();
  }
  return false;
}

// Section 5.4.10 (format 1.18): polygon coding 8, coding 7 whose quad
// symbols are decoded in the context 8 a + max(b, c) of the gate's count and
// its loop neighbours' counts.
void write_coding8_vectors(VectorWriter* w) {
  using namespace qmc::tools;
  using qmc::ErrorCode;
  const int coding = qmc::kPolygonQuadContextCoded;
  const Mesh cube = make_cube();  // 5.4.10's worked example of coding 8
  w->valid("valid_polygon_coding8_cube", encode_polygons(cube, coding), &cube);
  const Mesh quads = make_torus(16, 10);  // regular quads, a seam: x up to 8 a + 3
  w->valid("valid_polygon_coding8_quad_torus", encode_polygons(quads, coding), &quads);
  const Mesh grid = make_grid(7, 6);  // quads around a hole: symbol 18's virtual face too
  w->valid("valid_polygon_coding8_grid_hole", encode_polygons(grid, coding), &grid);
  // Triangles, quads and heptagons in three components: every group, both NT and OT.
  const Mesh mixed = combined(combined(make_prism(7), shifted(triangulated(make_refined_sphere(1)), 3.f)),
                              shifted(make_torus(6, 4), 6.f));
  w->valid("valid_polygon_coding8_all_groups", encode_polygons(mixed, coding), &mixed);
  // No quad at all: the decisions of coding 7, under coding 8's number.
  const Mesh sphere = perturbed(triangulated(make_refined_sphere(2)), 5, 0.01f);
  w->valid("valid_polygon_coding8_triangles", encode_polygons(sphere, coding), &sphere);
  RandomSoupOptions soup_options;  // non-manifold edges and vertices, loose faces, identifications
  soup_options.vertices = 120;
  soup_options.faces = 160;
  const Mesh soup = make_random_soup(22, soup_options);
  w->valid("valid_polygon_coding8_soup", encode_polygons(soup, coding), &soup);
  // A random quad disk whose traversal has a Q8 (three detours in one face).
  std::vector<uint8_t> disk_file;
  for (uint64_t seed = 1; disk_file.empty(); ++seed) {
    const Mesh disk = make_random_quad_disk(seed, 60);
    qmc::PolygonEncoding encoding;
    if (!qmc::encode_polygon_connectivity(disk, coding, true, true, true, &encoding).empty()) continue;
    if (encoding.symbol_counts[7] == 0) continue;
    disk_file = encode_polygons(disk, coding);
    w->valid("valid_polygon_coding8_three_detours", disk_file, &disk);
  }
  // Gates with b other than c and counts up to 7, which a reading of c alone or without the caps gets wrong.
  const Mesh pole = pole_disk(12, 4);
  w->valid("valid_polygon_coding8_pole12", encode_polygons(pole, coding), &pole);
  // Quads around three holes: symbol 18's ST and GK beside quads in many contexts (they keep theirs).
  Mesh holed = make_torus(12, 7);
  holed.face_sizes.resize(holed.face_count() - 3);
  for (const uint32_t f : {70u, 40u, 10u}) holed.corners.erase(holed.corners.begin() + 4 * f, holed.corners.begin() + 4 * f + 4);
  holed.corners.resize(4 * holed.face_sizes.size());
  w->valid("valid_polygon_coding8_torus_holes", encode_polygons(holed, coding), &holed);
  // What `qmc encode -q 12` writes for a quad torus of 1,040 vertices: coding 8 and POSN method 13 (1.18).
  {
    const Mesh big = make_torus(40, 26);
    qmc::EncodeOptions options;
    options.position_bits = 12;
    std::vector<uint8_t> out;
    qmc::EncodeStats stats;
    if (qmc::Status s = qmc::encode(big, options, &out, &stats);
        !s.ok() || stats.polygon.coding != coding || stats.positions.method != 13) {
      std::fprintf(stderr, "qmc-make-vectors: coding 8 with POSN 13: %s\n", s.to_string().c_str());
      std::exit(3);
    }
    w->valid("valid_polygon_coding8_posn13", out, &big);
  }
  const ChunkReplacer with_conn(encode_polygons(make_cube()));
  const auto quad_code = [](int symbol) {
    return coding7_symbols(
        qmc::kGroupQuads,
        [symbol](qmc::RangeEncoder* r, qmc::PolygonSymbolModel* m) { qmc::code_face_symbol(r, m, qmc::GateContext{}, symbol); },
        true);
  };
  w->valid("valid_polygon_coding8_pillow",
           with_conn(coding7_conn(8, 2, qmc::kGroupQuads, quad_code(0), one_component(0, 1), 0, coding)), nullptr);
  w->invalid("invalid_polygon_coding8_quad_code_13",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, quad_code(13), one_component(0, 1), 0, coding)),
             ErrorCode::kBadSymbol);
  w->invalid("invalid_polygon_coding8_groups_above_7",
             with_conn(coding7_conn(8, 2, 8, quad_code(0), one_component(0, 1), 0, coding)), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_polygon_coding8_symbols_cut", with_symbols_cut(disk_file, "coding 8 disk"), ErrorCode::kTruncated);
  // A quad code 13 whose decisions also read the fifth invented byte: truncated, checked first (5.4.10).
  for (int q1 = 1;; ++q1) {
    const std::vector<uint8_t> all = q1s_then_code13(q1);
    bool found = false;
    for (size_t keep = all.size() + 1; keep-- > 0 && !found;) {
      const std::vector<uint8_t> symbols(all.begin(), all.begin() + std::ptrdiff_t(keep));
      if (!code13_meets_truncation(symbols, q1)) continue;
      w->invalid("invalid_polygon_coding8_code_13_truncated",
                 with_conn(coding7_conn(uint32_t(4 * (q1 + 5)), uint32_t(q1 + 5), qmc::kGroupQuads, symbols,
                                        one_component(uint32_t(q1 + 3), 1), 0, coding)),
                 ErrorCode::kTruncated);
      found = true;
    }
    if (found) break;
  }
  w->invalid("invalid_polygon_unknown_coding_9",
             with_conn(coding7_conn(8, 2, qmc::kGroupQuads, quad_code(0), one_component(0, 1), 0, 9)),
             ErrorCode::kUnsupportedFeature);
}

// ---------------------------------------------------------------------------
// Section 15: aTTR, attributes of the corners.

std::vector<uint8_t> encode_with(const Mesh& mesh, const qmc::EncodeOptions& options, const char* what) {
  std::vector<uint8_t> out;
  if (qmc::Status s = qmc::encode(mesh, without_shear(options), &out); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s: %s\n", what, s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

// The file with an extra chunk inserted before chunk `at` (by type, nth 0).
std::vector<uint8_t> with_chunk_before(const std::vector<uint8_t>& file, uint32_t at, uint32_t type,
                                       std::vector<uint8_t> payload) {
  Chunks c = split_chunks(file);
  c.insert(c.begin() + std::ptrdiff_t(find_chunk(c, at)), Chunk{type, std::move(payload)});
  return join_chunks(c);
}

// The fields of an aTTR payload (15.1), each settable to break one rule.
struct AttrFields {
  uint64_t vertices = 8, corners = 24;
  std::string name = "uv";
  uint8_t kind = 1, components = 2, mapping = 1;
  uint64_t values = 24;
  uint8_t coding = 1;
  std::vector<uint8_t> mapping_stream;
  int64_t mapping_length = -1;  // -1: the stream's own
  std::vector<uint8_t> rest;    // the values part
  size_t cut = SIZE_MAX;        // payload cut to this many bytes
};

std::vector<uint8_t> attr_payload(const AttrFields& f) {
  std::vector<uint8_t> p;
  qmc::put_varint(&p, f.vertices);
  qmc::put_varint(&p, f.corners);
  qmc::put_u8(&p, uint8_t(f.name.size()));
  p.insert(p.end(), f.name.begin(), f.name.end());
  for (uint8_t b : {f.kind, f.components, f.mapping}) qmc::put_u8(&p, b);
  qmc::put_varint(&p, f.values);
  qmc::put_u8(&p, f.coding);
  if (f.mapping == 1 || f.mapping == 3) {
    qmc::put_varint(&p, f.mapping_length >= 0 ? uint64_t(f.mapping_length) : f.mapping_stream.size());
    p.insert(p.end(), f.mapping_stream.begin(), f.mapping_stream.end());
  }
  p.insert(p.end(), f.rest.begin(), f.rest.end());
  if (f.cut < p.size()) p.resize(f.cut);
  return p;
}

// Where an aTTR payload's components byte is, and the first byte after its
// coding (mapping_bytes, or coding 3's bits).
struct AttrFieldOffsets {
  size_t components, after_coding;
};
AttrFieldOffsets attr_field_offsets(const std::vector<uint8_t>& payload) {
  qmc::ByteReader r(payload.data(), payload.size());
  uint64_t skip = 0;
  uint8_t byte = 0;
  r.get_varint(&skip);
  r.get_varint(&skip);
  r.get_u8(&byte);
  r.skip(byte);
  AttrFieldOffsets at;
  at.components = r.position() + 1;
  for (int i = 0; i < 3; ++i) r.get_u8(&byte);  // kind, components, mapping
  r.get_varint(&skip);
  r.get_u8(&byte);  // coding
  at.after_coding = r.position();
  return at;
}

// A mapping stream (15.3) of the given choices, one per corner of `corners`.
std::vector<uint8_t> mapping_stream(const std::vector<uint32_t>& corners, uint32_t vertex_count, uint64_t value_count,
                                    const std::vector<qmc::MappingChoice>& choices) {
  qmc::RangeEncoder rc;
  qmc::AttributeMappingModel model;
  qmc::VertexValueLists lists;
  lists.reset(vertex_count, corners);
  uint32_t met = 0;
  qmc::MappingFault fault = qmc::MappingFault::kNone;
  for (size_t k = 0; k < choices.size(); ++k)
    qmc::code_corner_value(&rc, &model, &lists, corners[k], value_count, &met, choices[k], &fault);
  return rc.finish();
}

std::vector<uint8_t> exact_values(size_t floats) {
  std::vector<uint8_t> v;
  for (size_t i = 0; i < floats; ++i) qmc::put_f32le(&v, float(i) / 8);
  return v;
}

void write_attribute_valid(VectorWriter* w) {
  using namespace qmc::tools;
  qmc::EncodeOptions options = format_1_6_options();  // what `qmc encode` wrote before normals took 15.7's coding
  options.octahedral_normals = false;
  Mesh sphere = perturbed(triangulated(make_refined_sphere(3)), 7, 0.01f);
  add_chart_texcoords(&sphere);
  w->valid("valid_attr_texcoord_seams", encode_with(sphere, options, "seams"), &sphere);
  Mesh normals = perturbed(triangulated(make_refined_sphere(2)), 8, 0.01f);
  add_vertex_normals(&normals);
  w->valid("valid_attr_normal_per_vertex", encode_with(normals, options, "normals"), &normals);
  // Quads and polygons: the attribute mesh takes section 14's polygon rules.
  Mesh quads = make_torus(12, 8);
  add_chart_texcoords(&quads);
  add_vertex_normals(&quads);
  w->valid("valid_attr_quads_texcoord_normal", encode_with(quads, options, "quads"), &quads);
  // oRDR after the attributes (15.6): scrambled input, kept order, both mappings.
  Mesh scrambled = make_scrambled(triangulated(make_torus(10, 6)), 5);
  add_chart_texcoords(&scrambled);
  add_vertex_normals(&scrambled);
  qmc::EncodeOptions keep = options;
  keep.keep_order = true;
  w->valid("valid_attr_keep_order", encode_with(scrambled, keep, "keep order"), &scrambled);
  // Random tables: own values of a vertex, values of other vertices, unreferenced values, 1 and 3 components.
  Mesh random = triangulated(make_grid(7, 6));
  add_random_corner_attribute(&random, 3, "weights", qmc::AttributeKind::kGeneric, 1);
  add_random_corner_attribute(&random, 4, "colour", qmc::AttributeKind::kColour, 3);
  w->valid("valid_attr_random_corner_tables", encode_with(random, options, "random"), &random);
  // Exact binary32: -0.0, a NaN with a payload, infinities, denormals.
  Mesh exact = make_cube();
  add_random_corner_attribute(&exact, 6, "exact", qmc::AttributeKind::kGeneric, 2);
  const uint32_t patterns[] = {0x80000000u, 0x7FC01234u, 0x7F800000u, 0xFF800000u, 0x00000001u};
  for (size_t i = 0; i < 5; ++i) std::memcpy(&exact.attributes[0].values[i], &patterns[i], 4);
  qmc::EncodeOptions exact_options = options;
  exact_options.exact_attributes = true;
  w->valid("valid_attr_exact_binary32", encode_with(exact, exact_options, "exact"), &exact);
  // One value on every corner (every top 0: the encoder gives top 1).
  Mesh constant = make_cube();
  constant.attributes.push_back({"flat", qmc::AttributeKind::kGeneric, 2, {0.25f, -1.5f}, std::vector<uint32_t>(24, 0)});
  w->valid("valid_attr_one_value", encode_with(constant, options, "one value"), &constant);

  const std::vector<uint8_t> cube = encode_with(make_cube(), options, "cube");
  const Mesh cube_file = [&] {
    qmc::DecodedFile f;
    (void)qmc::decode(cube.data(), cube.size(), &f);
    return f.mesh;
  }();
  std::vector<qmc::MappingChoice> all_new(24);
  AttrFields f;
  f.mapping_stream = mapping_stream(cube_file.corners, 8, 24, all_new);
  f.rest = exact_values(48);
  // A kind this revision does not name is kept; a mapping or coding it does not define is skipped.
  AttrFields kind9 = f;
  kind9.kind = 9;
  w->valid("valid_attr_unknown_kind_kept", with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(kind9)),
           nullptr);
  AttrFields mapping2 = f;
  mapping2.mapping = 2;
  w->valid("valid_attr_unknown_mapping_skipped",
           with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(mapping2)), nullptr);
  AttrFields coding2 = f;
  coding2.coding = 2;
  w->valid("valid_attr_unknown_coding_skipped",
           with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(coding2)), nullptr);
  // Every corner refers to the value of the vertex's first corner, found as own
  // (n = 1), and the values beyond U (unreferenced): N = 30 with U = 8.
  std::vector<qmc::MappingChoice> own(24);
  {
    std::vector<int> seen(8, 0);
    for (size_t k = 0; k < 24; ++k)
      own[k] = seen[cube_file.corners[k]]++ ? qmc::MappingChoice{qmc::MappingChoice::kOwn, 0} : qmc::MappingChoice{};
  }
  AttrFields unreferenced = f;
  unreferenced.values = 30;
  unreferenced.mapping_stream = mapping_stream(cube_file.corners, 8, 30, own);
  unreferenced.rest = exact_values(60);
  w->valid("valid_attr_unreferenced_values",
           with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(unreferenced)), nullptr);
}

// Hand-made texture coordinates of a file of the cube: every corner a new
// value (in the file's corner order), exact binary32.
AttrFields cube_texcoord_fields(const std::vector<uint8_t>& cube) {
  qmc::DecodedFile decoded;
  (void)qmc::decode(cube.data(), cube.size(), &decoded);
  AttrFields f;
  f.mapping_stream = mapping_stream(decoded.mesh.corners, 8, 24, std::vector<qmc::MappingChoice>(24));
  f.rest = exact_values(48);
  return f;
}

void write_attribute_errors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  qmc::EncodeOptions options = format_1_6_options();
  options.octahedral_normals = false;
  const std::vector<uint8_t> cube = encode_with(make_cube(), options, "cube");
  qmc::DecodedFile decoded;
  (void)qmc::decode(cube.data(), cube.size(), &decoded);
  const std::vector<uint32_t>& corners = decoded.mesh.corners;
  const AttrFields f = cube_texcoord_fields(cube);
  const auto attr = [&](const AttrFields& x) {
    return with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(x));
  };
  const auto invalid = [&](const char* name, AttrFields x, ErrorCode e) { w->invalid(name, attr(x), e); };
  // Placement (15.1).
  w->invalid("invalid_attr_before_posn", with_chunk_before(cube, qmc::kChunkPositions, qmc::kChunkAttribute, attr_payload(f)),
             ErrorCode::kChunkOrder);
  {
    Mesh scrambled = make_scrambled(make_cube(), 3);
    qmc::EncodeOptions keep = options;
    keep.keep_order = true;
    const std::vector<uint8_t> ordered = encode_with(scrambled, keep, "ordered cube");
    qmc::DecodedFile d;
    (void)qmc::decode(ordered.data(), ordered.size(), &d);
    AttrFields g = f;
    g.mapping_stream = mapping_stream(corners, 8, 24, std::vector<qmc::MappingChoice>(24));
    w->invalid("invalid_attr_after_ordr", with_chunk_before(ordered, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(g)),
               ErrorCode::kChunkOrder);
  }
  {
    const std::vector<uint8_t> loop =
        loop_file(triangulated(make_torus(9, 6)), 1, torus_targets(1, 0.35), 12, qmc::PositionMethod::kPredicted, 2, true);
    w->invalid("invalid_attr_in_progressive_file",
               with_chunk_before(loop, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(f)), ErrorCode::kChunkOrder);
  }
  // Checks 1-3.
  AttrFields x = f;
  x.vertices = 9;
  invalid("invalid_attr_vertex_count_not_conn", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.corners = 23;
  invalid("invalid_attr_corner_count_not_conn", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.name = "";
  invalid("invalid_attr_empty_name", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.cut = 4;  // 8, 24, length 2, "u"
  invalid("invalid_attr_name_cut_short", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.cut = 7;  // ..., kind, components, then no mapping
  invalid("invalid_attr_mapping_missing", x, ErrorCode::kBadChunkPayload);
  {
    const std::vector<uint8_t> once = attr(f);
    w->invalid("invalid_attr_name_repeated",
               with_chunk_before(once, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(f)), ErrorCode::kBadChunkPayload);
  }
  x = f;
  x.components = 0;
  invalid("invalid_attr_components_0", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.components = 4;
  invalid("invalid_attr_components_4", x, ErrorCode::kBadChunkPayload);
  // Checks 5-8.
  x = f;
  x.mapping = 0;
  x.values = 9;
  invalid("invalid_attr_per_vertex_count_not_v", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.values = uint64_t(1) << 32;
  invalid("invalid_attr_value_count_above_2_32", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.cut = 9;  // ..., mapping, value_count, then no coding
  invalid("invalid_attr_coding_missing", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.mapping_length = int64_t(f.mapping_stream.size() + f.rest.size() + 1);
  invalid("invalid_attr_mapping_bytes_past_end", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.rest.pop_back();
  invalid("invalid_attr_exact_values_short", x, ErrorCode::kBadChunkPayload);
  x = f;
  x.coding = 0;
  x.values = 24;
  x.rest.clear();  // N = 24 > 512 (0 + 8)? no: add values so that N exceeds the bound
  x.values = 4097;
  x.mapping_stream = mapping_stream(corners, 8, 4097, std::vector<qmc::MappingChoice>(24));
  invalid("invalid_attr_values_unjustified", x, ErrorCode::kLimitExceeded);
  // Check 9: the mapping stream (15.3).
  x = f;
  x.mapping_stream = {0xFF, 0xFF, 0xFF, 0xFF};
  invalid("invalid_attr_mapping_bad_start", x, ErrorCode::kBadChunkPayload);
  {
    // A random table's mapping stream cut in half: the rest reads as zeros,
    // valid decisions (not new, j = 0) until more than 4 bytes are invented.
    Mesh grid = triangulated(make_grid(12, 12));
    add_random_corner_attribute(&grid, 9, "t", qmc::AttributeKind::kGeneric, 1);
    Chunks c = split_chunks(encode_with(grid, options, "grid"));
    std::vector<uint8_t>& p = c[find_chunk(c, qmc::kChunkAttribute)].payload;
    const size_t length_at = attr_field_offsets(p).after_coding;
    qmc::ByteReader r(p.data(), p.size());
    r.skip(length_at);
    uint64_t length = 0;
    r.get_varint(&length);
    std::vector<uint8_t> cut(p.begin(), p.begin() + std::ptrdiff_t(length_at));
    qmc::put_varint(&cut, length / 2);
    cut.insert(cut.end(), p.begin() + std::ptrdiff_t(r.position()), p.begin() + std::ptrdiff_t(r.position() + length / 2));
    cut.insert(cut.end(), p.begin() + std::ptrdiff_t(r.position() + length), p.end());
    p = cut;
    w->invalid("invalid_attr_mapping_truncated", join_chunks(c), ErrorCode::kTruncated);
  }
  x = f;
  x.mapping_stream.insert(x.mapping_stream.end(), 8, 0);
  invalid("invalid_attr_mapping_bytes_after_data", x, ErrorCode::kBadChunkPayload);
  {
    // Corner 0 "not new" with nothing met (n = 0, U = 0).
    std::vector<qmc::MappingChoice> c(1, qmc::MappingChoice{qmc::MappingChoice::kMet, 0});
    x = f;
    x.mapping_stream = mapping_stream(corners, 8, 24, c);
    invalid("invalid_attr_mapping_nothing_met", x, ErrorCode::kBadSymbol);
    // Corners 0-2 new (U = 3), then corner 3 "met" value 3 (2 bits: 3 >= U).
    c.assign(3, qmc::MappingChoice{});
    c.push_back({qmc::MappingChoice::kMet, 3});
    x.mapping_stream = mapping_stream(corners, 8, 24, c);
    invalid("invalid_attr_mapping_met_index_past", x, ErrorCode::kBadSymbol);
  }
  {
    // A vertex with 3 values (n = 3) whose next corner asks for own value 3
    // (2 bits): the triangulated cube, whose vertices have 4 to 6 corners.
    const std::vector<uint8_t> tri = encode_with(triangulated(make_cube()), options, "triangulated cube");
    qmc::DecodedFile d;
    (void)qmc::decode(tri.data(), tri.size(), &d);
    const std::vector<uint32_t>& tc = d.mesh.corners;
    std::vector<qmc::MappingChoice> c;
    std::vector<int> seen(8, 0);
    for (size_t k = 0; k < tc.size() && seen[tc[k]] < 3; ++k) {
      ++seen[tc[k]];
      c.push_back({});
    }
    c.push_back({qmc::MappingChoice::kOwn, 3});
    AttrFields t = f;
    t.corners = tc.size();
    t.values = tc.size();
    t.mapping_stream = mapping_stream(tc, 8, tc.size(), c);
    t.rest = exact_values(2 * tc.size());
    w->invalid("invalid_attr_mapping_own_index_past",
               with_chunk_before(tri, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(t)), ErrorCode::kBadSymbol);
  }
  // 15.4: the grid and the values' stream.
  AttrFields g = f;
  g.coding = 0;
  const auto grid = [](uint8_t kind, float o0, double step, uint64_t top0) {
    std::vector<uint8_t> v;
    qmc::put_u8(&v, kind);
    qmc::put_f32le(&v, o0);
    qmc::put_f32le(&v, 0.f);
    qmc::put_f64le(&v, step);
    if (kind == 1) qmc::put_f64le(&v, step);
    qmc::put_varint(&v, top0);
    qmc::put_varint(&v, 3);
    return v;
  };
  // Values 0.. on the grid (q = i mod 4, 0), coded by section 14's coder over the attribute mesh.
  qmc::Mesh attribute_mesh;
  attribute_mesh.face_sizes = decoded.mesh.face_sizes;
  std::vector<uint32_t> m(24);
  for (uint32_t k = 0; k < 24; ++k) m[k] = k;
  attribute_mesh.corners = m;
  std::vector<uint32_t> q(3 * 24, 0);
  for (uint32_t i = 0; i < 24; ++i) q[3 * i] = i % 4;
  const uint32_t top[3] = {3, 3, 0};
  const std::vector<uint8_t> stream = qmc::encode_predicted_grid(q, top, attribute_mesh, nullptr, qmc::CandidateChoice::kFewestBits);
  g.rest = grid(0, 0.f, 0.5, 3);
  g.rest.insert(g.rest.end(), stream.begin(), stream.end());
  w->valid("valid_attr_grid_hand_made", attr(g), nullptr);
  x = g;
  x.rest = grid(2, 0.f, 0.5, 3);
  invalid("invalid_attr_grid_above_1", x, ErrorCode::kBadChunkPayload);
  x = g;
  x.rest = grid(0, 0.f, 0.5, uint64_t(1) << 30);
  invalid("invalid_attr_grid_top_above_2_30", x, ErrorCode::kBadChunkPayload);
  x = g;
  x.rest = grid(0, std::numeric_limits<float>::infinity(), 0.5, 3);
  invalid("invalid_attr_grid_origin_not_finite", x, ErrorCode::kBadChunkPayload);
  x = g;
  x.rest = grid(1, 0.f, -0.5, 3);
  invalid("invalid_attr_grid_step_negative", x, ErrorCode::kBadChunkPayload);
  x = g;
  x.rest = grid(0, 3e38f, 1e38, 3);
  invalid("invalid_attr_grid_last_point_overflows", x, ErrorCode::kBadChunkPayload);
  // The longest cut of the values' stream that runs out of bytes (shorter
  // cuts may read zeros as a value outside the grid first).
  for (size_t n = stream.size(); n-- > 0;) {
    x = g;
    x.rest = grid(0, 0.f, 0.5, 3);
    x.rest.insert(x.rest.end(), stream.begin(), stream.begin() + std::ptrdiff_t(n));
    qmc::DecodedFile d;
    const std::vector<uint8_t> file = attr(x);
    if (qmc::decode(file.data(), file.size(), &d).code() != ErrorCode::kTruncated) continue;
    w->invalid("invalid_attr_values_truncated", file, ErrorCode::kTruncated);
    break;
  }
  x = g;
  x.rest = grid(0, 0.f, 0.5, 2);  // q = 3 is above top 2
  x.rest.insert(x.rest.end(), stream.begin(), stream.end());
  invalid("invalid_attr_value_above_top", x, ErrorCode::kBadSymbol);
  x = g;
  x.rest.insert(x.rest.end(), 8, 0);
  invalid("invalid_attr_values_bytes_after_data", x, ErrorCode::kBadChunkPayload);
}

// 15.7's prediction P_u of value 0 of a file's (per-vertex) normals, on the grid of B = 2.
uint32_t first_normal_prediction_u(const std::vector<uint8_t>& file) {
  qmc::DecodedFile d;
  (void)qmc::decode(file.data(), file.size(), &d);
  qmc::ValueCorners value_corners;
  value_corners.build(d.mesh.corners, d.mesh.vertex_count());
  qmc::CornerCycle cycle;
  cycle.build(d.mesh.face_sizes, d.mesh.corners.size());
  qmc::OctahedralFrame frame;
  uint32_t pu = 0, pv = 0;
  qmc::predict_octahedral(value_corners.begin(0), value_corners.end(0), d.mesh.corners, cycle, d.quantized.data(), 3,
                          &frame, &pu, &pv);
  return pu;
}

// Section 15.7: unit normals on the octahedral grid, predicted from the positions.
void write_octahedral_normal_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  qmc::EncodeOptions options = format_1_6_options();  // what `qmc encode` writes
  Mesh sphere = perturbed(triangulated(make_refined_sphere(2)), 11, 0.02f);
  add_vertex_normals(&sphere);
  const std::vector<uint8_t> smooth = encode_with(sphere, options, "octahedral sphere");
  w->valid("valid_attr_octahedral_vertex_normals", smooth, &sphere);
  // Per-corner normals of a cube's flat faces: every axis up once, both signs (frames t = 0, 1, 2, sigma = -1, +1).
  Mesh cube = make_cube();
  {
    MeshAttribute flat{"normal", qmc::AttributeKind::kNormal, 3, {}, {}};
    size_t k0 = 0;
    for (uint32_t d : cube.face_sizes) {
      double n[3] = {0, 0, 0};
      for (uint32_t i = 0; i < d; ++i) {
        const float* p = &cube.positions[3 * size_t(cube.corners[k0 + i])];
        const float* q = &cube.positions[3 * size_t(cube.corners[k0 + (i + 1) % d])];
        n[0] += (double(p[1]) - q[1]) * (double(p[2]) + q[2]);
        n[1] += (double(p[2]) - q[2]) * (double(p[0]) + q[0]);
        n[2] += (double(p[0]) - q[0]) * (double(p[1]) + q[1]);
      }
      const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const uint32_t value = uint32_t(flat.value_count());
      for (int a = 0; a < 3; ++a) flat.values.push_back(float(n[a] / l));
      for (uint32_t i = 0; i < d; ++i) flat.corner_values.push_back(value);
      k0 += d;
    }
    cube.attributes.push_back(flat);
  }
  qmc::EncodeOptions sixteen = options;
  sixteen.normal_bits = 16;
  w->valid("valid_attr_octahedral_face_normals_16_bits", encode_with(cube, sixteen, "octahedral cube"), &cube);
  qmc::EncodeOptions two = options;
  two.normal_bits = 2;
  w->valid("valid_attr_octahedral_2_bits", encode_with(sphere, two, "octahedral 2 bits"), nullptr);

  // Invalid: the payload of the sphere's normals with one thing broken.
  Chunks c = split_chunks(smooth);
  const size_t at = find_chunk(c, qmc::kChunkAttribute);
  const std::vector<uint8_t> payload = c[at].payload;
  const size_t components_at = attr_field_offsets(payload).components, bits_at = attr_field_offsets(payload).after_coding;
  const auto with_payload = [&](std::vector<uint8_t> p) {
    Chunks broken = c;
    broken[at].payload = std::move(p);
    return join_chunks(broken);
  };
  std::vector<uint8_t> p = payload;
  p[bits_at] = 1;
  w->invalid("invalid_attr_octahedral_bits_1", with_payload(p), ErrorCode::kBadChunkPayload);
  p[bits_at] = 17;
  w->invalid("invalid_attr_octahedral_bits_17", with_payload(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p[components_at] = 2;
  w->invalid("invalid_attr_octahedral_two_components", with_payload(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p.insert(p.end(), 8, 0);
  w->invalid("invalid_attr_octahedral_bytes_after_data", with_payload(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p.resize(bits_at + 1 + 4);
  p[bits_at + 1] = p[bits_at + 2] = p[bits_at + 3] = p[bits_at + 4] = 0xFF;
  w->invalid("invalid_attr_octahedral_bad_start", with_payload(p), ErrorCode::kBadChunkPayload);
  // The longest cut of the stream that runs out of bytes.
  bool truncated = false, outside = false;
  for (size_t n = payload.size(); n-- > bits_at + 1 && !truncated;) {
    std::vector<uint8_t> cut(payload.begin(), payload.begin() + std::ptrdiff_t(n));
    const std::vector<uint8_t> file = with_payload(cut);
    qmc::DecodedFile d;
    if (qmc::decode(file.data(), file.size(), &d).code() != ErrorCode::kTruncated) continue;
    w->invalid("invalid_attr_octahedral_truncated", file, ErrorCode::kTruncated);
    truncated = true;
  }
  {
    // B = 2 (M = 3) and value 0's u residual 3 away from its prediction, on the far side.
    const uint32_t pu = first_normal_prediction_u(smooth);
    qmc::RangeEncoder rc;
    qmc::OctahedralModel model;
    qmc::code_octahedral_residual(&rc, &model, 2, 0, 0, qmc::SignedResidual{3, pu == 0});
    const std::vector<uint8_t> stream = rc.finish();
    p.assign(payload.begin(), payload.begin() + std::ptrdiff_t(bits_at));
    p.push_back(2);
    p.insert(p.end(), stream.begin(), stream.end());
    w->invalid("invalid_attr_octahedral_outside_grid", with_payload(p), ErrorCode::kBadSymbol);
    outside = true;
  }
  if (!truncated || !outside) {
    std::fprintf(stderr, "qmc-make-vectors: octahedral: no truncated cut or no outside-grid stream\n");
    std::exit(3);
  }
}

// Section 16: fLBL, a label per face.
void write_face_label_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  qmc::EncodeOptions options = format_1_6_options();
  Mesh torus = triangulated(make_torus(10, 6));
  add_face_labels(&torus, 1, 9);
  const std::vector<uint8_t> file = encode_with(torus, options, "labels");
  w->valid("valid_flbl_material_group", file, &torus);
  Mesh scrambled = make_scrambled(make_torus(8, 5), 2);
  add_face_labels(&scrambled, 2, 4);
  qmc::EncodeOptions keep = options;
  keep.keep_order = true;
  w->valid("valid_flbl_keep_order", encode_with(scrambled, keep, "labels kept"), &scrambled);
  Mesh bare = make_cube();
  bare.face_labels.push_back({"tag", {}, {}, std::vector<uint32_t>(6, 0)});  // no value: every face none
  w->valid("valid_flbl_empty_table", encode_with(bare, options, "empty table"), &bare);

  // Invalid: the cube with one label chunk, its fields set by hand.
  const std::vector<uint8_t> cube = encode_with(make_cube(), options, "cube");
  qmc::DecodedFile d;
  (void)qmc::decode(cube.data(), cube.size(), &d);
  struct Fields {
    uint64_t faces = 6;
    std::string name = "material";
    std::vector<std::string> references{"m.mtl"}, values{"a", "b"};
    std::vector<uint32_t> labels{0, 0, 1, 1, 3, 0};  // 3 of a table of 2: past "none" (2)
    std::vector<uint8_t> stream;  // coded from labels unless set
    size_t cut = SIZE_MAX;
  };
  const auto payload = [](const Fields& f) {
    std::vector<uint8_t> p;
    qmc::put_varint(&p, f.faces);
    qmc::put_u8(&p, uint8_t(f.name.size()));
    p.insert(p.end(), f.name.begin(), f.name.end());
    for (const auto* table : {&f.references, &f.values}) {
      qmc::put_varint(&p, table->size());
      for (const std::string& s : *table) {
        qmc::put_varint(&p, s.size());
        p.insert(p.end(), s.begin(), s.end());
      }
    }
    std::vector<uint8_t> stream = f.stream;
    if (stream.empty()) {
      qmc::RangeEncoder rc;
      uint16_t same = qmc::kRangeProbabilityInit;
      uint32_t previous = uint32_t(f.values.size());
      for (size_t j = 0; j < f.labels.size(); ++j)
        previous = qmc::code_face_label(&rc, &same, j, previous, uint32_t(f.values.size()), f.labels[j]);
      stream = rc.finish();
    }
    p.insert(p.end(), stream.begin(), stream.end());
    if (f.cut < p.size()) p.resize(f.cut);
    return p;
  };
  const auto with = [&](const Fields& f) {
    return with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkFaceLabels, payload(f));
  };
  const Fields f;
  w->invalid("invalid_flbl_label_past_table", with(f), ErrorCode::kBadSymbol);
  Fields ok = f;
  ok.labels = {0, 0, 1, 1, 2, 0};  // face 4 unlabelled
  ok.values = {"a", "b"};
  w->valid("valid_flbl_hand_made", with(ok), nullptr);
  w->invalid("invalid_flbl_before_posn", with_chunk_before(cube, qmc::kChunkPositions, qmc::kChunkFaceLabels, payload(ok)),
             ErrorCode::kChunkOrder);
  {
    Mesh scrambled_cube = make_scrambled(make_cube(), 3);
    const std::vector<uint8_t> ordered = encode_with(scrambled_cube, keep, "ordered cube");
    w->invalid("invalid_flbl_after_ordr",
               with_chunk_before(ordered, qmc::kChunkEnd, qmc::kChunkFaceLabels, payload(ok)), ErrorCode::kChunkOrder);
  }
  Fields x = ok;
  x.faces = 7;
  w->invalid("invalid_flbl_face_count_not_conn", with(x), ErrorCode::kBadChunkPayload);
  x = ok;
  x.name = "";
  w->invalid("invalid_flbl_empty_name", with(x), ErrorCode::kBadChunkPayload);
  x = ok;
  x.cut = 5;  // 6, length 8, "mat"
  w->invalid("invalid_flbl_name_cut_short", with(x), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_flbl_name_repeated",
             with_chunk_before(with(ok), qmc::kChunkEnd, qmc::kChunkFaceLabels, payload(ok)), ErrorCode::kBadChunkPayload);
  x = ok;
  x.cut = 1 + 1 + 8 + 1 + 1 + 3;  // ..., references 1, "m.m": the reference cut short
  w->invalid("invalid_flbl_string_cut_short", with(x), ErrorCode::kBadChunkPayload);
  {
    std::vector<uint8_t> p = payload(ok);
    p.resize(1 + 1 + 8);
    qmc::put_varint(&p, 1000);  // 1000 references in the few bytes left
    p.insert(p.end(), 20, 0);
    w->invalid("invalid_flbl_count_above_bytes_left", with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkFaceLabels, p),
               ErrorCode::kBadChunkPayload);
  }
  x = ok;
  x.stream = {0xFF, 0xFF, 0xFF, 0xFF};
  w->invalid("invalid_flbl_bad_start", with(x), ErrorCode::kBadChunkPayload);
  {
    std::vector<uint8_t> p = payload(ok);
    p.insert(p.end(), 8, 0);
    w->invalid("invalid_flbl_bytes_after_data", with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkFaceLabels, p),
               ErrorCode::kBadChunkPayload);
  }
  {
    // 4097 faces from an empty stream: above 512 (0 + 8).
    Mesh many;
    for (int i = 0; i < 3; ++i) many.positions.insert(many.positions.end(), {float(i), float(i * i), 0.f});
    for (int i = 0; i < 4097; ++i) {
      many.face_sizes.push_back(3);
      many.corners.insert(many.corners.end(), {0, 1, 2});
    }
    Fields big = ok;
    big.faces = 4097;
    big.values.clear();
    big.labels.clear();
    std::vector<uint8_t> p = payload(big);
    w->invalid("invalid_flbl_faces_unjustified",
               with_chunk_before(encode_with(many, options, "4097 faces"), qmc::kChunkEnd, qmc::kChunkFaceLabels, p),
               ErrorCode::kLimitExceeded);
  }
  // The material run of the torus cut: the longest cut that runs out of bytes.
  Chunks c = split_chunks(file);
  const size_t at = find_chunk(c, qmc::kChunkFaceLabels);
  const std::vector<uint8_t> full = c[at].payload;
  for (size_t n = full.size(); n-- > 0;) {
    c[at].payload.assign(full.begin(), full.begin() + std::ptrdiff_t(n));
    const std::vector<uint8_t> cut = join_chunks(c);
    qmc::DecodedFile e;
    if (qmc::decode(cut.data(), cut.size(), &e).code() != ErrorCode::kTruncated) continue;
    w->invalid("invalid_flbl_truncated", cut, ErrorCode::kTruncated);
    break;
  }
}

// Points an independent decoder written from spec 15 raised: a skipped
// chunk's name still counts (15.1 check 2), and a residual of half the
// octahedral grid is valid (15.7: 13.5.6's overflow rule does not apply).
void write_attribute_review_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  qmc::EncodeOptions options = format_1_6_options();
  options.octahedral_normals = false;
  const std::vector<uint8_t> cube = encode_with(make_cube(), options, "cube");
  const AttrFields f = cube_texcoord_fields(cube);
  AttrFields skipped = f;
  skipped.coding = 2;
  const std::vector<uint8_t> first = with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(skipped));
  w->invalid("invalid_attr_name_of_skipped_chunk_repeated",
             with_chunk_before(first, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(f)), ErrorCode::kBadChunkPayload);

  Mesh sphere = perturbed(triangulated(make_refined_sphere(2)), 11, 0.02f);
  add_vertex_normals(&sphere);
  const std::vector<uint8_t> smooth = encode_with(sphere, format_1_6_options(), "octahedral sphere");
  Chunks c = split_chunks(smooth);
  const size_t at = find_chunk(c, qmc::kChunkAttribute);
  const size_t bits_at = attr_field_offsets(c[at].payload).after_coding;
  const uint32_t pu = first_normal_prediction_u(smooth);
  qmc::DecodedFile d;
  (void)qmc::decode(smooth.data(), smooth.size(), &d);
  qmc::RangeEncoder rc;
  qmc::OctahedralModel model;
  uint32_t activity = 0;
  for (size_t i = 0; i < d.mesh.vertex_count(); ++i) {
    const int bucket = qmc::octahedral_bucket(activity);
    const qmc::SignedResidual u = i == 0 ? qmc::SignedResidual{2, pu >= 2} : qmc::SignedResidual{};
    qmc::code_octahedral_residual(&rc, &model, 2, bucket, 0, u);
    qmc::code_octahedral_residual(&rc, &model, 2, bucket, 1, qmc::SignedResidual{});
    activity = u.magnitude;
  }
  const std::vector<uint8_t> stream = rc.finish();
  std::vector<uint8_t>& p = c[at].payload;
  p.resize(bits_at);
  p.push_back(2);
  p.insert(p.end(), stream.begin(), stream.end());
  w->valid("valid_attr_octahedral_residual_half_the_grid", join_chunks(c), nullptr);
}

// What `qmc encode` writes with predicted positions: POSN method 3 as
// format 1.7 wrote it (the label order, 14.4.1's graded start under 1,000
// vertices), or method 4 as 1.8 writes it (the geometry order, 14.6).
std::vector<uint8_t> encode_posn_as_written(const Mesh& mesh, int method, int bits,
                                            qmc::PositionGrid grid = qmc::PositionGrid::kUniform) {
  qmc::EncodeOptions options;
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.position_bits = bits;
  options.position_grid = grid;
  options.position_method = qmc::PositionMethod::kPredicted;
  options.candidate_choice = qmc::CandidateChoice::kFewestBits;
  options.geometry_order = method == 4;
  options.quad_twist = false;  // method 5 (14.7) came after these vectors
  options.attribute_geometry_order = false;  // aTTR codings 4, 5 and 6 came after these vectors
  options.attribute_graded_start = false;
  options.attribute_predicted_mapping = false;  // mapping 3 (15.11) came after these vectors
  options.attribute_guided = false;             // and coding 7 (15.12)
  options.angle_weighted_normals = false;       // and coding 8 (15.13)
  return encode_posn_method(mesh, options, method);
}

// Section 14.4.1 (format 1.7): POSN method 3, method 1 with the class
// probabilities started graded by bucket.
std::vector<uint8_t> encode_posn3(const Mesh& mesh, int bits, qmc::PositionGrid grid = qmc::PositionGrid::kUniform) {
  return encode_posn_as_written(mesh, 3, bits, grid);
}

void write_posn3_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  // Quads (polygon runs), triangles at 12 and 20 bits (classes far below and
  // above each bucket: both ends of the table), a soup (every prediction
  // kind, 14.3.2) and the per-axis grid.
  const Mesh quads = perturbed(qmc::tools::make_torus(16, 10), 3, 0.005f);
  w->valid("valid_posn3_quad_torus", encode_posn3(quads, 14), &quads);
  const Mesh sphere = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 5, 0.01f);
  w->valid("valid_posn3_sphere_12_bits", encode_posn3(sphere, 12), &sphere);
  w->valid("valid_posn3_sphere_20_bits", encode_posn3(sphere, 20), &sphere);
  qmc::tools::RandomSoupOptions soup_options;
  soup_options.vertices = 150;
  soup_options.faces = 120;
  soup_options.unreferenced = 6;
  const Mesh soup = qmc::tools::make_random_soup(31, soup_options);
  w->valid("valid_posn3_soup", encode_posn3(soup, 10), &soup);
  w->valid("valid_posn3_per_axis_grid", encode_posn3(quads, 12, qmc::PositionGrid::kPerAxis), &quads);
  // 15.4: an aTTR's values start every probability at 1024 whatever POSN's method.
  Mesh textured = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 9, 0.01f);
  qmc::tools::add_chart_texcoords(&textured);
  w->valid("valid_posn3_with_texcoords", encode_posn3(textured, 12), &textured);

  // The rules of 14.1 and 14.4 on method 3's path.
  const ChunkReplacer with_posn(encode_posn3(sphere, 12), qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  w->invalid("invalid_posn3_truncated_stream", with_posn({payload.begin(), payload.end() - 8}), ErrorCode::kTruncated);
  std::vector<uint8_t> p = payload;
  p.insert(p.end(), {0x55, 0x55, 0x55, 0x55, 0x55, 0x55});
  w->invalid("invalid_posn3_bytes_after_stream", with_posn(p), ErrorCode::kBadChunkPayload);
  // Tops of 1: a residual the grid cannot hold (header as 14.1: varint V,
  // 0x83, grid, origin 12 bytes, step 8, three tops of 2 bytes at 12 bits).
  std::vector<uint8_t> count;
  qmc::put_varint(&count, sphere.vertex_count());
  const size_t tops = count.size() + 2 + 12 + 8, stream = tops + 6;
  p = {payload.begin(), payload.begin() + tops};
  for (int a = 0; a < 3; ++a) qmc::put_varint(&p, 1);
  p.insert(p.end(), payload.begin() + stream, payload.end());
  w->invalid("invalid_posn3_value_outside_grid", with_posn(p), ErrorCode::kBadSymbol);
}

// The faces of a file's CONN and the integers of its POSN (any method).
void decode_grid(const Chunks& c, Mesh* faces, qmc::QuantizedPositions* grid) {
  const Chunk& conn = c[find_chunk(c, qmc::kChunkConnectivity)];
  const Chunk& posn = c[find_chunk(c, qmc::kChunkPositions)];
  uint32_t vertex_count = 0;
  qmc::ConnectivityMethod method;
  qmc::QuantizationInfo info;
  std::vector<float> positions;
  if (!qmc::decode_connectivity(conn.payload.data(), conn.payload.size(), &vertex_count, &method, faces).ok() ||
      !qmc::decode_positions(posn.payload.data(), posn.payload.size(), *faces, vertex_count, &info, &grid->q,
                             &positions)
           .ok()) {
    std::fprintf(stderr, "qmc-make-vectors: a file to rewrite does not decode\n");
    std::exit(3);
  }
  grid->min = info.min;
  grid->step = info.step;
  grid->top = info.top;
}

// The file's POSN written again in the geometry order (14.6), as method 5
// with quad_twist (14.7), else method 4, with start 0, or with the start its
// vertex count gives (14.5) when start_by_count: the same integers, so the
// mesh (and a progressive file's levels) do not change; QHDR says `minor`.
// With mask_contexts, methods 6 and 7 (14.8) instead of 4 and 5.
std::vector<uint8_t> with_posn_rewritten(const std::vector<uint8_t>& file, bool start_by_count, bool quad_twist,
                                         uint8_t minor, bool mask_contexts = false) {
  Chunks c = split_chunks(file);
  Mesh faces;
  qmc::QuantizedPositions grid;
  decode_grid(c, &faces, &grid);
  const qmc::ClassStart start = start_by_count && grid.q.size() / 3 < qmc::kGradedStartBelow
                                    ? qmc::ClassStart::kGraded
                                    : qmc::ClassStart::kFlat;
  c[find_chunk(c, qmc::kChunkPositions)].payload =
      qmc::encode_predicted_positions(grid, faces, nullptr, qmc::CandidateChoice::kFewestBits, start,
                                      qmc::PredictionOrder::kGeometry, quad_twist, mask_contexts);
  c[find_chunk(c, qmc::kChunkHeader)].payload = {1, minor};
  return join_chunks(c);
}

// A progressive file whose base POSN (method 1 on 6.1's grid) is written
// again as method 4 (start 0); QHDR says 1.8.
std::vector<uint8_t> with_method_4_base(const std::vector<uint8_t>& file) {
  return with_posn_rewritten(file, false, false, 8);
}

// Section 14.6 (format 1.8): POSN method 4, the decisions of method 1 or 3
// in the geometry order.
std::vector<uint8_t> encode_posn4(const Mesh& mesh, int bits, qmc::PositionGrid grid = qmc::PositionGrid::kUniform) {
  return encode_posn_as_written(mesh, 4, bits, grid);
}

void write_posn4_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  // Over 1,000 vertices (start 0): triangles at 12 and 20 bits, quads
  // (polygon runs), the per-axis grid, and a soup of many parts, faces
  // with a vertex twice (which close on no vertex, 14.6) and vertices no
  // face uses: 14.6's second rule.
  const Mesh sphere = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 41, 0.006f);
  w->valid("valid_posn4_sphere_12_bits", encode_posn4(sphere, 12), &sphere);
  w->valid("valid_posn4_sphere_20_bits", encode_posn4(sphere, 20), &sphere);
  const Mesh quads = perturbed(qmc::tools::make_torus(40, 30), 43, 0.003f);
  w->valid("valid_posn4_quad_torus", encode_posn4(quads, 14), &quads);
  w->valid("valid_posn4_per_axis_grid", encode_posn4(quads, 12, qmc::PositionGrid::kPerAxis), &quads);
  qmc::tools::RandomSoupOptions soup_options;
  soup_options.vertices = 1100;
  soup_options.faces = 900;
  soup_options.unreferenced = 30;
  const Mesh soup = qmc::tools::make_random_soup(47, soup_options);
  w->valid("valid_posn4_soup", encode_posn4(soup, 10), &soup);
  // Under 1,000 vertices with start 1 (14.4.1's probabilities).
  const Mesh small = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 53, 0.01f);
  w->valid("valid_posn4_graded_start", encode_posn4(small, 12), &small);
  // 15.4: an aTTR's values keep the label order whatever POSN's method.
  Mesh textured = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 59, 0.006f);
  qmc::tools::add_chart_texcoords(&textured);
  w->valid("valid_posn4_with_texcoords", encode_posn4(textured, 12), &textured);
  // 15.7: normals predicted from q by label, after 14.6's order is undone.
  Mesh with_normals = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 61, 0.006f);
  qmc::tools::add_vertex_normals(&with_normals);
  w->valid("valid_posn4_with_normals", encode_posn4(with_normals, 12), &with_normals);
  // 4.5: oRDR restores the input's order of a method-4 file.
  const Mesh scrambled = qmc::tools::make_scrambled(sphere, 67);
  qmc::EncodeOptions keep;
  keep.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  keep.triangle_twist = false;  // and method 8 (14.9)
  keep.mirror_symmetry = false;  // and method 9 (14.10)
  keep.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  keep.near_mirror = false;  // and POSN method 10 (14.11)
  keep.keep_order = true;
  w->valid("valid_ordr_posn4_scrambled", encode_with(scrambled, keep, "scrambled method-4 sphere"), &scrambled);
  // 12.2: a progressive file's base mesh in method 4.
  w->valid("valid_posn4_loop_base", with_method_4_base(loop_file(qmc::tools::triangulated(qmc::tools::make_torus(9, 6)), 2,
                                                                 qmc::tools::torus_targets(1, 0.35), 12,
                                                                 qmc::PositionMethod::kPredicted)),
           nullptr);

  // The rules of 14.1 and 14.4 on method 4's path: header as 14.1, varint V,
  // 0x84, start, grid, origin 12 bytes, step 8, three tops of 2 bytes at
  // 12 bits, then the stream.
  const ChunkReplacer with_posn(encode_posn4(sphere, 12), qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  std::vector<uint8_t> count;
  qmc::put_varint(&count, sphere.vertex_count());
  const size_t start = count.size() + 1, tops = start + 2 + 12 + 8, stream = tops + 6;
  w->invalid("invalid_posn4_start_missing", with_posn({payload.begin(), payload.begin() + start}),
             ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> p = payload;
  p[start] = 2;
  w->invalid("invalid_posn4_start_2", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn4_truncated_stream", with_posn({payload.begin(), payload.end() - 8}), ErrorCode::kTruncated);
  p = payload;
  p.insert(p.end(), {0x55, 0x55, 0x55, 0x55, 0x55, 0x55});
  w->invalid("invalid_posn4_bytes_after_stream", with_posn(p), ErrorCode::kBadChunkPayload);
  // Tops of 1: a residual the grid cannot hold.
  p = {payload.begin(), payload.begin() + tops};
  for (int a = 0; a < 3; ++a) qmc::put_varint(&p, 1);
  p.insert(p.end(), payload.begin() + stream, payload.end());
  w->invalid("invalid_posn4_value_outside_grid", with_posn(p), ErrorCode::kBadSymbol);
  // 14.1's bound before the order is computed: V = 4,800 > 512 (L + 8)
  // with no stream byte.
  const Mesh large = qmc::tools::make_torus(80, 60);
  const ChunkReplacer large_posn(encode_posn4(large, 12), qmc::kChunkPositions);
  std::vector<uint8_t> large_count;
  qmc::put_varint(&large_count, large.vertex_count());
  const size_t large_stream = large_count.size() + 2 + 1 + 12 + 8 + 6;
  w->invalid("invalid_posn4_stream_too_short",
             large_posn({large_posn.payload().begin(), large_posn.payload().begin() + large_stream}),
             ErrorCode::kLimitExceeded);
}

// The file's POSN written again as method 5 (14.7) with the start its
// vertex count gives (14.5); QHDR says 1.9. For meshes where method 4 would
// be the smaller.
std::vector<uint8_t> rewritten_as_method_5(const std::vector<uint8_t>& file) {
  return with_posn_rewritten(file, true, true, 9);
}

// Section 14.7 (format 1.9): POSN method 5 as `qmc encode` writes it where
// it is smaller than method 4; the generator fails if the encoder kept 4.
std::vector<uint8_t> encode_posn5(const Mesh& mesh, int bits) {
  qmc::EncodeOptions options;
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.position_bits = bits;
  options.position_method = qmc::PositionMethod::kPredicted;
  options.candidate_choice = qmc::CandidateChoice::kFewestBits;
  return encode_posn_method(mesh, options, 5);
}

// A disk of quads around a pole of `spokes` / 2 quads (more than 14.2's 12
// scanned corners when spokes > 24), then `rings` rings of `spokes` quads,
// on z = x y / 2 with a little noise: the twist searches start at the pole.
Mesh quad_pole_disk(uint32_t spokes, uint32_t rings) {
  Mesh m;
  qmc::tools::SplitMix64 random(71);
  const auto add_vertex = [&](float x, float y) {
    const float noise = 0.002f * (float(random.next() % 2001) / 1000.f - 1.f);
    m.positions.insert(m.positions.end(), {x, y, 0.5f * x * y + noise});
  };
  add_vertex(0, 0);
  for (uint32_t r = 1; r <= rings + 1; ++r)
    for (uint32_t k = 0; k < spokes; ++k)
      add_vertex(float(r) * std::cos(6.2831853f * float(k) / float(spokes)) / float(rings + 1),
                 float(r) * std::sin(6.2831853f * float(k) / float(spokes)) / float(rings + 1));
  const auto ring = [&](uint32_t r, uint32_t k) { return 1 + (r - 1) * spokes + k % spokes; };
  const auto quad = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    m.face_sizes.push_back(4);
    m.corners.insert(m.corners.end(), {a, b, c, d});
  };
  for (uint32_t k = 0; k < spokes; k += 2) quad(0, ring(1, k), ring(1, k + 1), ring(1, k + 2));
  for (uint32_t r = 1; r <= rings; ++r)
    for (uint32_t k = 0; k < spokes; ++k) quad(ring(r, k), ring(r + 1, k), ring(r + 1, k + 1), ring(r, k + 1));
  return m;
}

// The example of 14.7: two quads on z = x y, labels as given (indexed CONN).
Mesh twist_example() {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1, 2, 0, 0, 2, 1, 2};
  m.face_sizes = {4, 4};
  m.corners = {0, 1, 3, 2, 1, 4, 5, 3};
  return m;
}

// 14.7's search on a "book": a quad grid on z = 0.7 x y + 0.2 x^2 whose
// interior edge (s, p2) also borders `fins` faces of degree `degree`,
// listed first, so that their corners come first among those of s and p2:
// they are examined (and count toward 14.2's 8) but are no quads. A seed
// other than 0 picks the edge and shuffles the grid's faces.
Mesh twist_book(uint32_t fins, uint32_t degree, uint64_t seed = 0) {
  constexpr uint32_t nx = 8, ny = 7;
  Mesh m;
  for (uint32_t j = 0; j <= ny; ++j)
    for (uint32_t i = 0; i <= nx; ++i) {
      const float x = float(i) / nx, y = float(j) / ny;
      m.positions.insert(m.positions.end(), {x, y, 0.7f * x * y + 0.2f * x * x});
    }
  qmc::tools::SplitMix64 random(seed);
  const uint32_t s = seed ? uint32_t(1 + random.next() % (ny - 1)) * (nx + 1) + uint32_t(1 + random.next() % (nx - 1))
                          : 3 * (nx + 1) + 4;
  const uint32_t p2 = seed && random.next() % 2 ? s + nx + 1 : s + 1;
  for (uint32_t k = 0; k < fins; ++k) {
    std::vector<uint32_t> fin = k % 2 ? std::vector<uint32_t>{p2, s} : std::vector<uint32_t>{s, p2};
    for (uint32_t t = 0; t + 2 < degree; ++t) {
      fin.push_back(m.vertex_count());
      m.positions.insert(m.positions.end(), {m.positions[3 * s] + 0.01f * float(k), m.positions[3 * s + 1] - 0.01f * float(t),
                                             m.positions[3 * s + 2] + 0.3f + 0.05f * float(k)});
    }
    m.face_sizes.push_back(degree);
    m.corners.insert(m.corners.end(), fin.begin(), fin.end());
  }
  std::vector<uint32_t> cells(nx * ny);
  for (uint32_t c = 0; c < nx * ny; ++c) cells[c] = c;
  if (seed)
    for (uint32_t c = nx * ny - 1; c > 0; --c) std::swap(cells[c], cells[random.next() % (c + 1)]);
  for (const uint32_t c : cells) {
    const uint32_t a = c / nx * (nx + 1) + c % nx;
    m.face_sizes.push_back(4);
    m.corners.insert(m.corners.end(), {a, a + 1, a + nx + 2, a + nx + 1});
  }
  return m;
}

// The same grid with degenerate quads listed first on interior edges (s, p2):
// (s, p2, x, p2), where s's other neighbour y is p2, and (s, p2, s, y),
// where the vertex x opposite s is s; 14.7 asks for no distinct vertices.
Mesh twist_degenerate_quads() {
  Mesh m = twist_book(0, 4);
  Mesh out;
  out.positions = m.positions;
  for (uint32_t e = 0; e < 4; ++e) {
    const uint32_t s = (2 + e) * 9 + 2 + e, p2 = s + 1, extra = out.vertex_count();
    out.positions.insert(out.positions.end(), {out.positions[3 * s] + 0.05f, out.positions[3 * s + 1] + 0.05f,
                                               out.positions[3 * s + 2] + 0.2f});
    out.face_sizes.push_back(4);
    if (e % 2)
      out.corners.insert(out.corners.end(), {s, p2, s, extra});
    else
      out.corners.insert(out.corners.end(), {s, p2, extra, p2});
  }
  out.face_sizes.insert(out.face_sizes.end(), m.face_sizes.begin(), m.face_sizes.end());
  out.corners.insert(out.corners.end(), m.corners.begin(), m.corners.end());
  return out;
}

// The rules of 14.1 and 14.4 on the path of a method with the start byte
// (4 - 7), on `file` (its POSN one of them, a single-step grid): start 2,
// the stream cut short, and tops of 1, which no residual fits. The payload
// is varint V, selector, start, grid, origin 12 bytes, step 8, three tops
// as varints, then the stream.
void write_geometry_order_rejections(VectorWriter* w, const std::string& prefix, const std::vector<uint8_t>& file,
                                     size_t vertex_count, size_t features_bytes = 0) {
  using qmc::ErrorCode;
  const ChunkReplacer with_posn(file, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  std::vector<uint8_t> count;
  qmc::put_varint(&count, vertex_count);
  const size_t start = count.size() + 1, tops = start + features_bytes + 2 + 12 + 8;
  qmc::ByteReader after_tops(payload.data() + tops, payload.size() - tops);
  for (uint64_t top = 0, a = 0; a < 3; ++a) after_tops.get_varint(&top);
  const size_t stream = size_t(after_tops.cursor() - payload.data());
  std::vector<uint8_t> p = payload;
  p[start] = 2;
  w->invalid("invalid_" + prefix + "_start_2", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_" + prefix + "_truncated_stream", with_posn({payload.begin(), payload.end() - 8}),
             ErrorCode::kTruncated);
  p = {payload.begin(), payload.begin() + tops};
  for (int a = 0; a < 3; ++a) qmc::put_varint(&p, 1);
  p.insert(p.end(), payload.begin() + stream, payload.end());
  w->invalid("invalid_" + prefix + "_value_outside_grid", with_posn(p), ErrorCode::kBadSymbol);
}

// About 400 faces of 3 to 6 corners with a handle, two holes and
// non-manifold edges (the posn5 and posn6 vectors).
Mesh mixed_polygons(uint64_t seed) {
  qmc::RandomPolygonMeshOptions options;
  options.seed = seed;
  options.genus = 1;
  options.holes = 2;
  options.min_degree = 3;
  options.max_degree = 6;
  options.target_faces = 400;
  options.non_manifold = true;
  return qmc::make_random_polygon_mesh(options);
}

void write_posn5_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  // What the encoder writes: a smooth quad sphere over 1,000 vertices
  // (start 0) and under (start 1).
  const Mesh sphere = qmc::tools::make_refined_sphere(3);
  w->valid("valid_posn5_refined_sphere", encode_posn5(sphere, 14), &sphere);
  const Mesh small = qmc::tools::make_refined_sphere(2);
  w->valid("valid_posn5_graded_start", encode_posn5(small, 12), &small);
  // A pole of 16 quads: the searches of 14.2 over sorted links.
  const Mesh pole = quad_pole_disk(32, 6);
  w->valid("valid_posn5_pole", encode_posn5(pole, 14), &pole);
  // Rewritten as method 5: triangles, quads and larger faces with holes,
  // handles and non-manifold edges, where the twist's conditions (a quad
  // across, its corners decoded, 8 corners examined) fail often.
  const Mesh mixed = mixed_polygons(73);
  qmc::EncodeOptions options;
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.position_bits = 12;
  w->valid("valid_posn5_mixed_polygons", rewritten_as_method_5(encode_with(mixed, options, "mixed polygons")), &mixed);
  // 14.7's example, its labels kept by indexed connectivity.
  const Mesh example = twist_example();
  qmc::EncodeOptions indexed;
  indexed.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  indexed.triangle_twist = false;  // and method 8 (14.9)
  indexed.mirror_symmetry = false;  // and method 9 (14.10)
  indexed.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  indexed.near_mirror = false;  // and POSN method 10 (14.11)
  indexed.position_bits = 4;
  indexed.connectivity = qmc::ConnectivityChoice::kIndexed;
  w->valid("valid_posn5_example", rewritten_as_method_5(encode_with(example, indexed, "14.7's example")), &example);
  // Books of pentagons on one edge, face order kept (the seeds were picked
  // so that a decoder misreading 14.7 fails): with 3, the first corner
  // examined is no quad and a later one is (14.7 takes the first corner that
  // meets every condition); with 7, the own face's corner is the 8th
  // examined and the quad across would be the 9th; with 8, the bound stops
  // the search before the quad across.
  for (const auto& [fins, seed] : {std::pair<uint32_t, uint64_t>{3, 18}, {7, 10}, {8, 18}}) {
    const Mesh book = twist_book(fins, 5, seed);
    w->valid("valid_posn5_book_of_" + std::to_string(fins) + "_pentagons",
             rewritten_as_method_5(encode_with(book, indexed, "a book of pentagons")), &book);
  }
  const Mesh degenerate = twist_degenerate_quads();
  w->valid("valid_posn5_degenerate_quads", rewritten_as_method_5(encode_with(degenerate, indexed, "degenerate quads")),
           &degenerate);
  // 15.4: an aTTR's values take no twist, whatever POSN's method.
  Mesh textured = qmc::tools::make_refined_sphere(2);
  qmc::tools::add_chart_texcoords(&textured);
  qmc::EncodeOptions attributes;
  attributes.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  attributes.triangle_twist = false;  // and method 8 (14.9)
  attributes.mirror_symmetry = false;  // and method 9 (14.10)
  attributes.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  attributes.near_mirror = false;  // and POSN method 10 (14.11)
  attributes.position_bits = 12;
  w->valid("valid_posn5_with_texcoords", encode_posn_method(textured, attributes, 5), &textured);

  // The rules of 14.1 and 14.4 on method 5's path, as for method 4.
  write_geometry_order_rejections(w, "posn5", encode_posn5(sphere, 14), sphere.vertex_count());
}

// The file's POSN written again as method 6 (14.8), or 7 with quad_twist,
// with the start its vertex count gives (14.5); QHDR says 1.10.
std::vector<uint8_t> rewritten_with_mask_contexts(const std::vector<uint8_t>& file, bool quad_twist) {
  return with_posn_rewritten(file, true, quad_twist, 10, true);
}

// A torus of triangles whose vertices are pushed off the surface by up to
// `amount` of its size: the parallelograms of a vertex disagree by anything
// from nothing to thousands of grid steps at 16 bits, every context of 14.8.
Mesh rough_torus(float amount) {
  Mesh m = perturbed(qmc::tools::triangulated(qmc::tools::make_torus(40, 16)), 85, amount);
  // A few vertices far off: the largest distances, s = 11.
  for (size_t v = 0; v < m.vertex_count(); v += 97) m.positions[3 * v + 2] += 0.3f;
  return m;
}

// Terraces of 9 x 9 vertices and a book of `fins` triangles on one edge of
// them (a, b), the fins first in face order: a tip decoded late meets up to
// 7 parallelograms across (a, b) in the earlier fins, of which 14.3.1 keeps
// the first 4. Those lie near the grid and the later ones far off it, so
// 14.8's D over the 4 kept is much smaller than over all of them.
Mesh terraces_with_book(uint32_t fins) {
  Mesh m = qmc::tools::make_terraces(8, 3, 1);
  const uint32_t a = 4 * 9 + 4, b = a + 1;  // an interior edge of the grid
  static constexpr float kHeights[8] = {0.002f, -0.003f, 0.004f, -0.001f, 0.9f, -1.1f, 1.4f, -0.7f};
  Mesh book;
  book.positions = m.positions;
  for (uint32_t k = 0; k < fins; ++k) {
    const uint32_t tip = uint32_t(book.vertex_count());
    book.positions.insert(book.positions.end(), {0.5f * (m.positions[3 * a] + m.positions[3 * b]),
                                                 m.positions[3 * a + 1] + 0.02f * float(k % 3),
                                                 0.25f * kHeights[k % 8]});
    book.face_sizes.push_back(3);
    book.corners.insert(book.corners.end(), {a, b, tip});
  }
  book.face_sizes.insert(book.face_sizes.end(), m.face_sizes.begin(), m.face_sizes.end());
  book.corners.insert(book.corners.end(), m.corners.begin(), m.corners.end());
  return book;
}

void write_posn6_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  qmc::EncodeOptions options;  // what `qmc encode` writes
  options.triangle_twist = false;  // but POSN method 8 (14.9) came after these vectors
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.position_bits = 16;
  // What the encoder writes where the contexts pay: terraces, where the
  // parallelograms across a cliff are far off and the others agree.
  const Mesh terraces = qmc::tools::make_terraces(100, 4, 9);
  w->valid("valid_posn6_terraces", encode_posn_method(terraces, options, 6), &terraces);
  // Rewritten as method 6: a rough torus at 16 bits, every context.
  const Mesh rough = rough_torus(0.02f);
  w->valid("valid_posn6_rough_torus", rewritten_with_mask_contexts(encode_with(rough, options, "rough torus"), false),
           &rough);
  // Rewritten as method 6: a smooth sphere of triangles over 1,000 vertices
  // (start 0) and under (start 1).
  const Mesh sphere = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 86, 0.002f);
  options.position_bits = 14;
  w->valid("valid_posn6_refined_sphere", rewritten_with_mask_contexts(encode_with(sphere, options, "sphere"), false),
           &sphere);
  const Mesh small = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 87, 0.004f);
  options.position_bits = 12;
  w->valid("valid_posn6_graded_start", rewritten_with_mask_contexts(encode_with(small, options, "small sphere"), false),
           &small);
  // Rewritten as method 7: 14.7's twist in the candidates that 14.8 compares,
  // on quads around a pole, and on triangles, quads and larger faces with
  // holes, handles and non-manifold edges.
  const Mesh pole = quad_pole_disk(32, 6);
  options.position_bits = 14;
  w->valid("valid_posn7_pole", rewritten_with_mask_contexts(encode_with(pole, options, "pole"), true), &pole);
  const Mesh mixed = mixed_polygons(88);
  options.position_bits = 12;
  w->valid("valid_posn7_mixed_polygons", rewritten_with_mask_contexts(encode_with(mixed, options, "mixed"), true),
           &mixed);
  // 14.8's D over the 4 candidates 14.3.1 keeps, not over all it meets:
  // a book of 8 triangles on one edge, faces kept as they are.
  const Mesh book = terraces_with_book(8);
  qmc::EncodeOptions indexed = options;
  indexed.connectivity = qmc::ConnectivityChoice::kIndexed;
  w->valid("valid_posn6_book_of_8", rewritten_with_mask_contexts(encode_with(book, indexed, "book"), false), &book);
  // 15.4: an aTTR's values take s = 0, whatever POSN's method.
  Mesh textured = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 89, 0.004f);
  qmc::tools::add_chart_texcoords(&textured);
  qmc::EncodeOptions flat_values = options;  // 1,010 values: made when only smaller tables tried 15.10's start
  flat_values.attribute_graded_start = false;
  w->valid("valid_posn6_with_texcoords",
           rewritten_with_mask_contexts(encode_with(textured, flat_values, "texcoords"), false), &textured);

  // The rules of 14.1 and 14.4 on method 6's path, as for methods 4 and 5.
  options.position_bits = 16;
  write_geometry_order_rejections(w, "posn6", encode_posn_method(terraces, options, 6), terraces.vertex_count());
}

// The file's POSN written again as method 8 (14.9) with the triangle twist
// and the other features given, with the start its vertex count gives
// (14.5); QHDR says 1.11.
std::vector<uint8_t> rewritten_with_triangle_twist(const std::vector<uint8_t>& file, bool quad_twist,
                                                   bool mask_contexts) {
  Chunks c = split_chunks(file);
  Mesh faces;
  qmc::QuantizedPositions grid;
  decode_grid(c, &faces, &grid);
  const qmc::ClassStart start =
      grid.q.size() / 3 < qmc::kGradedStartBelow ? qmc::ClassStart::kGraded : qmc::ClassStart::kFlat;
  c[find_chunk(c, qmc::kChunkPositions)].payload =
      qmc::encode_predicted_positions(grid, faces, nullptr, qmc::CandidateChoice::kFewestBits, start,
                                      qmc::PredictionOrder::kGeometry, quad_twist, mask_contexts, true);
  c[find_chunk(c, qmc::kChunkHeader)].payload = {1, 11};
  return join_chunks(c);
}

// Spec 14.9's example: the hexagon of 6 triangles around vertex 0 on the
// lattice q(i, j) = (10 + 10 i, 10 + 10 j, 3 + 3 i j), and vertex 7 across
// the edge (1, 2), faces and labels as there (indexed CONN), step 1.
Mesh twist_hexagon() {
  Mesh m;
  m.positions = {10, 10, 3, 20, 10, 3, 10, 20, 3, 0, 20, 0, 0, 10, 3, 10, 0, 3, 20, 0, 0, 20, 20, 6};
  m.face_sizes.assign(7, 3);
  m.corners = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 1, 1, 7, 2};
  return m;
}

// A torus of 32 x 16 quads whose first half of faces is cut into triangles
// along one diagonal each (a regular triangulation there: 14.9's twists),
// the other half kept (14.7's), squeezed off round so twists are not zero.
Mesh half_triangulated_torus() {
  const Mesh torus = qmc::tools::make_torus(32, 16);
  Mesh m;
  m.positions = torus.positions;
  for (size_t v = 0; v < m.vertex_count(); ++v) m.positions[3 * v + 2] *= 0.6f + 0.1f * m.positions[3 * v];
  for (size_t f = 0, k = 0; f < torus.face_count(); k += torus.face_sizes[f], ++f) {
    const uint32_t* c = &torus.corners[k];
    if (f < torus.face_count() / 2 && torus.face_sizes[f] == 4) {
      m.face_sizes.insert(m.face_sizes.end(), {3, 3});
      m.corners.insert(m.corners.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
    } else {
      m.face_sizes.push_back(torus.face_sizes[f]);
      m.corners.insert(m.corners.end(), c, c + torus.face_sizes[f]);
    }
  }
  return m;
}

void write_posn8_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  qmc::EncodeOptions options;  // what `qmc encode` wrote before method 9 (14.10)
  options.mirror_symmetry = false;
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  // Spec 14.9's example, written as method 8 with the twist of triangles.
  const Mesh hexagon = twist_hexagon();
  const qmc::EncodeOptions unit = on_unit_grid(options);
  w->valid("valid_posn8_hexagon", rewritten_with_triangle_twist(encode_with(hexagon, unit, "hexagon"), false, false),
           &hexagon);
  // What the encoder writes where the twist pays: a regular torus of
  // triangles, under 10,000 vertices (features 4) and over (features 6).
  const Mesh torus = qmc::tools::triangulated(qmc::tools::make_torus(48, 32));
  options.position_bits = 12;
  w->valid("valid_posn8_torus", encode_posn_method(torus, options, 8), &torus);
  const Mesh big_torus = qmc::tools::triangulated(qmc::tools::make_torus(160, 64));
  options.position_bits = 14;
  w->valid("valid_posn8_big_torus", encode_posn_method(big_torus, options, 8), &big_torus);
  // Rewritten as method 8: features 0 (method 4's decoding), a graded start,
  // an irregular sphere (lambda learns little), a rough torus at 24 bits
  // (twists beyond 2^16 steps: the clamps of T and e and the halving of N and
  // D), quads, triangles and larger faces (features 7), a book of 8
  // triangles on one edge (only the 4 kept candidates carry twists).
  const Mesh small = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 90, 0.004f);
  options.position_bits = 12;
  qmc::EncodeOptions no_twist = options;
  no_twist.triangle_twist = false;
  no_twist.mirror_symmetry = false;  // and method 9 (14.10)
  no_twist.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  no_twist.near_mirror = false;  // and POSN method 10 (14.11)
  const std::vector<uint8_t> small_file = encode_with(small, no_twist, "small sphere");
  {
    Chunks c = split_chunks(small_file);
    Mesh faces;
    qmc::QuantizedPositions grid;
    decode_grid(c, &faces, &grid);
    std::vector<uint8_t> payload = qmc::encode_predicted_positions(
        grid, faces, nullptr, qmc::CandidateChoice::kFewestBits, qmc::ClassStart::kGraded,
        qmc::PredictionOrder::kGeometry, false, false, false);
    // Method 4 (0x84, start) as method 8 (0x88, start, features 0): the same stream.
    std::vector<uint8_t> count;
    qmc::put_varint(&count, grid.q.size() / 3);
    payload[count.size()] = 0x88;
    payload.insert(payload.begin() + count.size() + 2, 0);
    c[find_chunk(c, qmc::kChunkPositions)].payload = payload;
    c[find_chunk(c, qmc::kChunkHeader)].payload = {1, 11};
    w->valid("valid_posn8_features_0", join_chunks(c), &small);
  }
  w->valid("valid_posn8_graded_start", rewritten_with_triangle_twist(small_file, false, false), &small);
  const Mesh sphere = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 91, 0.01f);
  w->valid("valid_posn8_irregular_sphere",
           rewritten_with_triangle_twist(encode_with(sphere, no_twist, "sphere"), false, true), &sphere);
  const Mesh rough = rough_torus(0.3f);
  no_twist.position_bits = 24;
  w->valid("valid_posn8_rough_torus_24_bits",
           rewritten_with_triangle_twist(encode_with(rough, no_twist, "rough torus"), false, true), &rough);
  no_twist.position_bits = 12;
  const Mesh mixed = mixed_polygons(92);
  w->valid("valid_posn8_mixed_polygons",
           rewritten_with_triangle_twist(encode_with(mixed, no_twist, "mixed"), true, true), &mixed);
  // Both twists at once (features 5): a torus half of quads, half of their
  // triangles, a quadratic bump on it.
  const Mesh half = half_triangulated_torus();
  w->valid("valid_posn8_quads_and_triangles",
           rewritten_with_triangle_twist(encode_with(half, no_twist, "half torus"), true, false), &half);
  const Mesh book = terraces_with_book(8);
  qmc::EncodeOptions indexed = no_twist;
  indexed.connectivity = qmc::ConnectivityChoice::kIndexed;
  w->valid("valid_posn8_book_of_8", rewritten_with_triangle_twist(encode_with(book, indexed, "book"), false, false),
           &book);
  // 15.4: an aTTR's values take no twist, whatever POSN's method.
  Mesh textured = qmc::tools::triangulated(qmc::tools::make_torus(24, 16));
  qmc::tools::add_chart_texcoords(&textured);
  w->valid("valid_posn8_with_texcoords",
           rewritten_with_triangle_twist(encode_with(textured, no_twist, "texcoords"), false, false), &textured);

  // 14.1's checks of the features byte, then the rules of 14.1 and 14.4 on
  // method 8's path, as for methods 4 - 7.
  const std::vector<uint8_t> torus_file = encode_posn_method(torus, options, 8);
  const ChunkReplacer with_posn(torus_file, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  std::vector<uint8_t> count;
  qmc::put_varint(&count, torus.vertex_count());
  const size_t features = count.size() + 2;
  std::vector<uint8_t> p = payload;
  p[features] = 8;
  w->invalid("invalid_posn8_features_bit_3", with_posn(p), ErrorCode::kBadChunkPayload);
  p[features] = 0x84;
  w->invalid("invalid_posn8_features_bit_7", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn8_features_missing", with_posn({payload.begin(), payload.begin() + long(features)}),
             ErrorCode::kBadChunkPayload);
  write_geometry_order_rejections(w, "posn8", torus_file, torus.vertex_count(), 1);
}

// Spec 14.10's example: a kite of two triangles across the plane x = 6.
Mesh mirror_kite() {
  Mesh m;
  m.positions = {6, 0, 0, 6, 10, 0, 0, 5, 3, 12, 5, 3};
  m.face_sizes.assign(2, 3);
  m.corners = {0, 1, 2, 1, 0, 3};
  return m;
}

// A fan of `spokes` triangles around a centre on the plane x = 0: the
// centre is the image vertex of every rim vertex next to it, and has more
// than 14.10's 16 corners.
Mesh mirror_fan(uint32_t spokes) {
  Mesh m;
  m.positions = {0, 0, 0};
  for (uint32_t k = 0; k < spokes; ++k) {
    const double angle = 2 * 3.14159265358979 * k / spokes;
    m.positions.insert(m.positions.end(),
                       {float(std::cos(angle)), float(std::sin(angle)), float(0.2 * std::sin(3 * angle))});
    m.face_sizes.push_back(3);
    m.corners.insert(m.corners.end(), {0, 1 + k, 1 + (k + 1) % spokes});
  }
  return qmc::tools::make_mirrored_across_x(m, 1e-6f);
}

// A fan of 40 triangles on integer points around the centre (10, 10, 2),
// symmetric across x = 10: the centre lies on the plane, is the image
// vertex of itself and of every rim vertex next to it, and has 40 corners,
// so 14.10's bound of 16 corners bites.
Mesh mirror_fan_on_the_plane() {
  Mesh m;
  m.positions = {10, 10, 2};
  constexpr uint32_t kSpokes = 40;
  for (uint32_t k = 0; k < kSpokes; ++k) {
    const double angle = 2 * 3.14159265358979 * k / kSpokes;
    m.positions.insert(m.positions.end(), {float(10 + std::lround(8 * std::cos(angle))),
                                           float(10 + std::lround(8 * std::sin(angle))),
                                           float(2 + std::lround(2 * std::sin(3 * angle)))});
    m.face_sizes.push_back(3);
    m.corners.insert(m.corners.end(), {0, 1 + k, 1 + (k + 1) % kSpokes});
  }
  return m;
}

// The file's POSN written again as method 9 (14.10) with `plane` (or the
// one find_mirror_plane finds, which the file must have) and `features`,
// the start its vertex count gives (14.5): the same integers.
std::vector<uint8_t> rewritten_with_mirror(const std::vector<uint8_t>& file, uint8_t features,
                                           const qmc::MirrorPlane* plane = nullptr) {
  Chunks c = split_chunks(file);
  Mesh faces;
  qmc::QuantizedPositions grid;
  decode_grid(c, &faces, &grid);
  qmc::MirrorPlane found;
  if (!plane && !qmc::find_mirror_plane(grid, &found, false)) {
    std::fprintf(stderr, "qmc-make-vectors: a file to rewrite as method 9 has no mirror plane\n");
    std::exit(3);
  }
  const qmc::ClassStart start =
      grid.q.size() / 3 < qmc::kGradedStartBelow ? qmc::ClassStart::kGraded : qmc::ClassStart::kFlat;
  c[find_chunk(c, qmc::kChunkPositions)].payload = qmc::encode_predicted_positions(
      grid, faces, nullptr, qmc::CandidateChoice::kFewestBits, start, qmc::PredictionOrder::kGeometry,
      features & qmc::kQuadTwistFeature, features & qmc::kMaskContextsFeature,
      features & qmc::kTriangleTwistFeature, plane ? plane : &found);
  c[find_chunk(c, qmc::kChunkHeader)].payload = {1, uint8_t(plane && plane->near_images ? 13 : 12)};
  return join_chunks(c);
}

// Where 14.1's fields of a method-9 POSN payload of uniform grid (grid 0)
// start: start, features, mirror_axis, mirror_sum, grid, tops and stream;
// and the sum's value.
struct Posn9Fields {
  size_t start, features, axis, sum, grid, tops, stream;
  uint64_t sum_value;
};
Posn9Fields posn9_fields(const std::vector<uint8_t>& payload, size_t vertex_count) {
  std::vector<uint8_t> count;
  qmc::put_varint(&count, vertex_count);
  Posn9Fields f{};
  f.start = count.size() + 1;
  f.features = f.start + 1;
  f.axis = f.features + 1;
  f.sum = f.axis + 1;
  qmc::ByteReader in(payload.data() + f.sum, payload.size() - f.sum);
  in.get_varint(&f.sum_value);
  f.grid = size_t(in.cursor() - payload.data());
  f.tops = f.grid + 1 + 12 + 8;  // the grid byte, the origin, one step
  qmc::ByteReader tops(payload.data() + f.tops, payload.size() - f.tops);
  for (uint64_t top = 0, a = 0; a < 3; ++a) tops.get_varint(&top);
  f.stream = size_t(tops.cursor() - payload.data());
  return f;
}

void write_posn9_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  qmc::EncodeOptions options;  // what `qmc encode` wrote
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  // Spec 14.10's example, on the integers as given.
  const Mesh kite = mirror_kite();
  const qmc::EncodeOptions unit = on_unit_grid(options);
  const qmc::MirrorPlane kite_plane{0, 12};
  w->valid("valid_posn9_kite", rewritten_with_mirror(encode_with(kite, unit, "kite"), 0, &kite_plane), &kite);
  // What the encoder writes on mirrored meshes: a sphere of triangles (with
  // the twist of triangles where it pays), under 10,000 vertices and over
  // (14.8's contexts), and one of quads at 16 bits.
  const Mesh sphere = qmc::tools::make_mirrored_across_x(perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 93, 0.002f));
  options.position_bits = 12;
  w->valid("valid_posn9_sphere", encode_posn_method(sphere, options, 9), &sphere);
  const Mesh big = qmc::tools::make_mirrored_across_x(perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(5)), 94, 0.0005f),
                                     0.001f);
  options.position_bits = 14;
  w->valid("valid_posn9_big_sphere", encode_posn_method(big, options, 9), &big);
  const Mesh quads = qmc::tools::make_mirrored_across_x(perturbed(qmc::tools::make_refined_sphere(3), 95, 0.002f));
  options.position_bits = 16;
  w->valid("valid_posn9_quad_sphere", encode_posn_method(quads, options, 9), &quads);
  // Rewritten as method 9: every feature at once on triangles, quads and
  // larger faces; a small sphere (start 1); a sphere with no twins, its
  // plane taken all the same; the extreme sums 0 and 2 top (every image
  // clamped or out of the grid); a fan whose centre has 40 corners.
  options.position_bits = 12;
  const Mesh mixed = qmc::tools::make_mirrored_across_x(mixed_polygons(96));
  w->valid("valid_posn9_mixed_polygons", rewritten_with_mirror(encode_with(mixed, options, "mixed"), 7), &mixed);
  const Mesh small = qmc::tools::make_mirrored_across_x(perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 97, 0.004f));
  w->valid("valid_posn9_graded_start", rewritten_with_mirror(encode_with(small, options, "small"), 0), &small);
  const Mesh lopsided = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(2)), 98, 0.05f);
  const std::vector<uint8_t> lopsided_file = encode_with(lopsided, options, "lopsided");
  Mesh lopsided_faces;
  qmc::QuantizedPositions lopsided_grid;
  decode_grid(split_chunks(lopsided_file), &lopsided_faces, &lopsided_grid);
  const qmc::MirrorPlane middle{0, lopsided_grid.top[0]}, low{1, 0}, high{2, 2 * lopsided_grid.top[2]};
  w->valid("valid_posn9_no_twins", rewritten_with_mirror(lopsided_file, 0, &middle), &lopsided);
  w->valid("valid_posn9_sum_0", rewritten_with_mirror(lopsided_file, 2, &low), &lopsided);
  w->valid("valid_posn9_sum_twice_top", rewritten_with_mirror(lopsided_file, 4, &high), &lopsided);
  const Mesh fan = mirror_fan(40);
  qmc::EncodeOptions indexed = options;
  indexed.connectivity = qmc::ConnectivityChoice::kIndexed;
  w->valid("valid_posn9_fan_of_40", rewritten_with_mirror(encode_with(fan, indexed, "fan"), 0), &fan);
  const Mesh fan_on_plane = mirror_fan_on_the_plane();
  qmc::EncodeOptions unit_indexed = indexed;
  unit_indexed.position_step = 1;
  const qmc::MirrorPlane fan_plane{0, 16};  // the grid's origin is the box's corner (2, 2, 0): x = 10 is q = 8
  w->valid("valid_posn9_fan_on_the_plane",
           rewritten_with_mirror(encode_with(fan_on_plane, unit_indexed, "fan on the plane"), 0, &fan_plane),
           &fan_on_plane);
  // The twist of triangles (lambda learning) beside the mirror candidate: a
  // mirrored regular torus of triangles, features 4.
  const Mesh twisted_torus = qmc::tools::make_mirrored_across_x(qmc::tools::triangulated(qmc::tools::make_torus(48, 32)));
  w->valid("valid_posn9_torus_twist", rewritten_with_mirror(encode_with(twisted_torus, options, "torus"), 4),
           &twisted_torus);
  // 15.4: an aTTR's values take no mirror candidate, whatever POSN's method.
  Mesh textured = sphere;
  qmc::tools::add_chart_texcoords(&textured);
  w->valid("valid_posn9_with_texcoords", encode_posn_method(textured, options, 9), &textured);

  // 14.1's checks of the plane, then the rules of 14.1 and 14.4 on method 9's path.
  const std::vector<uint8_t> file = encode_posn_method(sphere, options, 9);
  const ChunkReplacer with_posn(file, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  const Posn9Fields f = posn9_fields(payload, sphere.vertex_count());
  const auto cut = [](const std::vector<uint8_t>& bytes, size_t end) {
    return std::vector<uint8_t>(bytes.begin(), bytes.begin() + long(end));
  };
  std::vector<uint8_t> p = payload;
  p[f.features] = 8;
  w->invalid("invalid_posn9_features_bit_3", with_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p[f.axis] = 3;
  w->invalid("invalid_posn9_axis_3", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn9_axis_missing", with_posn(cut(payload, f.axis)), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn9_sum_missing", with_posn(cut(payload, f.sum)), ErrorCode::kBadChunkPayload);
  p = cut(payload, f.sum);
  qmc::put_varint(&p, 2 * 4095 + 1);
  p.insert(p.end(), payload.begin() + long(f.grid), payload.end());
  w->invalid("invalid_posn9_sum_above_twice_top", with_posn(p), ErrorCode::kBadChunkPayload);
  // 14.1's order: the sum's check comes before the bound of V against the stream (no stream at all here).
  const ChunkReplacer with_big_posn(encode_posn_method(big, options, 9), qmc::kChunkPositions);
  const std::vector<uint8_t> big_payload = with_big_posn.payload();
  const Posn9Fields big_f = posn9_fields(big_payload, big.vertex_count());
  p = cut(big_payload, big_f.sum);
  qmc::put_varint(&p, 2 * 16383 + 1);
  p.insert(p.end(), big_payload.begin() + long(big_f.grid), big_payload.begin() + long(big_f.stream));
  w->invalid("invalid_posn9_sum_above_twice_top_no_stream", with_big_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p[f.start] = 2;
  w->invalid("invalid_posn9_start_2", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn9_truncated_stream", with_posn(cut(payload, payload.size() - 8)), ErrorCode::kTruncated);
  // The tops cut to the plane's half: the twins' values fall outside the grid.
  p = cut(payload, f.tops);
  for (int a = 0; a < 3; ++a) qmc::put_varint(&p, (f.sum_value + 1) / 2);
  p.insert(p.end(), payload.begin() + long(f.stream), payload.end());
  w->invalid("invalid_posn9_value_outside_grid", with_posn(p), ErrorCode::kBadSymbol);
}

// A lumpy sphere (its lumps break the planes across y and z) mirrored across
// x, its box reaching further on one side (one more vertex at x = 1.37):
// the plane falls between grid points and the halves are a step apart where
// they round apart (14.11).
Mesh lumpy_mirrored_sphere(int levels) {
  Mesh lumpy = qmc::tools::triangulated(qmc::tools::make_refined_sphere(levels));
  for (size_t v = 0; v < lumpy.vertex_count(); ++v) {
    float* p = &lumpy.positions[3 * v];
    p[1] += 0.1f * std::sin(3 * p[0] + 2 * p[2]);
    p[2] += 0.1f * std::cos(2 * p[1] + p[0]);
  }
  Mesh sphere = qmc::tools::make_mirrored_across_x(lumpy);
  sphere.positions.insert(sphere.positions.end(), {1.37f, 0.f, 0.f});
  return sphere;
}

// Section 12.7.2 (format 1.14): LEVL code 4, displacements and vertex
// corrections, valid and invalid.
std::vector<uint8_t> corrected_loop_file(const Mesh& base, int levels, const qmc::LevelCorrector& corrector,
                                         int displacement_code = 2) {
  std::vector<uint8_t> out;
  if (qmc::Status s = qmc::tools::make_loop_file(base, levels, qmc::tools::unit_sphere_targets(), 14, &out, nullptr,
                                                qmc::PositionMethod::kDeltas, displacement_code, false, nullptr,
                                                &corrector);
      !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

// The LevelCode of level j of a file, as the decoder reads it.
qmc::LevelCode level_code_of(const std::vector<uint8_t>& file, int j) {
  qmc::DecodedFile decoded;
  qmc::LoopEdges edges;
  qmc::LevelCode code;
  const Chunks chunks = split_chunks(file);
  const std::vector<uint8_t>& payload = chunks[find_chunk(chunks, qmc::kChunkLevel, j - 1)].payload;
  if (!qmc::decode(file.data(), file.size(), &decoded).ok() ||
      !qmc::number_loop_edges(decoded.levels[size_t(j - 1)], &edges).ok() ||
      !qmc::decode_level_code(payload.data(), payload.size(), uint8_t(j), edges,
                              decoded.levels[size_t(j - 1)].vertex_count(), &code)
           .ok()) {
    std::fprintf(stderr, "qmc-make-vectors: level %d does not decode\n", j);
    std::exit(3);
  }
  return code;
}

void write_levl4_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  const Mesh octahedron = qmc::tools::loop_octahedron();
  // Every 5th vertex of the finest level radially onto the sphere, in 2^-16.
  const std::vector<uint8_t> finest = corrected_loop_file(octahedron, 3, qmc::tools::sphere_corrections(5, 0x1p-16, {3}));
  w->valid("valid_levl4_octahedron_finest_corrected", finest, nullptr);
  // Corrections at levels 1 and 2, which levels 2 and 3 subdivide; level 3 code 0.
  w->valid("valid_levl4_corrected_then_subdivided",
           corrected_loop_file(octahedron, 3, qmc::tools::sphere_corrections(2, 0x1p-12, {1, 2}), 0), nullptr);
  // Every vertex (every gap 0), those that do not move with zero offsets, on a torus base.
  w->valid("valid_levl4_every_vertex",
           corrected_loop_file(qmc::tools::triangulated(qmc::tools::make_torus(6, 4)), 2,
                               qmc::tools::sphere_corrections(1, 0x1p-10, {2}, true)),
           nullptr);
  // Offsets of every class: 2^-20 steps, clamped to +-32767, and one -32768 (class 16).
  const qmc::LevelCorrector extreme = [](int j, const qmc::LoopMesh& level, qmc::LevelCode* code) {
    const qmc::Status s = qmc::tools::sphere_corrections(3, 0x1p-20, {2})(j, level, code);
    if (!code->corrections.empty()) code->corrections.front().offset[1] = -32768;
    return s;
  };
  w->valid("valid_levl4_extreme_offsets", corrected_loop_file(octahedron, 2, extreme), nullptr);
  // Gaps of every class up to 9, both first bits after the leading one, and
  // the direct bits beyond the second (the octahedron's level 4: 1,026 vertices).
  const qmc::LevelCorrector gaps = [](int j, const qmc::LoopMesh& level, qmc::LevelCode* code) {
    code->correction_step = 0x1p-12;
    code->corrections.clear();
    if (j != 4) return qmc::Status::Ok();
    uint32_t v = 0;
    for (uint32_t gap : {0u, 1u, 2u, 3u, 5u, 6u, 9u, 13u, 17u, 25u, 36u, 51u, 70u, 100u, 140u, 200u, 300u, 0u, 4u, 7u}) {
      v += gap;
      if (v >= level.vertex_count()) break;
      qmc::VertexCorrection c;
      c.vertex = v;
      c.offset[0] = int32_t(gap % 7) - 3, c.offset[1] = int32_t(gap % 5), c.offset[2] = -int32_t(gap % 11);
      code->corrections.push_back(c);
      ++v;
    }
    return qmc::Status::Ok();
  };
  w->valid("valid_levl4_gaps_of_every_class", corrected_loop_file(octahedron, 4, gaps), nullptr);

  // Code 4 with no correction: code 2's stream, C = 0.
  const Chunks plain = split_chunks(loop_file(octahedron, 2, qmc::tools::unit_sphere_targets(), 14,
                                              qmc::PositionMethod::kDeltas, 2));
  const size_t second = find_chunk(plain, qmc::kChunkLevel, 1);
  Chunks c = plain;
  std::vector<uint8_t> p = plain[second].payload;  // level, code, varint 48 (1 byte), step: 11 bytes
  p[1] = 4;
  std::vector<uint8_t> fields;
  qmc::put_f64le(&fields, 0x1p-10);
  qmc::put_varint(&fields, 0);
  p.insert(p.begin() + 11, fields.begin(), fields.end());
  c[second].payload = p;
  c[find_chunk(c, qmc::kChunkHeader)].payload[1] = 14;
  w->valid("valid_levl4_no_corrections", join_chunks(c), nullptr);

  // Invalid: the finest file's level 3 (level, code, varint 192, step,
  // correction_step, varint C, stream).
  const Chunks base = split_chunks(finest);
  const size_t last = find_chunk(base, qmc::kChunkLevel, 2);
  const std::vector<uint8_t> payload = base[last].payload;
  const size_t correction_step = 1 + 1 + 2 + 8, count = correction_step + 8;
  auto with_level = [&](std::vector<uint8_t> q) {
    Chunks d = base;
    d[last].payload = std::move(q);
    return join_chunks(d);
  };
  auto with_step = [&](double step) {
    std::vector<uint8_t> q = payload, b;
    qmc::put_f64le(&b, step);
    std::copy(b.begin(), b.end(), q.begin() + std::ptrdiff_t(correction_step));
    return with_level(q);
  };
  w->invalid("invalid_levl4_correction_step_zero", with_step(0.0), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_levl4_correction_step_nan", with_step(std::numeric_limits<double>::quiet_NaN()),
             ErrorCode::kBadChunkPayload);
  w->invalid("invalid_levl4_correction_step_missing",
             with_level({payload.begin(), payload.begin() + std::ptrdiff_t(correction_step + 4)}),
             ErrorCode::kBadChunkPayload);
  w->invalid("invalid_levl4_correction_count_missing",
             with_level({payload.begin(), payload.begin() + std::ptrdiff_t(count)}), ErrorCode::kBadChunkPayload);
  // Level 3 has 66 + 192 = 258 vertices: C = 259 (varint 0x83 0x02) is one too many.
  qmc::LevelCode code = level_code_of(finest, 3);
  const uint32_t vertices = 258;
  {
    std::vector<uint8_t> q(payload.begin(), payload.begin() + std::ptrdiff_t(count));
    qmc::put_varint(&q, vertices + 1);
    w->invalid("invalid_levl4_count_above_vertices", with_level(q), ErrorCode::kBadChunkPayload);
  }
  // Level 3's payload recoded from changed corrections, over level 2's edges.
  qmc::LoopEdges edges;
  qmc::DecodedFile decoded;
  if (!qmc::decode(finest.data(), finest.size(), &decoded).ok() ||
      !qmc::number_loop_edges(decoded.levels[2], &edges).ok())
    std::exit(3);
  const uint32_t coarse = decoded.levels[2].vertex_count();
  auto recoded = [&](const qmc::LevelCode& changed) {
    return with_level(qmc::corrected_level_payload(3, edges, coarse, changed));
  };
  qmc::LevelCode beyond = code;
  beyond.corrections.back().vertex = vertices;  // the gap points past the last vertex
  w->invalid("invalid_levl4_vertex_beyond_level", recoded(beyond), ErrorCode::kBadSymbol);
  qmc::LevelCode overflow = code;
  overflow.corrections[1].offset[2] = 32768;  // class 16, positive
  w->invalid("invalid_levl4_offset_overflow", recoded(overflow), ErrorCode::kBadSymbol);
  qmc::LevelCode huge = code;
  huge.correction_step = 0x1p1000;  // finite, but the corrected coordinates are not (12.8)
  w->invalid("invalid_levl4_coordinate_not_finite", recoded(huge), ErrorCode::kBadChunkPayload);
  p = payload;
  p.resize(p.size() - 6);  // the stream ends inside the corrections
  w->invalid("invalid_levl4_truncated", with_level(p), ErrorCode::kTruncated);
  p = payload;
  p.insert(p.end(), {0x55, 0x55, 0x55, 0x55, 0x55, 0x55});
  w->invalid("invalid_levl4_bytes_after_stream", with_level(p), ErrorCode::kBadChunkPayload);
  // 12.1: code 4 as code 2, the 12288 edges of the octahedron's level 5 in one stream byte, above 512 (1 + 8).
  const Chunks deep = split_chunks(loop_file(octahedron, 6, qmc::tools::unit_sphere_targets(), 14,
                                             qmc::PositionMethod::kDeltas, 2));
  const size_t sixth = find_chunk(deep, qmc::kChunkLevel, 5);
  Chunks e = deep;
  std::vector<uint8_t>& q = e[sixth].payload;
  q.resize(2 + 2 + 8);  // level, code, varint 12288, step
  q[1] = 4;
  qmc::put_f64le(&q, 0x1p-10);
  qmc::put_varint(&q, 0);
  q.push_back(0);  // one byte of stream
  e[find_chunk(e, qmc::kChunkHeader)].payload[1] = 14;
  w->invalid("invalid_levl4_edges_unjustified", join_chunks(e), ErrorCode::kLimitExceeded);
}

// What the encoder writes with POSN `method` on `mesh` at options' bits and
// at 16 bits, and on `textured` (the mesh with texture coordinates) at
// options' bits: valid_FAMILY_SHAPE_B_bits, valid_FAMILY_SHAPE_16_bits and
// valid_FAMILY_with_texcoords, in that order. Returns the first file.
std::vector<uint8_t> write_encoder_files(VectorWriter* w, const std::string& family, const std::string& shape,
                                         const Mesh& mesh, const Mesh& textured, const qmc::EncodeOptions& options,
                                         int method) {
  const std::vector<uint8_t> file = encode_posn_method(mesh, options, method);
  const std::string prefix = "valid_" + family + "_";
  w->valid(prefix + shape + "_" + std::to_string(options.position_bits) + "_bits", file, &mesh);
  qmc::EncodeOptions sixteen = options;
  sixteen.position_bits = 16;
  w->valid(prefix + shape + "_16_bits", encode_posn_method(mesh, sixteen, method), &mesh);
  w->valid(prefix + "with_texcoords", encode_posn_method(textured, options, method), &textured);
  return file;
}

void write_posn10_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  qmc::EncodeOptions options;  // what `qmc encode` writes
  // Spec 14.11's example: 14.10's kite with vertex 3 a step beside vertex 2's image.
  Mesh kite = mirror_kite();
  kite.positions[3 * 3] = 11;
  const qmc::EncodeOptions unit = on_unit_grid(options);
  const qmc::MirrorPlane kite_plane{0, 12, true};
  w->valid("valid_posn10_kite", rewritten_with_mirror(encode_with(kite, unit, "kite"), 0, &kite_plane), &kite);
  // What the encoder writes where the halves are a step apart: triangles at
  // 14 and 16 bits, with the triangle twist's features and mirrored texture
  // coordinates (aTTR coding 9 over method 10's positions).
  const Mesh sphere = lumpy_mirrored_sphere(3);
  options.position_bits = 14;
  Mesh textured = sphere;
  qmc::tools::add_mirrored_texcoords(&textured, 16, 9);
  const std::vector<uint8_t> file = write_encoder_files(w, "posn10", "sphere", sphere, textured, options, 10);

  // 14.1's checks of the plane on method 10's path, and 14.4's.
  const ChunkReplacer with_posn(file, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  const Posn9Fields f = posn9_fields(payload, sphere.vertex_count());
  std::vector<uint8_t> p = payload;
  p[f.axis] = 3;
  w->invalid("invalid_posn10_axis_3", with_posn(p), ErrorCode::kBadChunkPayload);
  p = std::vector<uint8_t>(payload.begin(), payload.begin() + long(f.sum));
  qmc::put_varint(&p, 2 * 16383 + 1);
  p.insert(p.end(), payload.begin() + long(f.grid), payload.end());
  w->invalid("invalid_posn10_sum_above_twice_top", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn10_truncated_stream",
             with_posn(std::vector<uint8_t>(payload.begin(), payload.end() - 64)), ErrorCode::kTruncated);
}

// 14.10's plane of a file's positions (with near, 14.11's counting too);
// the generator stops if they have none.
qmc::MirrorPlane mirror_plane_of(const std::vector<uint8_t>& file, bool near) {
  Mesh faces;
  qmc::QuantizedPositions grid;
  decode_grid(split_chunks(file), &faces, &grid);
  qmc::MirrorPlane plane;
  if (!qmc::find_mirror_plane(grid, &plane, near)) {
    std::fprintf(stderr, "qmc-make-vectors: a file to rewrite with a mirror plane has none\n");
    std::exit(3);
  }
  return plane;
}

// A file's POSN recoded in the geometry order with method 8's features,
// shear k (0: none), a mirror plane if given, and 14.13's edge extrapolation
// if asked: method 11 or 12 (14.12, 14.13), or 13 with axis_classes (14.14),
// in a file of that version. stats, if given, gets the coding's counts.
std::vector<uint8_t> recoded_posn(const std::vector<uint8_t>& file, uint8_t features, int k,
                                  const qmc::MirrorPlane* plane, bool extrapolate, qmc::PositionStats* stats = nullptr,
                                  bool axis_classes = false, int lattice = 1) {
  Chunks c = split_chunks(file);
  Mesh faces;
  qmc::QuantizedPositions grid;
  decode_grid(c, &faces, &grid);
  if (lattice > 1) {  // 14.15: placed near the decoded grid points, across the decoded faces' normals
    faces.positions.resize(grid.q.size());
    for (size_t i = 0; i < grid.q.size(); ++i)
      faces.positions[i] = float(double(grid.min[i % 3]) + double(grid.q[i]) * grid.step[i % 3]);
    if (!qmc::set_surface_lattice(faces, lattice, &grid).ok()) {
      std::fprintf(stderr, "qmc-make-vectors: the lattice does not apply to a file to rewrite\n");
      std::exit(3);
    }
  }
  const qmc::ClassStart start =
      grid.q.size() / 3 < qmc::kGradedStartBelow ? qmc::ClassStart::kGraded : qmc::ClassStart::kFlat;
  c[find_chunk(c, qmc::kChunkPositions)].payload = qmc::encode_predicted_positions(
      grid, faces, stats, qmc::CandidateChoice::kFewestBits, start, qmc::PredictionOrder::kGeometry,
      features & qmc::kQuadTwistFeature, features & qmc::kMaskContextsFeature,
      features & qmc::kTriangleTwistFeature, plane, k, extrapolate, axis_classes);
  c[find_chunk(c, qmc::kChunkHeader)].payload = {1, uint8_t(lattice > 1 ? 19 : axis_classes ? 17 : extrapolate ? 16 : 15)};
  return join_chunks(c);
}

// A file's POSN recoded as method 11 (14.12) with shear k over method 8's
// features and, if given, a mirror plane (plane 1 or 2 by its near_images).
std::vector<uint8_t> rewritten_with_shear(const std::vector<uint8_t>& file, uint8_t features, int k,
                                          const qmc::MirrorPlane* plane = nullptr) {
  return recoded_posn(file, features, k, plane, false);
}

// 14.3.4's two triangles (0, 1, 2) and (2, 1, 3) at these positions: vertex
// 3 predicted across the edge (2, 1) from vertex 0 (14.12's a, b and o are
// vertices 2, 1 and 0).
Mesh two_triangles(std::vector<float> positions) {
  Mesh m;
  m.positions = std::move(positions);
  m.face_sizes.assign(2, 3);
  m.corners = {0, 1, 2, 2, 1, 3};
  return m;
}

// Spec 14.12's example: vertex 3 a step beyond where the sheared
// parallelogram (k = 16) puts it, on x.
Mesh shear_example() { return two_triangles({10, 10, 5, 20, 10, 5, 15, 20, 5, 26, 19, 5}); }

// Vertex 3 of the example's two triangles where floor(k f e_y / 16) is
// floor(-32768.75) (k = 5, f = -26215, e = (-12, 4, 0)): a prediction of
// 34.49998 rounds to 34, where truncating would give 35; a fifth vertex no
// face uses, decoded last, widens the grid beyond 35.
Mesh shear_floor_example() { return two_triangles({15, 9, 5, 8, 24, 5, 20, 20, 5, 15, 34, 5, 30, 40, 5}); }

// e = (1, 0, 0) and g = (-3, -20000, 0): 14.12's shift by 1 takes e to 0,
// so E = 0 and the candidate (12, 20000, 0) is not sheared (tested on the
// unshifted e, f would be -3 / 2 and move it by -1.5 steps on x).
Mesh shear_edge_lost_to_the_shift() { return two_triangles({9, 0, 0, 11, 10000, 0, 10, 10000, 0, 12, 20000, 0}); }

// The example with vertex 2 on vertex 1: vertex 3's parallelogram has an
// edge of length 0, E = 0, and is not sheared.
Mesh shear_example_without_edge() {
  Mesh m = shear_example();
  std::copy(m.positions.begin() + 3, m.positions.begin() + 6, m.positions.begin() + 6);
  return m;
}

void write_posn11_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  qmc::EncodeOptions options;  // what `qmc encode` writes
  const qmc::EncodeOptions unit = on_unit_grid(options);
  const Mesh example = shear_example();
  w->valid("valid_posn11_example", rewritten_with_shear(encode_with(example, unit, "shear example"), 0, 16),
           &example);
  // 14.10's kite with the shear, its plane with method 9's image vertices
  // (plane 1), and 14.11's with method 10's (plane 2).
  const Mesh kite = mirror_kite();
  const qmc::MirrorPlane exact{0, 12, false};
  w->valid("valid_posn11_kite_plane_1", rewritten_with_shear(encode_with(kite, unit, "kite"), 0, 8, &exact), &kite);
  Mesh near_kite = mirror_kite();
  near_kite.positions[3 * 3] = 11;
  const qmc::MirrorPlane near{0, 12, true};
  w->valid("valid_posn11_kite_plane_2", rewritten_with_shear(encode_with(near_kite, unit, "kite"), 0, 4, &near),
           &near_kite);
  const Mesh no_edge = shear_example_without_edge();
  w->valid("valid_posn11_edge_of_length_0",
           rewritten_with_shear(encode_with(no_edge, unit, "shear example"), 0, 16), &no_edge);
  const Mesh floored = shear_floor_example();
  w->valid("valid_posn11_floor_of_a_negative_shear",
           rewritten_with_shear(encode_with(floored, unit, "shear example"), 0, 5), &floored);
  const Mesh lost = shear_edge_lost_to_the_shift();
  w->valid("valid_posn11_edge_lost_to_the_shift",
           rewritten_with_shear(encode_with(lost, unit, "shear example"), 0, 16), &lost);
  // Edges longer than 2^14 steps, shifted before the products (a coarse
  // sphere on a 24-bit grid), with every feature and 14.11's plane on a
  // mirrored lumpy sphere, and beside polygon runs and strips (the torus
  // half in quads, with 14.7's twist of quads too).
  const Mesh coarse = qmc::tools::make_jittered_sphere(1, 0.3f, 3);
  qmc::EncodeOptions fine = options;
  fine.position_bits = 24;
  w->valid("valid_posn11_long_edges_24_bits", rewritten_with_shear(encode_with(coarse, fine, "coarse"), 0, 12),
           &coarse);
  const Mesh mirrored = lumpy_mirrored_sphere(2);
  const std::vector<uint8_t> mirrored_file = encode_with(mirrored, options, "mirrored");
  const qmc::MirrorPlane near_plane = mirror_plane_of(mirrored_file, true);
  const std::vector<uint8_t> all_features = rewritten_with_shear(mirrored_file, 7, 10, &near_plane);
  w->valid("valid_posn11_every_feature_and_plane", all_features, &mirrored);
  const Mesh mirrored_exactly = qmc::tools::make_mirrored_across_x(qmc::tools::make_jittered_sphere(2, 0.3f, 7));
  const std::vector<uint8_t> exact_file = encode_with(mirrored_exactly, options, "mirrored");
  const qmc::MirrorPlane exact_plane = mirror_plane_of(exact_file, false);
  w->valid("valid_posn11_plane_1_triangle_twist", rewritten_with_shear(exact_file, 4, 12, &exact_plane),
           &mirrored_exactly);
  const Mesh half = half_triangulated_torus();
  w->valid("valid_posn11_quads_and_triangles", rewritten_with_shear(encode_with(half, options, "half torus"), 7, 16),
           &half);
  // What the encoder writes on an irregular triangulation, at 12 and 16 bits.
  const Mesh sphere = qmc::tools::make_jittered_sphere(3, 0.3f, 11);
  options.position_bits = 12;
  // Texture coordinates over method 11's positions: their values take no shear (15.4).
  Mesh textured = sphere;
  qmc::tools::add_chart_texcoords(&textured);
  const std::vector<uint8_t> file =
      write_encoder_files(w, "posn11", "irregular_sphere", sphere, textured, options, 11);

  // 14.1's checks of method 11's two bytes, and 14.4's end of stream.
  const ChunkReplacer with_posn(file, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  std::vector<uint8_t> count;
  qmc::put_varint(&count, sphere.vertex_count());
  const size_t shear = count.size() + 3, plane = shear + 1;  // after selector, start and features
  std::vector<uint8_t> p = payload;
  p[shear] = 0;
  w->invalid("invalid_posn11_shear_0", with_posn(p), ErrorCode::kBadChunkPayload);
  p[shear] = 17;
  w->invalid("invalid_posn11_shear_17", with_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p[plane] = 3;
  w->invalid("invalid_posn11_plane_3", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn11_shear_missing", with_posn(std::vector<uint8_t>(payload.begin(), payload.begin() + long(shear))),
             ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn11_plane_missing", with_posn(std::vector<uint8_t>(payload.begin(), payload.begin() + long(plane))),
             ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn11_truncated_stream",
             with_posn(std::vector<uint8_t>(payload.begin(), payload.end() - 64)), ErrorCode::kTruncated);
  // 14.10's checks of the plane, after method 11's bytes.
  const ChunkReplacer with_plane(all_features, qmc::kChunkPositions);
  const std::vector<uint8_t> planed = with_plane.payload();
  count.clear();
  qmc::put_varint(&count, mirrored.vertex_count());
  const size_t axis = count.size() + 5;  // after selector, start, features, shear and plane
  p = planed;
  p[axis] = 3;
  w->invalid("invalid_posn11_axis_3", with_plane(p), ErrorCode::kBadChunkPayload);
  p = std::vector<uint8_t>(planed.begin(), planed.begin() + long(axis + 1));
  qmc::put_varint(&p, (uint64_t(1) << 31));
  w->invalid("invalid_posn11_sum_2_31", with_plane(p), ErrorCode::kBadChunkPayload);
}

// A file's POSN recoded as method 12 (14.13) with shear k (0: none) over
// method 8's features and, if given, a mirror plane; the generator stops if
// the rule gives no vertex a candidate there.
std::vector<uint8_t> rewritten_with_extrapolation(const std::vector<uint8_t>& file, uint8_t features, int k,
                                                  const qmc::MirrorPlane* plane = nullptr) {
  qmc::PositionStats stats;
  std::vector<uint8_t> out = recoded_posn(file, features, k, plane, true, &stats);
  if (stats.extrapolated_vertices == 0) {
    std::fprintf(stderr, "qmc-make-vectors: 14.13's rule predicts no vertex of a method-12 vector\n");
    std::exit(3);
  }
  return out;
}

// Spec 14.13's example: a row of two quads over a row of two triangle pairs,
// on the unit grid (the file's labels are the faces' first uses, 5.2.1).
Mesh extrapolation_example() {
  Mesh m;
  for (uint32_t row = 0; row < 3; ++row)
    for (uint32_t i = 0; i < 3; ++i)
      m.positions.insert(m.positions.end(), {float(10 * i + (i * i) % 3), float(10 * row), float(i % 2)});
  const auto at = [](uint32_t row, uint32_t i) { return 3 * row + i; };
  for (uint32_t i = 0; i < 2; ++i) {
    m.face_sizes.push_back(4);
    m.corners.insert(m.corners.end(), {at(1, i), at(1, i + 1), at(2, i + 1), at(2, i)});
  }
  for (uint32_t i = 0; i < 2; ++i) {
    m.face_sizes.insert(m.face_sizes.end(), {3, 3});
    m.corners.insert(m.corners.end(), {at(0, i), at(0, i + 1), at(1, i + 1), at(0, i), at(1, i + 1), at(1, i)});
  }
  return m;
}

// A row of n quads and the next row of n triangle pairs below it: each
// vertex of the bottom boundary after the first two continues the boundary.
Mesh quads_over_triangles(uint32_t n) {
  Mesh m;
  for (uint32_t row = 0; row < 3; ++row)
    for (uint32_t i = 0; i <= n; ++i) {
      const float x = float(i), y = float(row);
      m.positions.insert(m.positions.end(), {x * 3 + 0.25f * float((i * 7 + row) % 5), y * 4, float((i * i) % 7)});
    }
  const auto at = [&](uint32_t row, uint32_t i) { return row * (n + 1) + i; };
  for (uint32_t i = 0; i < n; ++i) {
    m.face_sizes.push_back(4);
    m.corners.insert(m.corners.end(), {at(1, i), at(1, i + 1), at(2, i + 1), at(2, i)});
  }
  for (uint32_t i = 0; i < n; ++i) {
    m.face_sizes.insert(m.face_sizes.end(), {3, 3});
    m.corners.insert(m.corners.end(), {at(0, i), at(0, i + 1), at(1, i + 1), at(0, i), at(1, i + 1), at(1, i)});
  }
  return m;
}

// Faces of 3 to 9 corners over windows of 14 consecutive vertices, a
// fifth of them also through vertex 0 (the hub, of many corners), at
// random integer positions: vertices of many corners, faces of every degree
// beside them and more (u, w) pairs than 14.13 keeps, where a grid or a
// fan shows only the first boundary row (splitmix64, so every platform
// makes the same mesh).
Mesh windowed_polygon_soup(uint32_t vertex_count, uint32_t face_count, uint64_t seed) {
  uint64_t state = seed;
  const auto next = [&state](uint32_t n) { return uint32_t(qmc::splitmix64_mix(++state) % n); };
  Mesh m;
  for (uint32_t v = 0; v < vertex_count; ++v)
    m.positions.insert(m.positions.end(), {float(next(1001)), float(next(1001)), float(next(1001))});
  static constexpr uint32_t kDegrees[10] = {3, 3, 4, 4, 4, 5, 6, 7, 8, 9};
  for (uint32_t f = 0; f < face_count; ++f) {
    const uint32_t d = kDegrees[next(10)], first = next(vertex_count - 13);
    std::vector<uint32_t> window(14);
    for (uint32_t i = 0; i < 14; ++i) window[i] = first + i;
    for (uint32_t i = 0; i < d; ++i) std::swap(window[i], window[i + next(14 - i)]);  // the first d at random
    window.resize(d);
    if (next(5) == 0 && std::find(window.begin(), window.end(), 0u) == window.end()) window[0] = 0;
    m.face_sizes.push_back(d);
    m.corners.insert(m.corners.end(), window.begin(), window.end());
  }
  return m;
}

// 14.1's checks of the shear and plane bytes of methods 12 and 13 (a shear
// of 17, a plane of 3, a features bit 3, the shear or plane byte missing)
// and 14.4's end of stream, on `file`, an encoder's file of the family's
// method with no mirror plane.
void write_shear_and_plane_invalids(VectorWriter* w, const std::string& family, const std::vector<uint8_t>& file,
                                    size_t vertex_count) {
  using qmc::ErrorCode;
  const ChunkReplacer with_posn(file, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  std::vector<uint8_t> count;
  qmc::put_varint(&count, vertex_count);
  const size_t features = count.size() + 2, shear = features + 1, plane = shear + 1;
  const std::string prefix = "invalid_" + family + "_";
  std::vector<uint8_t> p = payload;
  p[shear] = 17;
  w->invalid(prefix + "shear_17", with_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p[plane] = 3;
  w->invalid(prefix + "plane_3", with_posn(p), ErrorCode::kBadChunkPayload);
  p = payload;
  p[features] = 8;
  w->invalid(prefix + "features_bit_3", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid(prefix + "shear_missing", with_posn(std::vector<uint8_t>(payload.begin(), payload.begin() + long(shear))),
             ErrorCode::kBadChunkPayload);
  w->invalid(prefix + "plane_missing", with_posn(std::vector<uint8_t>(payload.begin(), payload.begin() + long(plane))),
             ErrorCode::kBadChunkPayload);
  w->invalid(prefix + "truncated_stream", with_posn(std::vector<uint8_t>(payload.begin(), payload.end() - 16)),
             ErrorCode::kTruncated);
}

// Spec 14.13's example, quads over triangles with every feature and a shear
// (8), and a mirrored grid with each kind of plane (the second with shear
// 16), each recoded by `recode` (its features, shear and plane): the small
// vectors of POSN methods 12 and 13.
void write_recoded_small_meshes(
    VectorWriter* w, const std::string& family, const qmc::EncodeOptions& options,
    const std::function<std::vector<uint8_t>(const std::vector<uint8_t>&, uint8_t, int, const qmc::MirrorPlane*)>&
        recode) {
  const qmc::EncodeOptions unit = on_unit_grid(options);
  const std::string prefix = "valid_" + family + "_";
  const Mesh example = extrapolation_example();
  w->valid(prefix + "example", recode(encode_with(example, unit, "extrapolation example"), 0, 0, nullptr), &example);
  const Mesh mixed = quads_over_triangles(12);
  const std::vector<uint8_t> mixed_file = encode_with(mixed, unit, "quads over triangles");
  w->valid(prefix + "every_feature_and_shear", recode(mixed_file, 7, 8, nullptr), &mixed);
  const Mesh grid = qmc::tools::make_mirrored_across_x(qmc::tools::make_grid(6, 4));
  const std::vector<uint8_t> grid_file = encode_with(grid, options, "mirrored grid");
  const qmc::MirrorPlane exact_plane = mirror_plane_of(grid_file, false);
  w->valid(prefix + "plane_1", recode(grid_file, 0, 0, &exact_plane), &grid);
  qmc::MirrorPlane near_plane = exact_plane;
  near_plane.near_images = true;
  w->valid(prefix + "plane_2_shear", recode(grid_file, 1, 16, &near_plane), &grid);
}

void write_posn12_vectors(VectorWriter* w) {
  qmc::EncodeOptions options;  // what `qmc encode` writes
  const qmc::EncodeOptions unit = on_unit_grid(options);
  write_recoded_small_meshes(w, "posn12", options, [](const std::vector<uint8_t>& file, uint8_t features, int k,
                                                      const qmc::MirrorPlane* plane) {
    return rewritten_with_extrapolation(file, features, k, plane);
  });
  // What the encoder writes on an open grid of quads, at 12 and 16 bits,
  // and with texture coordinates (their values take no extrapolation, 15.4).
  const Mesh open = qmc::tools::make_bent_grid(24, 16);
  options.position_bits = 12;
  Mesh textured = open;
  qmc::tools::add_chart_texcoords(&textured);
  const std::vector<uint8_t> file = write_encoder_files(w, "posn12", "open_grid", open, textured, options, 12);

  write_shear_and_plane_invalids(w, "posn12", file, open.vertex_count());

  // Added after the spec-only check of 14.13, for the readings the vectors
  // above left open: vertices of more than 8 corners predicted by the rule,
  // faces of degree 5 to 9 beside them, more pairs than the 4 candidates
  // kept, and 14.8's contexts already learning.
  // Two seeds: each tells apart readings the other does not (v's first 8
  // corners against 9 or all, the near test over v's first 8 corners or all
  // of them, u's first 8 corners against 9 or all).
  for (uint64_t seed : {15, 16}) {
    const Mesh soup = windowed_polygon_soup(400, 333, seed);
    w->valid("valid_posn12_polygon_soup_seed_" + std::to_string(seed),
             rewritten_with_extrapolation(encode_with(soup, unit, "windowed polygon soup"), 7, 8), &soup);
  }
}

// A file's POSN recoded as method 13 (14.14): method 12's layout over
// method 8's features, shear k and, if given, a mirror plane, with the class
// probabilities per axis.
std::vector<uint8_t> rewritten_with_axis_classes(const std::vector<uint8_t>& file, uint8_t features, int k,
                                                 const qmc::MirrorPlane* plane = nullptr) {
  return recoded_posn(file, features, k, plane, true, nullptr, true);
}

void write_posn13_vectors(VectorWriter* w) {
  qmc::EncodeOptions options;  // what `qmc encode` writes
  // 14.14 on the small meshes of 14.13's vectors: every class decision with
  // the mean of two probabilities from the first vertex on, with start 1.
  write_recoded_small_meshes(w, "posn13", options, [](const std::vector<uint8_t>& file, uint8_t features, int k,
                                                      const qmc::MirrorPlane* plane) {
    return rewritten_with_axis_classes(file, features, k, plane);
  });
  // What the encoder writes from 1,000 vertices: a torus of triangles whose
  // axes differ (its z the axis of revolution), at 12 and 16 bits, and with
  // texture coordinates (their values use CLS alone, 15.4).
  const Mesh torus = qmc::tools::triangulated(qmc::tools::make_torus(48, 24));
  options.position_bits = 12;
  Mesh textured = torus;
  qmc::tools::add_chart_texcoords(&textured);
  const std::vector<uint8_t> file = write_encoder_files(w, "posn13", "torus", torus, textured, options, 13);

  write_shear_and_plane_invalids(w, "posn13", file, torus.vertex_count());
}

// A sphere of triangles, `segments` around and `rings` rings (rows of
// alternate offsets), radius jittered by up to 10 % (splitmix64, seed): the
// bottom pole's fan first, the rings' strips from the bottom up, the top
// pole's fan last, so that 14.6's order decodes the top pole once most of
// its ring is decoded (more than 16 corners with both neighbours decoded).
Mesh sphere_with_pole_last(uint32_t segments, uint32_t rings, uint64_t seed) {
  uint64_t state = seed;
  const auto unit = [&state] { return double(qmc::splitmix64_mix(++state) >> 11) / double(uint64_t(1) << 53); };
  const double pi = 3.14159265358979323846;
  Mesh m;
  // The poles' axis turned to (1, 1, 0.1), between x and y, where the normals'
  // sums over 16 corners and over all of them may favour different axes.
  const double d[3] = {0.70534, 0.70534, 0.070534}, e[3] = {0.70711, -0.70711, 0};
  const double f[3] = {d[1] * e[2] - d[2] * e[1], d[2] * e[0] - d[0] * e[2], d[0] * e[1] - d[1] * e[0]};
  const auto add = [&](double x, double y, double z) {
    m.positions.insert(m.positions.end(), {float(x * e[0] + y * f[0] + z * d[0]), float(x * e[1] + y * f[1] + z * d[1]),
                                           float(x * e[2] + y * f[2] + z * d[2])});
  };
  for (uint32_t r = 1; r < rings; ++r)
    for (uint32_t i = 0; i < segments; ++i) {
      const double theta = pi * r / rings, phi = 2 * pi * (i + 0.5 * (r % 2)) / segments;
      const double j = 1 + 0.2 * (unit() - 0.5);
      add(j * std::sin(theta) * std::cos(phi), j * std::sin(theta) * std::sin(phi), j * std::cos(theta));
    }
  const uint32_t bottom = (rings - 1) * segments, top = bottom + 1;
  add(0, 0, -1);
  add(0, 0, 1.0 + 0.4 * (unit() - 0.5));
  const auto at = [&](uint32_t r, uint32_t i) { return (r - 1) * segments + i % segments; };
  const auto triangle = [&m](uint32_t a, uint32_t b, uint32_t c) {
    m.face_sizes.push_back(3);
    m.corners.insert(m.corners.end(), {a, b, c});
  };
  for (uint32_t i = 0; i < segments; ++i) triangle(bottom, at(rings - 1, i + 1), at(rings - 1, i));
  for (uint32_t r = rings - 1; r > 1; --r)
    for (uint32_t i = 0; i < segments; ++i) {
      triangle(at(r, i), at(r, i + 1), at(r - 1, i + 1));
      triangle(at(r, i), at(r - 1, i + 1), at(r - 1, i));
    }
  for (uint32_t i = 0; i < segments; ++i) triangle(top, at(1, i), at(1, i + 1));
  return m;
}

// 14.15's lattice byte, and the tops it allows, on `file`, an encoder's
// method-14 file with no mirror plane: a lattice of 1 and of 17, the byte
// missing, and a top of 2^24 (the largest a grid may have otherwise).
void write_lattice_invalids(VectorWriter* w, const std::vector<uint8_t>& file, size_t vertex_count) {
  using qmc::ErrorCode;
  const ChunkReplacer with_posn(file, qmc::kChunkPositions);
  const std::vector<uint8_t> payload = with_posn.payload();
  std::vector<uint8_t> count;
  qmc::put_varint(&count, vertex_count);
  const size_t lattice = count.size() + 5;  // after selector, start, features, shear and plane
  std::vector<uint8_t> p = payload;
  p[lattice] = 1;
  w->invalid("invalid_posn14_lattice_1", with_posn(p), ErrorCode::kBadChunkPayload);
  p[lattice] = 17;
  w->invalid("invalid_posn14_lattice_17", with_posn(p), ErrorCode::kBadChunkPayload);
  w->invalid("invalid_posn14_lattice_missing",
             with_posn(std::vector<uint8_t>(payload.begin(), payload.begin() + long(lattice))),
             ErrorCode::kBadChunkPayload);
  // After the lattice byte, with a plane its axis byte and sum; then grid 0
  // (one step): the grid byte, the origin (12 bytes) and the step (8), then the tops.
  size_t grid = lattice + 1;
  if (payload[lattice - 1] != 0) {  // the plane byte
    ++grid;
    while (payload[grid] & 0x80) ++grid;
    ++grid;
  }
  if (payload[grid] != 0) {
    std::fprintf(stderr, "qmc-make-vectors: a method-14 file without one step\n");
    std::exit(3);
  }
  const size_t top = grid + 1 + 12 + 8;
  size_t first_top_end = top;
  while (payload[first_top_end] & 0x80) ++first_top_end;
  p.assign(payload.begin(), payload.begin() + long(top));
  qmc::put_varint(&p, uint64_t(1) << 24);
  p.insert(p.end(), payload.begin() + long(first_top_end) + 1, payload.end());
  w->invalid("invalid_posn14_top_2_24", with_posn(p), ErrorCode::kBadChunkPayload);
}

// The vectors of POSN method 14 (14.15): the small meshes of 14.13's
// vectors recoded on a lattice of 4 (no source check: placed near the
// decoded grid points, a vertex may lie k + 1/2 steps from its input), and
// what the encoder writes with --surface-lattice on a jittered sphere (a
// scan's noise) at 12 and 16 bits, with texture coordinates, and at k = 2
// and k = 16.
void write_posn14_vectors(VectorWriter* w) {
  qmc::EncodeOptions options;  // what `qmc encode` writes
  const qmc::EncodeOptions unit = on_unit_grid(options);
  const auto lattice = [](const std::vector<uint8_t>& file, uint8_t features, int k, const qmc::MirrorPlane* plane) {
    return recoded_posn(file, features, k, plane, true, nullptr, true, 4);
  };
  const Mesh example = extrapolation_example();
  w->valid("valid_posn14_example", lattice(encode_with(example, unit, "extrapolation example"), 0, 0, nullptr),
           nullptr);
  const Mesh mixed = quads_over_triangles(12);
  w->valid("valid_posn14_every_feature_and_shear",
           lattice(encode_with(mixed, unit, "quads over triangles"), 7, 8, nullptr), nullptr);
  const Mesh grid = qmc::tools::make_mirrored_across_x(qmc::tools::make_grid(6, 4));
  const std::vector<uint8_t> grid_file = encode_with(grid, options, "mirrored grid");
  qmc::MirrorPlane near_plane = mirror_plane_of(grid_file, false);
  near_plane.near_images = true;
  w->valid("valid_posn14_plane_2_shear", lattice(grid_file, 1, 16, &near_plane), nullptr);

  const Mesh sphere = qmc::tools::make_jittered_sphere(4, 0.01f, 7);
  options.position_bits = 12;
  options.surface_lattice = 4;
  Mesh textured = sphere;
  qmc::tools::add_chart_texcoords(&textured);
  const std::vector<uint8_t> file = write_encoder_files(w, "posn14", "sphere", sphere, textured, options, 14);
  for (int k : {2, 16}) {
    qmc::EncodeOptions other = options;
    other.surface_lattice = k;
    w->valid("valid_posn14_sphere_lattice_" + std::to_string(k), encode_posn_method(sphere, other, 14), &sphere);
  }
  write_shear_and_plane_invalids(w, "posn14", file, sphere.vertex_count());
  write_lattice_invalids(w, file, sphere.vertex_count());

  // Added after the spec-only check of 14.15, for readings the vectors above
  // left open: a polygon soup whose vertices have corners without both
  // neighbours decoded (those do not count towards the 16), 14.9's twist
  // correcting the P the normal is taken around (the encoder's triangle twist
  // on a jittered sphere), poles of 25 corners decoded after most of their
  // ring (the limit of 16 corners), a 20-bit grid (coarse buckets capped at
  // 15) and a per-axis grid of steps of three sizes (the normal in grid steps).
  const Mesh soup = qmc::tools::make_random_soup(1, qmc::tools::RandomSoupOptions{});
  w->valid("valid_posn14_soup", lattice(encode_with(soup, options, "random soup"), 2, 0, nullptr), nullptr);
  const Mesh jittered = qmc::tools::make_jittered_sphere(3, 0.3f, 3);  // qmc-meshgen jittered-sphere 3 3
  w->valid("valid_posn14_triangle_twist", encode_posn_method(jittered, options, 14), &jittered);
  for (uint64_t seed : {5, 7, 8}) {  // of seeds 1 - 8, those that tell 16 corners from 15, 17 and all
    const Mesh pole = sphere_with_pole_last(25, 6, seed);
    w->valid("valid_posn14_pole_last_seed_" + std::to_string(seed),
             recoded_posn(encode_with(pole, options, "sphere with its pole last"), 0, 0, nullptr, true, nullptr, true,
                          4),
             nullptr);
  }
  qmc::EncodeOptions twenty = options;
  twenty.position_bits = 20;
  w->valid("valid_posn14_sphere_20_bits", encode_posn_method(sphere, twenty, 14), &sphere);
  qmc::EncodeOptions per_axis = options;
  per_axis.position_grid = qmc::PositionGrid::kPerAxis;
  Mesh flattened = sphere;  // axes of three lengths: steps of three sizes
  for (size_t i = 0; i < flattened.positions.size(); ++i) flattened.positions[i] *= i % 3 == 0 ? 1.0f : i % 3 == 1 ? 0.4f : 0.15f;
  w->valid("valid_posn14_ellipsoid_per_axis_grid", encode_posn_method(flattened, per_axis, 14), &flattened);
}

// Section 15.9: aTTR coding 4, what `qmc encode` writes when it is the
// smaller; the generator fails if the encoder kept coding 0 instead.
std::vector<uint8_t> encode_coding4(const Mesh& mesh, bool posn_geometry_order, const char* what) {
  qmc::EncodeOptions options;
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.geometry_order = posn_geometry_order;
  options.attribute_graded_start = false;  // codings 5 and 6 came after these vectors
  options.attribute_predicted_mapping = false;  // and mapping 3 (15.11)
  options.attribute_guided = false;             // and coding 7 (15.12)
  options.angle_weighted_normals = false;       // and coding 8 (15.13)
  std::vector<uint8_t> out;
  qmc::EncodeStats stats;
  if (qmc::Status s = qmc::encode(mesh, without_shear(options), &out, &stats);
      !s.ok() || stats.attributes.empty() || !stats.attributes[0].geometry_order) {
    std::fprintf(stderr, "qmc-make-vectors: %s: not aTTR coding 4 (%s)\n", what, s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

// The aTTR payload of a two-component attribute on one grid (codings 0, 4,
// 5 and 6, mapping 1) with both tops set to 1: a value the grid cannot
// hold. After the mapping stream: grid 0, two f32 origins, one f64 step,
// two tops.
std::vector<uint8_t> with_tops_of_one(const std::vector<uint8_t>& payload, size_t before_grid = 0) {
  qmc::ByteReader r(payload.data(), payload.size());
  r.skip(attr_field_offsets(payload).after_coding);
  uint64_t mapping_bytes = 0;
  r.get_varint(&mapping_bytes);
  r.skip(mapping_bytes);
  const size_t tops = r.position() + before_grid + 1 + 8 + 8;
  r.skip(tops - r.position());
  uint64_t top = 0;
  r.get_varint(&top);
  r.get_varint(&top);
  std::vector<uint8_t> p(payload.begin(), payload.begin() + std::ptrdiff_t(tops));
  qmc::put_varint(&p, 1);
  qmc::put_varint(&p, 1);
  p.insert(p.end(), payload.begin() + std::ptrdiff_t(r.position()), payload.end());
  return p;
}

void write_attribute_coding4_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  // Texture coordinates with seams (mapping 1), over POSN method 4 and
  // over method 1: the order is the attribute mesh's own.
  Mesh textured = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 71, 0.006f);
  qmc::tools::add_chart_texcoords(&textured);
  const std::vector<uint8_t> over_posn4 = encode_coding4(textured, true, "coding 4 texcoords");
  w->valid("valid_attr_coding4_texcoords", over_posn4, &textured);
  w->valid("valid_attr_coding4_over_posn1", encode_coding4(textured, false, "coding 4 over method 1"), &textured);
  // One value per vertex (mapping 0): colours from the positions.
  Mesh coloured = perturbed(qmc::tools::triangulated(qmc::tools::make_refined_sphere(3)), 73, 0.006f);
  MeshAttribute colour{"colour", qmc::AttributeKind::kColour, 3, {}, coloured.corners};
  for (float x : coloured.positions) colour.values.push_back(0.5f + 0.35f * x);
  coloured.attributes.push_back(colour);
  w->valid("valid_attr_coding4_per_vertex_colours", encode_coding4(coloured, true, "coding 4 colours"), &coloured);

  // 15.4's rules on coding 4's path.
  Chunks c = split_chunks(over_posn4);
  const size_t at = find_chunk(c, qmc::kChunkAttribute);
  const std::vector<uint8_t> payload = c[at].payload;
  const auto with_payload = [&](std::vector<uint8_t> p) {
    Chunks d = c;
    d[at].payload = std::move(p);
    return join_chunks(d);
  };
  w->invalid("invalid_attr_coding4_truncated", with_payload({payload.begin(), payload.end() - 8}), ErrorCode::kTruncated);
  w->invalid("invalid_attr_coding4_value_outside_grid", with_payload(with_tops_of_one(payload)), ErrorCode::kBadSymbol);
}

// Section 15.10: aTTR codings 5 and 6, what `qmc encode` writes when the
// graded start is the smaller; the generator fails if the file's first
// attribute has another coding.
std::vector<uint8_t> encode_attribute_coding(const Mesh& mesh, const qmc::EncodeOptions& options, uint8_t coding,
                                             const char* what) {
  std::vector<uint8_t> out;
  qmc::DecodedFile file;
  if (qmc::Status s = qmc::encode(mesh, without_shear(options), &out); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s: %s\n", what, s.to_string().c_str());
    std::exit(3);
  }
  if (qmc::Status s = qmc::decode(out.data(), out.size(), &file);
      !s.ok() || file.attribute_codings.empty() || file.attribute_codings[0].coding != coding) {
    std::fprintf(stderr, "qmc-make-vectors: %s: not aTTR coding %u (%s)\n", what, unsigned(coding),
                 s.to_string().c_str());
    std::exit(3);
  }
  return out;
}

void write_attribute_coding56_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  // Texture coordinates with seams (mapping 1) on a torus of 160 vertices:
  // coding 6 over POSN method 4, coding 5 when the geometry order is not
  // allowed, and coding 6 over POSN method 1 (the start is the coding's,
  // not POSN's).
  Mesh textured = perturbed(qmc::tools::triangulated(qmc::tools::make_torus(20, 8)), 75, 0.004f);
  qmc::tools::add_chart_texcoords(&textured);
  qmc::EncodeOptions options;
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.attribute_predicted_mapping = false;  // mapping 3 (15.11) came after these vectors
  options.attribute_guided = false;             // and coding 7 (15.12)
  options.angle_weighted_normals = false;       // and coding 8 (15.13)
  const std::vector<uint8_t> six = encode_attribute_coding(textured, options, 6, "coding 6 texcoords");
  w->valid("valid_attr_coding6_texcoords", six, &textured);
  qmc::EncodeOptions label_order = options;
  label_order.attribute_geometry_order = false;
  const std::vector<uint8_t> five = encode_attribute_coding(textured, label_order, 5, "coding 5 texcoords");
  w->valid("valid_attr_coding5_texcoords", five, &textured);
  qmc::EncodeOptions over_posn1 = options;
  over_posn1.geometry_order = false;
  over_posn1.graded_class_start = false;
  w->valid("valid_attr_coding6_over_posn1", encode_attribute_coding(textured, over_posn1, 6, "coding 6 over method 1"),
           &textured);
  // One value per vertex (mapping 0): colours from the positions with a
  // little noise.
  Mesh coloured = qmc::tools::triangulated(qmc::tools::make_torus(12, 8));
  MeshAttribute colour{"colour", qmc::AttributeKind::kColour, 3, {}, coloured.corners};
  qmc::tools::SplitMix64 random(77);
  for (float x : coloured.positions) colour.values.push_back(0.5f + 0.35f * x + float(random.below(64)) / 4096.0f);
  coloured.attributes.push_back(colour);
  w->valid("valid_attr_coding6_per_vertex_colours",
           encode_attribute_coding(coloured, options, 6, "coding 6 colours"), &coloured);

  // Polygons (quads) and one component per value, one value per vertex: a
  // scalar from the positions with a little noise, in label order.
  Mesh quads = qmc::tools::make_torus(10, 6);
  MeshAttribute scalar{"height", qmc::AttributeKind::kGeneric, 1, {}, quads.corners};
  for (size_t v = 0; v < quads.vertex_count(); ++v)
    scalar.values.push_back(quads.positions[3 * v + 2] + float(random.below(64)) / 2048.0f);
  quads.attributes.push_back(scalar);
  w->valid("valid_attr_coding5_quads_one_component",
           encode_attribute_coding(quads, label_order, 5, "coding 5 scalar on quads"), &quads);

  // 15.4's rules on the paths of codings 5 and 6.
  const auto attribute_payload = [](const std::vector<uint8_t>& file) {
    Chunks c = split_chunks(file);
    return std::make_pair(c, find_chunk(c, qmc::kChunkAttribute));
  };
  // Cut 8 bytes short: the error comes late in the values, where a decoder
  // starting the class probabilities at 1024 has decoded other values.
  for (const auto& [name, file] : {std::make_pair("invalid_attr_coding5_truncated", &five),
                                   std::make_pair("invalid_attr_coding6_truncated", &six)}) {
    auto [c, at] = attribute_payload(*file);
    c[at].payload.resize(c[at].payload.size() - 8);
    w->invalid(name, join_chunks(c), ErrorCode::kTruncated);
  }
  auto [c, at] = attribute_payload(six);
  c[at].payload = with_tops_of_one(c[at].payload);
  w->invalid("invalid_attr_coding6_value_outside_grid", join_chunks(c), ErrorCode::kBadSymbol);
}

// Where an aTTR payload's values start: after the mapping stream, if the
// mapping (the byte after the components) is per corner.
size_t values_offset(const std::vector<uint8_t>& payload) {
  qmc::ByteReader r(payload.data(), payload.size());
  r.skip(attr_field_offsets(payload).after_coding);
  if (payload[attr_field_offsets(payload).components + 1] != 0) {
    uint64_t mapping_bytes = 0;
    r.get_varint(&mapping_bytes);
    r.skip(size_t(mapping_bytes));
  }
  return r.position();
}

// A file's first aTTR chunk, to make files with another payload in its place.
class AttributeChunk {
 public:
  explicit AttributeChunk(const std::vector<uint8_t>& file)
      : chunks_(split_chunks(file)), at_(find_chunk(chunks_, qmc::kChunkAttribute)) {}
  const std::vector<uint8_t>& payload() const { return chunks_[at_].payload; }
  std::vector<uint8_t> with(std::vector<uint8_t> payload) const {
    Chunks c = chunks_;
    c[at_].payload = std::move(payload);
    return join_chunks(c);
  }

 private:
  Chunks chunks_;
  size_t at_;
};

// Sections 15.12 and 15.14: aTTR coding 7 or 9, what `qmc encode` writes
// where guiding by the positions, or twins, are the smaller; the generator
// fails on another coding or options.
std::vector<uint8_t> encode_coding_with_options(const Mesh& mesh, const qmc::EncodeOptions& options, uint8_t coding,
                                                uint8_t expected_options, const char* what) {
  const std::vector<uint8_t> out = encode_attribute_coding(mesh, options, coding, what);
  qmc::DecodedFile file;
  (void)qmc::decode(out.data(), out.size(), &file);
  if (file.attribute_codings[0].options != expected_options) {
    std::fprintf(stderr, "qmc-make-vectors: %s: coding %u with options %u, not %u\n", what, unsigned(coding),
                 unsigned(file.attribute_codings[0].options), unsigned(expected_options));
    std::exit(3);
  }
  return out;
}

std::vector<uint8_t> encode_coding7(const Mesh& mesh, const qmc::EncodeOptions& options, uint8_t expected_options,
                                    const char* what) {
  return encode_coding_with_options(mesh, options, 7, expected_options, what);
}

// A bumpy grid of nx x ny quads (or their triangles) whose vertices are moved in the plane by up
// to a third of a cell (irregular faces, where parallelograms predict
// poorly), with texture coordinates (x, y) in two charts, x < 0 and x >= 0,
// the second shifted by 3 in u: a seam along x = 0; each value moved by up
// to uv_noise cells.
Mesh jittered_textured_grid(int nx, int ny, uint64_t seed, bool triangles, float uv_noise = 0) {
  Mesh mesh = triangles ? qmc::tools::triangulated(qmc::tools::make_grid(nx, ny)) : qmc::tools::make_grid(nx, ny);
  qmc::tools::SplitMix64 random(seed);
  const float cell = 2.0f / float(std::max(nx, ny));
  for (size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int a = 0; a < 2; ++a) mesh.positions[3 * v + a] += cell / 3 * (float(random.next() % 2001) / 1000.f - 1.f);
  MeshAttribute uv{"texcoord", qmc::AttributeKind::kTextureCoordinate, 2, {}, {}};
  std::vector<uint32_t> value_of(2 * mesh.vertex_count(), UINT32_MAX);
  size_t start = 0;
  for (uint32_t degree : mesh.face_sizes) {
    float centroid = 0;
    for (uint32_t i = 0; i < degree; ++i) centroid += mesh.positions[3 * size_t(mesh.corners[start + i])];
    const size_t chart = centroid < 0 ? 0 : 1;
    for (uint32_t i = 0; i < degree; ++i) {
      const uint32_t v = mesh.corners[start + i];
      uint32_t& value = value_of[chart * mesh.vertex_count() + v];
      if (value == UINT32_MAX) {
        value = uint32_t(uv.value_count());
        for (int a = 0; a < 2; ++a)
          uv.values.push_back(mesh.positions[3 * size_t(v) + a] + (a == 0 ? 3.0f * float(chart) : 0.0f) +
                              uv_noise * cell * (float(random.next() % 2001) / 1000.f - 1.f));
      }
      uv.corner_values.push_back(value);
    }
    start += degree;
  }
  mesh.attributes.push_back(std::move(uv));
  return mesh;
}

// The six sides of the cube [-1, 1]^3, each an n x n grid of triangles of
// its own (no vertex shared between sides) moved in its plane by up to a
// third of a cell, with texture coordinates the in-plane coordinates plus 3
// times the side's number in u: every axis has the same range, so POSN
// method 0's per-axis grid is uniform.
Mesh jittered_textured_cube_sides(int n, uint64_t seed) {
  Mesh mesh;
  MeshAttribute uv{"texcoord", qmc::AttributeKind::kTextureCoordinate, 2, {}, {}};
  qmc::tools::SplitMix64 random(seed);
  const float cell = 2.0f / float(n);
  for (int side = 0; side < 6; ++side) {
    const int axis = side / 2;
    const float level = side % 2 ? 1.0f : -1.0f;
    const uint32_t first = uint32_t(mesh.vertex_count());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        float s = -1 + cell * float(i), t = -1 + cell * float(j);
        if (i > 0 && i < n) s += cell / 3 * (float(random.next() % 2001) / 1000.f - 1.f);
        if (j > 0 && j < n) t += cell / 3 * (float(random.next() % 2001) / 1000.f - 1.f);
        float p[3];
        p[axis] = level;
        p[(axis + 1) % 3] = s;
        p[(axis + 2) % 3] = t;
        mesh.positions.insert(mesh.positions.end(), p, p + 3);
        uv.values.push_back(s + 3.0f * float(side));
        uv.values.push_back(t);
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t a = first + uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
        for (const std::array<uint32_t, 3>& f : {std::array<uint32_t, 3>{a, b, d}, std::array<uint32_t, 3>{a, d, c}}) {
          mesh.face_sizes.push_back(3);
          mesh.corners.insert(mesh.corners.end(), f.begin(), f.end());
        }
      }
  }
  uv.corner_values = mesh.corners;
  mesh.attributes.push_back(std::move(uv));
  return mesh;
}

// 15.12 where a value has more corners the guided rule applies to than
// candidates are kept (4): a soup of 48 triangles over 16 vertices, a value
// per vertex from its positions' integers, coding 7 written directly (the
// encoder would keep another coding for such a table). Such a corner adds
// nothing and leaves the orientation as it is: a decoder that takes the side
// there (and sets the orientation) reads value 14 outside the grid.
std::vector<uint8_t> coding7_over_soup() {
  qmc::tools::RandomSoupOptions o;
  o.vertices = 16;
  o.faces = 48;
  o.max_degree = 3;
  o.unreferenced = 0;
  o.repeated_corners = false;
  qmc::EncodeOptions options;
  options.mirror_symmetry = false;  // the positions as the vector was first made (method 3)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  const std::vector<uint8_t> plain = encode_with(qmc::tools::make_random_soup(13, o), options, "soup");
  qmc::DecodedFile d;
  (void)qmc::decode(plain.data(), plain.size(), &d);
  const uint32_t n = uint32_t(d.mesh.vertex_count()), top[3] = {8191, 8191, 0};
  std::vector<uint32_t> q(3 * size_t(n), 0);
  for (size_t v = 0; v < n; ++v) {
    q[3 * v] = d.quantized[3 * v] + d.quantized[3 * v + 1];
    q[3 * v + 1] = d.quantized[3 * v + 2] + d.quantized[3 * v] / 2;
  }
  qmc::PositionGuide guide;
  guide.vertex_of_corner = d.mesh.corners.data();
  guide.positions = d.quantized.data();
  const std::vector<uint8_t> stream = qmc::encode_predicted_grid(
      q, top, d.mesh, nullptr, qmc::CandidateChoice::kFewestBits, qmc::ClassStart::kFlat, qmc::PredictionOrder::kLabels,
      &guide);
  AttrFields f;  // "uv", a texture coordinate of 2 components
  f.vertices = f.values = n;
  f.corners = d.mesh.corners.size();
  f.mapping = 0;
  f.coding = 7;
  qmc::put_u8(&f.rest, 0);  // options: label order, flat start
  qmc::put_u8(&f.rest, 0);  // grid 0
  qmc::put_f32le(&f.rest, 0.0f);
  qmc::put_f32le(&f.rest, 0.0f);
  qmc::put_f64le(&f.rest, 1.0 / 8191);
  qmc::put_varint(&f.rest, top[0]);
  qmc::put_varint(&f.rest, top[1]);
  f.rest.insert(f.rest.end(), stream.begin(), stream.end());
  return with_chunk_before(plain, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(f));
}

void write_attribute_coding7_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  // Texture coordinates with a seam on 12 x 12 irregular quads split in triangles, each option.
  const Mesh textured = jittered_textured_grid(12, 12, 91, true);
  qmc::EncodeOptions options;  // what `qmc encode` writes
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  const std::vector<uint8_t> both = encode_coding7(textured, options, 1, "coding 7 texcoords");
  w->valid("valid_attr_coding7_texcoords", both, &textured);
  qmc::EncodeOptions labels = options;
  labels.attribute_geometry_order = false;
  labels.attribute_graded_start = false;
  w->valid("valid_attr_coding7_no_option", encode_coding7(textured, labels, 0, "coding 7, no option"), &textured);
  // 14.4.1's start pays on a smaller table (the encoder's choice, 15.8).
  const Mesh small = jittered_textured_grid(6, 6, 95, true, 0.25f);
  w->valid("valid_attr_coding7_graded_geometry_order", encode_coding7(small, options, 3, "coding 7, options 3"),
           &small);
  labels.attribute_graded_start = true;
  w->valid("valid_attr_coding7_graded_start", encode_coding7(small, labels, 2, "coding 7, option 2"), &small);
  // Over POSN method 1 and method 0 (15.7's q of each: the deltas' per-axis grid).
  qmc::EncodeOptions over_posn1 = options;
  over_posn1.geometry_order = false;
  over_posn1.graded_class_start = false;
  w->valid("valid_attr_coding7_over_posn1", encode_coding7(textured, over_posn1, 1, "coding 7 over method 1"),
           &textured);
  qmc::EncodeOptions over_posn0 = over_posn1;
  over_posn0.position_method = qmc::PositionMethod::kDeltas;
  over_posn0.position_grid = qmc::PositionGrid::kPerAxis;
  const Mesh cube = jittered_textured_cube_sides(5, 97);
  w->valid("valid_attr_coding7_over_posn0", encode_coding7(cube, over_posn0, 1, "coding 7 over method 0"), &cube);
  // Quads: the side from the face's own opposite corner (15.12, d >= 4).
  const Mesh quads = jittered_textured_grid(16, 16, 93, false);
  w->valid("valid_attr_coding7_quads", encode_attribute_coding(quads, options, 7, "coding 7 on quads"), &quads);

  w->valid("valid_attr_coding7_many_corners", coding7_over_soup(), nullptr);

  // 15.12's rules.
  const AttributeChunk chunk(both);
  const std::vector<uint8_t>& payload = chunk.payload();
  w->invalid("invalid_attr_coding7_truncated", chunk.with({payload.begin(), payload.end() - 8}),
             ErrorCode::kTruncated);
  w->invalid("invalid_attr_coding7_value_outside_grid", chunk.with(with_tops_of_one(payload, 1)),
             ErrorCode::kBadSymbol);
  // The options byte: after the mapping stream, before the grid.
  std::vector<uint8_t> bit_2 = payload;
  bit_2[values_offset(payload)] |= 4;
  w->invalid("invalid_attr_coding7_option_bit_2", chunk.with(bit_2), ErrorCode::kBadChunkPayload);
  // Coding 7 is for two components: the same chunk saying 3.
  std::vector<uint8_t> three = payload;
  three[attr_field_offsets(payload).components] = 3;
  w->invalid("invalid_attr_coding7_three_components", chunk.with(three), ErrorCode::kBadChunkPayload);
}

// Section 15.14: aTTR coding 9 written by hand over a file's CONN and POSN
// (mapping 0, C = 2 on a grid of step 1 from the origin): the options, the
// plane and the values' integers q (3 per vertex) as given.
std::vector<uint8_t> coding9_by_hand(const std::vector<uint8_t>& plain, uint8_t options, qmc::MirrorPlane plane,
                                     const std::vector<uint32_t>& q, const uint32_t top[3]) {
  qmc::DecodedFile d;
  if (qmc::Status s = qmc::decode(plain.data(), plain.size(), &d); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: coding 9 by hand: %s\n", s.to_string().c_str());
    std::exit(3);
  }
  const uint32_t n = uint32_t(d.mesh.vertex_count());
  const qmc::AttributeTwins twins{plane, &d.mesh, d.quantized.data(), n};
  qmc::PositionGuide guide;
  guide.vertex_of_corner = d.mesh.corners.data();
  guide.positions = d.quantized.data();
  const std::vector<uint8_t> stream = qmc::encode_predicted_grid(
      q, top, d.mesh, nullptr, qmc::CandidateChoice::kFewestBits,
      options & 2 ? qmc::ClassStart::kGraded : qmc::ClassStart::kFlat,
      options & 1 ? qmc::PredictionOrder::kGeometry : qmc::PredictionOrder::kLabels, options & 4 ? &guide : nullptr,
      false, false, false, &twins);
  AttrFields f;  // "uv", a texture coordinate of 2 components
  f.vertices = f.values = n;
  f.corners = d.mesh.corners.size();
  f.mapping = 0;
  f.coding = 9;
  qmc::put_u8(&f.rest, options);
  qmc::put_u8(&f.rest, uint8_t(plane.axis));
  qmc::put_varint(&f.rest, plane.sum);
  qmc::put_u8(&f.rest, 0);  // grid 0
  qmc::put_f32le(&f.rest, 0.0f);
  qmc::put_f32le(&f.rest, 0.0f);
  qmc::put_f64le(&f.rest, 1.0);
  qmc::put_varint(&f.rest, top[0]);
  qmc::put_varint(&f.rest, top[1]);
  f.rest.insert(f.rest.end(), stream.begin(), stream.end());
  return with_chunk_before(plain, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(f));
}

// The fan of 15.14's example, positions on integers (step 1 from (0, 0, 0)),
// written with its faces and labels as given; vertex 4 at (x4, 1, 0).
std::vector<uint8_t> twins_example_file(uint32_t x4) {
  Mesh fan;
  fan.positions = {2, 0, 0, 1, 3, 0, 0, 1, 0, 3, 3, 0, float(x4), 1, 0};
  fan.face_sizes = {3, 3, 3};
  fan.corners = {0, 1, 2, 0, 3, 1, 0, 4, 3};
  const qmc::EncodeOptions unit = on_unit_grid(format_1_6_options());
  const std::vector<uint8_t> file = encode_with(fan, unit, "twins example");
  qmc::DecodedFile d;
  (void)qmc::decode(file.data(), file.size(), &d);
  const std::vector<uint32_t> expected = {2, 0, 0, 1, 3, 0, 0, 1, 0, 3, 3, 0, x4, 1, 0};
  if (d.quantized != expected || d.mesh.corners != fan.corners) {
    std::fprintf(stderr, "qmc-make-vectors: the twins example's labels or integers moved\n");
    std::exit(3);
  }
  return file;
}

std::vector<uint8_t> encode_coding9(const Mesh& mesh, const qmc::EncodeOptions& options, uint8_t expected_options,
                                    const char* what) {
  return encode_coding_with_options(mesh, options, 9, expected_options, what);
}

// One attribute per vertex of `components` numbers on a mirrored mesh:
// (x, y, z)'s first components with x as |x| (a copy across the plane, not
// a flip), kind colour for 3.
Mesh with_vertex_attribute(Mesh mesh, uint32_t components) {
  MeshAttribute a{components == 3 ? "colour" : "weight",
                  components == 3 ? qmc::AttributeKind::kColour : qmc::AttributeKind::kGeneric, components, {}, {}};
  for (size_t v = 0; v < mesh.vertex_count(); ++v)
    for (uint32_t j = 0; j < components; ++j)
      a.values.push_back(j == 0 ? std::fabs(mesh.positions[3 * v]) : mesh.positions[3 * v + j]);
  a.corner_values = mesh.corners;
  mesh.attributes.push_back(std::move(a));
  return mesh;
}

void write_attribute_coding9_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  // Spec 15.14's example, its twin one step from the image, and a plane without twins.
  const uint32_t top[3] = {15, 6, 0};
  const std::vector<uint32_t> q = {10, 0, 0, 8, 6, 0, 5, 2, 0, 12, 6, 0, 15, 2, 0};
  w->valid("valid_attr_coding9_example", coding9_by_hand(twins_example_file(4), 0, {0, 4}, q, top), nullptr);
  w->valid("valid_attr_coding9_twin_a_step_away", coding9_by_hand(twins_example_file(3), 0, {0, 4}, q, top),
           nullptr);
  w->valid("valid_attr_coding9_no_twins", coding9_by_hand(twins_example_file(4), 0, {1, 40}, q, top), nullptr);
  w->valid("valid_attr_coding9_options_7", coding9_by_hand(twins_example_file(4), 7, {0, 4}, q, top), nullptr);
  // What the encoder writes: mirrored texture coordinates with seams on a
  // sphere of triangles and a torus of quads; over POSN method 0; a colour
  // and a one-component value per vertex.
  qmc::EncodeOptions options;  // what `qmc encode` wrote before POSN method 10
  options.near_mirror = false;  // (14.11), which came after these vectors
  Mesh sphere = make_mirrored_across_x(triangulated(make_refined_sphere(3)));
  add_mirrored_texcoords(&sphere, 16, 5);
  const std::vector<uint8_t> texcoords = encode_coding9(sphere, options, 0, "coding 9 texcoords");
  w->valid("valid_attr_coding9_texcoords", texcoords, &sphere);
  Mesh small = make_mirrored_across_x(triangulated(make_refined_sphere(2)));
  add_mirrored_texcoords(&small, 8, 7);
  w->valid("valid_attr_coding9_small", encode_coding9(small, options, 4, "coding 9, a small table"), &small);
  Mesh quads = make_mirrored_across_x(make_torus(16, 8));
  add_mirrored_texcoords(&quads, 12, 6);
  w->valid("valid_attr_coding9_quads", encode_coding9(quads, options, 6, "coding 9 on quads"), &quads);
  qmc::EncodeOptions over_posn0 = options;
  over_posn0.position_method = qmc::PositionMethod::kDeltas;
  over_posn0.position_grid = qmc::PositionGrid::kPerAxis;
  w->valid("valid_attr_coding9_over_posn0", encode_coding9(sphere, over_posn0, 0, "coding 9 over method 0"), &sphere);
  const Mesh colours = with_vertex_attribute(make_mirrored_across_x(triangulated(make_refined_sphere(2))), 3);
  const std::vector<uint8_t> coloured = encode_coding9(colours, options, 3, "coding 9 colours");
  w->valid("valid_attr_coding9_colours", coloured, &colours);
  const Mesh weights = with_vertex_attribute(make_mirrored_across_x(triangulated(make_refined_sphere(2))), 1);
  w->valid("valid_attr_coding9_one_component", encode_coding9(weights, options, 3, "coding 9 weights"), &weights);

  // 15.14's rules, on the texture coordinates' chunk: options, plane, then 15.4's.
  const AttributeChunk chunk(texcoords);
  const std::vector<uint8_t>& payload = chunk.payload();
  const size_t at = values_offset(payload);  // options, axis, sum
  std::vector<uint8_t> bit_3 = payload;
  bit_3[at] |= 8;
  w->invalid("invalid_attr_coding9_option_bit_3", chunk.with(bit_3), ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> guided_three = payload;
  guided_three[at] |= 4;
  guided_three[attr_field_offsets(payload).components] = 3;
  w->invalid("invalid_attr_coding9_guided_three_components", chunk.with(guided_three), ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> axis_3 = payload;
  axis_3[at + 1] = 3;
  w->invalid("invalid_attr_coding9_axis_3", chunk.with(axis_3), ErrorCode::kBadChunkPayload);
  qmc::ByteReader sum_reader(payload.data() + at + 2, payload.size() - at - 2);
  uint64_t sum = 0;
  sum_reader.get_varint(&sum);
  const size_t after_sum = at + 2 + sum_reader.position();
  std::vector<uint8_t> big_sum(payload.begin(), payload.begin() + std::ptrdiff_t(at + 2));
  qmc::put_varint(&big_sum, uint64_t(1) << 31);
  big_sum.insert(big_sum.end(), payload.begin() + std::ptrdiff_t(after_sum), payload.end());
  w->invalid("invalid_attr_coding9_sum_2_31", chunk.with(big_sum), ErrorCode::kBadChunkPayload);
  // The colours' chunk, whose values are few enough for 15.1 check 8 with an options byte alone.
  const AttributeChunk colour_chunk(coloured);
  const std::vector<uint8_t>& colour_payload = colour_chunk.payload();
  const size_t colour_at = values_offset(colour_payload);
  w->invalid("invalid_attr_coding9_no_plane",
             colour_chunk.with({colour_payload.begin(), colour_payload.begin() + std::ptrdiff_t(colour_at + 1)}),
             ErrorCode::kBadChunkPayload);
  w->invalid("invalid_attr_coding9_truncated", chunk.with({payload.begin(), payload.end() - 8}),
             ErrorCode::kTruncated);
  w->invalid("invalid_attr_coding9_value_outside_grid", chunk.with(with_tops_of_one(payload, after_sum - at)),
             ErrorCode::kBadSymbol);
}

// Unit normals weighting each face by its angle at the vertex (15.13's
// kind), per vertex, or per corner with a crease along x = 0 (each half's
// faces on their own).
void add_angle_weighted_normals(Mesh* mesh, bool crease) {
  const size_t n = mesh->vertex_count();
  std::vector<double> sum(6 * n, 0.0);  // per vertex, the x < 0 faces' then the others'
  std::vector<uint32_t> half_of_corner;
  size_t start = 0;
  for (uint32_t degree : mesh->face_sizes) {
    double centroid = 0;
    for (uint32_t i = 0; i < degree; ++i) centroid += mesh->positions[3 * size_t(mesh->corners[start + i])];
    const uint32_t half = crease && centroid >= 0 ? 1 : 0;
    for (uint32_t i = 0; i < degree; ++i) {
      const float* c = &mesh->positions[3 * size_t(mesh->corners[start + i])];
      const float* a = &mesh->positions[3 * size_t(mesh->corners[start + (i + 1) % degree])];
      const float* b = &mesh->positions[3 * size_t(mesh->corners[start + (i + degree - 1) % degree])];
      const double e[3] = {double(a[0]) - c[0], double(a[1]) - c[1], double(a[2]) - c[2]};
      const double f[3] = {double(b[0]) - c[0], double(b[1]) - c[1], double(b[2]) - c[2]};
      const double g[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
      const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      if (length > 0) {
        const double angle = std::atan2(length, e[0] * f[0] + e[1] * f[1] + e[2] * f[2]);
        for (int k = 0; k < 3; ++k) sum[6 * size_t(mesh->corners[start + i]) + 3 * half + k] += angle * g[k] / length;
      }
      half_of_corner.push_back(half);
    }
    start += degree;
  }
  // One value per (vertex, half) some corner uses, numbered as met.
  MeshAttribute normal{"normal", qmc::AttributeKind::kNormal, 3, {}, {}};
  std::vector<uint32_t> number(2 * n, UINT32_MAX);
  for (size_t k = 0; k < mesh->corners.size(); ++k) {
    const size_t j = 2 * size_t(mesh->corners[k]) + half_of_corner[k];
    if (number[j] == UINT32_MAX) {
      number[j] = uint32_t(normal.value_count());
      const double* s3 = &sum[3 * j];
      const double length = std::sqrt(s3[0] * s3[0] + s3[1] * s3[1] + s3[2] * s3[2]);
      for (int c = 0; c < 3; ++c) normal.values.push_back(length > 0 ? float(s3[c] / length) : (c == 2 ? 1.f : 0.f));
    }
    normal.corner_values.push_back(number[j]);
  }
  mesh->attributes.push_back(std::move(normal));
}

void write_attribute_coding8_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  qmc::EncodeOptions options;  // what `qmc encode` writes
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  // A bumpy grid of irregular triangles, and of quads, and the triangles with a crease.
  Mesh triangles = jittered_textured_grid(12, 12, 99, true);
  triangles.attributes.clear();
  add_angle_weighted_normals(&triangles, false);
  const std::vector<uint8_t> smooth = encode_attribute_coding(triangles, options, 8, "coding 8 normals");
  w->valid("valid_attr_coding8_normals", smooth, &triangles);
  Mesh quads = jittered_textured_grid(10, 10, 103, false);
  quads.attributes.clear();
  add_angle_weighted_normals(&quads, false);
  w->valid("valid_attr_coding8_quads", encode_attribute_coding(quads, options, 8, "coding 8 on quads"), &quads);
  Mesh creased = jittered_textured_grid(12, 12, 107, true);
  creased.attributes.clear();
  add_angle_weighted_normals(&creased, true);
  w->valid("valid_attr_coding8_crease", encode_attribute_coding(creased, options, 8, "coding 8 with a crease"),
           &creased);

  // 15.13's rules on coding 3's path.
  const AttributeChunk chunk(smooth);
  const std::vector<uint8_t>& payload = chunk.payload();
  w->invalid("invalid_attr_coding8_truncated", chunk.with({payload.begin(), payload.end() - 8}),
             ErrorCode::kTruncated);
  std::vector<uint8_t> two = payload;
  two[attr_field_offsets(payload).components] = 2;
  w->invalid("invalid_attr_coding8_two_components", chunk.with(two), ErrorCode::kBadChunkPayload);
  // B = 2: the grid of 4 points a side, the residuals coded for 10 bits land outside it.
  std::vector<uint8_t> coarse = payload;
  coarse[values_offset(payload)] = 2;
  w->invalid("invalid_attr_coding8_value_outside_grid", chunk.with(coarse), ErrorCode::kBadSymbol);
}

// Section 15.11: aTTR mapping 3, what `qmc encode` writes where its stream
// is the smaller; the generator fails if the file's attributes are not all
// per corner with mapping 3.
std::vector<uint8_t> encode_mapping3(const Mesh& mesh, const qmc::EncodeOptions& options, const char* what) {
  std::vector<uint8_t> out;
  qmc::DecodedFile file;
  if (qmc::Status s = qmc::encode(mesh, without_shear(options), &out); !s.ok()) {
    std::fprintf(stderr, "qmc-make-vectors: %s: %s\n", what, s.to_string().c_str());
    std::exit(3);
  }
  bool all = qmc::decode(out.data(), out.size(), &file).ok() && !file.attribute_codings.empty();
  for (const qmc::AttributeCoding& c : file.attribute_codings) all = all && c.mapping == 3;
  if (!all) {
    std::fprintf(stderr, "qmc-make-vectors: %s: not aTTR mapping 3\n", what);
    std::exit(3);
  }
  return out;
}

// A mapping-3 stream (15.11) giving corner k the value truth[k], the vertices
// in `single` single; any truth is coded, so a wrong one makes a bad stream.
std::vector<uint8_t> predicted_mapping_stream(const Mesh& faces, uint64_t value_count, const std::vector<uint32_t>& truth,
                                              const std::vector<uint8_t>& single) {
  qmc::RangeEncoder rc;
  qmc::PredictedMappingModel model;
  qmc::PredictedMapping mapping;
  mapping.reset(uint32_t(faces.vertex_count()), faces.face_sizes, faces.corners);
  uint32_t met = 0;
  qmc::MappingFault fault = qmc::MappingFault::kNone;
  for (size_t k = 0; k < truth.size(); ++k) mapping.code(&rc, &model, k, value_count, &met, truth.data(), &single, &fault);
  return rc.finish();
}

// Per-face values (flat shading): every corner of face f refers to value f,
// the face's unit normal from its first three corners.
void add_face_normals(Mesh* mesh) {
  MeshAttribute normal{"normal", qmc::AttributeKind::kNormal, 3, {}, {}};
  size_t start = 0;
  for (size_t f = 0; f < mesh->face_sizes.size(); ++f) {
    const float* p[3];
    for (int i = 0; i < 3; ++i) p[i] = &mesh->positions[3 * size_t(mesh->corners[start + i])];
    const double a[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double b[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double x : n) normal.values.push_back(float(x / length));
    for (uint32_t i = 0; i < mesh->face_sizes[f]; ++i) normal.corner_values.push_back(uint32_t(f));
    start += mesh->face_sizes[f];
  }
  mesh->attributes.push_back(normal);
}

void write_attribute_mapping3_vectors(VectorWriter* w) {
  using qmc::ErrorCode;
  using namespace qmc::tools;
  qmc::EncodeOptions options;  // what `qmc encode` wrote
  options.mask_contexts = false;  // POSN methods 6 and 7 (14.8) came after these vectors
  options.triangle_twist = false;  // and method 8 (14.9)
  options.mirror_symmetry = false;  // and method 9 (14.10)
  options.attribute_twins = false;  // aTTR coding 9 (15.14) came after these vectors
  options.near_mirror = false;  // and POSN method 10 (14.11)
  options.attribute_guided = false;  // coding 7 (15.12) came after these vectors
  options.angle_weighted_normals = false;  // and coding 8 (15.13)
  options.quad_twist = false;              // and POSN method 5 (14.7)
  // Texture coordinates with seams: charts on a torus of triangles, and on one of quads.
  Mesh textured = perturbed(triangulated(make_torus(20, 8)), 81, 0.004f);
  add_chart_texcoords(&textured);
  const std::vector<uint8_t> texcoords = encode_mapping3(textured, options, "mapping 3 texcoords");
  w->valid("valid_attr_mapping3_texcoords", texcoords, &textured);
  Mesh quads = make_torus(12, 6);
  add_chart_texcoords(&quads);
  w->valid("valid_attr_mapping3_quads", encode_mapping3(quads, options, "mapping 3 on quads"), &quads);
  // Flat shading: a normal per face (15.11's face rule), coding 3 (15.7).
  Mesh flat = perturbed(triangulated(make_refined_sphere(2)), 83, 0.01f);
  add_face_normals(&flat);
  w->valid("valid_attr_mapping3_flat_normals", encode_mapping3(flat, options, "mapping 3 flat normals"), &flat);
  // 15.6: oRDR restores the input's corners with mapping 3.
  qmc::EncodeOptions keep = options;
  keep.keep_order = true;
  w->valid("valid_attr_mapping3_keep_order", encode_mapping3(textured, keep, "mapping 3 kept order"), &textured);

  // 15.11's rules on a cube of 24 corners with exact values (coding 1): its
  // 24 values are one per corner, vertex 0 of several values.
  const std::vector<uint8_t> cube = encode_with(make_cube(), format_1_6_options(), "cube");
  qmc::DecodedFile cube_file;
  (void)qmc::decode(cube.data(), cube.size(), &cube_file);
  std::vector<uint32_t> truth(24);
  for (uint32_t k = 0; k < 24; ++k) truth[k] = k;
  const std::vector<uint8_t> none_single(8, 0);
  AttrFields f;
  f.mapping = 3;
  f.mapping_stream = predicted_mapping_stream(cube_file.mesh, 24, truth, none_single);
  f.rest = exact_values(48);
  w->valid("valid_attr_mapping3_every_corner_new", with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute,
                                                                     attr_payload(f)), nullptr);
  AttrFields cut = f;
  cut.mapping_stream.resize(cut.mapping_stream.size() - 3);
  w->invalid("invalid_attr_mapping3_truncated",
             with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(cut)), ErrorCode::kTruncated);
  AttrFields extra = f;
  extra.mapping_stream.push_back(0x55);
  extra.mapping_stream.push_back(0x55);
  extra.mapping_stream.push_back(0x55);
  extra.mapping_stream.push_back(0x55);
  extra.mapping_stream.push_back(0x55);
  w->invalid("invalid_attr_mapping3_bytes_after_data",
             with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(extra)),
             ErrorCode::kBadChunkPayload);
  // Corner 5 refers to value 6 when 5 values were met: "any value met
  // before" with 3 direct bits past U.
  std::vector<uint32_t> past = truth;
  past[5] = 6;
  AttrFields bad = f;
  bad.mapping_stream = predicted_mapping_stream(cube_file.mesh, 24, past, none_single);
  w->invalid("invalid_attr_mapping3_value_not_met",
             with_chunk_before(cube, qmc::kChunkEnd, qmc::kChunkAttribute, attr_payload(bad)), ErrorCode::kBadSymbol);
}

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: qmc-make-vectors DIR   (writes DIR/MANIFEST and DIR/vectors/*.qmc)\n");
    return 2;
  }
  VectorWriter w(argv[1]);
  write_valid(&w);
  write_container_errors(&w);
  write_order_errors(&w);
  write_connectivity_errors(&w);
  write_position_errors(&w);
  write_quad_valid(&w);
  write_quad_errors(&w);
  write_polygon_valid(&w);
  write_polygon_errors(&w);
  write_input_order_vectors(&w);
  write_polygon_seam_vectors(&w);
  write_loop_vectors(&w);
  write_geometry_image_vectors(&w);
  write_polygon_reading_vectors(&w);
  write_gim_reading_vectors(&w);
  write_hardening_vectors(&w);
  write_predicted_position_valid(&w);
  write_predicted_position_errors(&w);
  write_context_coded_valid(&w);
  write_context_coded_errors(&w);
  write_attribute_valid(&w);
  write_attribute_errors(&w);
  write_octahedral_normal_vectors(&w);
  write_face_label_vectors(&w);
  write_attribute_review_vectors(&w);
  write_posn3_vectors(&w);
  write_posn4_vectors(&w);
  write_attribute_coding4_vectors(&w);
  write_attribute_coding56_vectors(&w);
  write_attribute_mapping3_vectors(&w);
  write_attribute_coding7_vectors(&w);
  write_attribute_coding8_vectors(&w);
  write_attribute_coding9_vectors(&w);
  write_posn5_vectors(&w);
  write_posn6_vectors(&w);
  write_posn8_vectors(&w);
  write_posn9_vectors(&w);
  write_posn10_vectors(&w);
  write_levl4_vectors(&w);
  write_posn11_vectors(&w);
  write_posn12_vectors(&w);
  write_posn13_vectors(&w);
  write_coding8_vectors(&w);
  write_posn14_vectors(&w);
  w.finish();
  return 0;
}
