// The data that flows through the geometry-image encoder (seeds 000 and 002):
// input triangle mesh -> disk cut -> parametrization on the image rectangle
// -> samples on the pixel grid -> planes (spec/qmc-format.md section 13).
//
// Plain structs, binary64 throughout; nothing here owns more than vectors.
// Pixel (x, y) of a W x H image has raster index y * W + x; x grows to the
// right, y grows downwards (row 0 is the first row stored).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "decoder/gim_mesh_builder.h"  // SeamPair, GimFaceMode

namespace qmc {

// Triangle mesh of the encoder's geometry-image pipeline.
struct GimTriMesh {
  std::vector<double> positions;    // x0 y0 z0 x1 ...
  std::vector<uint32_t> triangles;  // a0 b0 c0 a1 ... (consistently oriented)
  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return triangles.size() / 3; }
};

// The mesh opened into a topological disk (seed 002 "Euler circuit cutting";
// a long path for genus 0, Gu's cut graph for genus > 0; an input that is
// already a disk is kept as it is).
struct DiskCut {
  // Disk vertex -> vertex of the input mesh. Cut vertices appear more than
  // once; every other vertex exactly once.
  std::vector<uint32_t> original_vertex;
  // The input triangles, same order and orientation, over disk vertices.
  std::vector<uint32_t> triangles;
  // The single boundary loop of the disk, as disk vertices, in the order that
  // keeps the disk on the left (counter-clockwise once flattened).
  std::vector<uint32_t> boundary_loop;
  // For boundary edge i (boundary_loop[i] -> boundary_loop[i + 1 mod n]):
  // the index j of the boundary edge that is the same input edge traversed
  // the other way (a cut edge), or -1 for an edge of the input's own boundary.
  std::vector<int32_t> boundary_mate;
  int genus = 0;
  int input_boundary_loops = 0;
  // Input vertices whose triangles form several fans (pinched, like the
  // cow's): each fan became its own vertex before cutting.
  uint32_t split_fan_vertices = 0;
  // Input edges the cut opened (each is two boundary edges with mates).
  uint32_t cut_edge_count = 0;
};

// A maximal stretch of the disk boundary between two cut nodes (see
// gim_parametrization.h): boundary edges first_edge .. first_edge +
// edge_count - 1 (mod n), and the border pixels it occupies on the image.
// A run and its mate run are the same input edges traversed in opposite
// directions and get the same pixel_steps, so border pixel k of a run and
// pixel pixel_steps - k of its mate are one surface point.
struct GimBorderRun {
  uint32_t first_edge = 0;
  uint32_t edge_count = 0;
  int32_t mate = -1;  // index of the mate run; -1 for the input's own boundary
  uint32_t first_border_pixel = 0;  // index into DiskParametrization::border_pixels
  uint32_t pixel_steps = 0;         // >= 1; the run ends at first_border_pixel + pixel_steps (mod P)
};

// Positions of the disk vertices on the image rectangle, in pixel units:
// u in [0, W - 1], v in [0, H - 1]. Boundary vertices lie on the rectangle's
// border; interior ones are convex combinations of their neighbours
// (Floater's mean-value coordinates).
struct DiskParametrization {
  uint32_t width = 0, height = 0;
  std::vector<double> uv;  // u0 v0 u1 v1 ... per disk vertex
  // Border pixels in counter-clockwise order starting at pixel (0, 0), and
  // for each the arc position along boundary_loop it stands for: edge index
  // plus the fraction along that edge, in [0, n).
  std::vector<uint32_t> border_pixels;
  std::vector<double> border_arc;
  // The boundary runs in boundary-loop order (seam alignment).
  std::vector<GimBorderRun> runs;
};

// A geometry image before quantization.
struct GimSamples {
  uint32_t width = 0, height = 0;
  std::vector<double> xyz;        // 3 per pixel, raster order
  std::vector<uint8_t> occupied;  // 1 per pixel; empty means every pixel is a vertex
  std::vector<SeamPair> seams;
  // Topology-preserving images only: triangles over raster indices.
  std::vector<uint32_t> triangles;
};

}  // namespace qmc
