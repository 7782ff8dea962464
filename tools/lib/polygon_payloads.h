// Hand-made CONN payloads of polygon codings 7 and 8 (spec/qmc-format.md
// 5.4.10), for the conformance vectors, the tests and the crafted files of
// bench/: each field written as the section lists it, the face symbols coded
// with the decoder's own model, so that a file can say what no encoder would.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "common/bit_writer.h"
#include "common/polygon_symbol_coding.h"
#include "common/range_coder.h"
#include "qmc/format.h"

namespace qmc::tools {

// A CONN payload of method 2 with coding 7 (or `coding`): V, F, flags 0, the
// coding, `groups`, symbol_bytes (the symbols' length plus `length_extra`),
// the symbols, then the bit stream `stream` writes (components and records).
std::vector<uint8_t> coding7_conn(uint32_t vertices, uint32_t faces, uint8_t groups,
                                  const std::vector<uint8_t>& symbols,
                                  const std::function<void(BitWriter*)>& stream, uint64_t length_extra = 0,
                                  int coding = kPolygonContextCoded);

// A symbol stream: `body` codes decisions with the model of 5.4.10 (coding
// 8's with quad_neighbours).
std::vector<uint8_t> coding7_symbols(uint8_t groups, const std::function<void(RangeEncoder*, PolygonSymbolModel*)>& body,
                                     bool quad_neighbours = false);

}  // namespace qmc::tools
