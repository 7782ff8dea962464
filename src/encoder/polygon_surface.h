// Makes any polygon mesh into the closed, oriented, manifold, genus-0
// surface that the polygon coder traverses (spec/qmc-format.md 5.4, 5.4.9):
// faces that repeat a vertex become loose faces; edges are paired only when
// used once in each direction; each vertex gets one copy per fan; holes are
// closed by virtual faces; each handle is cut along a non-separating cycle
// of a tree-cotree decomposition (Eppstein 2003) into a seam of two virtual
// faces.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/mesh.h"

namespace qmc {

inline constexpr uint32_t kVirtualFace = UINT32_MAX;

struct PolygonSurfaceModel {
  // Face f has corners face_begin[f] .. face_begin[f + 1] - 1; half-edge k
  // runs from corner k to the next corner of its face.
  std::vector<uint32_t> face_begin{0};
  std::vector<uint32_t> corners;     // surface vertex ids
  std::vector<uint32_t> source;      // input face, or kVirtualFace
  std::vector<uint32_t> twin;        // per half-edge
  std::vector<uint32_t> face_of;     // per half-edge
  // Per half-edge, the next one of its face: the searches of 5.4.9 turn
  // around vertices by twin and next millions of times on meshes of a few
  // handles, and a table lookup is one load where the face's range is three.
  std::vector<uint32_t> next_edge;
  std::vector<uint32_t> original;    // surface vertex -> input vertex
  // Seams: virtual faces a and b whose corner i and corner (shift - i) mod d
  // are the two sides of one cut vertex.
  struct Seam {
    uint32_t a, b, shift;
  };
  std::vector<Seam> seams;
  std::vector<uint32_t> loose;       // input faces kept out of the surface
  uint32_t holes = 0, handles = 0, vertex_copies = 0;

  uint32_t face_count() const { return uint32_t(source.size()); }
  uint32_t degree(uint32_t f) const { return face_begin[f + 1] - face_begin[f]; }
  uint32_t next(uint32_t h) const { return next_edge[h]; }
  uint32_t prev(uint32_t h) const {
    const uint32_t f = face_of[h];
    return h == face_begin[f] ? face_begin[f + 1] - 1 : h - 1;
  }
  uint32_t vertex_count() const { return uint32_t(original.size()); }
};

// Builds the surface; returns "" or why it cannot (never expected for valid
// input; the encoder then falls back and says so).
std::string build_polygon_surface(const Mesh& mesh, PolygonSurfaceModel* surface);

}  // namespace qmc
