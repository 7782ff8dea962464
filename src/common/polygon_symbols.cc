// Symbol tables of spec/qmc-format.md 5.4.3.
#include "common/polygon_symbols.h"

#include "common/polygon_symbol_coding.h"

namespace qmc {
namespace {

// Quads by Q-type (5.3.3 in gap terms): statuses of x = w1, y = w2, then the
// gap kinds from g1's side (R) to g0's side (L).
struct QuadRow {
  uint8_t x_anchor, y_anchor, gaps[3];
};
constexpr QuadRow kQuadRows[13] = {
    {1, 1, {1, 1, 1}},  // Q1: y adjacent, x adjacent, O on the boundary
    {1, 1, {0, 1, 1}},  // Q2: y adjacent, x far, O on the boundary
    {1, 1, {0, 0, 1}},  // Q3: y adjacent, x far, O not
    {1, 1, {1, 0, 1}},  // Q4: y adjacent, x adjacent, O not
    {0, 1, {0, 1, 0}},  // Q5: y adjacent, x free
    {1, 1, {1, 1, 0}},  // Q6: y far, x adjacent, O on the boundary
    {1, 1, {0, 1, 0}},  // Q7: y far, x far, O on the boundary
    {1, 1, {0, 0, 0}},  // Q8: y far, x far, O not
    {1, 1, {1, 0, 0}},  // Q9: y far, x adjacent, O not
    {0, 1, {0, 0, 0}},  // Q10: y far, x free
    {1, 0, {0, 0, 0}},  // Q11: y free, x far
    {1, 0, {1, 0, 0}},  // Q12: y free, x adjacent
    {0, 0, {0, 0, 0}},  // Q13: both free
};

// Triangles 13..17: status of w, then gap kinds.
struct TriangleRow {
  uint8_t anchor, gaps[2];
};
constexpr TriangleRow kTriangleRows[5] = {{0, {0, 0}}, {1, {1, 1}}, {1, {1, 0}}, {1, {0, 1}}, {1, {0, 0}}};

uint32_t anchors_of(uint32_t m, const uint8_t* statuses) {
  uint32_t k = 0;
  for (uint32_t i = 0; i < m; ++i) k += statuses[i];
  return k;
}

}  // namespace

void FaceShapes::add(uint32_t d, const uint8_t* statuses, const uint8_t* gaps, uint32_t gaps_count) {
  degree.push_back(d);
  status_begin.push_back(uint32_t(status.size()));
  gap_begin.push_back(uint32_t(gap_is_edge.size()));
  // Element by element: a face has at most a few, and a range insert per
  // face costs more than the copy (the vectors are reserved, 5.4.3).
  for (uint32_t i = 0; i + 2 < d; ++i) status.push_back(statuses[i]);
  for (uint32_t i = 0; i < gaps_count; ++i) gap_is_edge.push_back(gaps[i]);
}

uint32_t symbol_shape(int symbol, uint8_t statuses[2], uint8_t gaps[3], uint32_t* gaps_count) {
  if (symbol < 13) {
    const QuadRow& row = kQuadRows[symbol];
    statuses[0] = row.x_anchor;
    statuses[1] = row.y_anchor;
    *gaps_count = anchors_of(2, statuses) + 1;
    // Gaps whose anchor is missing collapse: the table lists them from g1's
    // side, so the first gaps_count entries that belong are taken in order.
    if (row.x_anchor && row.y_anchor) {
      for (int i = 0; i < 3; ++i) gaps[i] = row.gaps[i];
    } else if (row.x_anchor) {  // gaps g1-x, x-y-g0
      gaps[0] = row.gaps[0];
      gaps[1] = 0;
    } else if (row.y_anchor) {  // gaps g1-x-y, y-g0
      gaps[0] = 0;
      gaps[1] = row.gaps[1];
    } else {
      gaps[0] = 0;
    }
    return 4;
  }
  const TriangleRow& row = kTriangleRows[symbol - 13];
  statuses[0] = row.anchor;
  *gaps_count = row.anchor + 1u;
  gaps[0] = row.gaps[0];
  gaps[1] = row.gaps[1];
  return 3;
}

int face_symbol(const FaceShapes& shapes, size_t f) {
  const uint32_t d = shapes.degree[f];
  if (d != 3 && d != 4) return kPolygonOtherSymbol;
  const uint8_t* statuses = &shapes.status[shapes.status_begin[f]];
  const uint8_t* gaps = &shapes.gap_is_edge[shapes.gap_begin[f]];
  const uint32_t count = shapes.gap_count(f);
  for (int symbol = (d == 4 ? 0 : 13); symbol < (d == 4 ? 13 : 18); ++symbol) {
    uint8_t s[2], g[3];
    uint32_t n = 0;
    symbol_shape(symbol, s, g, &n);
    bool same = n == count;
    for (uint32_t i = 0; same && i < d - 2; ++i) same = s[i] == statuses[i];
    for (uint32_t i = 0; same && i < n; ++i) same = g[i] == gaps[i];
    if (same) return symbol;
  }
  return -1;  // not a valid shape (gap with free vertices marked as edge)
}

const PolygonSymbolModel kFreshPolygonSymbolModel{};

}  // namespace qmc
