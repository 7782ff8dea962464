// qmc bench: meshoptimizer (0.18, Debian libmeshoptimizer-dev) run the way
// its users store a mesh, in memory, so that it sits in the same tables as
// qmc and Draco:
//   1. faces fan-triangulated from their first corner (as draco_runner does);
//   2. positions rounded to Draco's grid: one step for all axes, the largest
//      side of the bounding box / (2^bits - 1), from the box's minimum corner;
//      the integers stored as uint16 x 4 (w = 0) up to 16 bits, else uint32 x 3;
//   3. meshopt_optimizeVertexCache, then meshopt_optimizeVertexFetch (which
//      also drops unreferenced vertices);
//   4. meshopt_encodeIndexBuffer (format version 1) and
//      meshopt_encodeVertexBuffer, each stream then compressed by zstd.
// The file is the two zstd frames plus a 28-byte header a reader needs to
// split and dequantize them: index count, vertex count, the first frame's
// size (uint32 each), the grid's origin (3 x float32) and step (float32).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "qmc/mesh.h"

namespace qmc::bench {

struct MeshoptOptions {
  int position_bits = 12;  // 1..30
  int zstd_level = 19;
};

struct MeshoptResult {
  bool ok = false;
  std::string error;
  static constexpr size_t kHeaderBytes = 28;
  size_t bytes = 0;                          // header + both zstd frames
  size_t index_bytes = 0, vertex_bytes = 0;  // the zstd frames
  size_t triangles = 0, vertices = 0;        // as stored (vertices: referenced ones)
  // One entry per run. encode: from the qmc::Mesh to the bytes (steps 1-4).
  // decode: zstd decompression and meshopt's two decoders, to the quantized
  // vertex and index buffers (dequantizing is left to the user's shader, as
  // meshoptimizer's users do; qmc and Draco output floats).
  std::vector<double> encode_seconds, decode_seconds;
};

// The step of Draco's grid for `bits`, which the integers above use: the
// largest side of the bounding box / (2^bits - 1), in Draco's float arithmetic.
double draco_grid_step(const qmc::Mesh& mesh, int bits);

// Encodes and decodes `mesh` `runs` times (runs >= 1), and checks that the
// decoded buffers equal the encoded ones. Fails on input it cannot take: a
// face with fewer than 3 corners, a corner out of range, a non-finite
// coordinate, or options out of range.
MeshoptResult run_meshopt(const qmc::Mesh& mesh, const MeshoptOptions& options, int runs);

}  // namespace qmc::bench
