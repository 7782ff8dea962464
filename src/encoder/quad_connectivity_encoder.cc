// Method 1 payload (spec 5.3.2) and the amortized choice of seed 001 ch. 4:
// the encoder measures the exact stream size under every coding and keeps
// the smallest (ties go to the lower coding number).
#include "encoder/quad_connectivity_encoder.h"

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/quad_codings.h"
#include "qmc/format.h"

namespace qmc {

std::vector<uint8_t> encode_quad_connectivity(const QuadTraversal& traversal, uint32_t vertex_count, int forced,
                                              QuadCodingChoice* choice) {
  *choice = QuadCodingChoice{};
  for (int c = 0; c < kQuadCodingCount; ++c) {
    choice->stream_bits[c] = quad_stream_bits(QuadCoding(c), traversal.types);
    const int64_t best = choice->stream_bits[choice->coding];
    if (choice->stream_bits[c] >= 0 && (best < 0 || choice->stream_bits[c] < best)) choice->coding = uint8_t(c);
  }
  if (forced >= 0) {
    if (forced >= kQuadCodingCount || choice->stream_bits[forced] < 0) return {};
    choice->coding = uint8_t(forced);
  }
  std::vector<uint8_t> payload;
  put_u8(&payload, uint8_t(ConnectivityMethod::kQuad));
  put_varint(&payload, vertex_count);
  put_varint(&payload, traversal.faces.size() / 4);
  put_u8(&payload, traversal.closed ? 1 : 0);
  put_u8(&payload, choice->coding);
  BitWriter bits;
  write_quad_stream(QuadCoding(choice->coding), traversal.types, &bits);
  const std::vector<uint8_t> stream = bits.finish();
  payload.insert(payload.end(), stream.begin(), stream.end());
  return payload;
}

}  // namespace qmc
