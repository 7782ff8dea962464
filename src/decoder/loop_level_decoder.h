// Decoder of the progressive chunks LOOP and LEVL (spec/qmc-format.md
// section 12; seed 003 §3.2.3 reconstruction and §4.2 displacement code).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/displacement_coding.h"
#include "decoder/loop_subdivision.h"
#include "qmc/decoder.h"
#include "qmc/status.h"

namespace qmc {

inline constexpr uint8_t kMaxLoopLevels = 8;

// Section 12.1: the LOOP payload; its level count K.
Status decode_loop_header(const uint8_t* payload, size_t size, uint8_t* level_count);

// Section 12.2: the decoded CONN mesh as a level-0 LoopMesh (positions still
// zero), checked and with its edge table.
Status loop_base_connectivity(const Mesh& mesh, uint32_t vertex_count, LoopMesh* base, LoopEdges* edges);

// Section 12.2: the binary64 base positions, 6.4 without the final rounding.
void loop_base_positions(const QuantizationInfo& info, const std::vector<uint32_t>& quantized, LoopMesh* base);

// Sections 12.1 and 12.7 - 12.7.2: one LEVL payload. Fills the displacement
// integers, one per coarse edge, the step, and code 4's corrections; nothing
// is subdivided yet.
struct LevelCode {
  double step = 0;
  std::vector<int8_t> m;  // -127 .. 127 per edge of the coarse level
  double correction_step = 0;                 // code 4
  std::vector<VertexCorrection> corrections;  // code 4, vertices increasing
};
Status decode_level_code(const uint8_t* payload, size_t size, uint8_t expected_level, const LoopEdges& edges,
                         uint32_t coarse_vertices, LevelCode* code);

// Section 12.5 steps 4-5 and 12.7: moves each edge point of `fine` (a
// loop_subdivide result of the coarse level) by m * step along its normal.
void displace_edge_points(const std::vector<double>& normals, const LevelCode& code, uint32_t coarse_vertices,
                          LoopMesh* fine);

// Section 12.7.2 (code 4): adds each correction's offsets times the
// correction step to the vertices of `fine`, after the displacements.
void correct_vertices(const LevelCode& code, LoopMesh* fine);

// Section 12.8: every coordinate finite in binary64 and in binary32.
Status check_level_range(const LoopMesh& level, uint8_t level_index);

// The whole of 12.5-12.8 for one level: coarse + LEVL payload -> fine.
Status decode_level(const uint8_t* payload, size_t size, uint8_t expected_level, const LoopMesh& coarse,
                    const LoopEdges& coarse_edges, LoopMesh* fine);

}  // namespace qmc
