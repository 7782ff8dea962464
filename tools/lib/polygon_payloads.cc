#include "polygon_payloads.h"

#include "common/byte_io.h"

namespace qmc::tools {

std::vector<uint8_t> coding7_conn(uint32_t vertices, uint32_t faces, uint8_t groups,
                                  const std::vector<uint8_t>& symbols,
                                  const std::function<void(BitWriter*)>& stream, uint64_t length_extra, int coding) {
  std::vector<uint8_t> p{uint8_t(ConnectivityMethod::kPolygon)};
  put_varint(&p, vertices);
  put_varint(&p, faces);
  p.push_back(0);
  p.push_back(uint8_t(coding));
  p.push_back(groups);
  put_varint(&p, symbols.size() + length_extra);
  p.insert(p.end(), symbols.begin(), symbols.end());
  BitWriter bits;
  stream(&bits);
  const std::vector<uint8_t> raw = bits.finish();
  p.insert(p.end(), raw.begin(), raw.end());
  return p;
}

std::vector<uint8_t> coding7_symbols(uint8_t groups, const std::function<void(RangeEncoder*, PolygonSymbolModel*)>& body,
                                     bool quad_neighbours) {
  RangeEncoder range;
  PolygonSymbolModel model;
  model.groups = groups;
  model.quad_neighbours = quad_neighbours;
  body(&range, &model);
  return range.finish();
}

}  // namespace qmc::tools
