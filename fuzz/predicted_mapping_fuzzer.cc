// libFuzzer target: the mapping stream of aTTR mapping 3 (spec section
// 15.11) over a polygon soup the input describes, so that faces with a
// vertex twice, vertices of high valence and values shared between vertices
// come without a valid CONN. Input: u8 vertex count - 1, u8 face count - 1,
// u16le value count N, then per face a u8 degree (3 + byte % 6) and that many
// u8 vertex labels (mod V), then the stream. A stream decoded without fault
// must give every corner a value below U <= N; the decoded m_k, coded again
// by the encoder's template, must decode to the same m_k.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "common/predicted_mapping.h"
#include "common/range_coder.h"

namespace {

struct Soup {
  uint32_t vertex_count = 0;
  std::vector<uint32_t> face_sizes, corners;
};

// Reads the soup; returns the offset of the stream, or 0 if the input is too short.
size_t read_soup(const uint8_t* data, size_t size, Soup* soup, uint64_t* value_count) {
  if (size < 4) return 0;
  soup->vertex_count = uint32_t(data[0]) + 1;
  const uint32_t faces = uint32_t(data[1]) + 1;
  *value_count = uint64_t(data[2]) | uint64_t(data[3]) << 8;
  size_t at = 4;
  for (uint32_t f = 0; f < faces; ++f) {
    if (at >= size) return 0;
    const uint32_t degree = 3 + data[at++] % 6;
    if (size - at < degree) return 0;
    for (uint32_t i = 0; i < degree; ++i) soup->corners.push_back(data[at++] % soup->vertex_count);
    soup->face_sizes.push_back(degree);
  }
  return at;
}

// Decodes every corner; false on a fault or a truncated stream.
bool decode(const Soup& soup, uint64_t value_count, const uint8_t* stream, size_t size, std::vector<uint32_t>* m,
            uint32_t* met) {
  qmc::RangeDecoder rc(stream, size);
  if (rc.bad_start()) return false;
  qmc::PredictedMappingModel model;
  qmc::PredictedMapping mapping;
  mapping.reset(soup.vertex_count, soup.face_sizes, soup.corners);
  for (size_t k = 0; k < soup.corners.size(); ++k) {
    qmc::MappingFault fault = qmc::MappingFault::kNone;
    m->push_back(mapping.code(&rc, &model, k, value_count, met, nullptr, nullptr, &fault));
    if (fault != qmc::MappingFault::kNone || rc.overrun()) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Soup soup;
  uint64_t value_count = 0;
  const size_t at = read_soup(data, size, &soup, &value_count);
  if (at == 0) return 0;
  std::vector<uint32_t> m;
  uint32_t met = 0;
  if (!decode(soup, value_count, data + at, size - at, &m, &met)) return 0;
  if (met > value_count) std::abort();
  for (uint32_t x : m)
    if (x >= met) std::abort();
  // The encoder's template codes the decoded values back.
  const std::vector<uint8_t> single = qmc::single_value_vertices(soup.corners, m, soup.vertex_count);
  qmc::RangeEncoder rc;
  qmc::PredictedMappingModel model;
  qmc::PredictedMapping mapping;
  mapping.reset(soup.vertex_count, soup.face_sizes, soup.corners);
  uint32_t coded_met = 0;
  for (size_t k = 0; k < m.size(); ++k) {
    qmc::MappingFault fault = qmc::MappingFault::kNone;
    if (mapping.code(&rc, &model, k, value_count, &coded_met, m.data(), &single, &fault) != m[k]) std::abort();
  }
  const std::vector<uint8_t> again = rc.finish();
  std::vector<uint32_t> m2;
  uint32_t met2 = 0;
  if (!decode(soup, value_count, again.data(), again.size(), &m2, &met2) || m2 != m || met2 != met) std::abort();
  return 0;
}
