// Seed 000 §1-3: the geometry image as the surface resampled on the pixel
// grid of the parameter rectangle (regular sampling; the adaptive sampling of
// §3.1 passes its own column and row positions), with seed 002's seam pairs
// so the rebuilt surface has no cracks. See gim_sampling.h for the contract.
#include "common/union_find.h"
#include "geometry/gim_sampling.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace qmc {
namespace {

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

// Barycentrics of (u, v) in triangle abc; false when it has no area.
bool barycentrics(const double* a, const double* b, const double* c, double u, double v, double* l) {
  const double d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  if (!(std::fabs(d) > 0)) return false;
  l[1] = ((u - a[0]) * (c[1] - a[1]) - (v - a[1]) * (c[0] - a[0])) / d;
  l[2] = ((b[0] - a[0]) * (v - a[1]) - (b[1] - a[1]) * (u - a[0])) / d;
  l[0] = 1 - l[1] - l[2];
  return true;
}

// Closest point of segment pq to (u, v): squared distance and parameter.
double segment_distance2(const double* p, const double* q, double u, double v, double* t) {
  const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
  *t = len2 > 0 ? std::clamp(((u - p[0]) * dx + (v - p[1]) * dy) / len2, 0.0, 1.0) : 0.0;
  const double ex = p[0] + *t * dx - u, ey = p[1] + *t * dy - v;
  return ex * ex + ey * ey;
}

Status check_inputs(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                    const std::vector<double>& column_u, const std::vector<double>& row_v) {
  const uint32_t W = param.width, H = param.height;
  if (W < 2 || H < 2) return invalid("parametrization has image size " + std::to_string(W) + " x " + std::to_string(H));
  const size_t P = 2 * size_t(W - 1) + 2 * size_t(H - 1);
  if (param.uv.size() != 2 * cut.original_vertex.size())
    return invalid("parametrization has " + std::to_string(param.uv.size() / 2) + " vertices, the cut " +
                   std::to_string(cut.original_vertex.size()));
  if (param.border_pixels.size() != P || param.border_arc.size() != P || param.runs.empty())
    return invalid("parametrization has " + std::to_string(param.border_pixels.size()) + " border pixels, the image " +
                   std::to_string(P));
  if (cut.triangles.size() != mesh.triangles.size() || cut.boundary_loop.size() != cut.boundary_mate.size() ||
      cut.boundary_loop.empty())
    return invalid("the cut does not match the mesh");
  for (uint32_t v : cut.original_vertex)
    if (v >= mesh.vertex_count()) return invalid("the cut refers to input vertex " + std::to_string(v));
  for (uint32_t v : cut.triangles)
    if (v >= cut.original_vertex.size()) return invalid("a cut triangle refers to disk vertex " + std::to_string(v));
  for (uint32_t v : cut.boundary_loop)
    if (v >= cut.original_vertex.size()) return invalid("the boundary loop refers to disk vertex " + std::to_string(v));
  for (const GimBorderRun& run : param.runs)
    if (run.pixel_steps == 0 || run.first_border_pixel >= P || run.mate >= int32_t(param.runs.size()) ||
        (run.mate >= 0 && param.runs[run.mate].pixel_steps != run.pixel_steps))
      return invalid("parametrization has an inconsistent border run");
  auto check_axis = [](const std::vector<double>& s, uint32_t n, const char* name) {
    if (s.size() != n)
      return invalid(std::string(name) + " has " + std::to_string(s.size()) + " entries, the image " +
                     std::to_string(n));
    if (std::fabs(s.front()) > 1e-9 || std::fabs(s.back() - (n - 1.0)) > 1e-9)
      return invalid(std::string(name) + " must run from 0 to " + std::to_string(n - 1));
    for (size_t i = 1; i < s.size(); ++i)
      if (!(s[i] > s[i - 1])) return invalid(std::string(name) + " is not strictly increasing at " + std::to_string(i));
    return Status::Ok();
  };
  if (Status s = check_axis(column_u, W, "column_u"); !s.ok()) return s;
  return check_axis(row_v, H, "row_v");
}

// Real border coordinate (0 .. P) of a border pixel's grid position,
// counter-clockwise in (u, v) from (0, 0) as in gim_parametrization.h.
double border_coordinate(uint32_t x, uint32_t y, uint32_t W, uint32_t H, const std::vector<double>& cu,
                         const std::vector<double>& rv) {
  const double w = W - 1.0, h = H - 1.0;
  if (y == 0) return cu[x];
  if (x == W - 1) return w + rv[y];
  if (y == H - 1) return w + h + (w - cu[x]);
  return 2 * w + h + (h - rv[y]);
}

// Position along the boundary loop at fraction t of run `run`'s 3-D length.
double arc_in_run(const GimTriMesh& mesh, const DiskCut& cut, const GimBorderRun& run, double t) {
  const size_t n = cut.boundary_loop.size();
  std::vector<double> len(run.edge_count);
  double total = 0;
  for (uint32_t j = 0; j < run.edge_count; ++j) {
    double p[3], q[3];
    boundary_point(mesh, cut, double((run.first_edge + j) % n), p);
    boundary_point(mesh, cut, double((run.first_edge + j + 1) % n), q);
    len[j] = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    total += len[j];
  }
  double target = std::clamp(t, 0.0, 1.0) * (total > 0 ? total : run.edge_count), acc = 0;
  for (uint32_t j = 0; j < run.edge_count; ++j) {
    const double l = total > 0 ? len[j] : 1.0;
    if (acc + l >= target || j + 1 == run.edge_count) {
      const double arc = (run.first_edge + j) % n + (l > 0 ? std::clamp((target - acc) / l, 0.0, 1.0) : 0.0);
      return arc >= n ? arc - n : arc;
    }
    acc += l;
  }
  return run.first_edge % n;
}

}  // namespace

void regular_sampling(uint32_t width, uint32_t height, std::vector<double>* column_u, std::vector<double>* row_v) {
  column_u->resize(width);
  row_v->resize(height);
  for (uint32_t i = 0; i < width; ++i) (*column_u)[i] = i;
  for (uint32_t j = 0; j < height; ++j) (*row_v)[j] = j;
}

void boundary_point(const GimTriMesh& mesh, const DiskCut& cut, double arc, double xyz[3]) {
  const size_t n = cut.boundary_loop.size();
  double e = std::floor(arc);
  const double f = arc - e;
  const size_t i = size_t(std::fmod(std::fmod(e, double(n)) + n, double(n)));
  const double* a = &mesh.positions[3 * size_t(cut.original_vertex[cut.boundary_loop[i]])];
  const double* b = &mesh.positions[3 * size_t(cut.original_vertex[cut.boundary_loop[(i + 1) % n]])];
  for (int k = 0; k < 3; ++k) xyz[k] = f == 0 ? a[k] : a[k] + f * (b[k] - a[k]);
}

ParamTriangleLocator::ParamTriangleLocator(const std::vector<double>& uv, const std::vector<uint32_t>& triangles)
    : uv_(uv), triangles_(triangles) {
  const size_t nt = triangles.size() / 3;
  if (nt == 0) return;
  double max_u = -std::numeric_limits<double>::infinity(), max_v = max_u;
  min_u_ = min_v_ = std::numeric_limits<double>::infinity();
  for (uint32_t v : triangles) {
    min_u_ = std::min(min_u_, uv[2 * size_t(v)]), max_u = std::max(max_u, uv[2 * size_t(v)]);
    min_v_ = std::min(min_v_, uv[2 * size_t(v) + 1]), max_v = std::max(max_v, uv[2 * size_t(v) + 1]);
  }
  // About one cell per triangle: a few candidates per query.
  const double span = std::max({max_u - min_u_, max_v - min_v_, 1e-12});
  const double cells_per_side = std::clamp(std::sqrt(double(nt)), 1.0, 4096.0);
  cell_ = span / cells_per_side;
  nu_ = std::max<uint32_t>(1, uint32_t(std::ceil((max_u - min_u_) / cell_)) + 1);
  nv_ = std::max<uint32_t>(1, uint32_t(std::ceil((max_v - min_v_) / cell_)) + 1);
  auto cell_range = [&](size_t t, uint32_t* u0, uint32_t* u1, uint32_t* v0, uint32_t* v1) {
    double lo_u = std::numeric_limits<double>::infinity(), hi_u = -lo_u, lo_v = lo_u, hi_v = -lo_u;
    for (int k = 0; k < 3; ++k) {
      const double* p = &uv[2 * size_t(triangles[3 * t + k])];
      lo_u = std::min(lo_u, p[0]), hi_u = std::max(hi_u, p[0]), lo_v = std::min(lo_v, p[1]),
      hi_v = std::max(hi_v, p[1]);
    }
    *u0 = std::min(nu_ - 1, uint32_t((lo_u - min_u_) / cell_)),
    *u1 = std::min(nu_ - 1, uint32_t((hi_u - min_u_) / cell_));
    *v0 = std::min(nv_ - 1, uint32_t((lo_v - min_v_) / cell_)),
    *v1 = std::min(nv_ - 1, uint32_t((hi_v - min_v_) / cell_));
  };
  cell_offset_.assign(size_t(nu_) * nv_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<uint32_t> fill(cell_offset_.begin(), cell_offset_.end() - 1);
    for (size_t t = 0; t < nt; ++t) {
      uint32_t u0, u1, v0, v1;
      cell_range(t, &u0, &u1, &v0, &v1);
      for (uint32_t cv = v0; cv <= v1; ++cv)
        for (uint32_t cu = u0; cu <= u1; ++cu) {
          const size_t c = size_t(cv) * nu_ + cu;
          if (pass == 0)
            ++cell_offset_[c + 1];
          else
            cell_items_[fill[c]++] = uint32_t(t);
        }
    }
    if (pass == 0) {
      for (size_t c = 0; c + 1 < cell_offset_.size(); ++c) cell_offset_[c + 1] += cell_offset_[c];
      cell_items_.resize(cell_offset_.back());
    }
  }
}

ParamTriangleLocator::Hit ParamTriangleLocator::locate(double u, double v) const {
  if (cell_offset_.empty()) return {};
  const double fu = (u - min_u_) / cell_, fv = (v - min_v_) / cell_;
  if (fu >= 0 && fv >= 0 && fu < nu_ && fv < nv_) {
    const size_t c = size_t(fv) * nu_ + size_t(fu);
    // Points on an edge shared by two triangles are inside both; the
    // tolerance only keeps rounding from pushing them out of both.
    const double tol = -1e-12;
    for (uint32_t k = cell_offset_[c]; k < cell_offset_[c + 1]; ++k) {
      const uint32_t t = cell_items_[k];
      double l[3];
      if (!barycentrics(&uv_[2 * size_t(triangles_[3 * t])], &uv_[2 * size_t(triangles_[3 * t + 1])],
                        &uv_[2 * size_t(triangles_[3 * t + 2])], u, v, l))
        continue;
      if (l[0] >= tol && l[1] >= tol && l[2] >= tol) return {t, l[0], l[1], l[2], true};
    }
  }
  return nearest(u, v);
}

// The closest triangle, searching rings of cells outwards from the query's
// (clamped) cell until no unsearched cell can hold anything closer.
ParamTriangleLocator::Hit ParamTriangleLocator::nearest(double u, double v) const {
  const int64_t cu = std::clamp<int64_t>(int64_t(std::floor((u - min_u_) / cell_)), 0, nu_ - 1);
  const int64_t cv = std::clamp<int64_t>(int64_t(std::floor((v - min_v_) / cell_)), 0, nv_ - 1);
  // Distance from the query to the clamped cell's box (outside the grid).
  const double du = std::max({0.0, min_u_ - u, u - (min_u_ + nu_ * cell_)});
  const double dv = std::max({0.0, min_v_ - v, v - (min_v_ + nv_ * cell_)});
  const double outside = std::hypot(du, dv);
  Hit best;
  double best_d2 = std::numeric_limits<double>::infinity();
  const int64_t max_ring = std::max(nu_, nv_);
  for (int64_t ring = 0; ring <= max_ring; ++ring) {
    for (int64_t y = cv - ring; y <= cv + ring; ++y) {
      if (y < 0 || y >= nv_) continue;
      const bool edge_row = y == cv - ring || y == cv + ring;
      for (int64_t x = cu - ring; x <= cu + ring; x += (edge_row ? 1 : 2 * std::max<int64_t>(ring, 1))) {
        if (x < 0 || x >= nu_) continue;
        const size_t c = size_t(y) * nu_ + size_t(x);
        for (uint32_t k = cell_offset_[c]; k < cell_offset_[c + 1]; ++k) {
          const uint32_t t = cell_items_[k];
          const double* p[3] = {&uv_[2 * size_t(triangles_[3 * t])], &uv_[2 * size_t(triangles_[3 * t + 1])],
                                &uv_[2 * size_t(triangles_[3 * t + 2])]};
          double l[3];
          if (barycentrics(p[0], p[1], p[2], u, v, l) && l[0] >= 0 && l[1] >= 0 && l[2] >= 0)
            return {t, l[0], l[1], l[2], true};
          for (int e = 0; e < 3; ++e) {
            double s;
            const double d2 = segment_distance2(p[e], p[(e + 1) % 3], u, v, &s);
            if (d2 < best_d2) {
              best_d2 = d2;
              best = {t, 0, 0, 0, false};
              double* bl[3] = {&best.b0, &best.b1, &best.b2};
              *bl[e] = 1 - s, *bl[(e + 1) % 3] = s;
            }
          }
        }
      }
    }
    // Cells beyond this ring are at least `ring` cells (plus the gap to the
    // grid) away from the query.
    if (best.triangle != UINT32_MAX && std::sqrt(best_d2) <= outside + ring * cell_) break;
  }
  return best;
}

Status sample_geometry_image(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                             const std::vector<double>& column_u, const std::vector<double>& row_v, GimSamples* out,
                             const std::function<void(double)>& progress, GimSampleStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  if (Status s = check_inputs(mesh, cut, param, column_u, row_v); !s.ok()) return s;
  const uint32_t W = param.width, H = param.height, P = uint32_t(param.border_pixels.size());
  GimSamples img;
  img.width = W, img.height = H;
  img.xyz.assign(3 * size_t(W) * H, 0.0);
  GimSampleStats st;

  const ParamTriangleLocator locator(param.uv, cut.triangles);
  for (uint32_t y = 1; y + 1 < H; ++y) {
    for (uint32_t x = 1; x + 1 < W; ++x) {
      const ParamTriangleLocator::Hit hit = locator.locate(column_u[x], row_v[y]);
      if (hit.triangle == UINT32_MAX) return invalid("the cut has no triangles to sample");
      st.clamped_pixels += !hit.inside;
      const double b[3] = {hit.b0, hit.b1, hit.b2};
      double* p = &img.xyz[3 * (size_t(y) * W + x)];
      for (int k = 0; k < 3; ++k) {
        const double* q = &mesh.positions[3 * size_t(cut.original_vertex[cut.triangles[3 * size_t(hit.triangle) + k]])];
        for (int a = 0; a < 3; ++a) p[a] += b[k] * q[a];
      }
    }
    if (progress) progress(0.9 * y / H);
  }

  // Border: a mated run's pixels come from their index within the run
  // (param.border_arc), so both sides of a seam are one computation; an
  // unmated run (the input's own boundary) follows the grid positions.
  for (const GimBorderRun& run : param.runs) {
    for (uint32_t k = 0; k < run.pixel_steps; ++k) {
      const uint32_t q = (run.first_border_pixel + k) % P, pixel = param.border_pixels[q];
      double arc = param.border_arc[q];
      if (run.mate < 0) {
        const double c = border_coordinate(pixel % W, pixel / W, W, H, column_u, row_v);
        // The border coordinate is only known modulo P; the pixel's index
        // k in the run picks the right turn (and keeps rounding at the
        // run's start from wrapping to its end).
        double t = c - run.first_border_pixel;
        t -= P * std::round((t - k) / P);
        arc = arc_in_run(mesh, cut, run, t / run.pixel_steps);
      }
      boundary_point(mesh, cut, arc, &img.xyz[3 * size_t(pixel)]);
    }
  }

  // Seams: pixel k of a run and pixel steps - k of its mate are one surface
  // point; nodes that several runs share chain up through the union.
  UnionFind same(P);
  for (const GimBorderRun& run : param.runs) {
    if (run.mate < 0) continue;
    const GimBorderRun& mate = param.runs[run.mate];
    for (uint32_t k = 0; k <= run.pixel_steps; ++k)
      same.unite((run.first_border_pixel + k) % P, (mate.first_border_pixel + mate.pixel_steps - k) % P);
  }
  std::vector<uint32_t> smallest(P, UINT32_MAX);
  for (uint32_t q = 0; q < P; ++q) smallest[same.find(q)] = std::min(smallest[same.find(q)], param.border_pixels[q]);
  for (uint32_t q = 0; q < P; ++q) {
    const uint32_t rep = smallest[same.find(q)], pixel = param.border_pixels[q];
    if (rep == pixel) continue;
    std::copy_n(&img.xyz[3 * size_t(rep)], 3, &img.xyz[3 * size_t(pixel)]);
    img.seams.push_back({rep, pixel});
  }
  std::sort(img.seams.begin(), img.seams.end(),
            [](const SeamPair& a, const SeamPair& b) { return a.a != b.a ? a.a < b.a : a.b < b.b; });
  st.seam_pairs = uint32_t(img.seams.size());
  *out = std::move(img);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  if (progress) progress(1.0);
  return Status::Ok();
}

}  // namespace qmc
