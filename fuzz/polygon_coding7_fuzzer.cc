// libFuzzer target: polygon coding 7 (spec/qmc-format.md 5.4.10), the face
// symbols range coded in the contexts of Spirale Reversi's gate; input and
// checks as context_coding_fuzz.h says.
#include "context_coding_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_context_coding(data, size, qmc::kPolygonContextCoded);
}
