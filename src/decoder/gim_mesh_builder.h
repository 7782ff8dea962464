// Rebuilding the mesh of a geometry image (spec/qmc-format.md section 13.9):
// occupied pixels become vertices, seam pairs merge pixels that are the same
// surface point, and faces come from the pixel grid (2 x 2 blocks as quads,
// or triangles split along the shorter diagonal) or, for topology-preserving
// images (seed 002), from an explicit triangle list over pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "qmc/status.h"

namespace qmc {

// Two pixels that are the same surface point (a cut seam); raster indices.
struct SeamPair {
  uint32_t a, b;
};

enum class GimFaceMode : uint8_t {
  kGridQuads = 0,          // every fully occupied 2 x 2 block is a quad
  kGridTriangles = 1,      // ... split along its shorter diagonal
  kExplicitTriangles = 2,  // triangles listed over occupied pixels (seed 002)
};

inline constexpr uint32_t kNoGimVertex = UINT32_MAX;

struct GimTopology {
  std::vector<uint32_t> vertex_of_pixel;  // W * H; kNoGimVertex for blank pixels
  std::vector<uint32_t> pixel_of_vertex;  // output vertex -> its representative pixel
  std::vector<uint32_t> face_sizes;       // 3 or 4
  std::vector<uint32_t> corners;          // over output vertices
};

struct GimTopologyInput {
  uint32_t width = 0, height = 0;
  const std::vector<uint8_t>* occupied = nullptr;  // W * H bytes (0/1); null: all occupied
  const std::vector<SeamPair>* seams = nullptr;    // may be null
  GimFaceMode mode = GimFaceMode::kGridQuads;
  // kGridTriangles: 3 binary64 coordinates per pixel, to choose diagonals.
  const double* xyz = nullptr;
  // kExplicitTriangles: 3 raster indices per triangle.
  const std::vector<uint32_t>* triangles = nullptr;
};

// Validates the input as section 13.9 requires (seams and triangles only on
// occupied pixels, and so on) and builds the mesh's vertices and faces.
Status build_gim_topology(const GimTopologyInput& in, GimTopology* out);

}  // namespace qmc
