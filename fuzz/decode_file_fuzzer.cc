// libFuzzer target: the whole-file decoder (spec sections 3-9). Any input
// must decode or be rejected with an error; a decoded file must serialize.
// Inputs are mutated as chunks and framed with valid lengths and CRCs
// (chunk_mutator_hooks.cc), so mutations reach the payload rules.
#include <cstddef>
#include <cstdint>

#include "chunk_mutator.h"
#include "qmc/decoder.h"

const size_t qmc::fuzz::kFilePrefixSize = 0;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::DecodedFile file;
  const qmc::Status s = qmc::decode(data, size, &file);
  if (s.ok()) {
    (void)qmc::canonical_output(file);
  } else if (s.message().empty()) {
    __builtin_trap();  // every rejection names its reason
  }
  return 0;
}
