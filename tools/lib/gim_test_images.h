// qmc tools: small geometry images made from formulas, for tests and the
// conformance vectors of spec section 13 (no generator pipeline involved, so
// the vectors depend only on the format).
#pragma once

#include <cstdint>

#include "geometry/gim_types.h"

namespace qmc::tools {

// A torus (radii 2 and 1) on an n x n grid whose last row and column repeat
// the first, closed by seam pairs (13.7): (n - 1)^2 vertices, genus 1.
GimSamples make_torus_geometry_image(uint32_t n);

// A paraboloid cap on an n x n grid, pixels outside the inscribed disk blank.
GimSamples make_disk_geometry_image(uint32_t n);

// A topology-preserving image (seed 002 style): a triangulated square with
// vertices on a sparse set of pixels of an n x n image (n >= 5), a few
// pixels blank between them, and the triangles listed over pixels.
GimSamples make_sparse_triangle_image(uint32_t n);

}  // namespace qmc::tools
