// The vertex relabelling of spec/qmc-format.md section 5.2.1.
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/mesh.h"

namespace qmc {

struct VertexOrder {
  std::vector<uint32_t> file_vertex;  // file label -> input index
  std::vector<uint32_t> label;        // input index -> file label
  uint32_t referenced = 0;            // labels below this are used by a face
};

// Labels vertices in order of first appearance in the face list (faces in
// order, corners in order), then unreferenced vertices in input order.
VertexOrder first_reference_order(const Mesh& mesh);

// The mesh with vertices renumbered and positions permuted to file order.
Mesh relabel(const Mesh& mesh, const VertexOrder& order);

}  // namespace qmc
