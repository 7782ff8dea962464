// Section 14.15 of spec/qmc-format.md (POSN method 14): the surface lattice.
// A vertex keeps the grid's step along the axis nearest the surface's normal
// and takes steps of k along the other two, so that what the grid would have
// spent on where a vertex lies within the surface is not spent: the distance
// between surfaces (Cignoni, Rocchini and Scopigno, "Metro", 1998) hardly
// sees a vertex move along its surface. The normal is estimated from what
// is decoded, in integers, so every decoder picks the same axis.
#pragma once

#include <cstdint>

#include "common/geometry_order.h"
#include "common/vertex_prediction.h"

namespace qmc {

// 14.15: the lattice's factor k, and the tops it allows (the normal's sums
// stay below 2^63: differences below 2^25, products below 2^50, at most
// kLatticeCorners corners).
inline constexpr int kLatticeLeastFactor = 2, kLatticeLargestFactor = 16;
inline constexpr uint32_t kLatticeTopBound = uint32_t(1) << 24;  // every top below it
inline constexpr int kLatticeCorners = 16;

// 14.15: the fine axis of the i-th visited vertex v predicted at P: the
// axis of the largest |N_a| (the first on a tie), N the sum over v's first
// kLatticeCorners corners whose two neighbours along the face are decoded
// of (q[next] - P) x (q[previous] - P); -1 where N is 0 (no lattice).
inline int lattice_fine_axis(const PredictionVisit& visit, uint32_t v, uint32_t i, const uint32_t* q,
                             const int64_t P[3]) {
  const VertexCorners& mesh = visit.mesh();
  int64_t n[3] = {0, 0, 0};
  int used = 0;
  const VertexCorners::Sides* sides = mesh.sides(v);
  for (const uint32_t* corner = mesh.begin(v); corner != mesh.end(v) && used < kLatticeCorners; ++corner, ++sides) {
    if (!visit.visited_before(sides->next, i) || !visit.visited_before(sides->previous, i)) continue;
    const uint32_t* a = &q[3 * size_t(sides->next)];
    const uint32_t* b = &q[3 * size_t(sides->previous)];
    const int64_t u[3] = {int64_t(a[0]) - P[0], int64_t(a[1]) - P[1], int64_t(a[2]) - P[2]};
    const int64_t w[3] = {int64_t(b[0]) - P[0], int64_t(b[1]) - P[1], int64_t(b[2]) - P[2]};
    n[0] += u[1] * w[2] - u[2] * w[1];
    n[1] += u[2] * w[0] - u[0] * w[2];
    n[2] += u[0] * w[1] - u[1] * w[0];
    ++used;
  }
  int fine = -1;
  uint64_t largest = 0;
  for (int a = 0; a < 3; ++a) {
    const uint64_t magnitude = n[a] < 0 ? uint64_t(0) - uint64_t(n[a]) : uint64_t(n[a]);
    if (magnitude > largest) largest = magnitude, fine = a;
  }
  return fine;
}

}  // namespace qmc
