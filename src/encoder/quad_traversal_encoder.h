// Gate-stack traversal of seed 001 §3.2 (Program 1), after Kronrod and
// Gotsman: every quad is classified as one of Q1..Q13 by how it meets the
// boundary of the part not yet encoded (spec/qmc-format.md section 5.3.3).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "qmc/mesh.h"

namespace qmc {

struct QuadTraversal {
  bool closed = false;                // a quad was cut open to make the first boundary
  std::vector<uint8_t> types;         // Q-types, compression order
  std::vector<uint32_t> file_vertex;  // file label -> input vertex (section 5.3.4)
  std::vector<uint32_t> faces;        // 4 file labels per quad, in the decoder's output order
  std::vector<uint32_t> face_source;  // output quad -> input face
  uint32_t claim_violations = 0;      // Q5, Q10, Q12, Q13 followed by Q1..Q5 (seed 001 §4.1)
};

// Runs the traversal. Returns "" on success, otherwise why the mesh is
// outside the scope of connectivity method 1 (it then goes through the
// indexed coding).
std::string encode_quad_traversal(const Mesh& mesh, QuadTraversal* out);

}  // namespace qmc
