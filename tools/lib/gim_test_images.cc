// Formula geometry images for tests and conformance vectors (spec 13).
#include "gim_test_images.h"

#include <cmath>

namespace qmc::tools {

GimSamples make_torus_geometry_image(uint32_t n) {
  GimSamples s;
  s.width = s.height = n;
  s.xyz.resize(size_t(n) * n * 3);
  const double two_pi = 6.283185307179586;
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      const double u = two_pi * double(x % (n - 1)) / (n - 1), v = two_pi * double(y % (n - 1)) / (n - 1);
      double* p = &s.xyz[3 * (size_t(y) * n + x)];
      p[0] = (2 + std::cos(v)) * std::cos(u);
      p[1] = (2 + std::cos(v)) * std::sin(u);
      p[2] = std::sin(v);
    }
  for (uint32_t y = 0; y < n; ++y) s.seams.push_back({y * n, y * n + n - 1});
  for (uint32_t x = 0; x < n; ++x) s.seams.push_back({x, (n - 1) * n + x});
  return s;
}

GimSamples make_disk_geometry_image(uint32_t n) {
  GimSamples s;
  s.width = s.height = n;
  s.xyz.resize(size_t(n) * n * 3);
  s.occupied.assign(size_t(n) * n, 0);
  const double c = 0.5 * (n - 1);
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      const double u = (x - c) / c, v = (y - c) / c;
      const size_t p = size_t(y) * n + x;
      s.xyz[3 * p] = u;
      s.xyz[3 * p + 1] = v;
      s.xyz[3 * p + 2] = 1 - (u * u + v * v);
      s.occupied[p] = u * u + v * v <= 1.0 ? 1 : 0;
    }
  return s;
}

GimSamples make_sparse_triangle_image(uint32_t n) {
  // Vertices on the even pixels of the grid; each 2 x 2-pixel cell of them is
  // two triangles, so odd pixels stay blank (filled by the planes' values).
  GimSamples s;
  s.width = s.height = n;
  s.xyz.resize(size_t(n) * n * 3);
  s.occupied.assign(size_t(n) * n, 0);
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      const size_t p = size_t(y) * n + x;
      s.xyz[3 * p] = 0.5 * x;
      s.xyz[3 * p + 1] = 0.5 * y;
      s.xyz[3 * p + 2] = 0.125 * ((x * 7 + y * 3) % 5);
      s.occupied[p] = (x % 2 == 0 && y % 2 == 0) ? 1 : 0;
    }
  for (uint32_t y = 0; y + 2 < n; y += 2)
    for (uint32_t x = 0; x + 2 < n; x += 2) {
      const uint32_t a = y * n + x, b = a + 2, c = a + 2 * n + 2, d = a + 2 * n;
      s.triangles.insert(s.triangles.end(), {a, b, c, a, c, d});
    }
  return s;
}

}  // namespace qmc::tools
