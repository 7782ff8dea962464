// Structure-aware mutation of qmc files for the libFuzzer targets that take a
// whole file (decode_file, stream_decoder). Byte mutations of a file almost
// always break a chunk's CRC-32 (spec 3.4), and the decoder rejects the file
// at `bad_crc` before any payload rule runs; a count stored as a multi-byte
// varint (CONN's vertex_count, GIMG's width) is in any case out of reach of
// single-byte flips. This mutator edits a file as chunks: payload bytes, one
// header field at a time (varint, u8, f32, f64) with values chosen near the
// limits of spec 8, 12.1, 13.3, 13.6-13.8, or whole chunks (insert, remove,
// duplicate, swap, retype), and then frames every chunk again with its
// length and CRC (spec 3.2, 3.4). It has no libFuzzer dependency: the byte
// mutator is passed in, so tests can drive it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace qmc::fuzz {

// For chunk_mutator_hooks.cc: the bytes a target reads before the file,
// defined by each target linking the hooks.
extern const size_t kFilePrefixSize;

struct Chunk {
  uint32_t type = 0;
  std::vector<uint8_t> payload;
};

// A fuzz input as spec 3.1-3.2 frame it: bytes the target reads before the
// file (stream_decoder's piece-size byte), the signature bytes, the chunks
// that frame completely, and whatever follows the last of them, kept as is.
struct FramedInput {
  std::vector<uint8_t> prefix;
  std::vector<uint8_t> signature;
  std::vector<Chunk> chunks;
  std::vector<uint8_t> tail;
};

FramedInput split_chunks(const uint8_t* data, size_t size, size_t prefix_size);
// The input written back, every chunk's length and CRC-32 computed afresh.
std::vector<uint8_t> frame_chunks(const FramedInput& input);
// Recomputes the CRC of every chunk that frames and changes no other byte:
// what a plain byte mutation needs to get past `bad_crc`.
void repair_crcs(uint8_t* data, size_t size, size_t prefix_size);

// A chunk's header field (spec 4.1, 4.5, 5.1, 5.3.2, 5.4.1, 6.3, 12.1,
// 13.2, 13.5.1, 13.7, 13.8): where it starts in the payload, its encoded
// size, its kind and its current value (the bit pattern for floats).
enum class FieldKind : uint8_t { kU8, kVarint, kF32, kF64 };
struct HeaderField {
  size_t offset = 0;
  size_t size = 0;
  FieldKind kind = FieldKind::kU8;
  uint64_t value = 0;
};
// The header fields of the chunk's type that its payload holds, in order;
// none for types without a header (GMSK, teXt, QEND, unknown types).
std::vector<HeaderField> header_fields(const Chunk& chunk);
// Replaces the field's bytes by `value` encoded as the field's kind (a varint
// in shortest form, so the payload may grow or shrink).
void set_header_field(Chunk* chunk, const HeaderField& field, uint64_t value);

// libFuzzer's LLVMFuzzerMutate: mutates data[0, size) in place, returns the
// new size, at most max_size.
using ByteMutator = size_t (*)(uint8_t* data, size_t size, size_t max_size);

class ChunkMutator {
 public:
  ChunkMutator(size_t prefix_size, ByteMutator mutate_bytes) : prefix_size_(prefix_size), mutate_bytes_(mutate_bytes) {}

  // LLVMFuzzerCustomMutator: returns the new size, at most max_size.
  size_t mutate(uint8_t* data, size_t size, size_t max_size, unsigned seed);
  // LLVMFuzzerCustomCrossOver: chunks of a and b combined into out; 0 when
  // the result would not fit in max_out_size.
  size_t cross_over(const uint8_t* a, size_t a_size, const uint8_t* b, size_t b_size, uint8_t* out,
                    size_t max_out_size, unsigned seed);

 private:
  bool mutate_payload_bytes(FramedInput* input, size_t spare);
  bool mutate_header_field(FramedInput* input);
  bool set_image_size(Chunk* gimg, const std::vector<HeaderField>& fields);
  bool mutate_chunk_list(FramedInput* input);
  size_t mutate_whole(uint8_t* data, size_t size, size_t max_size, bool fix_crcs);
  size_t pick(size_t n) { return n == 0 ? 0 : size_t(random_() % n); }

  size_t prefix_size_;
  ByteMutator mutate_bytes_;
  std::minstd_rand random_;
};

}  // namespace qmc::fuzz
