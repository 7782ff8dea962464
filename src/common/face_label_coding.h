// The labels of the faces (spec/qmc-format.md section 16.2): per face in
// coder order, "the same as the face before" or the label's index as
// direct bits. One template for the encoder and the decoder.
#pragma once

#include <cstdint>

#include "common/position_coding.h"

namespace qmc {

// 16.2 for face f: codes `label` (encoder) or decodes it (decoder: label
// ignored). `previous` is face f - 1's label; none = V_L. Returns the label,
// which the decoder checks against V_L.
template <class Coder>
uint32_t code_face_label(Coder* coder, uint16_t* same, uint64_t f, uint32_t previous, uint32_t none, uint32_t label) {
  if (f >= 1 && coder->code(label == previous, same)) return previous;
  uint32_t out = 0;
  for (int i = bit_length(none) - 1; i >= 0; --i) out = (out << 1) | uint32_t(coder->code_direct(int(label >> i & 1)));
  return out;
}

}  // namespace qmc
