// The oRDR chunk of spec section 4.5: encoding with keep_order restores the
// input's order exactly through every coder, decoders that skip the chunk
// get the coder order, and invalid payloads are rejected with 4.5's errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "common/bit_writer.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"
#include "decoder/order_decoder.h"
#include "mesh_generators.h"
#include "qmc/decoder.h"
#include "qmc/encoder.h"
#include "common/byte_io.h"
#include "chunk_list.h"
#include "roundtrip_check.h"
#include "splitmix64.h"

namespace qmc {
namespace {

using tools::Chunk;
using tools::join_chunks;
using tools::split_chunks;

std::vector<uint8_t> encode_mesh(const Mesh& mesh, bool keep_order,
                                 ConnectivityChoice connectivity = ConnectivityChoice::kAuto,
                                 EncodeStats* stats = nullptr) {
  EncodeOptions options;
  options.keep_order = keep_order;
  options.connectivity = connectivity;
  std::vector<uint8_t> out;
  const Status s = encode(mesh, options, &out, stats);
  EXPECT_TRUE(s.ok()) << s.to_string();
  return out;
}

bool has_order_chunk(const std::vector<uint8_t>& file) {
  for (const Chunk& c : split_chunks(file))
    if (c.type == kChunkOrder) return true;
  return false;
}


// Decodes `file` and expects exactly the input: same face sizes and corners,
// positions within the quantization bound, in the input's own order.
void expect_input_order(const Mesh& input, const std::vector<uint8_t>& file, const std::string& what) {
  DecodedFile d;
  const Status s = decode(file.data(), file.size(), &d);
  ASSERT_TRUE(s.ok()) << what << ": " << s.to_string();
  EXPECT_EQ(d.mesh.face_sizes, input.face_sizes) << what;
  EXPECT_EQ(d.mesh.corners, input.corners) << what;
  EXPECT_EQ(d.order_restored, has_order_chunk(file)) << what;
  const tools::RoundTripReport r = tools::check_round_trip(input, d, tools::identity_correspondence(input));
  EXPECT_TRUE(r.ok()) << what << ": " << r.face_mismatch << r.position_mismatch;
  EXPECT_TRUE(tools::check_round_trip(input, d).ok()) << what;  // what qmc verify runs
  // The same through the streaming decoder, one byte at a time (spec 3.5).
  StreamDecoder stream;
  for (uint8_t b : file) ASSERT_TRUE(stream.feed(&b, 1).ok()) << what;
  ASSERT_TRUE(stream.finish().ok()) << what;
  EXPECT_EQ(canonical_output(stream.file()), canonical_output(d)) << what;
}

TEST(Order, QuadCoderMeshesComeBackInInputOrder) {
  for (int n = 1; n <= 6; ++n) {
    const Mesh sphere = tools::make_quad_sphere(n);
    EncodeStats stats;
    const std::vector<uint8_t> file = encode_mesh(sphere, true, ConnectivityChoice::kQuad, &stats);
    EXPECT_EQ(stats.method, ConnectivityMethod::kQuad);
    EXPECT_TRUE(has_order_chunk(file)) << n;  // the traversal reorders the sphere
    expect_input_order(sphere, file, "quad sphere " + std::to_string(n));
    const Mesh shuffled = tools::make_scrambled(sphere, uint64_t(n));
    expect_input_order(shuffled, encode_mesh(shuffled, true, ConnectivityChoice::kQuad),
                       "scrambled quad sphere " + std::to_string(n));
  }
  for (int levels = 0; levels <= 2; ++levels) {
    const Mesh sphere = tools::make_refined_sphere(levels);
    expect_input_order(sphere, encode_mesh(sphere, true, ConnectivityChoice::kQuad),
                       "refined sphere " + std::to_string(levels));
  }
  const Mesh grid = tools::make_grid(9, 5);  // one boundary
  expect_input_order(grid, encode_mesh(grid, true, ConnectivityChoice::kQuad), "grid");
  Mesh cube = tools::make_cube();  // unreferenced vertices get the last labels
  cube.positions.insert(cube.positions.begin(), {9, 9, 9, -9, 9, 9});
  for (uint32_t& v : cube.corners) v += 2;
  expect_input_order(cube, encode_mesh(cube, true, ConnectivityChoice::kQuad), "cube with unreferenced vertices");
}

TEST(Order, IndexedAndAutoCodersComeBackInInputOrder) {
  tools::RandomSoupOptions options;
  options.vertices = 300;
  options.faces = 400;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const Mesh soup = tools::make_random_soup(seed, options);  // repeated corners, unreferenced vertices
    for (ConnectivityChoice c : {ConnectivityChoice::kIndexed, ConnectivityChoice::kAuto})
      expect_input_order(soup, encode_mesh(soup, true, c), "soup " + std::to_string(seed));
  }
  const Mesh torus = tools::make_scrambled(tools::make_torus(16, 8), 5);
  for (ConnectivityChoice c : {ConnectivityChoice::kIndexed, ConnectivityChoice::kAuto})
    expect_input_order(torus, encode_mesh(torus, true, c), "scrambled torus");
  const Mesh prism = tools::make_scrambled(tools::make_prism(12), 6);
  expect_input_order(prism, encode_mesh(prism, true), "scrambled prism");
  const Mesh empty;
  expect_input_order(empty, encode_mesh(empty, true), "empty mesh");
}

TEST(Order, NoChunkWhenTheCoderOrderIsTheInputOrder) {
  // The indexed coding keeps faces and corners; vertices numbered by first
  // reference keep their labels too (spec 5.2.1): nothing to restore.
  const Mesh tetra = tools::make_tetrahedron();
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_mesh(tetra, true, ConnectivityChoice::kIndexed, &stats);
  EXPECT_FALSE(has_order_chunk(file));
  for (const ChunkStats& c : stats.chunks) EXPECT_NE(c.type, kChunkOrder);
  EXPECT_EQ(file, encode_mesh(tetra, false, ConnectivityChoice::kIndexed));
  expect_input_order(tetra, file, "tetrahedron");
}

TEST(Order, IndexedCoderNeedsOnlyTheVertexMap) {
  const Mesh soup = tools::make_random_soup(3, tools::RandomSoupOptions{});
  const std::vector<uint8_t> file = encode_mesh(soup, true, ConnectivityChoice::kIndexed);
  DecodedFile d;
  ASSERT_TRUE(decode(file.data(), file.size(), &d).ok());
  EXPECT_TRUE(d.order_restored);
  EXPECT_EQ(d.order_flags, kOrderVertices);
}

TEST(Order, ChunkSitsAfterPosnAndIsCountedInStats) {
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_mesh(tools::make_quad_sphere(3), true, ConnectivityChoice::kQuad, &stats);
  const std::vector<Chunk> chunks = split_chunks(file);
  ASSERT_GE(chunks.size(), 5u);
  EXPECT_EQ(chunks[chunks.size() - 3].type, kChunkPositions);
  EXPECT_EQ(chunks[chunks.size() - 2].type, kChunkOrder);
  EXPECT_EQ(chunks.back().type, kChunkEnd);
  bool counted = false;
  for (const ChunkStats& c : stats.chunks)
    if (c.type == kChunkOrder) {
      counted = true;
      EXPECT_EQ(c.bytes, 12 + chunks[chunks.size() - 2].payload.size());
    }
  EXPECT_TRUE(counted);
  EXPECT_EQ(stats.total_bytes, file.size());
  EXPECT_FALSE(chunk_is_critical(kChunkOrder));
}

TEST(Order, DecoderWithoutOrderGetsTheCoderOrder) {
  // A decoder that does not know oRDR skips it (spec 3.3). Stripping the
  // chunk gives exactly the file written without keep_order.
  const Mesh sphere = tools::make_scrambled(tools::make_quad_sphere(4), 11);
  EncodeStats stats;
  const std::vector<uint8_t> plain = encode_mesh(sphere, false, ConnectivityChoice::kAuto, &stats);
  std::vector<Chunk> chunks = split_chunks(encode_mesh(sphere, true));
  chunks.erase(std::remove_if(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.type == kChunkOrder; }),
               chunks.end());
  EXPECT_EQ(join_chunks(chunks), plain);
  DecodedFile d;
  ASSERT_TRUE(decode(plain.data(), plain.size(), &d).ok());
  EXPECT_FALSE(d.order_restored);
  EXPECT_NE(d.mesh.corners, sphere.corners);
  const tools::RoundTripReport r =
      tools::check_round_trip(sphere, d, tools::Correspondence{stats.file_vertex, stats.face_source});
  EXPECT_TRUE(r.ok()) << r.face_mismatch;
  // Renamed to an unknown ancillary type, the chunk is skipped: coder order again.
  chunks = split_chunks(encode_mesh(sphere, true));
  for (Chunk& c : chunks)
    if (c.type == kChunkOrder) c.type = chunk_type('o', 'R', 'D', 'X');
  DecodedFile skipped;
  const std::vector<uint8_t> renamed = join_chunks(chunks);
  ASSERT_TRUE(decode(renamed.data(), renamed.size(), &skipped).ok());
  EXPECT_EQ(canonical_output(skipped), canonical_output(d));
}

TEST(Order, StreamingShowsCoderOrderUntilTheChunkArrives) {
  const Mesh sphere = tools::make_quad_sphere(3);
  const std::vector<uint8_t> file = encode_mesh(sphere, true, ConnectivityChoice::kQuad);
  const std::vector<Chunk> chunks = split_chunks(file);
  size_t before_order = 8;
  for (const Chunk& c : chunks) {
    if (c.type == kChunkOrder) break;
    before_order += 12 + c.payload.size();
  }
  StreamDecoder stream;
  ASSERT_TRUE(stream.feed(file.data(), before_order).ok());
  EXPECT_TRUE(stream.has_positions());
  EXPECT_FALSE(stream.file().order_restored);
  EXPECT_NE(stream.file().mesh.corners, sphere.corners);
  ASSERT_TRUE(stream.feed(file.data() + before_order, file.size() - before_order).ok());
  ASSERT_TRUE(stream.finish().ok());
  EXPECT_TRUE(stream.file().order_restored);
  EXPECT_EQ(stream.file().mesh.corners, sphere.corners);
}

TEST(Order, SpecExampleRotation) {
  // Spec 4.5: file face (5, 8, 2, 7), rotation 1, face_input 3, vertex_input
  // 5, 8, 2, 7 -> 50, 80, 20, 70: output face 3 is (80, 20, 70, 50).
  Mesh mesh;
  mesh.positions.assign(3 * 100, 0.f);
  mesh.face_sizes.assign(4, 4);
  mesh.corners = {5, 8, 2, 7, 0, 1, 3, 4, 6, 9, 10, 11, 12, 13, 14, 15};
  OrderMaps maps;
  maps.vertex_input.resize(100);
  for (uint32_t v = 0; v < 100; ++v) maps.vertex_input[v] = v;
  std::swap(maps.vertex_input[5], maps.vertex_input[50]);
  std::swap(maps.vertex_input[8], maps.vertex_input[80]);
  std::swap(maps.vertex_input[2], maps.vertex_input[20]);
  std::swap(maps.vertex_input[7], maps.vertex_input[70]);
  maps.face_input = {3, 0, 1, 2};
  maps.rotation = {1, 0, 0, 0};
  apply_order(maps, &mesh, nullptr);
  EXPECT_EQ(std::vector<uint32_t>(mesh.corners.begin() + 12, mesh.corners.end()),
            (std::vector<uint32_t>{80, 20, 70, 50}));
}

// --- invalid payloads ------------------------------------------------------

// A file of `mesh` (indexed coding, so the coder order is known) with `payload` as its oRDR.
class InvalidOrder : public ::testing::Test {
 protected:
  void SetUp() override {
    mesh_ = tools::make_cube();  // 8 vertices, 6 quads, vertices in first-reference order
    chunks_ = split_chunks(encode_mesh(mesh_, false, ConnectivityChoice::kIndexed));
  }
  ErrorCode decode_with(const std::vector<uint8_t>& payload, size_t position = 3) {
    std::vector<Chunk> c = chunks_;  // QHDR CONN POSN QEND
    c.insert(c.begin() + long(position), Chunk{kChunkOrder, payload});
    const std::vector<uint8_t> file = join_chunks(c);
    DecodedFile d;
    return decode(file.data(), file.size(), &d).code();
  }
  static std::vector<uint8_t> header(uint64_t v, uint64_t f, uint8_t flags) {
    std::vector<uint8_t> p;
    put_varint(&p, v);
    put_varint(&p, f);
    p.push_back(flags);
    return p;
  }
  static std::vector<uint8_t> with_stream(std::vector<uint8_t> p, const std::function<void(BitWriter*)>& body) {
    BitWriter bits;
    body(&bits);
    const std::vector<uint8_t> stream = bits.finish();
    p.insert(p.end(), stream.begin(), stream.end());
    return p;
  }
  // Values as the differences of spec 4.5 (any values: not necessarily a permutation).
  static void write_values(BitWriter* bits, const std::vector<int64_t>& values) {
    std::vector<uint64_t> freq(kMagnitudeClasses, 0);
    int64_t previous = -1;
    for (int64_t v : values) {
      const int64_t e = v - previous - 1;
      ++freq[magnitude_class(uint32_t(e < 0 ? -e : e))];
      previous = v;
    }
    const std::vector<uint8_t> lengths = huffman_code_lengths(freq);
    write_code_lengths(bits, lengths);
    HuffmanEncoder code(lengths);
    previous = -1;
    for (int64_t v : values) {
      const int64_t e = v - previous - 1;
      const uint32_t m = uint32_t(e < 0 ? -e : e);
      const int c = magnitude_class(m);
      code.write(bits, uint32_t(c));
      if (c > 0) bits->write_bit(e < 0);
      write_magnitude_extra(bits, m, c);
      previous = v;
    }
  }
  static void write_rotations(BitWriter* bits, const std::vector<uint32_t>& offsets) {
    std::vector<uint64_t> freq(kMagnitudeClasses, 0);
    for (uint32_t s : offsets) ++freq[magnitude_class(s)];
    const std::vector<uint8_t> lengths = huffman_code_lengths(freq);
    write_code_lengths(bits, lengths);
    HuffmanEncoder code(lengths);
    for (uint32_t s : offsets) {
      code.write(bits, uint32_t(magnitude_class(s)));
      write_magnitude_extra(bits, s, magnitude_class(s));
    }
  }
  std::vector<uint8_t> faces_payload(const std::vector<int64_t>& values) const {
    return with_stream(header(8, 6, kOrderFaces), [&](BitWriter* b) { write_values(b, values); });
  }
  Mesh mesh_;
  std::vector<Chunk> chunks_;
};

TEST_F(InvalidOrder, ValidHandMadePayloadsDecode) {
  EXPECT_EQ(decode_with(faces_payload({5, 4, 3, 2, 1, 0})), ErrorCode::kOk);
  EXPECT_EQ(decode_with(header(8, 6, 0)), ErrorCode::kOk);  // flags 0: identity, accepted
  EXPECT_EQ(decode_with(with_stream(header(8, 6, kOrderRotations),
                                    [&](BitWriter* b) { write_rotations(b, {0, 1, 2, 3, 3, 0}); })),
            ErrorCode::kOk);
  EXPECT_EQ(decode_with(with_stream(header(8, 6, kOrderVertices),
                                    [&](BitWriter* b) { write_values(b, {7, 6, 5, 4, 3, 2, 1, 0}); })),
            ErrorCode::kOk);
}

TEST_F(InvalidOrder, CountsMustMatchConn) {
  EXPECT_EQ(decode_with(header(9, 6, 0)), ErrorCode::kBadChunkPayload);
  EXPECT_EQ(decode_with(header(8, 5, 0)), ErrorCode::kBadChunkPayload);
  EXPECT_EQ(decode_with({}), ErrorCode::kBadChunkPayload);
  EXPECT_EQ(decode_with({8, 6}), ErrorCode::kBadChunkPayload);          // flags missing
  EXPECT_EQ(decode_with({0x88, 0x00, 6, 0}), ErrorCode::kBadChunkPayload);  // varint not shortest
}

TEST_F(InvalidOrder, FlagsAndEmptyMaps) {
  EXPECT_EQ(decode_with(header(8, 6, 8)), ErrorCode::kBadChunkPayload);
  EXPECT_EQ(decode_with(header(8, 6, 0x80)), ErrorCode::kBadChunkPayload);
  std::vector<uint8_t> p = header(8, 6, 0);
  p.push_back(0);
  EXPECT_EQ(decode_with(p), ErrorCode::kBadChunkPayload);  // flags 0 with a stream
  // A flag set for zero elements: a mesh of points only.
  Mesh points;
  points.positions = {0, 0, 0, 1, 1, 1};
  std::vector<Chunk> c = split_chunks(encode_mesh(points, false, ConnectivityChoice::kIndexed));
  c.insert(c.end() - 1, Chunk{kChunkOrder, with_stream(header(2, 0, kOrderFaces), [](BitWriter* b) {
                                write_code_lengths(b, {1});
                              })});
  const std::vector<uint8_t> file = join_chunks(c);
  DecodedFile d;
  EXPECT_EQ(decode(file.data(), file.size(), &d).code(), ErrorCode::kBadChunkPayload);
}

TEST_F(InvalidOrder, NotAPermutation) {
  EXPECT_EQ(decode_with(faces_payload({0, 1, 2, 2, 4, 5})), ErrorCode::kBadSymbol);  // repeat
  EXPECT_EQ(decode_with(faces_payload({0, 1, 2, 3, 4, 6})), ErrorCode::kBadSymbol);  // beyond F - 1
  EXPECT_EQ(decode_with(faces_payload({1, 0, -1, 2, 3, 4})), ErrorCode::kBadSymbol);  // negative
  EXPECT_EQ(decode_with(with_stream(header(8, 6, kOrderVertices),
                                    [&](BitWriter* b) { write_values(b, {0, 1, 2, 3, 4, 5, 6, 0}); })),
            ErrorCode::kBadSymbol);
  EXPECT_EQ(decode_with(with_stream(header(8, 6, kOrderVertices),
                                    [&](BitWriter* b) { write_values(b, {0, 1, 2, 3, 4, 5, 6, 8}); })),
            ErrorCode::kBadSymbol);
}

TEST_F(InvalidOrder, RotationOutOfRange) {
  EXPECT_EQ(decode_with(with_stream(header(8, 6, kOrderRotations),
                                    [&](BitWriter* b) { write_rotations(b, {0, 1, 2, 4, 0, 0}); })),
            ErrorCode::kBadSymbol);
}

TEST_F(InvalidOrder, TruncatedAndUnjustified) {
  // The sixth value's last extra bit lies past the end of the stream.
  const std::vector<uint8_t> cut = with_stream(header(8, 6, kOrderFaces), [&](BitWriter* b) {
    write_code_lengths(b, {1, 0, 0, 1});  // class 0: '0', class 3: '1' + sign + 2 extra bits
    int zeros = 0;
    while ((b->bit_count() + 3) % 8 != 0) {  // values 0, 1, ... (e = 0)
      b->write_bit(false);
      ++zeros;
    }
    ASSERT_LT(zeros, 6);
    b->write_bits(0b100, 3);  // class 3, positive, first of its two extra bits
  });
  EXPECT_EQ(decode_with(cut), ErrorCode::kTruncated);
  // 6 values cannot fit in one byte of stream: limit_exceeded before the table.
  std::vector<uint8_t> p = header(8, 6, kOrderFaces | kOrderRotations);
  p.push_back(0);
  EXPECT_EQ(decode_with(p), ErrorCode::kLimitExceeded);
}

TEST_F(InvalidOrder, BadTablesCodeWordsAndPadding) {
  EXPECT_EQ(decode_with(with_stream(header(8, 6, kOrderFaces),
                                    [](BitWriter* b) {
                                      write_code_lengths(b, {1, 1, 1});  // over-subscribed
                                      b->write_bits(0, 8);
                                    })),
            ErrorCode::kBadHuffmanTable);
  EXPECT_EQ(decode_with(with_stream(header(8, 6, kOrderFaces),
                                    [](BitWriter* b) {
                                      write_code_lengths(b, {1});  // single code word '0'
                                      b->write_bits(0, 2);
                                      b->write_bits(1, 1);  // '1' is no code word
                                      b->write_bits(0, 8);
                                    })),
            ErrorCode::kBadSymbol);
  std::vector<uint8_t> p = faces_payload({5, 4, 3, 2, 1, 0});
  p.back() |= 1;  // a padding bit set (the stream does not end on a byte boundary)
  EXPECT_EQ(decode_with(p), ErrorCode::kBadChunkPayload);
  p = faces_payload({5, 4, 3, 2, 1, 0});
  p.push_back(0);
  EXPECT_EQ(decode_with(p), ErrorCode::kBadChunkPayload);
}

TEST_F(InvalidOrder, PlacementRules) {
  const std::vector<uint8_t> good = faces_payload({5, 4, 3, 2, 1, 0});
  EXPECT_EQ(decode_with(good, 3), ErrorCode::kOk);
  EXPECT_EQ(decode_with(good, 2), ErrorCode::kChunkOrder);  // before POSN
  EXPECT_EQ(decode_with(good, 1), ErrorCode::kChunkOrder);  // before CONN
  std::vector<Chunk> c = chunks_;
  c.insert(c.begin() + 3, Chunk{kChunkOrder, good});
  c.insert(c.begin() + 3, Chunk{kChunkOrder, good});
  const std::vector<uint8_t> twice = join_chunks(c);
  DecodedFile d;
  EXPECT_EQ(decode(twice.data(), twice.size(), &d).code(), ErrorCode::kChunkOrder);
}

TEST_F(InvalidOrder, InvalidChunkIsAnErrorNotIgnored) {
  // Even a broken ancillary oRDR rejects the whole file (spec 4.5).
  std::vector<Chunk> c = chunks_;
  c.insert(c.begin() + 3, Chunk{kChunkOrder, faces_payload({0, 0, 0, 0, 0, 0})});
  const std::vector<uint8_t> file = join_chunks(c);
  DecodedFile d;
  EXPECT_FALSE(decode(file.data(), file.size(), &d).ok());
  StreamDecoder stream;
  EXPECT_FALSE(stream.feed(file.data(), file.size()).ok());
}

// Section 4.5: input face face_input[f] is file face f, its labels mapped by
// vertex_input, starting at the file face's corner rotation[f]; a map the
// flags leave out is the identity.
void expect_faces_moved_as_the_maps_say(const Mesh& file, const OrderMaps& maps, const Mesh& input) {
  ASSERT_EQ(input.face_count(), file.face_count());
  const auto vertex = [&](uint32_t v) { return maps.vertex_input.empty() ? v : maps.vertex_input[v]; };
  std::vector<size_t> input_start(input.face_count() + 1, 0);
  for (size_t g = 0; g < input.face_count(); ++g) input_start[g + 1] = input_start[g] + input.face_sizes[g];
  size_t file_start = 0;
  for (size_t f = 0; f < file.face_count(); ++f) {
    const uint32_t d = file.face_sizes[f];
    const size_t g = maps.face_input.empty() ? f : maps.face_input[f];
    const uint32_t r = maps.rotation.empty() ? 0 : maps.rotation[f];
    ASSERT_EQ(input.face_sizes[g], d) << "face " << f;
    for (uint32_t i = 0; i < d; ++i)
      EXPECT_EQ(input.corners[input_start[g] + i], vertex(file.corners[file_start + (r + i) % d]))
          << "face " << f << " corner " << i;
    file_start += d;
  }
}

TEST(Order, RandomPayloadsAreRejectedOrApplied) {
  // Bytes after a valid header: whatever decodes must be a valid set of maps.
  const Mesh sphere = tools::make_quad_sphere(2);
  std::vector<uint8_t> f = encode_mesh(sphere, false, ConnectivityChoice::kQuad);
  DecodedFile coder;
  ASSERT_TRUE(decode(f.data(), f.size(), &coder).ok());
  tools::SplitMix64 rng(42);
  int accepted = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<uint8_t> p;
    put_varint(&p, sphere.vertex_count());
    put_varint(&p, sphere.face_count());
    p.push_back(uint8_t(1 + rng.below(7)));
    const uint32_t n = rng.below(200);
    for (uint32_t i = 0; i < n; ++i) p.push_back(uint8_t(rng.below(4) == 0 ? rng.below(256) : rng.below(3)));
    OrderMaps maps;
    if (!decode_order(p.data(), p.size(), uint32_t(sphere.vertex_count()), coder.mesh, &maps).ok()) continue;
    ++accepted;
    Mesh m = coder.mesh;
    apply_order(maps, &m, nullptr);
    expect_faces_moved_as_the_maps_say(coder.mesh, maps, m);
  }
  SUCCEED() << accepted << " random payloads accepted";
}

TEST(Order, MapsOfRealFilesMoveEveryFaceAsSection45Says) {
  for (uint64_t seed : {1, 2, 3}) {
    const Mesh scrambled = tools::make_scrambled(tools::make_quad_sphere(3), seed);
    const std::vector<Chunk> chunks = split_chunks(encode_mesh(scrambled, true));
    const std::vector<uint8_t> order = chunks[tools::find_chunk(chunks, kChunkOrder)].payload;
    DecodedFile coder;
    const std::vector<uint8_t> plain = encode_mesh(scrambled, false);
    ASSERT_TRUE(decode(plain.data(), plain.size(), &coder).ok());
    OrderMaps maps;
    ASSERT_TRUE(decode_order(order.data(), order.size(), uint32_t(scrambled.vertex_count()), coder.mesh, &maps).ok());
    Mesh m = coder.mesh;
    apply_order(maps, &m, nullptr);
    expect_faces_moved_as_the_maps_say(coder.mesh, maps, m);
    EXPECT_EQ(m.corners, scrambled.corners) << "seed " << seed;  // and that is the input
  }
}

}  // namespace
}  // namespace qmc
