// A test mesh as the progressive coder's triangle mesh (spec 12): polygons
// fanned into triangles (tools::triangulated), positions widened to binary64.
#pragma once

#include "decoder/loop_subdivision.h"
#include "mesh_generators.h"
#include "qmc/mesh.h"

namespace qmc {

inline LoopMesh loop_mesh_of(const Mesh& polygons) {
  const Mesh m = tools::triangulated(polygons);
  LoopMesh out;
  out.positions.assign(m.positions.begin(), m.positions.end());
  out.triangles = m.corners;
  return out;
}

}  // namespace qmc
