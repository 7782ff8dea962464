// The per-corner mapping of an attribute (spec/qmc-format.md section 15.3):
// for each corner, a new value, a value of an earlier corner of the same
// vertex, or any value met before, as range-coded decisions. One template
// runs on both sides, so encoder and decoder cannot drift apart.
#pragma once

#include <cstdint>
#include <vector>

#include "common/position_coding.h"

namespace qmc {

// 15.3: the probabilities of one mapping stream, all starting at 1024.
struct AttributeMappingModel {
  uint16_t fresh[3] = {1024, 1024, 1024};  // NEW[min(n, 2)]
  uint16_t own = 1024;                     // OWN
};

// The lists S_v of 15.3, each in slots reserved up front for as many
// entries as the vertex has corners, so every step is O(1).
class VertexValueLists {
 public:
  // corners: the vertex label of every corner (all < vertex_count).
  void reset(uint32_t vertex_count, const std::vector<uint32_t>& corners) {
    first_.assign(size_t(vertex_count) + 1, 0);
    for (uint32_t v : corners) ++first_[v + 1];
    for (size_t v = 0; v < vertex_count; ++v) first_[v + 1] += first_[v];
    length_.assign(vertex_count, 0);
    slots_.resize(corners.size());
  }
  uint32_t length(uint32_t v) const { return length_[v]; }
  uint32_t at(uint32_t v, uint32_t j) const { return slots_[first_[v] + j]; }
  // At most one append per corner of v, so the slots suffice.
  void append(uint32_t v, uint32_t value) { slots_[first_[v] + length_[v]++] = value; }

 private:
  std::vector<uint32_t> first_, length_, slots_;
};

// What the decoder found wrong with a corner's decisions (15.3).
enum class MappingFault { kNone, kOwnIndex, kNothingMet, kMetIndex };

// Codes `bits` direct bits of value, the most significant first (15.3).
template <class Coder>
uint32_t code_direct_bits(Coder* coder, int bits, uint32_t value) {
  uint32_t out = 0;
  for (int i = bits - 1; i >= 0; --i) out = (out << 1) | uint32_t(coder->code_direct(int(value >> i & 1)));
  return out;
}

// The encoder's choice for one corner: new, own (index j in S_v) or met (value).
struct MappingChoice {
  enum Branch { kNew, kOwn, kMet } branch = kNew;
  uint32_t index = 0;  // kOwn: j; kMet: the value
};

// 15.3's first decision for a corner of vertex v: NEW[min(n, 2)], coded
// only while U < N. On 1 the corner takes the next value, appended to S_v.
template <class Coder>
bool code_new_value(Coder* coder, AttributeMappingModel* m, VertexValueLists* lists, uint32_t v,
                    uint64_t value_count, uint32_t* met, MappingChoice choice, uint32_t* value) {
  const uint32_t n = lists->length(v);
  if (*met >= value_count || !coder->code(choice.branch == MappingChoice::kNew, &m->fresh[n < 2 ? n : 2]))
    return false;
  *value = (*met)++;
  lists->append(v, *value);
  return true;
}

// 15.3's decisions after NEW = 0: OWN and an index into S_v, or any value
// met before. *fault is set when the decoded decisions break a rule.
template <class Coder>
uint32_t code_earlier_value(Coder* coder, AttributeMappingModel* m, VertexValueLists* lists, uint32_t v,
                            uint32_t met, MappingChoice choice, MappingFault* fault) {
  const uint32_t n = lists->length(v);
  if (n >= 1 && coder->code(choice.branch == MappingChoice::kOwn, &m->own)) {
    const uint32_t j = n == 1 ? 0 : code_direct_bits(coder, bit_length(n - 1), choice.index);
    if (j >= n) {
      *fault = MappingFault::kOwnIndex;
      return 0;
    }
    return lists->at(v, j);
  }
  if (met == 0) {
    *fault = MappingFault::kNothingMet;
    return 0;
  }
  const uint32_t value = code_direct_bits(coder, bit_length(met - 1), choice.index);
  if (value >= met) {
    *fault = MappingFault::kMetIndex;
    return 0;
  }
  lists->append(v, value);
  return value;
}

// 15.3 for corner of vertex v: codes `choice` (encoder) or decodes it
// (decoder: choice ignored); returns the value m_k, updating *met (U) and
// the lists.
template <class Coder>
uint32_t code_corner_value(Coder* coder, AttributeMappingModel* m, VertexValueLists* lists, uint32_t v,
                           uint64_t value_count, uint32_t* met, MappingChoice choice, MappingFault* fault) {
  uint32_t value = 0;
  if (code_new_value(coder, m, lists, v, value_count, met, choice, &value)) return value;
  return code_earlier_value(coder, m, lists, v, *met, choice, fault);
}

}  // namespace qmc
