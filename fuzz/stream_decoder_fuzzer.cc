// libFuzzer target: the streaming decoder against the whole-buffer decoder.
// The first input byte chooses the piece sizes; the rest is the file. Spec
// 3.5 requires the same result however the bytes arrive, so any difference
// is a bug and aborts. The file after the first byte is mutated as chunks
// with valid lengths and CRCs (chunk_mutator_hooks.cc).
#include <cstddef>
#include <cstdint>

#include "chunk_mutator.h"
#include "fuzz_limits.h"
#include "qmc/decoder.h"

const size_t qmc::fuzz::kFilePrefixSize = 1;  // the piece-size byte

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const size_t piece = size_t(data[0] % 17) + 1;
  ++data;
  --size;
  const qmc::DecoderLimits limits = qmc::fuzz::small_output_limits();
  qmc::DecodedFile whole;
  const qmc::Status a = qmc::decode(data, size, &whole, limits);
  qmc::StreamDecoder stream(limits);
  qmc::Status b;
  for (size_t pos = 0; pos < size && b.ok(); pos += piece)
    b = stream.feed(data + pos, pos + piece <= size ? piece : size - pos);
  if (b.ok()) b = stream.finish();
  if (a.code() != b.code()) __builtin_trap();
  if (a.ok() && qmc::canonical_output(whole) != qmc::canonical_output(stream.file())) __builtin_trap();
  return 0;
}
