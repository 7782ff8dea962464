// Chunk framing of spec/qmc-format.md sections 3.1-3.4.
#include "encoder/chunk_writer.h"

#include "common/byte_io.h"
#include "common/crc32.h"
#include "qmc/format.h"

namespace qmc {

void write_signature(std::vector<uint8_t>* out) {
  out->insert(out->end(), kSignature, kSignature + sizeof(kSignature));
}

void write_chunk(std::vector<uint8_t>* out, uint32_t type, const std::vector<uint8_t>& payload) {
  const size_t start = out->size();
  put_u32be(out, type);  // the four letters in reading order
  put_u32le(out, uint32_t(payload.size()));
  out->insert(out->end(), payload.begin(), payload.end());
  put_u32le(out, crc32(out->data() + start, out->size() - start));
}

}  // namespace qmc
