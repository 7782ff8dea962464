// Connectivity method 1 (spec/qmc-format.md 5.3.2): flags, coding, the
// interaction codes of seed 001 chapter 4, then Spirale Reversi.
#include "decoder/quad_connectivity_decoder.h"

#include <string>

#include "common/bit_reader.h"
#include "common/byte_io.h"
#include "common/quad_codings.h"
#include "decoder/spirale_reversi_decoder.h"

namespace qmc {

Status decode_quad_connectivity(const uint8_t* data, size_t size, uint32_t vertex_count, uint32_t face_count,
                                Mesh* mesh, QuadConnectivityInfo* info) {
  ByteReader in(data, size);
  uint8_t flags = 0, coding = 0;
  if (!in.get_u8(&flags) || !in.get_u8(&coding))
    return Status(ErrorCode::kBadChunkPayload, "CONN: quad header cut short");
  if (flags > 1) return Status(ErrorCode::kBadChunkPayload, "CONN: reserved quad flags set");
  if (coding >= kQuadCodingCount)
    return Status(ErrorCode::kUnsupportedFeature, "CONN: quad coding " + std::to_string(coding));
  info->closed = flags & 1;
  info->coding = coding;
  if (face_count < 1u + (info->closed ? 1u : 0u))
    return Status(ErrorCode::kBadChunkPayload, "CONN: too few quads for the quad coder");
  const uint32_t operations = face_count - (info->closed ? 1 : 0);
  BitReader bits(in.cursor(), in.remaining());
  // Every code word takes at least one bit.
  if (operations > bits.bits_remaining())
    return Status(ErrorCode::kLimitExceeded, "CONN: " + std::to_string(operations) +
                                                 " interaction codes cannot fit in " + std::to_string(size) + " bytes");
  std::vector<uint8_t> types;
  if (Status s = read_quad_stream(QuadCoding(coding), operations, &bits, &types); !s.ok()) return s;
  if (!bits.at_clean_end()) return Status(ErrorCode::kBadChunkPayload, "CONN: bits left over after the last code");
  return spirale_reversi_decode(types, info->closed, vertex_count, mesh);
}

}  // namespace qmc
