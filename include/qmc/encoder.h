// qmc encoder: polygon mesh in, .qmc bytes out.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "qmc/format.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

// Which connectivity coding to use (section 5.1).
enum class ConnectivityChoice : uint8_t {
  kAuto,     // the quad coder where the mesh is in its scope, else the polygon coder
  kIndexed,  // always the indexed coding
  kQuad,     // the quad coder or an error naming why it cannot be used
  kPolygon,  // always the polygon coder (section 5.4)
};

struct EncodeOptions {
  int position_bits = kDefaultPositionBits;  // 1..30, section 6.1
  ConnectivityChoice connectivity = ConnectivityChoice::kAuto;
  // Quad coder only: force a coding (0..4, section 5.3.5); -1 picks the
  // smallest. A forced coding that cannot express the mesh is an error.
  int quad_coding = -1;
  // Polygon coder only: force a coding (0..5, section 5.4.4); -1 picks the smallest.
  int polygon_coding = -1;
  std::vector<std::string> texts;            // written as teXt chunks ("key=value")
  // Write an oRDR chunk (section 4.5) so that the decoder restores the
  // input's order of vertices, faces and corners exactly; nothing is
  // written when the coder order already is the input's order.
  bool keep_order = false;
};

struct ChunkStats {
  uint32_t type = 0;
  uint64_t bytes = 0;  // whole chunk: 12 bytes of framing plus the payload
};

struct QuadCoderStats {
  bool closed = false;                   // a quad was cut open (closed mesh)
  uint8_t coding = 0;                    // chosen coding, spec 5.3.5
  std::array<int64_t, 5> coding_bits{};  // symbol-stream bits per coding; -1 = not applicable
  uint32_t claim_violations = 0;         // Q5/Q10/Q12/Q13 followed by Q1-Q5
  std::array<uint32_t, 14> type_counts{};  // index 1..13
};

struct PolygonCoderStats {
  uint8_t coding = 0;                    // chosen coding, spec 5.4.4
  std::array<int64_t, 6> coding_bits{};  // face-symbol bits per coding; -1 = not applicable
  uint32_t components = 0, holes = 0, handles = 0, identifications = 0, loose_faces = 0;
  uint32_t non_quad_faces = 0;
  uint64_t record_bits = 0;              // bits of the records of 5.4.7 and 5.4.8
};

struct EncodeStats {
  ConnectivityMethod method = ConnectivityMethod::kIndexed;
  std::string fallback_reason;  // why the quad coder was not used (kAuto), empty if it was
  std::string polygon_fallback_reason;  // why the polygon coder was not used either (never expected)
  QuadCoderStats quad;          // filled when method == kQuad
  PolygonCoderStats polygon;    // filled when method == kPolygon
  std::vector<ChunkStats> chunks;
  uint64_t total_bytes = 0;
  // Vertex order of the file: file_vertex[i] is the input index of the
  // vertex the decoder will output as vertex i (sections 5.2.1, 5.3.4) in
  // coder order, i.e. before an oRDR chunk (keep_order) is applied.
  std::vector<uint32_t> file_vertex;
  // Face order of the file: face_source[i] is the input index of the face
  // the decoder will output as face i.
  std::vector<uint32_t> face_source;
};

// Encodes `mesh`. Fails (never silently drops anything) on input the format
// cannot carry: non-finite coordinates, faces with fewer than 3 corners,
// corner indices out of range, more than 2^32 - 1 vertices or faces.
Status encode(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out,
              EncodeStats* stats = nullptr);

}  // namespace qmc
