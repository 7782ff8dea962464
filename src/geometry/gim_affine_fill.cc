// Seed 002 "Methods", "TPGIM generation by shape deformation": the blank
// pixels of a topology-preserving geometry image get the 3-D point their
// triangle's affine map sends them to, so the planes are smooth and the
// blank pixels lie on the surface. The seed rotates each 3-D triangle into
// the plane, solves the 2-D affine map between the pixel triangle and the
// rotated one, and rotates back; the composition is the unique affine map
// taking the pixel triangle's corners to the 3-D corners, i.e. barycentric
// interpolation, which is what is computed here (exact integer barycentric
// numerators, one division).
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "geometry/gim_topology_preserving.h"

namespace qmc {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

struct Corner {
  int64_t x, y;
};

int64_t orient(Corner a, Corner b, Corner c) { return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y); }

struct Filler {
  const std::vector<uint32_t>& tris;
  const std::vector<int64_t>& xy;
  const std::vector<double>& positions;
  uint32_t W, H;
  std::vector<double>* xyz;

  Corner corner(uint32_t t, int i) const {
    const uint32_t v = tris[3 * size_t(t) + i];
    return {xy[2 * size_t(v)], xy[2 * size_t(v) + 1]};
  }
  void put(size_t pixel, uint32_t t, const double l[3]) const {
    for (int a = 0; a < 3; ++a) {
      double s = 0;
      for (int i = 0; i < 3; ++i) s += l[i] * positions[3 * size_t(tris[3 * size_t(t) + i]) + a];
      (*xyz)[3 * pixel + a] = s;
    }
  }
};

// Pixels inside or on the triangle, row by row: the row's x range comes from
// the edges in floating point, widened by one, and every pixel in it is then
// tested exactly.
void rasterize(const Filler& f, uint32_t t, std::vector<uint32_t>* owner, uint64_t* count) {
  const Corner c[3] = {f.corner(t, 0), f.corner(t, 1), f.corner(t, 2)};
  const int64_t det = orient(c[0], c[1], c[2]);
  if (det <= 0) return;
  const int64_t y0 = std::max<int64_t>(0, std::min({c[0].y, c[1].y, c[2].y}));
  const int64_t y1 = std::min<int64_t>(f.H - 1, std::max({c[0].y, c[1].y, c[2].y}));
  const int64_t xmin = std::max<int64_t>(0, std::min({c[0].x, c[1].x, c[2].x}));
  const int64_t xmax = std::min<int64_t>(f.W - 1, std::max({c[0].x, c[1].x, c[2].x}));
  for (int64_t y = y0; y <= y1; ++y) {
    double lo = INFINITY, hi = -INFINITY;
    for (int e = 0; e < 3; ++e) {
      const Corner a = c[e], b = c[(e + 1) % 3];
      if ((a.y - y) * (b.y - y) > 0) continue;  // edge does not reach this row
      if (a.y == b.y) {
        lo = std::min({lo, double(a.x), double(b.x)}), hi = std::max({hi, double(a.x), double(b.x)});
      } else {
        const double x = a.x + double(b.x - a.x) * double(y - a.y) / double(b.y - a.y);
        lo = std::min(lo, x), hi = std::max(hi, x);
      }
    }
    if (lo > hi) continue;
    const int64_t xa = std::max<int64_t>(xmin, int64_t(std::floor(lo)) - 1);
    const int64_t xb = std::min<int64_t>(xmax, int64_t(std::ceil(hi)) + 1);
    for (int64_t x = xa; x <= xb; ++x) {
      const Corner q{x, y};
      const int64_t w0 = orient(q, c[1], c[2]), w1 = orient(c[0], q, c[2]), w2 = orient(c[0], c[1], q);
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const size_t pixel = size_t(y) * f.W + size_t(x);
      if ((*owner)[pixel] != kNone) continue;
      const double l[3] = {double(w0) / double(det), double(w1) / double(det), double(w2) / double(det)};
      f.put(pixel, t, l);
      (*owner)[pixel] = t;
      ++*count;
    }
  }
}

// Barycentric coordinates of the closest point of triangle t to pixel (x, y).
void clamped_barycentric(const Filler& f, uint32_t t, double x, double y, double l[3]) {
  const Corner c[3] = {f.corner(t, 0), f.corner(t, 1), f.corner(t, 2)};
  const double det = double(orient(c[0], c[1], c[2]));
  l[0] = 1, l[1] = 0, l[2] = 0;  // replaced by the first edge unless its distance is NaN
  double best = INFINITY;
  for (int e = 0; e < 3; ++e) {  // closest point on each edge
    const Corner a = c[e], b = c[(e + 1) % 3];
    const double ex = double(b.x - a.x), ey = double(b.y - a.y), len2 = ex * ex + ey * ey;
    double s = len2 > 0 ? ((x - a.x) * ex + (y - a.y) * ey) / len2 : 0;
    s = std::clamp(s, 0.0, 1.0);
    const double px = a.x + s * ex - x, py = a.y + s * ey - y, d = px * px + py * py;
    if (d < best) {
      best = d;
      l[e] = 1 - s, l[(e + 1) % 3] = s, l[(e + 2) % 3] = 0;
    }
  }
  if (det > 0) {  // a point inside is its own closest point
    const Corner q{int64_t(x), int64_t(y)};
    const int64_t w0 = orient(q, c[1], c[2]), w1 = orient(c[0], q, c[2]), w2 = orient(c[0], c[1], q);
    if (w0 >= 0 && w1 >= 0 && w2 >= 0) l[0] = w0 / det, l[1] = w1 / det, l[2] = w2 / det;
  }
}

}  // namespace

void fill_by_shape_deformation(const std::vector<uint32_t>& triangles, const std::vector<int64_t>& xy,
                               const std::vector<double>& positions, uint32_t width, uint32_t height,
                               std::vector<double>* xyz, uint64_t* pixels_in_triangles, uint64_t* pixels_outside) {
  const size_t n = size_t(width) * height;
  xyz->assign(3 * n, 0.0);
  std::vector<uint32_t> owner(n, kNone);
  const Filler f{triangles, xy, positions, width, height, xyz};
  uint64_t inside = 0, outside = 0;
  for (uint32_t t = 0; t < triangles.size() / 3; ++t) rasterize(f, t, &owner, &inside);
  // Pixels no triangle covers (the rectangle's corners when no vertex sits
  // there): breadth-first from the covered ones, each taking the triangle of
  // the neighbour it was reached from, clamped to that triangle.
  std::deque<size_t> queue;
  for (size_t i = 0; i < n; ++i) {
    if (owner[i] == kNone) continue;
    const size_t x = i % width, y = i / width;
    if ((x > 0 && owner[i - 1] == kNone) || (x + 1 < width && owner[i + 1] == kNone) ||
        (y > 0 && owner[i - width] == kNone) || (y + 1 < height && owner[i + width] == kNone))
      queue.push_back(i);
  }
  while (!queue.empty()) {
    const size_t i = queue.front();
    queue.pop_front();
    const int64_t x = int64_t(i % width), y = int64_t(i / width);
    const int64_t nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
    for (int k = 0; k < 4; ++k) {
      if (nx[k] < 0 || ny[k] < 0 || nx[k] >= int64_t(width) || ny[k] >= int64_t(height)) continue;
      const size_t j = size_t(ny[k]) * width + size_t(nx[k]);
      if (owner[j] != kNone) continue;
      owner[j] = owner[i];
      double l[3];
      clamped_barycentric(f, owner[j], double(nx[k]), double(ny[k]), l);
      f.put(j, owner[j], l);
      ++outside;
      queue.push_back(j);
    }
  }
  // Vertex pixels: the input positions bit for bit (a barycentric sum could
  // turn -0.0 into +0.0).
  for (size_t v = 0; v < xy.size() / 2; ++v) {
    const size_t pixel = size_t(xy[2 * v + 1]) * width + size_t(xy[2 * v]);
    for (int a = 0; a < 3; ++a) (*xyz)[3 * pixel + a] = positions[3 * v + a];
  }
  if (pixels_in_triangles) *pixels_in_triangles = inside;
  if (pixels_outside) *pixels_outside = outside;
}

}  // namespace qmc
