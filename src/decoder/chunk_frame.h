// The frame of one chunk, spec/qmc-format.md sections 3.2-3.4 in the order
// of 3.6: type letters, length, then (once all its bytes are there) CRC;
// and the version in QHDR (4.1). Shared by the decoder and peek().
#pragma once

#include <cstddef>
#include <cstdint>

#include "qmc/status.h"

namespace qmc {

struct ChunkFrame {
  uint32_t type = 0;
  uint32_t length = 0;    // payload bytes
  bool complete = false;  // all 12 + length bytes are there and the CRC matches
};

// Section 4.1: QHDR's payload, its length checked before the version.
Status read_version(const uint8_t* payload, uint32_t length, uint8_t* major, uint8_t* minor);

// Reads the chunk at `chunk`, of which `available` bytes have arrived, found
// at file offset `offset` (for messages). kOk with complete = false means
// more bytes are needed; a length above `max_length` is kLimitExceeded.
Status read_chunk_frame(const uint8_t* chunk, size_t available, uint64_t offset, uint32_t max_length,
                        ChunkFrame* frame);

}  // namespace qmc
