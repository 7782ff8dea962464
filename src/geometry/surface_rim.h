// The boundary of a triangle mesh as curves, for fitting a control mesh's
// boundary to it (loop_fitting.h). Loop's boundary rule (spec 12.5) makes the
// boundary of every level a cubic B-spline of the base mesh's boundary, and
// the levels move edge points only along surface normals (12.6, 12.7), never
// across the surface: where the base's boundary curve runs, the decoded
// boundary runs. So the base's boundary limit positions are fitted onto the
// original's boundary itself: each onto the loop its own boundary loop
// stands for, near where the vertex stood, since the nearest point of the
// whole boundary may lie on another loop, or on another stretch of the same
// loop where it turns back on itself (beetle's rim around its legs).
#pragma once

#include <cstdint>
#include <vector>

#include "decoder/loop_subdivision.h"
#include "geometry/triangle_bvh.h"

namespace qmc {

class SurfaceRim {
 public:
  SurfaceRim() = default;
  // The edges of `mesh` in one face only, grouped into loops: two such edges
  // sharing a vertex are in one loop (so loops touching at a vertex are one).
  explicit SurfaceRim(const LoopMesh& mesh);

  bool empty() const { return loops_.empty(); }
  uint32_t loop_count() const { return uint32_t(loops_.size()); }
  // The loop with the edge nearest to p (the rim must not be empty).
  uint32_t nearest_loop(const Vec3d& p) const;
  // The point of loop `loop` nearest to p.
  Vec3d nearest_on_loop(uint32_t loop, const Vec3d& p) const;

 private:
  // Each edge (a, b) as the degenerate triangle (a, b, b), whose closest
  // point TriangleBvh finds as the segment's: all of them, and per loop.
  TriangleBvh all_;
  std::vector<uint32_t> loop_of_edge_;  // in all_'s order
  std::vector<TriangleBvh> loops_;
};

// Where step III takes each boundary vertex of a control mesh (edges:
// build_loop_edges of it). Its boundary loop stands for the rim loop nearest
// to most of the loop's vertices (ties: the lowest index); its anchor is the
// point of that rim loop nearest to the vertex as it stands before fitting.
// A target is the point of the rim loop nearest to the vertex's limit
// position, or the anchor if that point is farther from the anchor than
// kRimReach times the distance from the anchor to the farther of its two
// boundary neighbours' anchors: a limit point between two stretches of the
// rim is taken to its own. (0.3: on beetle, whose rim turns back around the
// legs, 0.5 let three levels' boundary fold onto the wrong stretch, L2 6.4e-4
// of the diagonal instead of 1.2e-4; 0.2 and 0.3 did not.)
inline constexpr double kRimReach = 0.3;
struct RimAnchors {
  std::vector<uint32_t> loop;   // per control vertex; kNoVertex: an interior vertex, or no rim
  std::vector<Vec3d> anchor;
  std::vector<double> reach2;   // the squared distance a target may lie from the anchor
};
RimAnchors rim_anchors(const SurfaceRim& rim, const LoopMesh& control, const LoopEdges& edges);
Vec3d rim_target(const SurfaceRim& rim, const RimAnchors& anchors, uint32_t v, const Vec3d& limit);

}  // namespace qmc
