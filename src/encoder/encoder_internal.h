// Pieces of the encoder entry point (encoder.cc) that the progressive
// encoder (loop_encoder.cc) reuses for its base mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "encoder/polygon_traversal_encoder.h"
#include "qmc/encoder.h"

namespace qmc {

// The connectivity chosen for the file: CONN payload and the mesh in file
// order (positions permuted, faces relabelled and reordered).
struct FileConnectivity {
  ConnectivityMethod method = ConnectivityMethod::kIndexed;
  std::vector<uint8_t> payload;
  Mesh mesh;
  std::vector<uint32_t> file_vertex, face_source;
  int polygon_coding = -1;  // method 2's coding (5.4.4)
};

// The checks of encode() that concern the options alone.
Status validate_options(const EncodeOptions& options);

// Every check of encode() before it codes: the options, then the mesh
// (coordinates, face sizes, corner indices, attributes).
Status validate_input(const Mesh& mesh, const EncodeOptions& options);

// Section 5.1: the quad coder where it applies (kAuto), else the polygon
// coder (its components started as `start` says), else the indexed coding,
// as `options.connectivity` asks.
Status choose_connectivity(const Mesh& mesh, const EncodeOptions& options, FileConnectivity* conn, EncodeStats* st,
                           TraversalStart start = {});

// Section 4.1: the lowest minor version that defines the connectivity and
// the POSN method.
uint8_t minor_version_for(const FileConnectivity& conn, int position_method);

// Appends a chunk and records its size in the stats.
void add_chunk(std::vector<uint8_t>* out, EncodeStats* stats, uint32_t type, const std::vector<uint8_t>& payload);

}  // namespace qmc
