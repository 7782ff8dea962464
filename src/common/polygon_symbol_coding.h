// Codings 7 and 8 of the polygon coder (spec/qmc-format.md 5.4.10): face
// symbols range coded (13.5.2) in the order Spirale Reversi applies them,
// each decision in a context of how many faces already surround the gate's
// vertices. Spirale Reversi rebuilds each vertex's fan face by face, so the
// count at the gate says how close the vertex is to being closed (symbol 13
// makes it inner): the valence idea of Touma and Gotsman (1998) and Alliez
// and Desbrun (2001), read from the reverse decoder's own state. One
// template runs on both sides, so encoder and decoder cannot drift apart.
#pragma once

#include <array>
#include <cstdint>

#include "common/range_coder.h"
#include "qmc/format.h"

namespace qmc {

// A probability of a 0 (1/2048 units) that adapts faster while it is young:
// after its n-th decision it moves by 1/min(n + 2, 32) of the distance to
// the coded bit, as a count would (5.4.10).
struct CountedProbability {
  uint16_t p = kRangeProbabilityInit;
  uint8_t n = 0;
};

inline constexpr uint32_t kCountedMaxDivisor = 32;
inline constexpr int kCountedMinProbability = 31, kCountedMaxProbability = 2017;

// floor(65536 / d) for d = 0 .. 32 (0 and 1 unused).
constexpr std::array<uint32_t, kCountedMaxDivisor + 1> counted_reciprocals() {
  std::array<uint32_t, kCountedMaxDivisor + 1> r{};
  for (uint32_t d = 2; d <= kCountedMaxDivisor; ++d) r[d] = 65536u / d;
  return r;
}
inline constexpr std::array<uint32_t, kCountedMaxDivisor + 1> kCountedReciprocal = counted_reciprocals();

inline void counted_adapt(CountedProbability* m, int bit) {
  const uint32_t d = m->n + 2u < kCountedMaxDivisor ? m->n + 2u : kCountedMaxDivisor;
  const uint32_t r = kCountedReciprocal[d];
  int p = m->p;
  if (bit == 0)
    p += int((uint32_t(2048 - p) * r) >> 16);
  else
    p -= int((uint32_t(p) * r) >> 16);
  p = p < kCountedMinProbability ? kCountedMinProbability : p > kCountedMaxProbability ? kCountedMaxProbability : p;
  m->p = uint16_t(p);
  if (m->n < kCountedMaxDivisor - 2) ++m->n;
}

template <class Coder>
int code_counted(Coder* coder, CountedProbability* m, int bit) {
  const int got = coder->code_fixed(bit, m->p);
  counted_adapt(m, got);
  return got;
}

// The decoder's view of the gate (5.4.10): the face counts of the gate
// node's vertex and of its loop neighbours, each capped at 7; all 0 when
// there is no current loop.
struct GateContext {
  uint32_t gate = 0, next = 0, prev = 0;
};
inline constexpr uint32_t kGateCountCap = 7;

// Codings 7 and 8 carry their symbols range coded after the header, in
// `groups`, `symbol_bytes` and `symbols` (5.4.1, 5.4.10).
inline bool is_context_coding(int coding) {
  return coding == kPolygonContextCoded || coding == kPolygonQuadContextCoded;
}

// Which symbol groups the payload uses (5.4.10's `groups` byte).
inline constexpr uint8_t kGroupTriangles = 1, kGroupQuads = 2, kGroupOther = 4;

// The context of a quad symbol's decisions: coding 7's the gate's count a
// (Q[a]); coding 8's also the larger count of the gate's two loop
// neighbours, 8 a + max(b, c) (Q8), which tells a regular quad mesh's
// shapes apart where a alone does not (5.4.10).
inline constexpr int kQuadContexts = (kGateCountCap + 1) * (kGateCountCap + 1);
inline uint32_t quad_context(const GateContext& g, bool neighbours) {
  return neighbours ? g.gate * (kGateCountCap + 1) + (g.next > g.prev ? g.next : g.prev) : g.gate;
}

struct PolygonSymbolModel {
  uint8_t groups = 0;
  bool quad_neighbours = false;                  // coding 8: quads in Q8's contexts
  int previous_group = 0;                       // 0 triangle, 1 quad, 2 other
  CountedProbability not_triangle[3], other[3];  // by previous_group
  CountedProbability tri_free[512], tri_split[512], tri_side[512], tri_closing[512];
  CountedProbability quad[kQuadContexts][16];  // by quad_context, tree node
  CountedProbability other_status, other_gap;
};

// A model as every payload starts it, copied whole instead of built entry by
// entry: the encoder starts one for each coding it tries and for its check.
// Defined out of line, so that the copy is one block copy (a constant the
// compiler could see would be stored entry by entry again).
extern const PolygonSymbolModel kFreshPolygonSymbolModel;

inline int symbol_group(int symbol) { return symbol < 13 ? 1 : symbol < 18 ? 0 : 2; }

// Codes the symbol (0 .. 18) of one face; the decoder's `symbol` is ignored
// and the decoded one returned, or -1 for a quad code 13 .. 15
// (bad_symbol). Symbol 18's shape follows through code_other_shape.
template <class Coder>
int code_face_symbol(Coder* coder, PolygonSymbolModel* m, const GateContext& g, int symbol) {
  const bool tri = m->groups & kGroupTriangles, quad = m->groups & kGroupQuads, other = m->groups & kGroupOther;
  const int want = symbol_group(symbol);
  bool is_triangle = tri;
  if (tri && (quad || other)) is_triangle = !code_counted(coder, &m->not_triangle[m->previous_group], want != 0);
  int group = 0;
  if (!is_triangle) group = quad && other ? 1 + code_counted(coder, &m->other[m->previous_group], want == 2) : quad ? 1 : 2;
  m->previous_group = group;
  if (group == 2) return 18;
  if (group == 0) {
    const uint32_t c = (g.gate * 8 + g.next) * 8 + g.prev;
    if (!code_counted(coder, &m->tri_free[c], symbol != 13)) return 13;
    if (!code_counted(coder, &m->tri_split[c], symbol == 14 || symbol == 17))
      return code_counted(coder, &m->tri_side[c], symbol == 16) ? 16 : 15;
    return code_counted(coder, &m->tri_closing[c], symbol == 17) ? 17 : 14;
  }
  CountedProbability(&tree)[16] = m->quad[quad_context(g, m->quad_neighbours)];
  uint32_t node = 1;
  for (int i = 3; i >= 0; --i) node = 2 * node + uint32_t(code_counted(coder, &tree[node], (symbol >> i) & 1));
  return node - 16 < 13 ? int(node - 16) : -1;
}

// Symbol 18's m = d - 2 statuses (1 = anchor), then the kind (1 = edge gap)
// of each gap without a free vertex; gaps with free vertices are detours (0).
// In for the encoder, out for the decoder; returns the number of gaps, or 0
// if the decoder ran out of stream (truncated).
template <class Coder>
uint32_t code_other_shape(Coder* coder, PolygonSymbolModel* m, uint32_t statuses, uint8_t* status, uint8_t* gaps) {
  uint32_t gap_count = 0, free_in_gap = 0;
  for (uint32_t i = 0; i < statuses; ++i) {
    status[i] = uint8_t(code_counted(coder, &m->other_status, status[i]));
    if (coder->overrun()) return 0;
    if (!status[i]) {
      ++free_in_gap;
      continue;
    }
    gaps[gap_count] = free_in_gap == 0 ? uint8_t(code_counted(coder, &m->other_gap, gaps[gap_count])) : 0;
    ++gap_count;
    free_in_gap = 0;
  }
  gaps[gap_count] = free_in_gap == 0 ? uint8_t(code_counted(coder, &m->other_gap, gaps[gap_count])) : 0;
  return coder->overrun() ? 0 : gap_count + 1;
}

// Symbol 18's d - 5 as an Exp-Golomb code of decode_direct bits: z zero
// bits, a one, z bits. Returns false for a 32nd zero (bad_chunk_payload).
template <class Coder>
bool code_other_degree(Coder* coder, uint32_t* value) {
  const uint64_t v = uint64_t(*value) + 1;
  int length = 0;
  while ((v >> (length + 1)) != 0) ++length;
  int zeros = 0;
  while (!coder->code_direct(zeros >= length)) {
    if (++zeros == 32 || coder->overrun()) return false;
  }
  uint64_t got = 1;
  for (int i = zeros - 1; i >= 0; --i) got = (got << 1) | uint64_t(coder->code_direct(int((v >> i) & 1)));
  *value = uint32_t(got - 1);
  return true;
}

}  // namespace qmc
