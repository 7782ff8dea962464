// Indexed connectivity coding of spec/qmc-format.md section 5.2: face
// degrees as magnitude classes, corners as "new vertex", a slot of the
// recent-vertex list, or a back distance to an older label.
#include "encoder/indexed_connectivity_encoder.h"

#include "common/bit_writer.h"
#include "common/byte_io.h"
#include "common/huffman.h"
#include "common/magnitude_code.h"
#include "common/recent_vertex_list.h"
#include "qmc/format.h"

namespace qmc {
namespace {

constexpr uint32_t kCornerNew = 0;
constexpr uint32_t kCornerRecentBase = 1;  // + slot, 0..31
constexpr uint32_t kCornerBackBase = kCornerRecentBase + RecentVertexList::kCapacity - 1;  // + class 1..32
constexpr uint32_t kCornerAlphabet = kCornerBackBase + 33;

// One corner reduced to its symbol and the value its extra bits carry.
struct CornerSymbol {
  uint32_t symbol;
  uint32_t back_distance;  // only for back references
};

std::vector<CornerSymbol> corner_symbols(const Mesh& mesh) {
  std::vector<CornerSymbol> out;
  out.reserve(mesh.corners.size());
  RecentVertexList recent;
  uint32_t next_label = 0;
  for (uint32_t v : mesh.corners) {
    if (v == next_label) {
      out.push_back({kCornerNew, 0});
      ++next_label;
    } else if (int slot = recent.find(v); slot >= 0) {
      out.push_back({kCornerRecentBase + uint32_t(slot), 0});
    } else {
      const uint32_t d = next_label - v;
      out.push_back({kCornerBackBase + uint32_t(magnitude_class(d)), d});
    }
    recent.touch(v);
  }
  return out;
}

}  // namespace

std::vector<uint8_t> encode_indexed_connectivity(const Mesh& mesh) {
  std::vector<uint8_t> payload;
  put_u8(&payload, uint8_t(ConnectivityMethod::kIndexed));
  put_varint(&payload, mesh.vertex_count());
  put_varint(&payload, mesh.face_count());
  if (mesh.face_count() == 0) return payload;

  const std::vector<CornerSymbol> corners = corner_symbols(mesh);
  std::vector<uint64_t> degree_freq(kMagnitudeClasses, 0), corner_freq(kCornerAlphabet, 0);
  for (uint32_t d : mesh.face_sizes) ++degree_freq[magnitude_class(d - 3)];
  for (const CornerSymbol& c : corners) ++corner_freq[c.symbol];
  const std::vector<uint8_t> degree_lengths = huffman_code_lengths(degree_freq);
  const std::vector<uint8_t> corner_lengths = huffman_code_lengths(corner_freq);
  const HuffmanEncoder degree_code(degree_lengths), corner_code(corner_lengths);

  BitWriter bits;
  write_code_lengths(&bits, degree_lengths);
  write_code_lengths(&bits, corner_lengths);
  size_t k = 0;
  for (uint32_t degree : mesh.face_sizes) {
    const int c = magnitude_class(degree - 3);
    degree_code.write(&bits, uint32_t(c));
    write_magnitude_extra(&bits, degree - 3, c);
    for (uint32_t i = 0; i < degree; ++i, ++k) {
      corner_code.write(&bits, corners[k].symbol);
      if (corners[k].symbol >= kCornerBackBase + 1) {
        write_magnitude_extra(&bits, corners[k].back_distance, int(corners[k].symbol - kCornerBackBase));
      }
    }
  }
  const std::vector<uint8_t> stream = bits.finish();
  payload.insert(payload.end(), stream.begin(), stream.end());
  return payload;
}

}  // namespace qmc
