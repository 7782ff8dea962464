// Connectivity method 2 (spec/qmc-format.md 5.4): surface, traversal and
// the records that give the input back, written as one CONN payload.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/polygon_symbols.h"
#include "encoder/polygon_traversal_encoder.h"
#include "qmc/format.h"
#include "qmc/mesh.h"

namespace qmc {

struct PolygonEncoding {
  std::vector<uint8_t> payload;
  Mesh file_mesh;                      // faces in file order and file labels (no positions)
  std::vector<uint32_t> file_vertex;   // file label -> input vertex
  std::vector<uint32_t> face_source;   // file face -> input face
  uint8_t coding = 0;
  std::array<int64_t, kPolygonCodingCount> coding_bits{};  // symbol bits per coding, -1 where not applicable
  uint32_t components = 0, holes = 0, handles = 0, identifications = 0, loose_faces = 0;
  uint32_t non_quad_faces = 0;
  std::array<uint32_t, kPolygonSymbolCount> symbol_counts{};  // coded faces per symbol (5.4.3)
  uint64_t record_bits = 0;            // virtual faces, seams, identifications, loose faces
};

// Returns "" or why the mesh cannot go through method 2. `forced` is a
// coding 0..5, 7 or 8, or -1 for the smallest.
// `context_coding`: coding 7 may be the smallest (5.4.10, format 1.6), and
// with `quad_contexts` coding 8 too (format 1.18).
// `unused_along_curve`: vertices no face uses follow a Z-order curve
// (sort_along_curve), else the input's order. `start`: each component's
// first face (polygon_traversal_encoder.h).
std::string encode_polygon_connectivity(const Mesh& mesh, int forced, bool context_coding, bool quad_contexts,
                                        bool unused_along_curve, PolygonEncoding* out, TraversalStart start = {});

}  // namespace qmc
