// Vertex positions: the grid and its integer coordinates (spec/qmc-format.md
// sections 6.1 and 14.1), method 0's Huffman-coded deltas (seed 001 §2.6
// and §5.1.2, section 6) and method 1's predicted, range-coded residuals
// (section 14).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/geometry_order.h"
#include "common/mirror_prediction.h"
#include "common/value_twins.h"
#include "common/position_coding.h"
#include "qmc/encoder.h"
#include "qmc/mesh.h"
#include "qmc/status.h"

namespace qmc {

struct QuantizedPositions {
  int bits = 0;                        // method 0's n; the bit length of the largest top otherwise
  bool per_axis_bits = false;          // the grid of section 6.1 (method 0 can carry it)
  std::array<float, 3> min{}, max{};   // box (6.1) or origin (14.1) and the grid's last point
  std::array<double, 3> step{};
  std::array<uint32_t, 3> top{};
  std::vector<uint32_t> q;  // 3 per vertex
  // POSN method 14 (14.15): with lattice k > 1 each vertex is placed on the
  // surface lattice around its prediction as it is coded, near x (the
  // input in grid units) and across the surface of `normal` (unit, by
  // vertex), 3 per vertex each (set_surface_lattice).
  int lattice = 1;
  std::vector<double> x, normal;
};

// 14.15: the lattice of factor k (2 .. 16) for positions quantized from
// mesh (the coder's faces and binary32 positions): x and the area-weighted
// normals. Tops must be below 2^24 (an error naming the bits otherwise).
Status set_surface_lattice(const Mesh& mesh, int k, QuantizedPositions* positions);

// Section 6.1: each axis over its own range in 2^bits - 1 steps.
QuantizedPositions quantize_positions(const std::vector<float>& positions, int bits);

// The grid the options ask for (bits and grid, step, or max error; section
// 14.1), or an error naming what cannot be represented.
Status quantize_positions(const std::vector<float>& positions, const EncodeOptions& options,
                          QuantizedPositions* out);

// Method 0 (section 6.3); positions must be on a per-axis grid.
std::vector<uint8_t> encode_positions(const QuantizedPositions& positions);

// 14.4.1's start of the class probabilities pays below this many vertices
// (or attribute values, 15.10): 6-11 % of the positions of the corpus's
// control meshes. Above, it saves at most about 1 % and can lose more where
// the bucket overestimates every class (the 2,304-vertex regular torus at
// 12 bits: 6.5 % more), so method 1 stays.
inline constexpr size_t kGradedStartBelow = 1000;

// 14.5: from this many vertices the encoder writes 14.8's contexts (POSN
// methods 6 and 7). On the corpus's 7 meshes of that size, at 12, 14 and 16
// bits, POSN is smaller with them in 19 of 21 cases (face.obj by 2.8-6.4 %,
// beetle by 2.2-4.8 %) and larger in 2 (camelhead by 0.11 % and 0.02 %);
// on its meshes of 1,000-5,000 vertices larger in 17 of 24 (up to 1.3 %:
// 12 sets of probabilities learn too slowly there). A rule, not a second
// pass: the encode costs nothing more.
inline constexpr size_t kMaskContextsFrom = 10000;

// 14.14: from this many vertices the encoder writes POSN method 13's class
// probabilities per axis. On the corpus's meshes of that size, at 12, 14 and
// 16 bits, POSN is smaller with them in 28 of 36 cases (torus by 7 - 8.5 %,
// beetle by 1.3 - 2.5 %, face by 0.6 - 2.4 %, stanford-bunny by 1.0 - 1.2 %)
// and at most 0.6 % larger (cow at 14 bits); under 1,000 vertices every
// control mesh larger (cylinder_ngon_caps by 5 - 7 %: four tables learn
// slower than one). A rule, not a second pass. Not below kGradedStartBelow,
// where the encoder compares payloads without it.
inline constexpr size_t kAxisClassesFrom = 1000;
static_assert(kAxisClassesFrom >= kGradedStartBelow, "the small meshes' comparisons code without 14.14");

// Sections 14.2 - 14.4 over any faces whose corners are below q.size() / 3:
// the range-coded stream of POSN method 1, 3 or 4 (in 14.6's order) or of
// an aTTR's values (15.4, 15.9, 15.10, 15.12 with a guide). The caller
// checks 14.1's bound on the stream's length.
std::vector<uint8_t> encode_predicted_grid(const std::vector<uint32_t>& q, const uint32_t top[3], const Mesh& faces,
                                           PositionStats* stats, CandidateChoice choice,
                                           ClassStart start = ClassStart::kFlat,
                                           PredictionOrder order = PredictionOrder::kLabels,
                                           const PositionGuide* guide = nullptr, bool quad_twist = false,
                                           bool mask_contexts = false, bool triangle_twist = false,
                                           const AttributeTwins* twins = nullptr);

// Method 1, or 3 with the graded start (section 14), or 4 in the geometry
// order (5 with quad_twist, 6 or 7 with mask_contexts too, 8 with
// triangle_twist and the features of those two; 9 with a mirror plane
// too, 14.10; 11 with a shear, 14.12; 12 with extrapolate, 14.13; 13 with
// axis_classes, which implies extrapolate, 14.14), over
// the file's faces; stats may be null. Empty when the vertices cost too
// little for 14.1's bound (all on one point).
std::vector<uint8_t> encode_predicted_positions(const QuantizedPositions& positions, const Mesh& faces,
                                                PositionStats* stats,
                                                CandidateChoice choice = CandidateChoice::kFewestBits,
                                                ClassStart start = ClassStart::kFlat,
                                                PredictionOrder order = PredictionOrder::kLabels,
                                                bool quad_twist = false, bool mask_contexts = false,
                                                bool triangle_twist = false, const MirrorPlane* mirror = nullptr,
                                                int shear = 0, bool extrapolate = false, bool axis_classes = false);

// 14.10's plane for POSN methods 9 and 10, if the vertices have one: of the planes
// halfway across the grid on each axis (sum top - 2 .. top + 2) and the
// plane most pairs of vertices make, the one whose reflection puts the most
// of a sample of the vertices exactly onto vertices; taken if it does so
// for 1/8 of all of them (1/16 under 1,000). With near (method 10), if none
// is taken, from 1,000 vertices on the same counting a vertex within a step
// of the image too; plane->near_images says whether near was allowed.
bool find_mirror_plane(const QuantizedPositions& positions, MirrorPlane* plane, bool near);

// 14.4.1's start when the options ask for POSN method 3.
inline ClassStart class_start(const EncodeOptions& options) {
  return options.graded_class_start ? ClassStart::kGraded : ClassStart::kFlat;
}

// 14.6's order when the options allow POSN method 4.
inline PredictionOrder prediction_order(const EncodeOptions& options) {
  return options.geometry_order ? PredictionOrder::kGeometry : PredictionOrder::kLabels;
}

// The POSN payload the options ask for: predicted positions (method 4 in
// the geometry order, or 5 where quad_twist allows it and it is smaller,
// either as 6 or 7 where mask_contexts allows it and that is smaller, as
// 8 where triangle_twist allows it and a pass of predictions says it pays,
// either as 9 where mirror allows it and the vertices have a mirror plane
// (14.10), as 10 where near_mirror allows it too (14.11; under 1,000
// vertices the smaller of 9 and 10), any of 4 - 10 as 11 where shear
// allows it and the sheared parallelograms code smaller (14.12), any of
// 4 - 11 as 12 where edge_extrapolation allows it and the rule gives some
// vertex a candidate (14.13), any of 4 - 12 as 13 where
// axis_class_probabilities allows it (with edge_extrapolation) from
// kAxisClassesFrom vertices on (14.14), else 3 with `start` graded under
// 1,000 vertices, or 1), method 0, or the smaller of the two when both can
// carry the grid. Fills stats.
std::vector<uint8_t> encode_positions(const QuantizedPositions& positions, const Mesh& faces,
                                      PositionMethod method, CandidateChoice choice, ClassStart start,
                                      PredictionOrder order, bool quad_twist, bool mask_contexts,
                                      bool triangle_twist, bool mirror, bool near_mirror, bool shear,
                                      PositionStats* stats, bool edge_extrapolation = false,
                                      bool axis_class_probabilities = false);

}  // namespace qmc
