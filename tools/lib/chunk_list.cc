// Chunk lists (see the header).
#include "chunk_list.h"

#include <cstdio>
#include <cstdlib>

#include "common/byte_io.h"
#include "encoder/chunk_writer.h"
#include "qmc/decoder.h"

namespace qmc::tools {

Chunks split_chunks(const std::vector<uint8_t>& file) {
  Chunks out;
  for (size_t pos = 8; pos + 12 <= file.size();) {
    const uint32_t length = load_u32le(&file[pos + 4]);
    if (length > file.size() - pos - 12) break;
    out.push_back({load_u32be(&file[pos]), {file.begin() + long(pos) + 8, file.begin() + long(pos + 8 + length)}});
    pos += 12 + size_t(length);
  }
  return out;
}

std::vector<uint8_t> join_chunks(const Chunks& chunks) {
  std::vector<uint8_t> out;
  write_signature(&out);
  for (const Chunk& c : chunks) write_chunk(&out, c.type, c.payload);
  return out;
}

size_t find_chunk(const Chunks& chunks, uint32_t type, int nth) {
  for (size_t i = 0, seen = 0; i < chunks.size(); ++i)
    if (chunks[i].type == type && int(seen++) == nth) return i;
  std::fprintf(stderr, "find_chunk: the file has no chunk %s number %d\n", chunk_type_name(type).c_str(), nth);
  std::abort();
}

}  // namespace qmc::tools
