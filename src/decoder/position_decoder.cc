// Positions of spec/qmc-format.md section 6 (seed 001 §2.6, §5.1.2):
// per-axis Huffman-coded deltas between consecutive vertices in file order.
#include "decoder/position_decoder.h"

#include <cmath>
#include <string>

#include "bitio/bit_reader.h"
#include "bitio/byte_io.h"
#include "bitio/exact_arith.h"
#include "bitio/huffman.h"
#include "bitio/magnitude_code.h"

namespace qmc {
namespace {

Status bad_payload(const std::string& message) { return Status(ErrorCode::kBadChunkPayload, "POSN: " + message); }

Status read_header(ByteReader* in, uint32_t vertex_count, QuantizationInfo* info) {
  uint64_t count = 0;
  uint8_t bits = 0;
  if (!in->get_varint(&count) || !in->get_u8(&bits)) return bad_payload("header cut short or malformed varint");
  if (count != vertex_count)
    return bad_payload("vertex_count " + std::to_string(count) + " differs from CONN's " +
                       std::to_string(vertex_count));
  if (bits < 1 || bits > 30) return bad_payload("quantization bits " + std::to_string(bits) + " outside 1..30");
  info->bits = bits;
  for (int a = 0; a < 3; ++a)
    if (!in->get_f32le(&info->min[a])) return bad_payload("bounding box cut short");
  for (int a = 0; a < 3; ++a)
    if (!in->get_f32le(&info->max[a])) return bad_payload("bounding box cut short");
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(info->min[a]) || !std::isfinite(info->max[a]) || !(info->min[a] <= info->max[a]))
      return bad_payload("bounding box axis " + std::to_string(a) + " is not finite with min <= max");
  return Status::Ok();
}

}  // namespace

void dequantization_steps(const QuantizationInfo& info, double lo[3], double step[3]) {
  for (int a = 0; a < 3; ++a) {
    lo[a] = double(info.min[a]);
    step[a] = (double(info.max[a]) - lo[a]) / double((uint64_t(1) << info.bits) - 1);
  }
}

Status decode_positions(const uint8_t* payload, size_t size, uint32_t vertex_count, QuantizationInfo* info,
                        std::vector<uint32_t>* quantized, std::vector<float>* positions) {
  ByteReader in(payload, size);
  if (Status s = read_header(&in, vertex_count, info); !s.ok()) return s;
  BitReader bits(in.cursor(), in.remaining());
  quantized->clear();
  positions->clear();
  if (vertex_count == 0) {
    if (!bits.at_clean_end()) return bad_payload("data after an empty vertex list");
    return Status::Ok();
  }
  // Each vertex costs at least three code words of one bit.
  if (uint64_t(vertex_count) * 3 > bits.bits_remaining())
    return Status(ErrorCode::kLimitExceeded, "POSN: " + std::to_string(vertex_count) +
                                                 " vertices cannot fit in " + std::to_string(size) + " bytes");
  const uint32_t alphabet = uint32_t(info->bits) + 1;
  HuffmanDecoder codes[3];
  for (HuffmanDecoder& code : codes)
    if (Status s = read_table(&bits, alphabet, &code); !s.ok()) return s;
  const int64_t top = (int64_t(1) << info->bits) - 1;
  quantized->resize(size_t(vertex_count) * 3);
  int64_t previous[3] = {0, 0, 0};
  for (size_t i = 0; i < size_t(vertex_count) * 3; ++i) {
    const int axis = int(i % 3);
    const int c = codes[axis].decode(&bits);
    if (c < 0) return Status(ErrorCode::kBadSymbol, "POSN: invalid delta code word");
    const int64_t q = previous[axis] + read_signed_extra(&bits, c);
    if (bits.overrun()) return Status(ErrorCode::kTruncated, "POSN: bit stream ends before the last vertex");
    const bool flat = info->min[axis] == info->max[axis];
    if (q < 0 || q > top || (flat && q != 0))
      return Status(ErrorCode::kBadSymbol, "POSN: vertex " + std::to_string(i / 3) + " axis " +
                                               std::to_string(axis) + " decodes to " + std::to_string(q) +
                                               ", outside 0.." + std::to_string(flat ? 0 : top));
    previous[axis] = q;
    (*quantized)[i] = uint32_t(q);
  }
  if (!bits.at_clean_end()) return bad_payload("bits left over after the last vertex");
  // Section 6.4, the step of each axis computed once; mul() keeps the
  // product out of any fused multiply-add.
  double step[3], lo[3];
  dequantization_steps(*info, lo, step);
  positions->resize(quantized->size());
  for (size_t i = 0; i < quantized->size(); i += 3)
    for (int a = 0; a < 3; ++a) {
      const double scaled = mul(double((*quantized)[i + a]), step[a]);
      (*positions)[i + a] = float(lo[a] + scaled);
    }
  return Status::Ok();
}

}  // namespace qmc
