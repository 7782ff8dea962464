// Seed 000 §4: enhanced-ROI geometry images (see gim_roi.h).
#include "geometry/gim_roi.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>

#include "geometry/gim_sampling.h"

namespace qmc {
namespace {

Status parse_error(size_t line, const std::string& what) {
  return Status(ErrorCode::kInvalidArgument, "ROI file line " + std::to_string(line) + ": " + what);
}

std::vector<std::string> tokens_of(const std::string& line) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

bool parse_index(const std::string& s, uint32_t* out) {
  const char* end = s.data() + s.size();
  auto r = std::from_chars(s.data(), end, *out);
  return r.ec == std::errc() && r.ptr == end;
}

bool parse_number(const std::string& s, double* out) {
  const char* end = s.data() + s.size();
  auto r = std::from_chars(s.data(), end, *out);
  return r.ec == std::errc() && r.ptr == end && std::isfinite(*out);
}

}  // namespace

Status parse_roi_file(const std::string& text, RegionOfInterest* out) {
  RegionOfInterest roi;
  size_t line_no = 0, pos = 0;
  while (pos < text.size()) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    std::string line = text.substr(pos, eol - pos);
    pos = eol + 1, ++line_no;
    if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    const std::vector<std::string> t = tokens_of(line);
    if (t.empty()) continue;
    if (t[0] == "vertex" || t[0] == "face") {
      std::vector<uint32_t>& list = t[0] == "vertex" ? roi.vertices : roi.faces;
      if (t.size() == 1) return parse_error(line_no, "'" + t[0] + "' without indices");
      for (size_t k = 1; k < t.size(); ++k) {
        uint32_t index;
        if (!parse_index(t[k], &index)) return parse_error(line_no, "'" + t[k] + "' is not a non-negative integer");
        list.push_back(index);
      }
    } else if (t[0] == "box") {
      if (t.size() != 7) return parse_error(line_no, "box needs 6 numbers, got " + std::to_string(t.size() - 1));
      RoiBox box;
      for (int k = 0; k < 6; ++k)
        if (!parse_number(t[1 + k], k < 3 ? &box.lo[k] : &box.hi[k - 3]))
          return parse_error(line_no, "'" + t[1 + k] + "' is not a finite number");
      for (int k = 0; k < 3; ++k)
        if (box.lo[k] > box.hi[k]) return parse_error(line_no, "box minimum above its maximum on axis " + std::to_string(k));
      roi.boxes.push_back(box);
    } else {
      return parse_error(line_no, "unknown keyword '" + t[0] + "' (expected vertex, face or box)");
    }
  }
  if (roi.vertices.empty() && roi.faces.empty() && roi.boxes.empty())
    return Status(ErrorCode::kInvalidArgument, "ROI file selects nothing");
  *out = std::move(roi);
  return Status::Ok();
}

Status roi_parameter_rect(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                          const RegionOfInterest& roi, RoiRect* rect) {
  const size_t n = mesh.vertex_count();
  if (param.uv.size() != 2 * cut.original_vertex.size()) return Status(ErrorCode::kInvalidArgument, "ROI: parametrization does not match the cut");
  std::vector<uint8_t> selected(n, 0);
  for (uint32_t v : roi.vertices) {
    if (v >= n) return Status(ErrorCode::kInvalidArgument, "ROI vertex " + std::to_string(v) + " out of range (mesh has " + std::to_string(n) + ")");
    selected[v] = 1;
  }
  for (uint32_t f : roi.faces) {
    if (f >= mesh.triangle_count()) return Status(ErrorCode::kInvalidArgument, "ROI face " + std::to_string(f) + " out of range (mesh has " + std::to_string(mesh.triangle_count()) + ")");
    for (int k = 0; k < 3; ++k) selected[mesh.triangles[3 * size_t(f) + k]] = 1;
  }
  for (const RoiBox& b : roi.boxes)
    for (size_t v = 0; v < n; ++v) {
      bool inside = true;
      for (int k = 0; k < 3; ++k) inside = inside && mesh.positions[3 * v + k] >= b.lo[k] && mesh.positions[3 * v + k] <= b.hi[k];
      if (inside) selected[v] = 1;
    }
  RoiRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (size_t d = 0; d < cut.original_vertex.size(); ++d) {
    if (cut.original_vertex[d] >= n) return Status(ErrorCode::kInvalidArgument, "ROI: cut does not match the mesh");
    if (!selected[cut.original_vertex[d]]) continue;
    r.u0 = std::min(r.u0, param.uv[2 * d]), r.u1 = std::max(r.u1, param.uv[2 * d]);
    r.v0 = std::min(r.v0, param.uv[2 * d + 1]), r.v1 = std::max(r.v1, param.uv[2 * d + 1]);
  }
  if (!(r.u0 <= r.u1)) return Status(ErrorCode::kInvalidArgument, "ROI selects no vertex of the mesh");
  *rect = r;
  return Status::Ok();
}

int roi_region(const RoiRect& rect, double u, double v) {
  if (rect.contains(u, v)) return 4;
  if (v < rect.v0) return 0;
  if (v > rect.v1) return 1;
  return u < rect.u0 ? 2 : 3;
}

namespace {

// Region weights for the current sample positions (seed 000 §4).
void region_weights(const DiskParametrization& param, const RoiRect& rect, const std::vector<double>& pixel_uv,
                    double roi_weight, RoiSamplingStats* st) {
  double vertices[5] = {0, 0, 0, 0, 0}, samples[5] = {0, 0, 0, 0, 0};
  for (size_t d = 0; d < param.uv.size() / 2; ++d) ++vertices[roi_region(rect, param.uv[2 * d], param.uv[2 * d + 1])];
  for (size_t p = 0; p < pixel_uv.size() / 2; ++p) ++samples[roi_region(rect, pixel_uv[2 * p], pixel_uv[2 * p + 1])];
  const double total_vertices = std::max<double>(1, double(param.uv.size() / 2));
  const double n2 = double(pixel_uv.size() / 2);
  int order[4] = {0, 1, 2, 3};
  for (int r = 0; r < 4; ++r) {
    st->n_ideal[r] = vertices[r] / total_vertices * n2;
    st->surplus[r] = samples[r] - st->n_ideal[r];
  }
  // Most surplus first gets the lowest weight; ties by region number.
  std::stable_sort(order, order + 4, [&](int a, int b) { return st->surplus[a] > st->surplus[b]; });
  for (int k = 0; k < 4; ++k) st->weight[order[k]] = k + 1;
  st->weight[4] = roi_weight;
}

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Is the grid cell with top-left pixel (x, y) strictly convex with the
// orientation of the unmoved grid (u right, v down: positive cross products)?
bool cell_convex(const std::vector<double>& uv, uint32_t w, uint32_t x, uint32_t y) {
  const size_t c[4] = {size_t(y) * w + x, size_t(y) * w + x + 1, size_t(y + 1) * w + x + 1, size_t(y + 1) * w + x};
  for (int k = 0; k < 4; ++k) {
    const size_t a = c[k], b = c[(k + 1) % 4], d = c[(k + 2) % 4];
    if (!(cross2(uv[2 * b] - uv[2 * a], uv[2 * b + 1] - uv[2 * a + 1], uv[2 * d] - uv[2 * b], uv[2 * d + 1] - uv[2 * b + 1]) > 0))
      return false;
  }
  return true;
}

bool cells_convex_around(const std::vector<double>& uv, uint32_t w, uint32_t x, uint32_t y) {
  return cell_convex(uv, w, x - 1, y - 1) && cell_convex(uv, w, x, y - 1) && cell_convex(uv, w, x - 1, y) &&
         cell_convex(uv, w, x, y);
}

uint32_t count_in_roi(const RoiRect& rect, const std::vector<double>& uv) {
  uint32_t n = 0;
  for (size_t p = 0; p < uv.size() / 2; ++p) n += rect.contains(uv[2 * p], uv[2 * p + 1]);
  return n;
}

}  // namespace

Status roi_adapt_sampling(const DiskParametrization& param, const RoiRect& rect, uint32_t width, uint32_t height,
                          const std::vector<uint8_t>* fixed, const RoiSamplingOptions& options,
                          std::vector<double>* pixel_uv, RoiSamplingStats* stats,
                          const std::function<void(double)>& progress) {
  const size_t pixels = size_t(width) * height;
  if (width < 2 || height < 2 || pixel_uv->size() != 2 * pixels) return Status(ErrorCode::kInvalidArgument, "ROI sampling: pixel_uv must hold 2 values for each of W x H >= 2 x 2 pixels");
  if (fixed && fixed->size() != pixels) return Status(ErrorCode::kInvalidArgument, "ROI sampling: `fixed` needs one byte per pixel");
  if (!(options.roi_weight > 0)) return Status(ErrorCode::kInvalidArgument, "ROI sampling: roi_weight must be positive");
  std::vector<double>& uv = *pixel_uv;
  for (uint32_t y = 0; y + 1 < height; ++y)
    for (uint32_t x = 0; x + 1 < width; ++x)
      if (!cell_convex(uv, width, x, y)) return Status(ErrorCode::kInvalidArgument, "ROI sampling: grid cell (" + std::to_string(x) + ", " + std::to_string(y) + ") of the initial positions is not convex");
  RoiSamplingStats st;
  st.roi_samples_before = count_in_roi(rect, uv);
  const uint32_t target = options.target_roi_samples ? options.target_roi_samples : 2 * std::max(1u, st.roi_samples_before);
  // The six neighbours of the (x,y)-(x+1,y+1) triangulation.
  static const int kRing[6][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 0}, {-1, -1}, {0, -1}};
  uint32_t in_roi = st.roi_samples_before;
  for (uint32_t sweep = 0; sweep < options.max_sweeps && in_roi < target; ++sweep) {
    if (progress) progress(double(sweep) / options.max_sweeps);
    region_weights(param, rect, uv, options.roi_weight, &st);
    uint64_t moved = 0;
    for (uint32_t y = 1; y + 1 < height; ++y)
      for (uint32_t x = 1; x + 1 < width; ++x) {
        const size_t p = size_t(y) * width + x;
        if (fixed && (*fixed)[p]) continue;
        const double u0 = uv[2 * p], v0 = uv[2 * p + 1];
        double su = 0, sv = 0, sw = 0;
        for (const auto& o : kRing) {
          const size_t q = size_t(int(y) + o[1]) * width + size_t(int(x) + o[0]);
          const double qu = uv[2 * q], qv = uv[2 * q + 1];
          const double w = st.weight[roi_region(rect, qu, qv)] * std::hypot(qu - u0, qv - v0);
          su += w * qu, sv += w * qv, sw += w;
        }
        if (!(sw > 0)) continue;
        double du = su / sw - u0, dv = sv / sw - v0;
        if (std::hypot(du, dv) < 1e-9) continue;
        bool placed = false;
        for (uint32_t h = 0; h <= options.max_halvings && !placed; ++h, du *= 0.5, dv *= 0.5) {
          uv[2 * p] = u0 + du, uv[2 * p + 1] = v0 + dv;
          placed = cells_convex_around(uv, width, x, y);
        }
        if (!placed) {
          uv[2 * p] = u0, uv[2 * p + 1] = v0;
          ++st.blocked_moves;
          continue;
        }
        ++moved;
        in_roi += int(rect.contains(uv[2 * p], uv[2 * p + 1])) - int(rect.contains(u0, v0));
      }
    st.moves += moved;
    ++st.sweeps;
    if (moved == 0) break;
  }
  st.roi_samples_after = count_in_roi(rect, uv);
  if (progress) progress(1.0);
  if (stats) *stats = st;
  return Status::Ok();
}

std::vector<double> pixel_uv_from_lines(const std::vector<double>& column_u, const std::vector<double>& row_v) {
  std::vector<double> uv(2 * column_u.size() * row_v.size());
  for (size_t y = 0; y < row_v.size(); ++y)
    for (size_t x = 0; x < column_u.size(); ++x) {
      uv[2 * (y * column_u.size() + x)] = column_u[x];
      uv[2 * (y * column_u.size() + x) + 1] = row_v[y];
    }
  return uv;
}

Status sample_at_pixel_uv(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                          const std::vector<double>& pixel_uv, const std::vector<uint8_t>* keep,
                          GimSamples* samples) {
  const size_t pixels = size_t(samples->width) * samples->height;
  if (pixel_uv.size() != 2 * pixels) return Status(ErrorCode::kInvalidArgument, "sample_at_pixel_uv: pixel_uv needs 2 values per pixel");
  if (keep && keep->size() != pixels) return Status(ErrorCode::kInvalidArgument, "sample_at_pixel_uv: `keep` needs one byte per pixel");
  if (param.uv.size() != 2 * cut.original_vertex.size() || cut.triangles.empty()) return Status(ErrorCode::kInvalidArgument, "sample_at_pixel_uv: parametrization does not match the cut");
  for (uint32_t v : cut.original_vertex)
    if (v >= mesh.vertex_count()) return Status(ErrorCode::kInvalidArgument, "sample_at_pixel_uv: cut does not match the mesh");
  samples->xyz.resize(3 * pixels);
  const ParamTriangleLocator locator(param.uv, cut.triangles);
  for (size_t p = 0; p < pixels; ++p) {
    if (keep && (*keep)[p]) continue;
    const ParamTriangleLocator::Hit hit = locator.locate(pixel_uv[2 * p], pixel_uv[2 * p + 1]);
    if (hit.triangle == UINT32_MAX) return Status(ErrorCode::kInvalidArgument, "sample_at_pixel_uv: no triangle to sample");
    const double b[3] = {hit.b0, hit.b1, hit.b2};
    for (int a = 0; a < 3; ++a) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += b[k] * mesh.positions[3 * size_t(cut.original_vertex[cut.triangles[3 * size_t(hit.triangle) + k]]) + a];
      samples->xyz[3 * p + a] = s;
    }
  }
  return Status::Ok();
}

std::vector<uint8_t> roi_face_mask(const std::vector<double>& pixel_uv, const std::vector<uint32_t>& triangles,
                                   const RoiRect& rect) {
  std::vector<uint8_t> mask(triangles.size() / 3, 0);
  for (size_t t = 0; t < mask.size(); ++t) {
    double u = 0, v = 0;
    for (int k = 0; k < 3; ++k) u += pixel_uv[2 * size_t(triangles[3 * t + k])] / 3, v += pixel_uv[2 * size_t(triangles[3 * t + k]) + 1] / 3;
    mask[t] = rect.contains(u, v);
  }
  return mask;
}

std::vector<uint8_t> seam_pixels(const GimSamples& samples) {
  std::vector<uint8_t> out(size_t(samples.width) * samples.height, 0);
  for (const SeamPair& s : samples.seams) {
    if (s.a < out.size()) out[s.a] = 1;
    if (s.b < out.size()) out[s.b] = 1;
  }
  return out;
}

std::vector<uint8_t> roi_fixed_pixels(const GimSamples& samples) {
  const uint32_t w = samples.width, h = samples.height;
  std::vector<uint8_t> out(size_t(w) * h, 0);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      if (x == 0 || y == 0 || x + 1 == w || y + 1 == h) out[size_t(y) * w + x] = 1;
  for (const SeamPair& s : samples.seams) {
    if (s.a < out.size()) out[s.a] = 1;
    if (s.b < out.size()) out[s.b] = 1;
  }
  return out;
}

}  // namespace qmc
