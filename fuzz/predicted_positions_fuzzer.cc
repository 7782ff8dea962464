// libFuzzer target: a POSN payload (spec sections 6 and 14) against the faces
// of a CONN payload in the same input: u16le length of the CONN payload, the
// CONN payload, then the POSN payload. Methods 1 and 3 - 14 predict every
// vertex from those faces (14.2-14.3; methods 4 - 14 in 14.6's order,
// renamed; 5 and 7 with 14.7's twist of quads; 6 and 7 with 14.8's contexts
// of the candidate decisions; 8 - 14 with the features their byte names,
// 14.9's twist of triangles and its learnt weight among them; 9 - 14 with
// 14.10's mirror candidate, its plane any the payload states; 11 - 14 with
// 14.12's shear, 12 - 14 with 14.13's edges, 13 and 14 with 14.14's
// classes per axis, 14 on 14.15's lattice, its factor any the payload states),
// so any face list CONN accepts, degenerate faces and unreferenced vertices
// included, reaches the predictor. Accepted
// values must lie on the grid the payload declares, every output coordinate
// must be finite, and decoding twice must give the same values.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "conn_prefix.h"
#include "decoder/position_decoder.h"
#include "fuzz_limits.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::Mesh mesh;
  uint32_t vertex_count = 0;
  const uint8_t* payload = nullptr;
  size_t length = 0;
  if (!qmc::fuzz::decode_conn_prefix(data, size, &mesh, &vertex_count, &payload, &length)) return 0;
  if (vertex_count > qmc::fuzz::kMaxVertices) return 0;
  qmc::QuantizationInfo info;
  std::vector<uint32_t> q;
  std::vector<float> positions;
  if (!qmc::decode_positions(payload, length, mesh, vertex_count, &info, &q, &positions).ok()) return 0;
  if (q.size() != 3 * size_t(vertex_count) || positions.size() != q.size()) __builtin_trap();
  for (size_t i = 0; i < q.size(); ++i)
    if (q[i] > info.top[i % 3] || !std::isfinite(positions[i])) __builtin_trap();
  qmc::QuantizationInfo again_info;
  std::vector<uint32_t> again;
  std::vector<float> again_positions;
  if (!qmc::decode_positions(payload, length, mesh, vertex_count, &again_info, &again, &again_positions).ok() ||
      again != q)
    __builtin_trap();
  return 0;
}
