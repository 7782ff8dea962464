// The oRDR chunk (spec/qmc-format.md section 4.5): the encoder input's order
// of vertices, faces and corners, applied to a mesh decoded in coder order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Flags of section 4.5: which maps the chunk carries (a clear flag is the identity).
inline constexpr uint8_t kOrderFaces = 1, kOrderVertices = 2, kOrderRotations = 4;

// The three maps of section 4.5, indexed in file (coder) order. An empty
// vector is the identity (vertex_input, face_input) or all zero (rotation).
struct OrderMaps {
  uint8_t flags = 0;
  std::vector<uint32_t> vertex_input;  // file vertex label -> input vertex index
  std::vector<uint32_t> face_input;    // file face -> input face index
  std::vector<uint32_t> rotation;      // file face -> input corner 0 is file corner rotation
};

// Parses and validates an oRDR payload against the mesh as CONN gave it
// (face_sizes, corners; vertex_count is CONN's). Every rejection is one of
// section 4.5's checks, in its order.
Status decode_order(const uint8_t* payload, size_t size, uint32_t vertex_count, const Mesh& mesh, OrderMaps* maps);

// Puts the vertices (positions and, if it holds 3 per vertex, `quantized`),
// the faces and each face's corners into input order, with the mesh's
// attributes (15.6; attribute_per_vertex[i] != 0 for one of mapping 0, whose
// values move with the vertices). `maps` must come from decode_order on the
// same mesh.
void apply_order(const OrderMaps& maps, Mesh* mesh, std::vector<uint32_t>* quantized,
                 const std::vector<uint8_t>& attribute_per_vertex = {});

}  // namespace qmc
