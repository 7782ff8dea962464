// libFuzzer target: a CONN payload straight into the connectivity decoder
// (spec section 5), past the CRC that shields it in whole files. A decoded
// face list must be consistent: degrees >= 3, labels below vertex_count.
#include <cstddef>
#include <cstdint>

#include "decoder/connectivity_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  qmc::Mesh mesh;
  uint32_t vertex_count = 0;
  qmc::ConnectivityMethod method;
  if (!qmc::decode_connectivity(data, size, &vertex_count, &method, &mesh).ok()) return 0;
  size_t corners = 0;
  for (uint32_t d : mesh.face_sizes) {
    if (d < 3) __builtin_trap();
    corners += d;
  }
  if (corners != mesh.corners.size()) __builtin_trap();
  for (uint32_t v : mesh.corners)
    if (v >= vertex_count) __builtin_trap();
  return 0;
}
