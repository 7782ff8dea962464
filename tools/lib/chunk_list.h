// A .qmc file as a list of chunks (spec/qmc-format.md section 3), for the
// tests and the conformance vectors, which take well-formed files apart and
// put them back together reordered, cut or edited.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc::tools {

struct Chunk {
  uint32_t type;
  std::vector<uint8_t> payload;
};
using Chunks = std::vector<Chunk>;

// The chunks after the signature, up to the first one that does not fit.
Chunks split_chunks(const std::vector<uint8_t>& file);

// Signature, then each chunk with its length and a fresh CRC.
std::vector<uint8_t> join_chunks(const Chunks& chunks);

// Index of the nth chunk of `type`; the caller knows the file holds it, so a
// missing chunk aborts with a message.
size_t find_chunk(const Chunks& chunks, uint32_t type, int nth = 0);

}  // namespace qmc::tools
