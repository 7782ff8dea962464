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

// Which input vertex and face each decoded vertex and face stands for.
struct Correspondence {
  std::vector<uint32_t> file_vertex;  // decoded vertex -> input vertex
  std::vector<uint32_t> face_source;  // decoded face -> input face
  bool exact_corners = false;         // each face must start at its source's first corner
};

// The input's own order (a file whose oRDR chunk was applied, spec 4.5):
// identity maps, faces compared corner by corner without rotation.
Correspondence identity_correspondence(const Mesh& original);

// The correspondence the spec defines for `method`: section 5.2.1 for the
// indexed coding, the traversal of section 5.3.3-5.3.4 for the quad coder.
bool spec_correspondence(const Mesh& original, ConnectivityMethod method, Correspondence* c, std::string* why);

struct RoundTripReport {
  bool faces_equal = false;
  std::string face_mismatch;        // first difference, if any
  bool positions_within_bound = false;
  std::string position_mismatch;    // first coordinate outside its bound
  double max_error = 0, rms_error = 0;  // Euclidean, per vertex
  double max_bbox_side = 0;
  bool ok() const { return faces_equal && positions_within_bound; }
};

// Every decoded face must be its source face relabelled (for the quad coder
// possibly starting at another corner unless c.exact_corners, never
// reversed); every coordinate
// must lie within half a quantization step (plus binary32 rounding) of the
// input, or k steps on POSN method 14's lattice of factor k (spec 14.15).
RoundTripReport check_round_trip(const Mesh& original, const DecodedFile& decoded, const Correspondence& c);
// The same with the spec's correspondence for the file's method, or the
// identity_correspondence when the decoder applied an oRDR chunk.
RoundTripReport check_round_trip(const Mesh& original, const DecodedFile& decoded);

}  // namespace qmc::tools
