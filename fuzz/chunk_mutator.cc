// See chunk_mutator.h. The chunk framing of spec 3.2 is written here only;
// the CRC is src/common's.
#include "chunk_mutator.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <limits>

#include "common/byte_io.h"
#include "common/crc32.h"
#include "qmc/format.h"

namespace qmc::fuzz {
namespace {

constexpr size_t kSignatureSize = 8;
constexpr size_t kChunkFrameSize = 12;  // type, length, CRC (spec 3.2)

using K = FieldKind;

// The leading fields of each chunk type, in payload order. GIMG lists its
// first plane entry (format 0); CONN lists flags and coding of methods 1 and
// 2 (bit-stream bytes for method 0, harmless to rewrite).
struct HeaderLayout {
  uint32_t type;
  std::vector<FieldKind> fields;
  bool varints_follow;  // GSEM: five varints per run after run_count
};

const std::vector<HeaderLayout>& header_layouts() {
  static const std::vector<HeaderLayout> layouts = {
      {kChunkHeader, {K::kU8, K::kU8}, false},                                          // 4.1
      {kChunkConnectivity, {K::kU8, K::kVarint, K::kVarint, K::kU8, K::kU8}, false},    // 5.1, 5.3.2, 5.4.1
      {kChunkPositions, {K::kVarint, K::kU8, K::kF32, K::kF32, K::kF32, K::kF32, K::kF32, K::kF32}, false},  // 6.3
      {kChunkOrder, {K::kVarint, K::kVarint, K::kU8}, false},                           // 4.5
      {kChunkLoop, {K::kU8, K::kU8}, false},                                            // 12.1
      {kChunkLevel, {K::kU8, K::kU8, K::kVarint, K::kF64}, false},                      // 12.1
      {kChunkGeometryImage,
       {K::kVarint, K::kVarint, K::kU8, K::kU8, K::kU8, K::kU8, K::kU8, K::kF64, K::kF64},
       false},                                                                          // 13.2
      {kChunkGimSeams, {K::kVarint}, true},                                             // 13.7
      {kChunkGimFaces, {K::kVarint}, false},                                            // 13.8
      {kChunkGimPlane, {K::kU8}, false},                                                // 13.5.1
  };
  return layouts;
}

// Every type of spec 3.3, plus an unknown critical and an unknown ancillary
// type (3.3's skip-or-reject rule).
const uint32_t kKnownTypes[] = {
    kChunkHeader,        kChunkConnectivity, kChunkPositions, kChunkEnd,      kChunkText,
    kChunkOrder,         kChunkLoop,         kChunkLevel,     kChunkGeometryImage, kChunkGimMask,
    kChunkGimSeams,      kChunkGimFaces,     kChunkGimPlane,  chunk_type('Q', 'Z', 'Z', 'Z'),
    chunk_type('q', 'z', 'z', 'z')};

// A payload that passes the chunk's first checks, for inserting a chunk the
// input does not have yet (e.g. LOOP into a method-0 file).
std::vector<uint8_t> minimal_payload(uint32_t type) {
  if (type == kChunkHeader) return {kFormatMajor, kFormatMinor};
  if (type == kChunkLoop) return {1, 0};  // one level, scheme 0
  if (type == kChunkGimPlane) return {0};  // predictor 0, empty stream
  if (type == kChunkText) return {'k', '=', 'v'};
  return {};
}

bool read_field(ByteReader* in, FieldKind kind, uint64_t* value) {
  switch (kind) {
    case K::kU8: {
      uint8_t v = 0;
      if (!in->get_u8(&v)) return false;
      *value = v;
      return true;
    }
    case K::kVarint:
      return in->get_varint(value);
    case K::kF32: {
      float v = 0;
      if (!in->get_f32le(&v)) return false;
      uint32_t bits = 0;
      std::memcpy(&bits, &v, 4);
      *value = bits;
      return true;
    }
    case K::kF64: {
      double v = 0;
      if (!in->get_f64le(&v)) return false;
      std::memcpy(value, &v, 8);
      return true;
    }
  }
  return false;
}

std::vector<uint8_t> encode_field(FieldKind kind, uint64_t value) {
  std::vector<uint8_t> bytes;
  switch (kind) {
    case K::kU8:
      put_u8(&bytes, uint8_t(value));
      break;
    case K::kVarint:
      put_varint(&bytes, value);
      break;
    case K::kF32:
      put_u32le(&bytes, uint32_t(value));
      break;
    case K::kF64:
      put_u32le(&bytes, uint32_t(value));
      put_u32le(&bytes, uint32_t(value >> 32));
      break;
  }
  return bytes;
}

const Chunk* find_chunk(const FramedInput& input, uint32_t type) {
  for (const Chunk& c : input.chunks)
    if (c.type == type) return &c;
  return nullptr;
}

// Counts that decide allocations sit right at or just past a limit: the
// justification rules of 13.3 / 13.6 (512 (L + 1)), bits of the payload
// (6.3, 12.1), W H and 2 W H of the image (13.7, 13.8), the other counts of
// the file, powers of two and the sizes of issue #12's memory bombs.
std::vector<uint64_t> interesting_counts(const FramedInput& input, const Chunk& chunk, uint64_t old) {
  const uint64_t length = chunk.payload.size();
  std::vector<uint64_t> values = {0,          1,          2,          3,           4096,      65535,
                                  65536,      1u << 24,   20'000'000, 200'000'000, 0x7FFFFFFF, 0x80000000,
                                  0xFFFFFFFF, 1ull << 32, old + 1,    old - 1,     old * 2,   old / 2,
                                  length,     length + 1, 8 * length, 8 * length + 1, 512 * (length + 1),
                                  512 * (length + 1) + 1};
  for (uint32_t type : {kChunkConnectivity, kChunkGeometryImage}) {
    const Chunk* c = find_chunk(input, type);
    if (c == nullptr) continue;
    const std::vector<HeaderField> fields = header_fields(*c);
    const size_t first = type == kChunkConnectivity ? 1 : 0;  // V, F or W, H
    if (fields.size() < first + 2) continue;
    const uint64_t a = fields[first].value, b = fields[first + 1].value;
    values.insert(values.end(), {a, b, a + 1, b + 1});
    if (type == kChunkGeometryImage)
      values.insert(values.end(), {a * b, a * b - 1, a * b + 1, a * b / 2, 2 * a * b, 2 * a * b + 1});
  }
  return values;
}

const uint8_t kInterestingBytes[] = {0, 1, 2, 3, 4, 5, 7, 8, 15, 16, 17, 0x7F, 0x80, 0xFE, 0xFF};

uint64_t interesting_float_bits(FieldKind kind, size_t index) {
  const double doubles[] = {0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, 1e300,
                            std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::denorm_min()};
  const double d = doubles[index % std::size(doubles)];
  if (kind == K::kF64) {
    uint64_t bits = 0;
    std::memcpy(&bits, &d, 8);
    return bits;
  }
  const float f = float(d);
  uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  return bits;
}

}  // namespace

FramedInput split_chunks(const uint8_t* data, size_t size, size_t prefix_size) {
  FramedInput input;
  const size_t prefix = std::min(prefix_size, size);
  input.prefix.assign(data, data + prefix);
  const size_t signature_end = std::min(size, prefix + kSignatureSize);
  input.signature.assign(data + prefix, data + signature_end);
  size_t pos = signature_end;
  while (size - pos >= kChunkFrameSize) {
    const uint32_t length = load_u32le(data + pos + 4);
    if (length > size - pos - kChunkFrameSize) break;
    const uint8_t* payload = data + pos + 8;
    input.chunks.push_back({load_u32be(data + pos), std::vector<uint8_t>(payload, payload + length)});
    pos += kChunkFrameSize + length;
  }
  input.tail.assign(data + pos, data + size);
  return input;
}

std::vector<uint8_t> frame_chunks(const FramedInput& input) {
  std::vector<uint8_t> out(input.prefix);
  out.insert(out.end(), input.signature.begin(), input.signature.end());
  for (const Chunk& chunk : input.chunks) {
    const size_t start = out.size();
    put_u32be(&out, chunk.type);
    put_u32le(&out, uint32_t(chunk.payload.size()));
    out.insert(out.end(), chunk.payload.begin(), chunk.payload.end());
    put_u32le(&out, crc32(out.data() + start, out.size() - start));
  }
  out.insert(out.end(), input.tail.begin(), input.tail.end());
  return out;
}

void repair_crcs(uint8_t* data, size_t size, size_t prefix_size) {
  size_t pos = std::min(size, prefix_size + kSignatureSize);
  while (size - pos >= kChunkFrameSize) {
    const uint32_t length = load_u32le(data + pos + 4);
    if (length > size - pos - kChunkFrameSize) break;
    const uint32_t crc = crc32(data + pos, 8 + size_t(length));
    for (size_t k = 0; k < 4; ++k) data[pos + 8 + length + k] = uint8_t(crc >> (8 * k));  // u32le
    pos += kChunkFrameSize + length;
  }
}

std::vector<HeaderField> header_fields(const Chunk& chunk) {
  std::vector<HeaderField> fields;
  const auto layout = std::find_if(header_layouts().begin(), header_layouts().end(),
                                   [&](const HeaderLayout& l) { return l.type == chunk.type; });
  if (layout == header_layouts().end()) return fields;
  constexpr size_t kMaxFollowingVarints = 64;  // enough runs of GSEM to reach its limits
  ByteReader in(chunk.payload.data(), chunk.payload.size());
  const size_t count = layout->fields.size() + (layout->varints_follow ? kMaxFollowingVarints : 0);
  for (size_t i = 0; i < count; ++i) {
    HeaderField field;
    field.offset = in.position();
    field.kind = i < layout->fields.size() ? layout->fields[i] : K::kVarint;
    if (!read_field(&in, field.kind, &field.value)) break;
    field.size = in.position() - field.offset;
    fields.push_back(field);
  }
  return fields;
}

void set_header_field(Chunk* chunk, const HeaderField& field, uint64_t value) {
  const std::vector<uint8_t> bytes = encode_field(field.kind, value);
  std::vector<uint8_t>& p = chunk->payload;
  p.erase(p.begin() + field.offset, p.begin() + field.offset + field.size);
  p.insert(p.begin() + field.offset, bytes.begin(), bytes.end());
}

size_t ChunkMutator::mutate(uint8_t* data, size_t size, size_t max_size, unsigned seed) {
  random_.seed(seed);
  const size_t strategy = pick(16);
  // 1 in 16: libFuzzer's own mutation, CRCs left broken (truncation, bad
  // lengths, bad types and bad CRCs stay reachable); 3 in 16: the same with
  // the CRCs repaired.
  if (strategy == 0) return mutate_whole(data, size, max_size, false);
  if (strategy < 4) return mutate_whole(data, size, max_size, true);
  FramedInput input = split_chunks(data, size, prefix_size_);
  if (input.chunks.empty()) return mutate_whole(data, size, max_size, true);
  if (!input.prefix.empty() && pick(8) == 0) input.prefix[pick(input.prefix.size())] = uint8_t(random_());
  bool changed = false;
  if (strategy < 9)
    changed = mutate_header_field(&input);
  else if (strategy < 14)
    changed = mutate_payload_bytes(&input, max_size > size ? max_size - size : 0);
  else
    changed = mutate_chunk_list(&input);
  const std::vector<uint8_t> out = frame_chunks(input);
  if (!changed || out.size() > max_size) return mutate_whole(data, size, max_size, true);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

size_t ChunkMutator::mutate_whole(uint8_t* data, size_t size, size_t max_size, bool fix_crcs) {
  if (size == 0 && max_size > 0) data[size++] = uint8_t(random_());
  size = mutate_bytes_(data, size, max_size);
  if (fix_crcs) repair_crcs(data, size, prefix_size_);
  return size;
}

bool ChunkMutator::mutate_payload_bytes(FramedInput* input, size_t spare) {
  std::vector<uint8_t>& payload = input->chunks[pick(input->chunks.size())].payload;
  if (payload.empty()) {
    if (spare == 0) return false;
    payload.push_back(uint8_t(random_()));
    --spare;
  }
  const size_t size = payload.size();
  payload.resize(size + spare);
  payload.resize(mutate_bytes_(payload.data(), size, payload.size()));
  return true;
}

bool ChunkMutator::mutate_header_field(FramedInput* input) {
  Chunk& chunk = input->chunks[pick(input->chunks.size())];
  std::vector<HeaderField> fields = header_fields(chunk);
  // Also any varint in the payload, wherever it starts (method data, runs,
  // types this file does not describe).
  if (fields.empty() || pick(4) == 0) {
    if (chunk.payload.empty()) return false;
    HeaderField any;
    any.offset = pick(chunk.payload.size());
    any.kind = K::kVarint;
    ByteReader in(chunk.payload.data() + any.offset, chunk.payload.size() - any.offset);
    if (!in.get_varint(&any.value)) return false;
    any.size = in.position();
    fields = {any};
  }
  if (chunk.type == kChunkGeometryImage && fields.size() >= 2 && pick(4) == 0) return set_image_size(&chunk, fields);
  const HeaderField& field = fields[pick(fields.size())];
  uint64_t value = 0;
  if (field.kind == K::kU8) {
    value = pick(4) == 0 ? field.value + 1 : kInterestingBytes[pick(std::size(kInterestingBytes))];
  } else if (field.kind == K::kVarint) {
    if (pick(4) == 0) {
      const uint64_t power = uint64_t(1) << pick(64);
      value = power + uint64_t(pick(3)) - 1;  // 2^k - 1, 2^k, 2^k + 1
    } else {
      const std::vector<uint64_t> values = interesting_counts(*input, chunk, field.value);
      value = values[pick(values.size())];
    }
  } else {
    value = interesting_float_bits(field.kind, pick(16));
  }
  set_header_field(&chunk, field, value);
  return true;
}

// W and H together (spec 13.2): the memory bombs of issue #12 item 2 need
// both large, with W H at most 2^24 so that GIMG itself passes.
bool ChunkMutator::set_image_size(Chunk* gimg, const std::vector<HeaderField>& fields) {
  static const uint64_t kSizes[][2] = {{4096, 4096}, {65535, 256}, {256, 65535}, {65535, 255},
                                       {8192, 2048}, {65535, 1},   {1, 65535},   {4097, 4096}};
  const uint64_t* size = kSizes[pick(std::size(kSizes))];
  set_header_field(gimg, fields[1], size[1]);  // H first: W's offset stays valid
  set_header_field(gimg, fields[0], size[0]);
  return true;
}

bool ChunkMutator::mutate_chunk_list(FramedInput* input) {
  std::vector<Chunk>& chunks = input->chunks;
  const size_t i = pick(chunks.size()), j = pick(chunks.size() + 1);
  switch (pick(5)) {
    case 0:
      chunks.erase(chunks.begin() + i);
      return true;
    case 1:
      chunks.insert(chunks.begin() + j, Chunk(chunks[i]));
      return true;
    case 2:
      if (j == chunks.size() || i == j) return false;
      std::swap(chunks[i], chunks[j]);
      return true;
    case 3: {
      const uint32_t type = kKnownTypes[pick(std::size(kKnownTypes))];
      const Chunk* same = find_chunk(*input, type);
      Chunk chunk{type, same != nullptr && pick(2) == 0 ? same->payload : minimal_payload(type)};
      chunks.insert(chunks.begin() + j, std::move(chunk));
      return true;
    }
    default:
      chunks[i].type = kKnownTypes[pick(std::size(kKnownTypes))];
      return true;
  }
}

size_t ChunkMutator::cross_over(const uint8_t* a, size_t a_size, const uint8_t* b, size_t b_size, uint8_t* out,
                                size_t max_out_size, unsigned seed) {
  random_.seed(seed);
  FramedInput first = split_chunks(a, a_size, prefix_size_);
  const FramedInput second = split_chunks(b, b_size, prefix_size_);
  if (first.chunks.empty() || second.chunks.empty()) return 0;
  const size_t i = pick(first.chunks.size()), j = pick(second.chunks.size());
  switch (pick(3)) {
    case 0:  // a's chunks before i, then b's from j on
      first.chunks.resize(i);
      first.chunks.insert(first.chunks.end(), second.chunks.begin() + j, second.chunks.end());
      first.tail = second.tail;
      break;
    case 1:
      first.chunks[i] = second.chunks[j];
      break;
    default:
      first.chunks.insert(first.chunks.begin() + i, second.chunks[j]);
      break;
  }
  const std::vector<uint8_t> framed = frame_chunks(first);
  if (framed.size() > max_out_size) return 0;
  std::memcpy(out, framed.data(), framed.size());
  return framed.size();
}

}  // namespace qmc::fuzz
