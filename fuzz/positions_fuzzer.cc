// libFuzzer target: a POSN payload straight into the position decoder (spec
// sections 6 and 14, a mesh without faces, so method 1 predicts every
// vertex from the previous one); the vertex count it must agree with is
// taken from the payload's own first field. Decoded values must respect
// their bounds. fuzz/predicted_positions_fuzzer.cc gives method 1 faces.
#include <cstddef>
#include <cstdint>

#include "common/byte_io.h"
#include "decoder/position_decoder.h"
#include "fuzz_limits.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::ByteReader peek(data, size);
  uint64_t count = 0;
  if (!peek.get_varint(&count) || count > UINT32_MAX) return 0;
  // 14.1's bound alone lets 28 KB claim 10.6 M vertices, 127 MB of
  // integers (regressions/positions/).
  if (count > qmc::fuzz::kMaxVertices) return 0;
  qmc::QuantizationInfo info;
  std::vector<uint32_t> q;
  std::vector<float> positions;
  if (!qmc::decode_positions(data, size, qmc::Mesh{}, uint32_t(count), &info, &q, &positions).ok()) return 0;
  if (q.size() != 3 * count || positions.size() != q.size()) __builtin_trap();
  for (size_t i = 0; i < q.size(); ++i)
    if (q[i] > info.top[i % 3]) __builtin_trap();
  return 0;
}
