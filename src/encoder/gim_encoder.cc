// The geometry-image encoder (spec/qmc-format.md section 13.11): cut to a
// disk, parametrize on the rectangle, then either sample it (seed 000:
// regular, vertex-density-equalized (§3.1), Hausdorff-adjusted (§3.2-3.3),
// region of interest (§4)) or move every vertex to its own pixel (seed 002),
// and write the chunks.
#include "encoder/gim_encoder.h"

#include <chrono>
#include <cmath>

#include "common/union_find.h"
#include "geometry/triangle_bvh.h"  // Vec3d

#include "geometry/gim_adaptive_sampling.h"
#include "geometry/gim_cut.h"
#include "geometry/gim_hausdorff.h"
#include "geometry/gim_parametrization.h"
#include "geometry/gim_roi.h"
#include "geometry/gim_sampling.h"
#include "geometry/gim_topology_preserving.h"
#include "encoder/gim_writer.h"

namespace qmc {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The topology-preserving generator rescales the parametrization to its own
// grid; this is only the resolution of the Floater layout it starts from.
inline constexpr uint32_t kTopologyPreservingLayoutSide = 1024;

std::function<void(double)> stage_progress(const EncodeOptions& options, const char* stage) {
  if (!options.progress) return {};
  return [&options, stage](double f) { options.progress(stage, f); };
}

Status region_of_interest(const GimTriMesh& tri, const DiskCut& cut, const DiskParametrization& param,
                          const EncodeOptions& options, const std::vector<double>& column_u,
                          const std::vector<double>& row_v, GimSamples* samples, std::vector<double>* pixel_uv,
                          RoiRect* rect) {
  RegionOfInterest roi;
  if (Status s = parse_roi_file(options.gim.roi, &roi); !s.ok()) return s;
  if (Status s = roi_parameter_rect(tri, cut, param, roi, rect); !s.ok()) return s;
  *pixel_uv = pixel_uv_from_lines(column_u, row_v);
  // Border and seam pixels keep the boundary samples (mates bit-identical).
  const std::vector<uint8_t> fixed = roi_fixed_pixels(*samples);
  RoiSamplingStats roi_stats;
  if (Status s = roi_adapt_sampling(param, *rect, samples->width, samples->height, &fixed, RoiSamplingOptions{},
                                    pixel_uv, &roi_stats, stage_progress(options, "region of interest"));
      !s.ok())
    return s;
  return sample_at_pixel_uv(tri, cut, param, *pixel_uv, &fixed, samples);
}

Status sampled_image(const GimTriMesh& tri, const DiskCut& cut, const EncodeOptions& options, GimSamples* samples,
                     GimEncodeStats* gs) {
  const uint32_t n = options.gim.size;
  if (n < 2) return Status(ErrorCode::kInvalidArgument, "a geometry image needs at least 2 x 2 samples");
  auto t = Clock::now();
  DiskParametrization param;
  if (Status s = parametrize_on_rectangle(tri, cut, n, n, &param, stage_progress(options, "parametrize")); !s.ok())
    return s;
  gs->seconds_parametrize = seconds_since(t);
  t = Clock::now();
  std::vector<double> column_u, row_v;
  if (options.gim.sampling == GimSampling::kRegular)
    regular_sampling(n, n, &column_u, &row_v);
  else
    vertex_density_equalization(param.uv, n, n, double(n - 1), double(n - 1), &column_u, &row_v);
  if (Status s = sample_geometry_image(tri, cut, param, column_u, row_v, samples, stage_progress(options, "sample"));
      !s.ok())
    return s;
  std::vector<double> pixel_uv;
  RoiRect rect;
  const bool roi = !options.gim.roi.empty();
  if (roi) {
    if (Status s = region_of_interest(tri, cut, param, options, column_u, row_v, samples, &pixel_uv, &rect); !s.ok())
      return s;
  }
  gs->seconds_sample = seconds_since(t);
  if (options.gim.sampling != GimSampling::kHausdorff) return Status::Ok();
  t = Clock::now();
  std::vector<uint32_t> grid;
  grid_triangles_over_pixels(samples->width, samples->height, nullptr, samples->xyz.data(), &grid);
  std::vector<uint8_t> face_mask;
  HausdorffAdjustInput in;
  in.original = &tri;
  in.cut = &cut;
  in.param = &param;
  in.column_u = &column_u;
  in.row_v = &row_v;
  in.gim_triangles = &grid;
  if (roi) {  // seed 000 §4: the directed distance from the ROI only
    in.pixel_uv = &pixel_uv;
    face_mask = roi_face_mask(pixel_uv, grid, rect);
    in.gim_face_mask = &face_mask;
  }
  in.options.max_iterations = options.gim.hausdorff_iterations;
  HausdorffAdjustStats hs;
  if (Status s = hausdorff_adjust(in, samples, &hs, stage_progress(options, "Hausdorff adjustment")); !s.ok()) return s;
  gs->hausdorff_before = hs.hausdorff_before;
  gs->hausdorff_after = hs.hausdorff_after;
  gs->hausdorff_iterations = hs.iterations;
  gs->seconds_adjust = seconds_since(t);
  return Status::Ok();
}

Status topology_preserving_image(const GimTriMesh& tri, const DiskCut& cut, const EncodeOptions& options,
                                 GimSamples* samples, GimEncodeStats* gs) {
  auto t = Clock::now();
  DiskParametrization param;
  const uint32_t side = kTopologyPreservingLayoutSide;
  if (Status s = parametrize_on_rectangle(tri, cut, side, side, &param, stage_progress(options, "parametrize"));
      !s.ok())
    return s;
  gs->seconds_parametrize = seconds_since(t);
  t = Clock::now();
  TopologyPreservingOptions tp;
  tp.max_side = options.gim.size;
  TopologyPreservingStats ts;
  if (Status s = make_topology_preserving_image(tri, cut, param, tp, samples, &ts,
                                                stage_progress(options, "integer placement"));
      !s.ok())
    return s;
  gs->seconds_sample = seconds_since(t);
  return Status::Ok();
}

// Section 13.2 kinds 3, 4, 5: unit normals per vertex pixel, area-weighted
// over the triangles of the decoded mesh (the grid's, or GFAC's), summed
// over seam mates so both sides of a cut agree; blank pixels get 0.
std::vector<GimExtraPlane> normal_planes(const GimSamples& s) {
  const size_t pixels = size_t(s.width) * s.height;
  std::vector<uint32_t> grid;
  if (s.triangles.empty()) grid_triangles_over_pixels(s.width, s.height, nullptr, s.xyz.data(), &grid);
  const std::vector<uint32_t>& tris = s.triangles.empty() ? grid : s.triangles;
  std::vector<Vec3d> n(pixels);
  auto point = [&](uint32_t p) { return Vec3d{s.xyz[3 * size_t(p)], s.xyz[3 * size_t(p) + 1], s.xyz[3 * size_t(p) + 2]}; };
  for (size_t t = 0; t + 2 < tris.size(); t += 3) {
    const Vec3d a = point(tris[t]), face = cross(point(tris[t + 1]) - a, point(tris[t + 2]) - a);
    for (int k = 0; k < 3; ++k) n[tris[t + size_t(k)]] = n[tris[t + size_t(k)]] + face;
  }
  UnionFind mates(pixels);
  for (const SeamPair& pair : s.seams) mates.unite(pair.a, pair.b);
  std::vector<Vec3d> sum(pixels);
  for (uint32_t p = 0; p < pixels; ++p) sum[mates.find(p)] = sum[mates.find(p)] + n[p];
  std::vector<GimExtraPlane> planes(3);
  for (int a = 0; a < 3; ++a) planes[size_t(a)].kind = uint8_t(3 + a), planes[size_t(a)].values.assign(pixels, 0.0);
  for (uint32_t p = 0; p < pixels; ++p) {
    const Vec3d v = sum[mates.find(p)];
    const double length = std::sqrt(dot(v, v));
    if (length == 0) continue;
    for (int a = 0; a < 3; ++a) planes[size_t(a)].values[p] = component(v, a) / length;
  }
  return planes;
}

}  // namespace

Status encode_geometry_image(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* out,
                             EncodeStats* st) {
  GimEncodeStats& gs = st->gim;
  size_t split = 0;
  const GimTriMesh tri = gim_mesh_from(mesh, &split);
  gs.polygons_split = uint32_t(split);
  auto t = Clock::now();
  DiskCut cut;
  GimCutStats cut_stats;
  if (Status s = cut_to_disk(tri, &cut, stage_progress(options, "cut"), &cut_stats); !s.ok()) return s;
  gs.seconds_cut = seconds_since(t);
  gs.genus = cut.genus;
  gs.boundary_loops = cut.input_boundary_loops;
  gs.cut_nodes = cut_stats.cut_nodes;
  gs.cut_paths = cut_stats.cut_paths;
  gs.unreferenced_vertices = cut_stats.unreferenced_vertices;
  GimSamples samples;
  const Status made = options.gim.topology_preserving ? topology_preserving_image(tri, cut, options, &samples, &gs)
                                                      : sampled_image(tri, cut, options, &samples, &gs);
  if (!made.ok()) return made;
  t = Clock::now();
  const std::vector<GimExtraPlane> extra = options.gim.normal_planes ? normal_planes(samples) : std::vector<GimExtraPlane>{};
  if (Status s = write_geometry_image(samples, extra, options.gim, options.texts, out, st); !s.ok()) return s;
  gs.seconds_code = seconds_since(t);
  return Status::Ok();
}

}  // namespace qmc
