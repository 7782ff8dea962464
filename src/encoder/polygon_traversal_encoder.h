// Gate-stack traversal of the polygon coder (spec/qmc-format.md 5.4.2): seed
// 001's traversal (§3.2) with every face, of any degree, classified by its
// anchors and gaps. Runs over the closed genus-0 surface of
// polygon_surface.h, one component after the other.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/polygon_symbols.h"
#include "encoder/polygon_surface.h"

namespace qmc {

struct PolygonTraversal {
  std::vector<uint32_t> component_faces, first_degree;  // n_c, d_c
  FaceShapes shapes;                                     // coded faces, stream order
  std::vector<uint32_t> order;     // surface face index -> surface face
  std::vector<uint32_t> rotation;  // per surface face index: corner the output starts at
  std::vector<uint32_t> label;     // surface vertex -> surface label
  uint32_t labels = 0;
};

std::string traverse_polygon_surface(const PolygonSurfaceModel& surface, PolygonTraversal* out);

}  // namespace qmc
