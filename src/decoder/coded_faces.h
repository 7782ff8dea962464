// Codings 7 and 8 of the polygon coder (spec/qmc-format.md 5.4.10): each face
// symbol range decoded when Spirale Reversi is about to apply it, in the
// context of the gate. The per-face work of the connectivity decoder, in a
// file of its own so that a build can compile it for speed and the rest of
// polygon_connectivity_decoder.cc (headers, stored codings, records) for
// size, as the WebAssembly build does (web/CMakeLists.txt).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/polygon_symbol_coding.h"
#include "common/polygon_symbols.h"
#include "common/range_coder.h"
#include "decoder/output_budget.h"
#include "decoder/polygon_spirale_reversi.h"
#include "qmc/status.h"

namespace qmc {

// Symbols 0 .. 17 are applied from the fixed table; only symbol 18's shapes
// are stored.
class CodedFaces final : public FaceSymbolSource {
 public:
  // `corners` checks symbol 18's faces against the output's limit (8.1).
  CodedFaces(const uint8_t* data, size_t size, uint8_t groups, bool quad_neighbours, OtherFaceCorners* corners);
  // 13.5.2's check of the stream's first bytes.
  Status start() const;
  Status face(const GateContext& gate, size_t f, const FaceShapes** shapes, size_t* index) override;
  // 13.5.2's end check.
  Status end() override;

 private:
  Status other_shape();

  RangeDecoder range_;
  OtherFaceCorners* corners_;
  uint64_t bytes_;
  PolygonSymbolModel model_ = kFreshPolygonSymbolModel;
  const FaceShapes fixed_;
  FaceShapes shapes_;  // symbol 18's faces so far
  std::vector<uint8_t> scratch_;
};

}  // namespace qmc
