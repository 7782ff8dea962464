// Gate-stack traversal of the polygon coder (spec/qmc-format.md 5.4.2): seed
// 001's traversal (§3.2) with every face, of any degree, classified by its
// anchors and gaps. Runs over the closed genus-0 surface of
// polygon_surface.h, one component after the other.
#pragma once

#include <array>
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

// Which first face each component starts from, and at which corner (5.4.2
// leaves both to the encoder). Start t takes, among the component's
// candidates (its virtual faces by index if it has any, a closed hole,
// else its faces in the order a flood from its lowest face reaches them),
// the one at the fraction frac(t / phi) of the list (a Weyl sequence: any
// first n starts are spread over it), with c0 its corner t mod d. Start 0 is
// the usual one: the first virtual face, else the lowest face, at corner 0.
struct TraversalStart {
  uint32_t trial = 0;
};

// Component 0's first two labels under starts 0 .. starts - 1 (one flood):
// the surface vertices c1 and c0 of its first face, which the decoder
// outputs as vertices 0 and 1. Empty for a surface without faces.
std::vector<std::array<uint32_t, 2>> first_labels(const PolygonSurfaceModel& surface, uint32_t starts);

std::string traverse_polygon_surface(const PolygonSurfaceModel& surface, PolygonTraversal* out,
                                     TraversalStart start = {});

}  // namespace qmc
