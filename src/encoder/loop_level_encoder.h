// The LEVL chunk on the encoder side (spec/qmc-format.md sections 12.1,
// 12.7, 12.10): seed 003 §3.2.2's scalar displacements, quantized by §4.2's
// 7-bit magnitudes, computed in a closed loop from the decoder's own
// reconstruction of the level below so that quantization errors never
// accumulate across levels.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "decoder/loop_level_decoder.h"
#include "decoder/loop_subdivision.h"
#include "encoder/encoder_internal.h"

namespace qmc {

// Step 12.5 1-4 as the decoder does them: the subdivided level before any
// displacement, and the normal of each edge point (3 per coarse edge).
void predict_level(const LoopMesh& coarse, const LoopEdges& coarse_edges, LoopMesh* fine,
                   std::vector<double>* normals);

struct LevelCodeStats {
  uint32_t edge_points = 0, zeros = 0, clamped = 0;
  double step = 0;
  uint8_t code = 0;  // the displacement code written (12.7, 12.7.1 or 12.7.2)
};

// 12.10: what the least-error step of `level` (1..levels) is multiplied by:
// options.finest_step_scale at the finest level, its square root at the
// level below, 1 further down. A coarse level's rounding is corrected by the
// edge points of the levels after it, the finest level's is not (measured on
// camelhead, K = 2: scaling level 1's step by 4 gave 7975 bytes at
// relative L2 1.54e-4, scaling level 2's 6108 bytes at 1.49e-4).
double level_step_scale(const EncodeOptions& options, int level, int levels);

// Chooses the step (the least-error one times step_scale) and the integers
// m for edge-point targets (3 doubles per coarse edge), applies them to
// `fine` exactly as the decoder will, and returns the LEVL payload:
// displacement code 0 (12.7), 2 (12.7.1), or with code = -1 the smaller of
// the two. `kept`, if not null, receives the step and the integers.
std::vector<uint8_t> encode_level(uint8_t level, const LoopEdges& coarse_edges, uint32_t coarse_vertices,
                                  const std::vector<double>& normals, const std::vector<double>& targets,
                                  int code, double step_scale, LoopMesh* fine, LevelCodeStats* stats,
                                  LevelCode* kept = nullptr);

// 12.7.2: the LEVL payload of displacement code 4, `code`'s displacements
// range coded as 12.7.1 codes them, then its corrections (vertices
// increasing, offsets within -32767 .. 32767).
std::vector<uint8_t> corrected_level_payload(uint8_t level, const LoopEdges& coarse_edges, uint32_t coarse_vertices,
                                             const LevelCode& code);

// 12.7.2: vertex corrections for the decoder's reconstruction of level j
// (1 .. K, displaced), their step in code->correction_step and the
// corrections in code->corrections (none: the level is coded as it is).
using LevelCorrector = std::function<Status(int j, const LoopMesh& level, LevelCode* code)>;

// Where the edge points of `level` should go: given the decoder's
// subdivided level (before displacement) and the edge-point normals (3 per
// coarse edge), fills 3 doubles per coarse edge.
using LevelTargets = std::function<void(int level, const LoopMesh& fine, const std::vector<double>& normals,
                                        uint32_t coarse_vertices, std::vector<double>* targets)>;

// The closed loop of 12.10 (issue 17): the distance of a decoded level (or
// of the base) to the input, and other targets to try for a level that the
// encoder's own would leave no nearer the input than the level below.
struct LevelJudge {
  struct Alternative {
    uint8_t id;  // what LoopLevelStats::targets records when it is kept (1..255)
    LevelTargets targets;
  };
  std::function<double(const LoopMesh& level)> distance;
  std::vector<Alternative> alternatives;
};

// Section 12: writes a progressive file whose base mesh has the connectivity
// `conn` (triangles, CONN order) and binary64 positions `base_positions`
// (CONN order), quantized with options.position_bits, and `levels` levels
// whose displacements aim at `targets`, each computed from the decoder's own
// reconstruction of the level below. With a `judge`, a level that `targets`
// would leave less than 1 % nearer the input than the level below takes the
// first alternative that is, or else the nearest of them all. With a
// `corrector`, each level takes the corrections it gives (code 4) unless,
// with a judge, they would leave it no nearer the input than the level below.
Status write_loop_file(const FileConnectivity& conn, const std::vector<double>& base_positions, int levels,
                       const EncodeOptions& options, const LevelTargets& targets, const LevelJudge* judge,
                       const LevelCorrector* corrector, std::vector<uint8_t>* out, EncodeStats* stats);

}  // namespace qmc
