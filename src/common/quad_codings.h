// Interaction-type codes of seed 001 (Q. Jing, "Compression and
// Decompression of Quadrilateral Meshes", 2003), chapter 4: Codings I, II
// and III (tables 4-2, 4-6, 4-8), the plain 4-bit code of section 4.1, and
// a canonical-Huffman coding of the same (type, next class) pairs
// (spec/qmc-format.md section 5.3.5). Shared by encoder and decoder.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "common/bit_reader.h"
#include "common/bit_writer.h"
#include "qmc/format.h"
#include "qmc/status.h"

namespace qmc {

// Q1..Q13 are 1..13. Class A is Q1-Q5, class B is Q6-Q13 (seed 001 §4.1).
inline constexpr int kQuadTypeCount = 13;
enum class QuadClass : uint8_t { kA = 0, kB = 1 };
inline QuadClass quad_class(int type) { return type <= 5 ? QuadClass::kA : QuadClass::kB; }

// One code word of Codings I-III: writes `bits` (length `length`).
struct QuadCodeWord {
  uint8_t bits = 0, length = 0;  // length 0: this (type, next class) has no code word
};

// code_word(coding, type, next) for Codings I-III; length 0 if the table has
// no entry (the seed's claim: Q5, Q10, Q12, Q13 are never followed by Q1-5).
QuadCodeWord fixed_code_word(QuadCoding coding, int type, QuadClass next);

// Decodes one code word of Codings I-III in the context of the current
// quad's class. Returns the type (1..13) and sets *next, or returns 0 for a
// bit string that is no code word, -1 if the stream ended inside it.
int read_fixed_code_word(QuadCoding coding, QuadClass current, BitReader* reader, QuadClass* next);

// Huffman coding (5.3.5): the alphabet of a context is its class's types
// times the two next classes.
uint32_t quad_pair_alphabet(QuadClass context);
uint32_t quad_pair_symbol(int type, QuadClass next);           // within the type's class
int quad_pair_type(QuadClass context, uint32_t symbol, QuadClass* next);

// Exact size in bits of the symbol stream of `types` (compression order)
// under `coding`, tables included; -1 if the coding cannot express it.
int64_t quad_stream_bits(QuadCoding coding, const std::vector<uint8_t>& types);

// Writes the symbol stream (first-class bit, tables, code words) of 5.3.
void write_quad_stream(QuadCoding coding, const std::vector<uint8_t>& types, BitWriter* writer);

// Reads `count` interaction types written by write_quad_stream.
Status read_quad_stream(QuadCoding coding, uint32_t count, BitReader* reader, std::vector<uint8_t>* types);

}  // namespace qmc
