// CONN header of spec/qmc-format.md section 5.1 and dispatch on its method.
#include "decoder/connectivity_decoder.h"

#include <string>

#include "common/byte_io.h"
#include "decoder/indexed_connectivity_decoder.h"
#include "decoder/polygon_connectivity_decoder.h"
#include "decoder/quad_connectivity_decoder.h"

namespace qmc {

Status read_connectivity_header(const uint8_t* payload, size_t size, uint8_t* method, uint64_t* vertex_count,
                                uint64_t* face_count, size_t* method_data) {
  ByteReader in(payload, size);
  if (!in.get_u8(method)) return Status(ErrorCode::kBadChunkPayload, "CONN payload is empty");
  if (*method > uint8_t(ConnectivityMethod::kPolygon))
    return Status(ErrorCode::kUnsupportedFeature, "connectivity method " + std::to_string(*method));
  if (!in.get_varint(vertex_count) || *vertex_count > UINT32_MAX)
    return Status(ErrorCode::kBadChunkPayload, "CONN vertex_count missing, malformed or above 2^32 - 1");
  if (!in.get_varint(face_count) || *face_count > UINT32_MAX)
    return Status(ErrorCode::kBadChunkPayload, "CONN face_count missing, malformed or above 2^32 - 1");
  *method_data = size - in.remaining();
  return Status::Ok();
}

Status decode_connectivity(const uint8_t* payload, size_t size, uint32_t* vertex_count,
                           ConnectivityMethod* method, Mesh* mesh, QuadConnectivityInfo* quad_info,
                           PolygonConnectivityInfo* polygon_info, const OutputBudget* budget) {
  uint8_t method_id = 0;
  uint64_t vertices = 0, faces = 0;
  size_t start = 0;
  if (Status s = read_connectivity_header(payload, size, &method_id, &vertices, &faces, &start); !s.ok()) return s;
  ByteReader in(payload + start, size - start);
  Status s;
  if (method_id == uint8_t(ConnectivityMethod::kIndexed)) {
    s = decode_indexed_connectivity(in.cursor(), in.remaining(), uint32_t(vertices), uint32_t(faces), mesh);
  } else if (method_id == uint8_t(ConnectivityMethod::kPolygon)) {
    PolygonConnectivityInfo polygon;
    s = decode_polygon_connectivity(in.cursor(), in.remaining(), uint32_t(vertices), uint32_t(faces), mesh, &polygon,
                                    budget);
    if (polygon_info) *polygon_info = polygon;
  } else {
    QuadConnectivityInfo quad;
    s = decode_quad_connectivity(in.cursor(), in.remaining(), uint32_t(vertices), uint32_t(faces), mesh, &quad);
    if (quad_info) *quad_info = quad;
  }
  if (!s.ok()) return s;
  *vertex_count = uint32_t(vertices);
  *method = ConnectivityMethod(method_id);
  return Status::Ok();
}

}  // namespace qmc
