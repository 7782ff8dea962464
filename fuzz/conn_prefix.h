// Input layout shared by the fuzz targets that need a mesh: u16le length of
// a CONN payload, the CONN payload, then the payload under test.
#pragma once

#include <cstddef>
#include <cstdint>

#include "decoder/connectivity_decoder.h"

namespace qmc::fuzz {

// Decodes the CONN prefix; false if it is cut short or CONN rejects it.
inline bool decode_conn_prefix(const uint8_t* data, size_t size, Mesh* mesh, uint32_t* vertex_count,
                               const uint8_t** rest, size_t* rest_size) {
  if (size < 2) return false;
  const size_t conn_size = data[0] | size_t(data[1]) << 8;
  if (size - 2 < conn_size) return false;
  ConnectivityMethod method;
  if (!decode_connectivity(data + 2, conn_size, vertex_count, &method, mesh).ok()) return false;
  *rest = data + 2 + conn_size;
  *rest_size = size - 2 - conn_size;
  return true;
}

}  // namespace qmc::fuzz
