// Checks a decoded file against the mesh that was encoded, under the vertex
// relabelling of spec/qmc-format.md section 5.2.1. Implemented here from the
// spec, independently of the encoder, so that `qmc verify` and the tests
// check the encoder rather than repeat it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/decoder.h"
#include "qmc/mesh.h"

namespace qmc::tools {

// file label -> input vertex index: first reference in face order, then the
// unreferenced vertices in input order.
std::vector<uint32_t> spec_vertex_order(const Mesh& mesh);

struct RoundTripReport {
  bool faces_equal = false;
  std::string face_mismatch;        // first difference, if any
  bool positions_within_bound = false;
  std::string position_mismatch;    // first coordinate outside its bound
  double max_error = 0, rms_error = 0;  // Euclidean, per vertex
  double max_bbox_side = 0;
  bool ok() const { return faces_equal && positions_within_bound; }
};

// Faces must match exactly after relabelling; every coordinate must lie
// within half a quantization step (plus binary32 rounding) of the input.
RoundTripReport check_round_trip(const Mesh& original, const DecodedFile& decoded);

}  // namespace qmc::tools
