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

// Sorts `vertices` (indices into mesh.positions) along a Z-order curve over
// their bounding box, ties in input order. Vertices no face uses
// get the last labels, in an order the polygon and quad coders' encoders
// choose (spec 5.4.9); predicted from the vertex before (14.3.2), so
// neighbours on the curve cost far fewer bits than the input's order
// (stanford-bunny's 1,113 unused vertices: see docs/results/compression.md).
void sort_along_curve(const Mesh& mesh, std::vector<uint32_t>* vertices);

// The mesh with vertices renumbered and positions permuted to file order.
Mesh relabel(const Mesh& mesh, const VertexOrder& order);

}  // namespace qmc
