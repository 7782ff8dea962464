// Indexed connectivity decoding, spec/qmc-format.md section 5.2. Every count
// is checked against the bits present before anything is allocated, and
// every corner label against the labels issued so far.
#include "decoder/indexed_connectivity_decoder.h"

#include <string>

#include "common/bit_reader.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"
#include "common/recent_vertex_list.h"

namespace qmc {
namespace {

constexpr uint32_t kCornerNew = 0;
constexpr uint32_t kCornerRecentBase = 1;
constexpr uint32_t kCornerBackBase = kCornerRecentBase + RecentVertexList::kCapacity - 1;
constexpr uint32_t kCornerAlphabet = kCornerBackBase + 33;

Status bad(const std::string& message) { return Status(ErrorCode::kBadSymbol, "CONN: " + message); }
Status truncated() { return Status(ErrorCode::kTruncated, "CONN: bit stream ends before the last face"); }

// Resolves one corner symbol to a vertex label (section 5.2.3).
Status decode_corner(BitReader* bits, const HuffmanDecoder& code, const RecentVertexList& recent,
                     uint32_t vertex_count, uint32_t* next_label, uint32_t* label) {
  const int symbol = code.decode(bits);
  if (symbol < 0) return bad("invalid corner code word");
  if (uint32_t(symbol) == kCornerNew) {
    if (*next_label >= vertex_count)
      return bad("corner introduces vertex " + std::to_string(*next_label) + " but vertex_count is " +
                 std::to_string(vertex_count));
    *label = (*next_label)++;
  } else if (uint32_t(symbol) <= kCornerBackBase) {
    const int slot = symbol - int(kCornerRecentBase);
    if (slot >= recent.size())
      return bad("recent-vertex slot " + std::to_string(slot) + " of a list of " + std::to_string(recent.size()));
    *label = recent.at(slot);
  } else {
    const uint32_t distance = read_magnitude_extra(bits, int(uint32_t(symbol) - kCornerBackBase));
    if (distance > *next_label)
      return bad("back distance " + std::to_string(distance) + " exceeds the " + std::to_string(*next_label) +
                 " vertices seen");
    *label = *next_label - distance;
  }
  return Status::Ok();
}

}  // namespace

Status decode_indexed_connectivity(const uint8_t* data, size_t size, uint32_t vertex_count,
                                   uint32_t face_count, Mesh* mesh) {
  mesh->face_sizes.clear();
  mesh->corners.clear();
  BitReader bits(data, size);
  if (face_count == 0) {
    if (!bits.at_clean_end()) return Status(ErrorCode::kBadChunkPayload, "CONN: data after an empty face list");
    return Status::Ok();
  }
  // Each face costs at least 4 bits: one degree and three corner code words.
  if (uint64_t(face_count) * 4 > bits.bits_remaining())
    return Status(ErrorCode::kLimitExceeded, "CONN: " + std::to_string(face_count) +
                                                 " faces cannot fit in " + std::to_string(size) + " bytes");
  HuffmanDecoder degree_code, corner_code;
  if (Status s = read_table(&bits, kMagnitudeClasses, &degree_code); !s.ok()) return s;
  if (Status s = read_table(&bits, kCornerAlphabet, &corner_code); !s.ok()) return s;

  mesh->face_sizes.reserve(face_count);
  mesh->corners.reserve(size_t(face_count) * 3);
  RecentVertexList recent;
  uint32_t next_label = 0;
  for (uint32_t f = 0; f < face_count; ++f) {
    const int c = degree_code.decode(&bits);
    if (c < 0) return bad("invalid degree code word");
    const uint64_t degree = uint64_t(read_magnitude_extra(&bits, c)) + 3;
    if (bits.overrun()) return truncated();
    if (degree > bits.bits_remaining() || degree > UINT32_MAX)
      return Status(ErrorCode::kLimitExceeded, "CONN: face " + std::to_string(f) + " of degree " +
                                                   std::to_string(degree) + " cannot fit in the bits left");
    mesh->face_sizes.push_back(uint32_t(degree));
    for (uint64_t i = 0; i < degree; ++i) {
      uint32_t label = 0;
      if (Status s = decode_corner(&bits, corner_code, recent, vertex_count, &next_label, &label); !s.ok())
        return s;
      recent.touch(label);
      mesh->corners.push_back(label);
    }
    if (bits.overrun()) return truncated();
  }
  if (!bits.at_clean_end())
    return Status(ErrorCode::kBadChunkPayload, "CONN: bits left over after the last face");
  return Status::Ok();
}

}  // namespace qmc
