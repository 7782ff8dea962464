// libFuzzer target: the whole-file decoder (spec sections 3-9). Any input
// must decode or be rejected with an error; a decoded file must serialize.
// Inputs are mutated as chunks and framed with valid lengths and CRCs
// (chunk_mutator_hooks.cc), so mutations reach the payload rules.
#include <cstddef>
#include <cstdint>

#include "chunk_mutator.h"
#include "fuzz_limits.h"
#include "qmc/decoder.h"

const size_t qmc::fuzz::kFilePrefixSize = 0;

namespace {

// peek() (spec 8.1) agrees with the decoder on a file it decoded: the counts
// it read are those decoded, and its lower bound of the output holds and is
// within the limit the decoder enforced.
void check_peek(const uint8_t* data, size_t size, const qmc::DecodedFile& decoded, const qmc::DecoderLimits& limits) {
  qmc::FileSummary summary;
  if (!qmc::peek(data, size, &summary).ok()) __builtin_trap();  // the decoder read these chunks too
  const size_t output = qmc::canonical_output(decoded).size();
  if (summary.min_output_bytes > output || output > limits.max_output_bytes) __builtin_trap();
  if (summary.has_connectivity && decoded.loop_level_count == 0 && summary.vertex_count != decoded.mesh.vertex_count())
    __builtin_trap();
  if (summary.has_geometry_image && summary.gim_width != decoded.gim.width) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const qmc::DecoderLimits limits = qmc::fuzz::small_output_limits();
  qmc::DecodedFile file;
  const qmc::Status s = qmc::decode(data, size, &file, limits);
  if (s.ok()) {
    check_peek(data, size, file, limits);
  } else if (s.message().empty()) {
    __builtin_trap();  // every rejection names its reason
  }
  return 0;
}
