// qmc bench: runs Google Draco (1.5.5) on a qmc::Mesh entirely in memory, so
// that benchmarks compare codecs on identical input without any file format
// in between.
//
// The mesh handed to Draco mirrors what Draco's own OBJ loader builds, and
// the bytes equal draco_encoder's (-qp 12 -cl 10 [-preserve_polygons]) on the
// same positions-only OBJ: faces fan-triangulated from their first corner,
// and with preserve_polygons an "added_edges" attribute (per corner: is the
// opposite edge a triangulation diagonal?) that the decoding side uses to
// merge the fans back into polygons. Differences: positions are one value per
// qmc vertex, where the OBJ loader merges equal coordinates; and faces of any
// size are accepted, where the 1.5.5 OBJ loader rejects more than 8 corners.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "qmc/mesh.h"

namespace qmc::bench {

struct DracoOptions {
  int position_bits = 12;       // 1..30; 0 leaves positions unquantized (lossless)
  int compression_level = 10;   // 0..10; encoder and decoder speed are 10 - level.
                                // Always edgebreaker: draco_encoder would switch to
                                // its sequential method at level 0.
  bool preserve_polygons = false;
  // Every position replaced by (0,0,0): a constant attribute codes to a few
  // bytes, so the file is essentially the connectivity (and polygon flags)
  // plus Draco's header. Draco has no separate connectivity stream; its
  // positions cost the real file's bytes minus this one's.
  bool positions_at_origin = false;
  // After the timed runs, one more decode from a heap handed back to the
  // system (bench/cold_heap.h), timed into cold_decode_seconds.
  bool cold_heap_decode = false;
};

struct DracoResult {
  bool ok = false;
  std::string error;
  size_t bytes = 0;
  // One entry per run. encode: EncodeMeshToBuffer only (building the
  // draco::Mesh is not timed). decode: DecodeMeshFromBuffer only (turning
  // the draco::Mesh back into a qmc::Mesh is not timed).
  std::vector<double> encode_seconds, decode_seconds;
  double cold_decode_seconds = 0;  // with cold_heap_decode
  // As a polygon mesh when polygons were preserved, else triangles. Vertex
  // order is Draco's; vertices may be split (non-manifold) or missing
  // (unreferenced), so compare with nearest_vertex_error.
  qmc::Mesh decoded;

  // What Draco silently loses, made visible. Draco's edgebreaker skips every
  // triangle that has a repeated vertex; the OBJ-style polygon attribute then
  // cannot always rebuild the face it came from.
  size_t input_triangles = 0;        // triangles handed to Draco after fan triangulation
  size_t degenerate_triangles = 0;   // of those, with a repeated vertex: expected to be dropped
  size_t dropped_triangles = 0;      // input_triangles minus triangles decoded (measured)
  size_t dropped_faces = 0;          // input faces with no non-degenerate triangle: gone entirely
  size_t damaged_faces = 0;          // input faces that lost some but not all of their triangles
  size_t unreferenced_vertices = 0;  // input vertices no kept triangle uses: Draco does not store them
  size_t unrecovered_polygons = 0;   // decoded triangle groups that did not close into one polygon
                                     // (emitted as separate triangles instead)
};

// Encodes and decodes `mesh` `runs` times (runs >= 1). Fails on input Draco
// cannot take: no faces, a face with fewer than 3 corners, a corner index out
// of range, a non-finite coordinate, or options out of range.
DracoResult run_draco(const qmc::Mesh& mesh, const DracoOptions& options, int runs);

}  // namespace qmc::bench
