// Canonical, length-limited Huffman coding (spec/qmc-format.md section 7.3).
// Code lengths come from package-merge (Larmore & Hirschberg 1990), which is
// optimal under the length limit; codes are assigned canonically so that a
// table of lengths is all a decoder needs.
#pragma once

#include <cstdint>
#include <vector>

#include "common/bit_reader.h"
#include "common/bit_writer.h"
#include "qmc/status.h"

namespace qmc {

// Section 7.3: code lengths are 1..15 bits; 0 marks an unused symbol.
inline constexpr int kMaxHuffmanLength = 15;

// Optimal code lengths for `frequencies` with no length above max_length.
// Symbols of frequency 0 get length 0. A single used symbol gets length 1.
// Requires 2^max_length >= number of used symbols.
std::vector<uint8_t> huffman_code_lengths(const std::vector<uint64_t>& frequencies,
                                          int max_length = kMaxHuffmanLength);

// Canonical codes for a set of lengths: shorter codes first, ties by symbol.
class HuffmanEncoder {
 public:
  explicit HuffmanEncoder(const std::vector<uint8_t>& lengths);
  void write(BitWriter* writer, uint32_t symbol) const {
    writer->write_bits(codes_[symbol], lengths_[symbol]);
  }
  int length(uint32_t symbol) const { return lengths_[symbol]; }

 private:
  std::vector<uint8_t> lengths_;
  std::vector<uint32_t> codes_;
};

// Section 7.3.1: the code-length table in the bit stream.
void write_code_lengths(BitWriter* writer, const std::vector<uint8_t>& lengths);
// Reads a table for an alphabet of `alphabet_size` symbols (trailing unused
// symbols are implied). Rejects tables section 7.3.2 declares invalid.
Status read_code_lengths(BitReader* reader, uint32_t alphabet_size, std::vector<uint8_t>* lengths);

// Table-driven decoder: one lookup of the next max-length bits per symbol.
class HuffmanDecoder {
 public:
  // Validates the lengths (section 7.3.2) and builds the lookup table.
  Status init(const std::vector<uint8_t>& lengths);
  // The next symbol, or -1 if the bits form no code word (possible only for
  // the single-symbol code). Reading past the end sets reader->overrun().
  int decode(BitReader* reader) const {
    const Entry e = table_[reader->peek_bits(table_bits_)];
    if (e.length == 0) return -1;
    reader->skip_bits(e.length);
    return e.symbol;
  }

 private:
  struct Entry {
    uint16_t symbol = 0;
    uint8_t length = 0;  // 0: no code word starts with these bits
  };
  std::vector<Entry> table_;
  int table_bits_ = 0;
};

// Reads a code-length table (7.3.1) and validates it (7.3.2) into `decoder`.
Status read_table(BitReader* reader, uint32_t alphabet_size, HuffmanDecoder* decoder);

}  // namespace qmc
