// The opposite-edge (OE) table of seed 001 §3.1: for every edge of every
// quad, the matching edge of the quad across it (or none on the boundary),
// plus the checks that decide whether a mesh is in the quad coder's scope
// (spec/qmc-format.md section 5.3.1).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/mesh.h"

namespace qmc {

inline constexpr uint32_t kNoEdge = UINT32_MAX;

// Edge 4f + i of quad f runs from corner i to corner (i + 1) % 4.
struct OppositeEdgeTable {
  std::vector<uint32_t> across;  // edge -> the same edge in the neighbouring quad, or kNoEdge
  uint32_t boundary_loops = 0;
  uint32_t components = 0;
  int64_t euler_characteristic = 0;  // V - E + F over referenced vertices

  static uint32_t quad_of(uint32_t edge) { return edge / 4; }
  static uint32_t next(uint32_t edge) { return (edge & ~3u) | ((edge + 1) & 3u); }
  static uint32_t prev(uint32_t edge) { return (edge & ~3u) | ((edge + 3) & 3u); }
};

// Builds the table. Returns an empty string if the mesh is all quads,
// manifold and consistently oriented, else the reason it is not.
std::string build_opposite_edge_table(const Mesh& mesh, OppositeEdgeTable* table);

}  // namespace qmc
