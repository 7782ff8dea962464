// libFuzzer target: polygon coding 8 (spec/qmc-format.md 5.4.10), coding 7
// whose quad symbols are decoded in the contexts of the gate and its loop
// neighbours; input and checks as context_coding_fuzz.h says (the inputs of
// polygon_coding7 serve, the layouts being the same).
#include "context_coding_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return fuzz_context_coding(data, size, qmc::kPolygonQuadContextCoded);
}
