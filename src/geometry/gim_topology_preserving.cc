// Seed 002 "Methods": topology-preserving geometry images (see
// gim_topology_preserving.h). This file: the pipeline, its input checks and
// output, and step 1, "Gaining nearly uniform distribution" (eq. 2, the
// geometry phase of Xu et al.'s capacity-constrained Delaunay triangulation,
// without the connectivity phase so the triangles stay the input's).
#include "geometry/gim_topology_preserving.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace qmc {
namespace {

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Twice the signed area of triangle t in uv.
double area2(const std::vector<uint32_t>& tris, const std::vector<double>& uv, size_t t) {
  const uint32_t a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
  return (uv[2 * b] - uv[2 * a]) * (uv[2 * c + 1] - uv[2 * a + 1]) -
         (uv[2 * c] - uv[2 * a]) * (uv[2 * b + 1] - uv[2 * a + 1]);
}

// Variance of the triangle areas over their squared mean (eq. 2 summed over
// the mesh, scale-free).
double area_energy(const std::vector<uint32_t>& tris, const std::vector<double>& uv) {
  const size_t nt = tris.size() / 3;
  if (nt == 0) return 0;
  double sum = 0, sum2 = 0;
  for (size_t t = 0; t < nt; ++t) {
    const double a = area2(tris, uv, t);
    sum += a, sum2 += a * a;
  }
  const double mean = sum / nt;
  return mean != 0 ? std::max(0.0, sum2 / nt - mean * mean) / (mean * mean) : 0;
}

// One incident triangle seen from its vertex v: (v, p, q) counter-clockwise,
// so its doubled area is alpha * x + beta * y + gamma at v = (x, y).
struct Wedge {
  double alpha, beta, gamma;
};

// The point minimizing the variance of the incident areas (eq. 2); the
// coordinates fixed by the border stay. False when the system is singular.
bool equal_area_point(const std::vector<Wedge>& w, uint8_t sides, double x0, double y0, double* x, double* y) {
  const size_t k = w.size();
  if (k < 2) return false;
  double ma = 0, mb = 0, mg = 0;
  for (const Wedge& e : w) ma += e.alpha, mb += e.beta, mg += e.gamma;
  ma /= k, mb /= k, mg /= k;
  double saa = 0, sab = 0, sbb = 0, sag = 0, sbg = 0;
  for (const Wedge& e : w) {
    const double a = e.alpha - ma, b = e.beta - mb, g = e.gamma - mg;
    saa += a * a, sab += a * b, sbb += b * b, sag += a * g, sbg += b * g;
  }
  const bool free_x = !(sides & (kSideMinX | kSideMaxX)), free_y = !(sides & (kSideMinY | kSideMaxY));
  if (free_x && free_y) {
    const double det = saa * sbb - sab * sab;
    if (!(std::fabs(det) > 1e-12 * (saa + sbb) * (saa + sbb))) return false;
    *x = (-sag * sbb + sbg * sab) / det;
    *y = (-sbg * saa + sag * sab) / det;
  } else if (free_x) {
    if (!(saa > 0)) return false;
    *x = -(sag + sab * y0) / saa, *y = y0;
  } else if (free_y) {
    if (!(sbb > 0)) return false;
    *x = x0, *y = -(sbg + sab * x0) / sbb;
  } else {
    return false;
  }
  return std::isfinite(*x) && std::isfinite(*y);
}

// Smallest height (doubled area / longest edge) of v's triangles with v at (x, y).
double min_altitude(const PlanarDisk& disk, const VertexCorners& ring, uint32_t v, const std::vector<double>& p, double x, double y) {
  const std::vector<uint32_t>& tris = *disk.triangles;
  double best = INFINITY;
  for (uint32_t k = ring.offset[v]; k < ring.offset[v + 1]; ++k) {
    const uint32_t c = ring.corner[k], t = c / 3, i = c % 3;
    const uint32_t a = tris[3 * t + (i + 1) % 3], b = tris[3 * t + (i + 2) % 3];
    const double ax = p[2 * a] - x, ay = p[2 * a + 1] - y, bx = p[2 * b] - x, by = p[2 * b + 1] - y;
    const double ar = ax * by - bx * ay;
    const double l = std::max({ax * ax + ay * ay, bx * bx + by * by, (ax - bx) * (ax - bx) + (ay - by) * (ay - by)});
    best = std::min(best, ar / std::sqrt(l));
  }
  return best;
}

// Moves vertex v towards its equal-area point, halving the move until no
// incident triangle that was positive loses more than its floor.
bool relax_vertex(const PlanarDisk& disk, const VertexCorners& ring, uint32_t v, double w_rect, double h_rect,
                  std::vector<double>* uv, std::vector<Wedge>* wedges) {
  const std::vector<uint32_t>& tris = *disk.triangles;
  std::vector<double>& p = *uv;
  wedges->clear();
  double before_min = INFINITY, mean = 0;
  for (uint32_t k = ring.offset[v]; k < ring.offset[v + 1]; ++k) {
    const uint32_t c = ring.corner[k], t = c / 3, i = c % 3;
    const uint32_t a = tris[3 * t + (i + 1) % 3], b = tris[3 * t + (i + 2) % 3];
    const Wedge e{p[2 * a + 1] - p[2 * b + 1], p[2 * b] - p[2 * a], p[2 * a] * p[2 * b + 1] - p[2 * b] * p[2 * a + 1]};
    wedges->push_back(e);
    const double ar = e.alpha * p[2 * v] + e.beta * p[2 * v + 1] + e.gamma;
    before_min = std::min(before_min, ar), mean += ar;
  }
  if (wedges->empty()) return false;
  mean /= wedges->size();
  // Triangles that are not positive now (a flawed parametrization) are left
  // to the integer placement; the others must stay clearly positive.
  const double floor = 1e-6 * std::fabs(mean);
  double x, y;
  if (!equal_area_point(*wedges, disk.sides[v], p[2 * v], p[2 * v + 1], &x, &y)) return false;
  x = std::clamp(x, 0.0, w_rect), y = std::clamp(y, 0.0, h_rect);
  const double x0 = p[2 * v], y0 = p[2 * v + 1];
  for (int halving = 0; halving < 8; ++halving) {
    bool ok = true;
    for (size_t i = 0; i < wedges->size() && ok; ++i) {
      const Wedge& e = (*wedges)[i];
      const double now = e.alpha * x0 + e.beta * y0 + e.gamma, after = e.alpha * x + e.beta * y + e.gamma;
      ok = now <= floor || after > floor;
    }
    // The seed's control on large angles: equal areas alone make long thin
    // triangles, and the integer grid needs height, so a move may not lower
    // the smallest triangle height around the vertex.
    ok = ok && min_altitude(disk, ring, v, p, x, y) >= min_altitude(disk, ring, v, p, x0, y0);
    if (ok) {
      p[2 * v] = x, p[2 * v + 1] = y;
      return true;
    }
    x = 0.5 * (x + x0), y = 0.5 * (y + y0);
  }
  return false;
}

// Border line bits of a boundary vertex from its parametric position.
uint8_t border_sides(double u, double v, double w, double h) {
  const double tol = 1e-9 * std::max(w, h);
  uint8_t s = 0;
  if (std::fabs(u) <= tol) s |= kSideMinX;
  if (std::fabs(u - w) <= tol) s |= kSideMaxX;
  if (std::fabs(v) <= tol) s |= kSideMinY;
  if (std::fabs(v - h) <= tol) s |= kSideMaxY;
  return s;
}

Status check_inputs(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param) {
  const size_t nv = cut.original_vertex.size();
  if (param.width < 2 || param.height < 2) return invalid("parametrization rectangle smaller than 2 x 2");
  if (param.uv.size() != 2 * nv)
    return invalid("parametrization has " + std::to_string(param.uv.size() / 2) + " points for " + std::to_string(nv) + " disk vertices");
  if (cut.triangles.size() != mesh.triangles.size() || cut.triangles.size() % 3)
    return invalid("the cut has " + std::to_string(cut.triangles.size() / 3) + " triangles, the mesh " + std::to_string(mesh.triangle_count()));
  for (uint32_t v : cut.original_vertex)
    if (v >= mesh.vertex_count()) return invalid("the cut refers to input vertex " + std::to_string(v));
  for (uint32_t v : cut.triangles)
    if (v >= nv) return invalid("a cut triangle refers to disk vertex " + std::to_string(v));
  for (uint32_t v : cut.boundary_loop)
    if (v >= nv) return invalid("the boundary loop refers to disk vertex " + std::to_string(v));
  for (double c : param.uv)
    if (!std::isfinite(c)) return invalid("parametrization has a non-finite coordinate");
  return Status::Ok();
}

// Pockets: a triangle with all three corners on one border line (an ear of
// the cut, a strip of several, possibly around interior vertices that the
// parametrization put on the line because their whole one-ring is there).
// A vertex on a line (boundary, or interior at the line within tolerance)
// all of whose triangles lie on that line is marked line | kSideOutward, to
// be placed beyond the line (see the header); the pocket's other corners
// (the ends of the chord that closes it) stay on the line.
Status mark_outward(const std::vector<uint32_t>& tris, const std::vector<double>& uv, double w, double h,
                    PlanarDisk* disk) {
  const size_t nv = disk->sides.size();
  std::vector<uint8_t> line(nv);
  for (size_t v = 0; v < nv; ++v) line[v] = disk->sides[v] ? disk->sides[v] : border_sides(uv[2 * v], uv[2 * v + 1], w, h);
  std::vector<uint8_t> all(nv, 0xF);  // lines shared by every triangle of the vertex
  for (size_t t = 0; t < tris.size(); t += 3) {
    const uint8_t common = line[tris[t]] & line[tris[t + 1]] & line[tris[t + 2]];
    for (int i = 0; i < 3; ++i) all[tris[t + i]] &= common;
  }
  for (size_t v = 0; v < nv; ++v) {
    const uint8_t l = all[v] & line[v];
    if (l && !(l & (l - 1)) && !(line[v] & (line[v] - 1))) disk->sides[v] = uint8_t(l | kSideOutward);
  }
  for (size_t t = 0; t < tris.size(); t += 3) {
    const uint32_t* c = &tris[t];
    const bool some_outward = (disk->sides[c[0]] | disk->sides[c[1]] | disk->sides[c[2]]) & kSideOutward;
    if ((line[c[0]] & line[c[1]] & line[c[2]]) && !some_outward)
      return invalid("triangle " + std::to_string(t / 3) +
                     " has all three corners on one border line of the parametrization and none of them can move "
                     "off it; no integer placement keeps it non-degenerate");
  }
  return Status::Ok();
}

// Border bits of every disk vertex, with the middle corners of degenerate
// border triangles marked kSideOutward.
Status classify_border(const DiskCut& cut, const DiskParametrization& param, PlanarDisk* disk) {
  const double w = param.width - 1.0, h = param.height - 1.0;
  disk->sides.assign(cut.original_vertex.size(), 0);
  for (uint32_t v : cut.boundary_loop) {
    const uint8_t s = border_sides(param.uv[2 * size_t(v)], param.uv[2 * size_t(v) + 1], w, h);
    if (s == 0)
      return invalid("boundary vertex " + std::to_string(v) + " at (" + std::to_string(param.uv[2 * size_t(v)]) + ", " +
                     std::to_string(param.uv[2 * size_t(v) + 1]) + ") is not on the rectangle's border");
    disk->sides[v] = s;
  }
  disk->boundary_loop = cut.boundary_loop;
  return mark_outward(cut.triangles, param.uv, w, h, disk);
}

// SeamPairs chaining the pixels of every input vertex that has several.
std::vector<SeamPair> seams_of(const DiskCut& cut, const std::vector<int64_t>& xy, uint32_t width, size_t input_vertices) {
  std::vector<std::vector<uint32_t>> pixels(input_vertices);
  for (size_t d = 0; d < cut.original_vertex.size(); ++d)
    pixels[cut.original_vertex[d]].push_back(uint32_t(xy[2 * d + 1] * width + xy[2 * d]));
  std::vector<SeamPair> seams;
  for (std::vector<uint32_t>& p : pixels) {
    std::sort(p.begin(), p.end());
    for (size_t i = 1; i < p.size(); ++i) seams.push_back({p[i - 1], p[i]});
  }
  return seams;
}

}  // namespace

void equalize_triangle_areas(const PlanarDisk& disk, const TopologyPreservingOptions& opt, std::vector<double>* uv,
                             TopologyPreservingStats* stats) {
  const std::vector<uint32_t>& tris = *disk.triangles;
  const size_t nv = disk.sides.size();
  double w = 0, h = 0;
  for (size_t v = 0; v < nv; ++v) w = std::max(w, (*uv)[2 * v]), h = std::max(h, (*uv)[2 * v + 1]);
  const VertexCorners ring = vertex_corners(tris, nv);
  // Outward vertices keep their place, and so do the other corners of their
  // triangles: sliding one past the outward vertex would undo its pocket.
  std::vector<uint8_t> pinned(nv, 0);
  for (size_t t = 0; t < tris.size(); t += 3)
    if ((disk.sides[tris[t]] | disk.sides[tris[t + 1]] | disk.sides[tris[t + 2]]) & kSideOutward)
      pinned[tris[t]] = pinned[tris[t + 1]] = pinned[tris[t + 2]] = 1;
  std::vector<Wedge> wedges;
  double energy = area_energy(tris, *uv);
  if (stats) stats->area_variance_before = energy;
  int sweeps = 0;
  uint32_t rejected = 0;
  for (; sweeps < opt.max_area_sweeps; ++sweeps) {
    for (uint32_t v = 0; v < nv; ++v) {
      const uint8_t s = disk.sides[v];
      if (s != 0 && (!opt.slide_boundary || (s & (s - 1)) || pinned[v])) continue;  // corners never move
      if (!relax_vertex(disk, ring, v, w, h, uv, &wedges)) ++rejected;
    }
    const double next = area_energy(tris, *uv);
    const bool converged = energy - next < opt.energy_threshold * energy;
    energy = next;
    if (converged) {
      ++sweeps;
      break;
    }
  }
  if (stats) stats->area_sweeps = sweeps, stats->area_variance_after = energy, stats->area_moves_rejected = rejected;
}

Status make_topology_preserving_image(const GimTriMesh& mesh, const DiskCut& cut, const DiskParametrization& param,
                                      const TopologyPreservingOptions& opt, GimSamples* out,
                                      TopologyPreservingStats* stats, const std::function<void(double)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  TopologyPreservingStats st;
  if (Status s = check_inputs(mesh, cut, param); !s.ok()) return s;
  PlanarDisk disk;
  disk.triangles = &cut.triangles;
  if (Status s = classify_border(cut, param, &disk); !s.ok()) return s;
  const size_t nv = cut.original_vertex.size();

  auto t = std::chrono::steady_clock::now();
  std::vector<double> uv = param.uv;
  equalize_triangle_areas(disk, opt, &uv, &st);
  st.seconds_areas = seconds_since(t);
  if (progress) progress(0.2);

  std::vector<int64_t> xy;
  uint64_t width = 0, height = 0;
  auto sub = [&](double f) {
    if (progress) progress(0.2 + 0.6 * f);
  };
  Status placed = place_on_integer_grid(disk, uv, param.width - 1.0, param.height - 1.0, opt, &xy, &width, &height, &st, sub);
  if (stats) *stats = st;
  if (!placed.ok()) return placed;
  if (width * height > UINT32_MAX) return invalid("image of " + std::to_string(width * height) + " pixels: raster indices exceed 32 bits");

  t = std::chrono::steady_clock::now();
  GimSamples result;
  result.width = uint32_t(width), result.height = uint32_t(height);
  std::vector<double> positions(3 * nv);
  for (size_t d = 0; d < nv; ++d)
    for (int a = 0; a < 3; ++a) positions[3 * d + a] = mesh.positions[3 * size_t(cut.original_vertex[d]) + a];
  fill_by_shape_deformation(cut.triangles, xy, positions, result.width, result.height, &result.xyz,
                            &st.pixels_in_triangles, &st.pixels_outside);
  result.occupied.assign(size_t(width) * height, 0);
  for (size_t d = 0; d < nv; ++d) result.occupied[size_t(xy[2 * d + 1]) * width + size_t(xy[2 * d])] = 1;
  result.triangles.resize(cut.triangles.size());
  for (size_t c = 0; c < cut.triangles.size(); ++c) {
    const uint32_t d = cut.triangles[c];
    result.triangles[c] = uint32_t(xy[2 * size_t(d) + 1] * int64_t(width) + xy[2 * size_t(d)]);
  }
  result.seams = seams_of(cut, xy, result.width, mesh.vertex_count());
  st.seconds_fill = seconds_since(t);
  st.width = result.width, st.height = result.height;
  st.seconds_total = seconds_since(start);
  if (stats) *stats = st;
  *out = std::move(result);
  if (progress) progress(1.0);
  return Status::Ok();
}

VertexCorners vertex_corners(const std::vector<uint32_t>& triangles, size_t vertex_count) {
  VertexCorners r;
  r.offset.assign(vertex_count + 1, 0);
  for (uint32_t v : triangles) ++r.offset[v + 1];
  for (size_t v = 0; v < vertex_count; ++v) r.offset[v + 1] += r.offset[v];
  r.corner.resize(triangles.size());
  std::vector<uint32_t> fill(r.offset.begin(), r.offset.end() - 1);
  for (size_t c = 0; c < triangles.size(); ++c) r.corner[fill[triangles[c]]++] = uint32_t(c);
  return r;
}

}  // namespace qmc
