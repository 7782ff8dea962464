// Spirale Reversi for polygon faces (spec/qmc-format.md 5.4.5): seed 001's
// reverse decoding (§3.3, after Isenburg and Snoeyink's Spirale Reversi)
// generalized from the 13 quad types to faces of any degree described by
// their anchors and gaps. Rebuilds the closed genus-0 surface of every
// component from its face symbols, last to first.
#pragma once

#include <cstdint>
#include <vector>

#include "common/polygon_symbol_coding.h"
#include "common/polygon_symbols.h"
#include "qmc/status.h"

namespace qmc {

struct PolygonSurface {
  std::vector<uint32_t> face_degree;  // per surface face, in surface face index order (5.4.1)
  std::vector<uint32_t> corners;      // surface labels
  uint32_t labels = 0;                // N: number of surface labels
};

// Codings 7 and 8 (5.4.10): the faces come one at a time, each symbol decoded (or
// encoded) in the context of the gate it is about to be applied at.
class FaceSymbolSource {
 public:
  virtual ~FaceSymbolSource() = default;
  // Coded face f (its index in stream order, all components), applied next
  // at `gate`: sets the shapes holding it and its index there.
  virtual Status face(const GateContext& gate, size_t f, const FaceShapes** shapes, size_t* index) = 0;
  // After the last face, before the directed-edge check.
  virtual Status end() { return Status::Ok(); }
};

// components[c] = n_c, first_degree[c] = d_c; `shapes` holds the sum of
// (n_c - 1) coded faces in stream order.
Status polygon_spirale_reversi(const std::vector<uint32_t>& components, const std::vector<uint32_t>& first_degree,
                               const FaceShapes& shapes, PolygonSurface* surface);
// The same, the faces taken from `source` in the order they are applied,
// with each vertex's faces counted for the gate contexts. Room for
// `expected_faces` faces (of 3 corners) is reserved up front, the rest
// grows as faces are decoded.
Status polygon_spirale_reversi(const std::vector<uint32_t>& components, const std::vector<uint32_t>& first_degree,
                               FaceSymbolSource* source, size_t expected_faces, PolygonSurface* surface);
// The encoder of codings 7 and 8 (5.4.10): the same run for the gate contexts only,
// each component checked to close but no surface built or labelled (the
// encoder's self-check decodes the whole payload afterwards).
Status polygon_spirale_contexts(const std::vector<uint32_t>& components, const std::vector<uint32_t>& first_degree,
                                FaceSymbolSource* source);

}  // namespace qmc
