// libFuzzer target: a code-length table followed by code words (spec 7.3).
// Invalid tables must be refused; valid ones must decode until the input
// runs out without reading outside it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/bit_reader.h"
#include "common/huffman.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const uint32_t alphabet = uint32_t(data[0]) + 1;
  qmc::BitReader reader(data + 1, size - 1);
  std::vector<uint8_t> lengths;
  if (!qmc::read_code_lengths(&reader, alphabet, &lengths).ok()) return 0;
  if (lengths.size() != alphabet) __builtin_trap();
  qmc::HuffmanDecoder decoder;
  if (!decoder.init(lengths).ok()) return 0;
  while (!reader.overrun() && reader.bits_remaining() > 0) {
    const int symbol = decoder.decode(&reader);
    if (symbol >= int(alphabet) || (symbol >= 0 && lengths[size_t(symbol)] == 0)) __builtin_trap();
    if (symbol < 0) break;
  }
  return 0;
}
