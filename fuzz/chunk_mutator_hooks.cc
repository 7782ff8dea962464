// libFuzzer's custom mutation hooks for the whole-file targets (decode_file,
// stream_decoder): inputs are mutated as chunks and framed again with valid
// lengths and CRCs (chunk_mutator.h). Each target defines
// qmc::fuzz::kFilePrefixSize, the bytes it reads before the file.
#include <cstddef>
#include <cstdint>

#include "chunk_mutator.h"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

qmc::fuzz::ChunkMutator& mutator() {
  static qmc::fuzz::ChunkMutator m(qmc::fuzz::kFilePrefixSize, LLVMFuzzerMutate);
  return m;
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
  return mutator().mutate(data, size, max_size, seed);
}

extern "C" size_t LLVMFuzzerCustomCrossOver(const uint8_t* a, size_t a_size, const uint8_t* b, size_t b_size,
                                            uint8_t* out, size_t max_out_size, unsigned int seed) {
  return mutator().cross_over(a, a_size, b, b_size, out, max_out_size, seed);
}
