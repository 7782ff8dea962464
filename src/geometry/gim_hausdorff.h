// Seed 000 §3.2-3.3: Hausdorff-error-driven adjustment of the geometry
// image's samples (Algorithms 1-3, eqs. (5)-(17)).
//
// Meshes. M is the input (its disk: DiskCut::triangles over disk vertices,
// positions of DiskCut::original_vertex, parameter positions
// DiskParametrization::uv). The GIM mesh is the image's reconstruction: one
// vertex per pixel (GimSamples::xyz), triangles over raster indices (not
// merged across seams: each triangle keeps the pixels it has in the grid, so
// its parameter footprint is small), and seam pairs tying pixels together:
// a move of one pixel moves its whole seam group identically. Only GIM
// vertices ever move; M is fixed.
//
// Face distances (§3.2, eq. (6)). The directed Hausdorff distance of a face f
// to the other mesh is evaluated at the barycentric lattice of order s
// (options.lattice_order, default 4): the points (i a + j b + k c) / s with
// i + j + k = s, i.e. for s = 4 the 3 vertices, 3 points on each edge (the
// quarter points and the midpoint) and the 3 interior points (2,1,1)/4,
// (1,2,1)/4, (1,1,2)/4: 15 points. For each point the distance is the exact
// point-triangle distance (triangle_bvh.h) minimized over the candidate faces
// of the other mesh; the face's value is the largest, with the point p* and
// the nearest face f* that give it (the seed's three recorded items).
// D1 = {d(f, GIM) : f in M}, D2 = {d(g, M) : g in GIM}.
//
// Face neighbourhoods (§3.2, figure 3). The candidate faces of a target face
// are the faces of the other mesh whose parameter-domain triangles share a
// point with the target's parameter triangle scaled by
// options.footprint_scale (2: "enlarge twice") about its centroid. Parameter
// positions never change, so the candidate lists are built once; only when a
// list comes out empty (an empty pixel region, say) it is filled instead
// with the faces that a BVH over the other mesh, as it is at the start, finds
// nearest to the target's lattice points. The values are upper bounds of
// the true distances (a minimum over fewer faces), equal when the nearest
// face is among the candidates, which is what the footprint is for.
//
// Iteration (Algorithm 1). With m1 = max D1 and m2 = max D2: if m1 > m2 the
// worst point p* lies on M and the features of the GIM face f* nearest to it
// move (Algorithm 2, eqs. (9), (16), (17)); otherwise p* lies on a GIM face
// p1p2p3 at barycentric (alpha, beta, gamma) and p1, p2, p3 move (Algorithm
// 3, eqs. (10), (12), (15)). The distance type of p* and f* comes from eq.
// (5) (classify_distance). The step is -rho^k times the gradient of d^2, for
// k = 0..K (options.step_count, K = 100, rho = 1/2): the first k whose max of
// the driving set (D1 or D2) drops below its old value is taken -- provided
// also that the other set's max stays at or below the old symmetric
// distance max(m1, m2); the seed does not say so, but without it a step could
// trade a D1 improvement for a larger D2 and raise the Hausdorff distance.
// A step recomputes only the GIM faces around the moved pixels (their seam
// groups included) and the M faces whose candidate lists contain one of
// those faces, and keeps both maxima in max-trees, so one trial costs a few
// hundred point-triangle distances. The run stops, as the seed's does, at
// the first iteration where no k is accepted; or after
// options.max_iterations accepted steps; or when the point-triangle distance
// evaluations reach options.work_budget (a bound independent of the clock).
//
// ROI mode (seed 000 §4): with input.gim_face_mask, only D2 over the masked
// GIM faces is computed and driven down (the directed Hausdorff distance
// from the ROI to M), always by Algorithm 3.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "geometry/gim_types.h"
#include "geometry/triangle_bvh.h"
#include "qmc/status.h"

namespace qmc {

// ---- Distance types and gradients (eqs. (5), (7)-(17)) ----------------------

enum class GimDistanceType : uint8_t { kPointFace = 0, kPointEdge = 1, kPointPoint = 2 };

// Which feature of triangle (t.a, t.b, t.c) = (corner 0, 1, 2) is nearest to p.
struct GimFeature {
  GimDistanceType type = GimDistanceType::kPointFace;
  uint8_t corner[2] = {0, 0};  // point-point: corner[0]; point-edge: the edge corner[0] -> corner[1]
};

// Eq. (5): the signs of lambda_1..3 (the edge lines' values at the
// projection of p times their values at the opposite corners) split the
// triangle's plane into 7 regions: inside (point-face), beyond one edge
// (point-edge) and beyond two edges (point-point). The edge lines alone do
// not give the nearest feature everywhere -- beyond edge bc but past b, the
// nearest point is b, and at an obtuse corner part of its region is nearer an
// edge -- so edge regions whose foot falls outside the segment become
// point-point, and corner regions whose foot falls inside an adjacent edge
// become point-edge. The distance of the returned type is then the exact
// point-triangle distance. A degenerate (zero-area) triangle gives the
// nearest of its edges or corners.
GimFeature classify_distance(const Vec3d& p, const Triangle3d& t);

// The squared distances of eqs. (8), (11), (14), written as the seed does.
double squared_distance_pp(const Vec3d& p, const Vec3d& q);
double squared_distance_pe(const Vec3d& p, const Vec3d& q1, const Vec3d& q2);
double squared_distance_pf(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, const Vec3d& q3);

// Gradients of d^2 with respect to the feature's corners, p fixed (max D1 >
// max D2, Algorithm 2): eq. (9), eq. (16) (out[0..1]), eq. (17) (out[0..2]).
Vec3d gradient_pp_feature(const Vec3d& p, const Vec3d& q);
void gradient_pe_feature(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, Vec3d out[2]);
void gradient_pf_feature(const Vec3d& p, const Vec3d& q1, const Vec3d& q2, const Vec3d& q3, Vec3d out[3]);

// Gradients of d^2 with respect to the corners p1, p2, p3 of the face holding
// p = bary[0] p1 + bary[1] p2 + bary[2] p3, the feature fixed (max D1 <=
// max D2, Algorithm 3): eq. (10), eq. (12), eq. (15).
void gradient_pp_point(const Vec3d p[3], const double bary[3], const Vec3d& q, Vec3d out[3]);
void gradient_pe_point(const Vec3d p[3], const double bary[3], const Vec3d& q1, const Vec3d& q2, Vec3d out[3]);
void gradient_pf_point(const Vec3d p[3], const double bary[3], const Vec3d& q1, const Vec3d& q2, const Vec3d& q3,
                       Vec3d out[3]);

// ---- Parameter-domain triangles ---------------------------------------------

// A uniform bucket grid over 2-D triangles: which triangles meet a given
// triangle, and which triangle holds a point. Also used by gim_roi.cc to
// sample the image at arbitrary per-pixel parameter positions.
class ParamTriangleIndex {
 public:
  // `uv`: 2 per vertex; `triangles`: 3 vertex indices each.
  void build(const std::vector<double>& uv, const std::vector<uint32_t>& triangles);
  // Triangles whose closed region meets the closed triangle (u[k], v[k]), k < 3.
  void overlapping(const double u[3], const double v[3], std::vector<uint32_t>* out) const;
  // The triangle holding (u, v), with its barycentric coordinates (the one
  // with the largest smallest coordinate if several; a point up to 1e-9 of a
  // triangle's size outside still counts). False if none.
  bool locate(double u, double v, uint32_t* triangle, double bary[3]) const;

 private:
  void cell_range(double lo_u, double lo_v, double hi_u, double hi_v, int range[4]) const;
  const std::vector<double>* uv_ = nullptr;
  const std::vector<uint32_t>* triangles_ = nullptr;
  double lo_[2] = {0, 0}, cell_ = 1;
  int nu_ = 0, nv_ = 0;
  std::vector<uint32_t> cell_start_, cell_items_;
  mutable std::vector<uint32_t> stamp_;
  mutable uint32_t epoch_ = 0;
};

// ---- The GIM mesh of a regular image ----------------------------------------

// Triangles over raster indices for a W x H grid: every 2 x 2 block whose
// four pixels are occupied (`occupied` null: all) gives two triangles, split
// along the shorter diagonal of `xyz` (ties and xyz == null: the diagonal
// from (x, y) to (x + 1, y + 1)), both oriented (x,y) -> (x+1,y) -> ... as the
// raster lies (counter-clockwise with y downwards is clockwise on screen; the
// distances here do not depend on orientation).
void grid_triangles_over_pixels(uint32_t width, uint32_t height, const std::vector<uint8_t>* occupied,
                                const double* xyz, std::vector<uint32_t>* triangles);

// ---- The adjustment -----------------------------------------------------------

struct HausdorffAdjustOptions {
  uint32_t max_iterations = 2000;  // accepted steps
  uint32_t step_count = 100;       // K: step sizes rho^0 .. rho^K
  double rho = 0.5;
  uint32_t lattice_order = 4;      // s: (s + 1)(s + 2) / 2 points per face
  double footprint_scale = 2.0;
  uint64_t work_budget = 2000000000;  // point-triangle distance evaluations, set-up included
};

struct HausdorffAdjustInput {
  const GimTriMesh* original = nullptr;        // M
  const DiskCut* cut = nullptr;                // M's disk triangles and vertex map
  const DiskParametrization* param = nullptr;  // uv per disk vertex, pixel units
  // Parameter position of pixel (x, y): pixel_uv[2 (y W + x) + 0..1] if
  // given, else (column_u[x], row_v[y]).
  const std::vector<double>* column_u = nullptr;
  const std::vector<double>* row_v = nullptr;
  const std::vector<double>* pixel_uv = nullptr;
  // GIM triangles over raster indices; null: samples->triangles.
  const std::vector<uint32_t>* gim_triangles = nullptr;
  // ROI mode: one byte per GIM triangle; see the top of this file.
  const std::vector<uint8_t>* gim_face_mask = nullptr;
  HausdorffAdjustOptions options;
};

enum class HausdorffStop : uint8_t { kNoStep, kMaxIterations, kWorkBudget, kZeroDistance };

struct HausdorffAdjustStats {
  // Neighbourhood-evaluated maxima (see above), before and after.
  double d1_before = 0, d2_before = 0, d1_after = 0, d2_after = 0;
  double hausdorff_before = 0, hausdorff_after = 0;
  uint32_t iterations = 0;          // accepted steps
  uint64_t step_trials = 0;         // k values tried, all iterations
  uint32_t algorithm2_steps = 0;    // steps driven by D1
  uint32_t algorithm3_steps = 0;    // steps driven by D2
  uint32_t type_steps[3] = {0, 0, 0};  // by GimDistanceType
  uint32_t fallback_faces = 0;      // faces whose candidates came from the BVH
  uint64_t distance_evaluations = 0;
  HausdorffStop stop = HausdorffStop::kNoStep;
};

// Runs Algorithm 1 on samples->xyz in place (seam groups stay identical).
// `progress`, if set, gets the fraction of max_iterations done now and then.
Status hausdorff_adjust(const HausdorffAdjustInput& input, GimSamples* samples, HausdorffAdjustStats* stats,
                        const std::function<void(double)>& progress = {});

// For measuring: the per-face distances at the same lattice points, but each
// point's distance taken against the whole other mesh (a BVH), so no
// neighbourhood approximation. d1: per M triangle; d2: per GIM triangle.
Status gim_face_distances_exact(const HausdorffAdjustInput& input, const GimSamples& samples,
                                std::vector<double>* d1, std::vector<double>* d2);

}  // namespace qmc
