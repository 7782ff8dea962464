// Face symbols of the polygon coder (spec/qmc-format.md 5.4.3): how a face
// meets the boundary of the part not yet encoded, as anchor/free statuses of
// its vertices after the gate and edge-gap/detour kinds of its gaps. Quads
// map onto seed 001's Q1..Q13, triangles onto five symbols, other degrees
// are spelled out bit by bit. Shared by encoder and decoder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc {

inline constexpr int kPolygonSymbolCount = 19;  // 0..12 quads, 13..17 triangles, 18 other
inline constexpr int kPolygonOtherSymbol = 18;

// The shapes of a sequence of faces, flat: face f has `degree[f]` corners,
// m = degree - 2 statuses (1 = anchor) at status_begin[f], and one kind per
// gap (1 = edge gap, 0 = detour) at gap_begin[f]; a face has (anchors + 1)
// gaps.
struct FaceShapes {
  std::vector<uint32_t> degree, status_begin, gap_begin;
  std::vector<uint8_t> status, gap_is_edge;

  size_t size() const { return degree.size(); }
  uint32_t gap_count(size_t f) const {
    const size_t end = f + 1 < size() ? gap_begin[f + 1] : gap_is_edge.size();
    return uint32_t(end - gap_begin[f]);
  }
  void reserve(size_t faces) {
    degree.reserve(faces);
    status_begin.reserve(faces);
    gap_begin.reserve(faces);
    status.reserve(faces);
    gap_is_edge.reserve(2 * faces);
  }
  // Appends a face; gaps are derived by the caller.
  void add(uint32_t d, const uint8_t* statuses, const uint8_t* gaps, uint32_t gaps_count);
};

// Symbol 0..18 of face f.
int face_symbol(const FaceShapes& shapes, size_t f);
// Shape of symbol 0..17 (degree 4 or 3): writes statuses and gap kinds,
// returns the degree and sets *gaps_count.
uint32_t symbol_shape(int symbol, uint8_t statuses[2], uint8_t gaps[3], uint32_t* gaps_count);
// Class A (0) if the last gap is an edge gap, else B (1) (5.4.3).
inline int face_class(const FaceShapes& shapes, size_t f) {
  return shapes.gap_is_edge[shapes.gap_begin[f] + shapes.gap_count(f) - 1] ? 0 : 1;
}

}  // namespace qmc
