#include "decoder/chunk_frame.h"

#include <string>

#include "common/byte_io.h"
#include "common/crc32.h"
#include "qmc/decoder.h"

namespace qmc {
namespace {

bool is_ascii_letter(uint8_t c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

}  // namespace

Status read_version(const uint8_t* payload, uint32_t length, uint8_t* major, uint8_t* minor) {
  if (length != 2)
    return Status(ErrorCode::kBadChunkPayload, "QHDR payload is " + std::to_string(length) + " bytes, not 2");
  if (payload[0] != kFormatMajor)
    return Status(ErrorCode::kUnsupportedVersion, "format version " + std::to_string(payload[0]) + "." +
                                                      std::to_string(payload[1]) + "; this decoder reads " +
                                                      std::to_string(kFormatMajor) + ".x");
  *major = payload[0];
  *minor = payload[1];
  return Status::Ok();
}

Status read_chunk_frame(const uint8_t* chunk, size_t available, uint64_t offset, uint32_t max_length,
                        ChunkFrame* frame) {
  *frame = ChunkFrame{};
  if (available < 8) return Status::Ok();
  const std::string at = "at byte " + std::to_string(offset) + ": ";
  frame->type = load_u32be(chunk);
  frame->length = load_u32le(chunk + 4);
  const std::string name = chunk_type_name(frame->type);
  for (int i = 0; i < 4; ++i)
    if (!is_ascii_letter(chunk[i]))
      return Status(ErrorCode::kBadChunkType, at + "chunk type " + name + " is not four ASCII letters");
  if (frame->length > kMaxChunkLength)
    return Status(ErrorCode::kBadChunkLength,
                  at + "chunk " + name + " length " + std::to_string(frame->length) + " exceeds 2^31 - 1");
  if (frame->length > max_length)
    return Status(ErrorCode::kLimitExceeded, at + "chunk " + name + " length " + std::to_string(frame->length) +
                                                 " exceeds this decoder's limit (DecoderLimits::max_chunk_length)");
  if (available < 12 || available - 12 < uint64_t(frame->length)) return Status::Ok();
  if (load_u32le(chunk + 8 + frame->length) != crc32(chunk, 8 + size_t(frame->length)))
    return Status(ErrorCode::kBadCrc, at + "chunk " + name + " CRC mismatch");
  frame->complete = true;
  return Status::Ok();
}

}  // namespace qmc
