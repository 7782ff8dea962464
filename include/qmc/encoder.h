// qmc encoder: polygon mesh in, .qmc bytes out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/format.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

struct EncodeOptions {
  int position_bits = kDefaultPositionBits;  // 1..30, section 6.1
  std::vector<std::string> texts;            // written as teXt chunks ("key=value")
};

struct ChunkStats {
  uint32_t type = 0;
  uint64_t bytes = 0;  // whole chunk: 12 bytes of framing plus the payload
};

struct EncodeStats {
  ConnectivityMethod method = ConnectivityMethod::kIndexed;
  std::vector<ChunkStats> chunks;
  uint64_t total_bytes = 0;
  // Vertex order of the file: file_vertex[i] is the input index of the
  // vertex the decoder will output as vertex i (section 5.2.1 relabelling).
  std::vector<uint32_t> file_vertex;
};

// Encodes `mesh`. Fails (never silently drops anything) on input the format
// cannot carry: non-finite coordinates, faces with fewer than 3 corners,
// corner indices out of range, more than 2^32 - 1 vertices or faces.
Status encode(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out,
              EncodeStats* stats = nullptr);

}  // namespace qmc
