// qmc: the polygon mesh that goes into the encoder and comes out of the decoder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc {

// A polygon soup: positions plus faces given as vertex-index cycles.
// Face f has face_sizes[f] corners, stored consecutively in `corners`.
// Nothing here requires the mesh to be manifold, oriented or free of
// unreferenced vertices: every container of the format can carry it.
struct Mesh {
  std::vector<float> positions;      // x0 y0 z0 x1 y1 z1 ...
  std::vector<uint32_t> face_sizes;  // degree of each face, >= 3
  std::vector<uint32_t> corners;     // concatenated face cycles

  size_t vertex_count() const { return positions.size() / 3; }
  size_t face_count() const { return face_sizes.size(); }
};

}  // namespace qmc
