// Progressive files (spec section 12) whose levels aim at analytic surfaces:
// a sphere, a torus, a height field. They exercise the format and the
// decoder independently of the remeshing pipeline (seed 003 steps II-VI),
// for the tests, the conformance vectors and the fuzz seeds.
#pragma once

#include <cstdint>
#include <vector>

#include "encoder/loop_level_encoder.h"
#include "qmc/encoder.h"
#include "qmc/mesh.h"

namespace qmc::tools {

// The octahedron scaled so that the Loop limit positions of its vertices
// lie on the unit sphere: what the fitting step (seed 003 step III) would
// make of it, known in closed form (limit = w / (w + 4) p, w = 3 / (8
// beta(4)), the four neighbours summing to zero).
Mesh loop_octahedron();

// Edge points aim at the unit sphere (radial projection).
LevelTargets unit_sphere_targets();
// Edge points aim at the torus of radii R, r around the z axis (nearest point).
LevelTargets torus_targets(double R, double r);
// Edge points aim at z = 0.3 sin(2x) cos(3y) above their own x, y.
LevelTargets height_field_targets();

// 12.7.2's corrections (LEVL code 4) at the levels listed: every `every`-th
// vertex moved towards its radial projection on the unit sphere, in units
// of `step`; vertices that would not move are left out unless list_unmoved
// (a correction of zero offsets is valid, and changes nothing).
LevelCorrector sphere_corrections(int every, double step, std::vector<int> levels, bool list_unmoved = false);

// A progressive file of the triangle mesh `base` (coded with the polygon
// coder, positions with `bits` bits on section 6.1's grid, by the POSN
// method given) and `levels` levels aiming at `targets`, with the LEVL
// displacement code given (0, 2, or -1 for the smaller), and, with a
// `judge`, 12.10's closed loop (write_loop_file), and with a `corrector`
// its corrections (code 4). Fails on a base that section 12.2 does not allow.
Status make_loop_file(const Mesh& base, int levels, const LevelTargets& targets, int bits, std::vector<uint8_t>* out,
                      EncodeStats* stats = nullptr, PositionMethod base_positions = PositionMethod::kDeltas,
                      int displacement_code = 0, bool context_coded_faces = false, const LevelJudge* judge = nullptr,
                      const LevelCorrector* corrector = nullptr);

}  // namespace qmc::tools
