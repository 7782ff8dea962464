#include "mesh_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace qmc::tools {
namespace {

using Point = std::array<double, 3>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Point vertex(const qmc::Mesh& mesh, size_t i) {
  return {mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
}

double squared_distance(const Point& a, const Point& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

struct Box {
  Point lo{0, 0, 0}, hi{0, 0, 0};
};

Box bounding_box(const qmc::Mesh& mesh) {
  Box box;
  const size_t n = mesh.vertex_count();
  if (n == 0) return box;
  box.lo = box.hi = vertex(mesh, 0);
  for (size_t i = 1; i < n; ++i) {
    const Point p = vertex(mesh, i);
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = std::min(box.lo[a], p[a]);
      box.hi[a] = std::max(box.hi[a], p[a]);
    }
  }
  return box;
}

ErrorMetrics metrics_with_bbox(const qmc::Mesh& original) {
  const Box box = bounding_box(original);
  ErrorMetrics m;
  double diagonal_squared = 0;
  for (int a = 0; a < 3; ++a) {
    const double side = box.hi[a] - box.lo[a];
    m.max_bbox_side = std::max(m.max_bbox_side, side);
    diagonal_squared += side * side;
  }
  m.bbox_diagonal = std::sqrt(diagonal_squared);
  return m;
}

// Accumulates squared distances; kept separate so both metrics agree on how
// max and rms are derived.
struct Accumulator {
  double max_squared = 0, sum_squared = 0;
  size_t count = 0;

  void add(double d2) {
    max_squared = std::max(max_squared, d2);
    sum_squared += d2;
    ++count;
  }
  void finish(ErrorMetrics* m) const {
    m->compared = count;
    m->max_error = std::sqrt(max_squared);
    m->rms_error = count == 0 ? 0 : std::sqrt(sum_squared / static_cast<double>(count));
  }
};

// Uniform grid over a point set, cells stored as a counting-sorted index list
// so that building it is two linear passes and no per-cell allocation.
class PointGrid {
 public:
  explicit PointGrid(const qmc::Mesh& mesh);

  // Squared distance from q to the nearest stored point (infinite if none).
  double nearest_squared(const Point& q) const;

 private:
  std::array<long, 3> cell_of(const Point& p) const;
  size_t cell_index(long x, long y, long z) const;
  double scan_cell(long x, long y, long z, const Point& q, double best) const;
  double scan_shell(const std::array<long, 3>& c, long r, const Point& q, double best) const;
  double unsearched_lower_bound(const std::array<long, 3>& c, long r, const Point& q) const;

  const qmc::Mesh& mesh_;
  Box box_;
  double cell_size_ = 1;
  std::array<long, 3> dims_{1, 1, 1};
  std::vector<uint32_t> cell_start_;  // size cells + 1
  std::vector<uint32_t> points_;      // point ids grouped by cell
};

// Picks the cell size whose grid has about one cell per point; binary search
// because flat or needle-like boxes make the closed-form cube root useless.
double choose_cell_size(const Box& box, size_t n) {
  double longest = 0;
  for (int a = 0; a < 3; ++a) longest = std::max(longest, box.hi[a] - box.lo[a]);
  if (!(longest > 0) || !std::isfinite(longest)) return 1;
  const auto cells_for = [&](double s) {
    double cells = 1;
    for (int a = 0; a < 3; ++a) cells *= std::floor((box.hi[a] - box.lo[a]) / s) + 1;
    return cells;
  };
  double lo = longest / static_cast<double>(n) / 4, hi = longest * 2;
  for (int i = 0; i < 60; ++i) {
    const double mid = std::sqrt(lo * hi);
    if (cells_for(mid) > static_cast<double>(n)) lo = mid; else hi = mid;
  }
  return hi;
}

PointGrid::PointGrid(const qmc::Mesh& mesh) : mesh_(mesh), box_(bounding_box(mesh)) {
  const size_t n = mesh.vertex_count();
  cell_size_ = choose_cell_size(box_, std::max<size_t>(n, 1));
  for (int a = 0; a < 3; ++a) {
    const double extent = (box_.hi[a] - box_.lo[a]) / cell_size_;
    dims_[a] = std::isfinite(extent) ? static_cast<long>(extent) + 1 : 1;
  }
  const size_t cells = static_cast<size_t>(dims_[0] * dims_[1] * dims_[2]);
  cell_start_.assign(cells + 1, 0);
  std::vector<uint32_t> cell_of_point(n);
  for (size_t i = 0; i < n; ++i) {
    const auto c = cell_of(vertex(mesh, i));
    cell_of_point[i] = static_cast<uint32_t>(cell_index(c[0], c[1], c[2]));
    ++cell_start_[cell_of_point[i] + 1];
  }
  for (size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  points_.resize(n);
  std::vector<uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (size_t i = 0; i < n; ++i) points_[fill[cell_of_point[i]]++] = static_cast<uint32_t>(i);
}

// Clamps into the grid so that queries outside the box start from the
// nearest cell; non-finite coordinates land in cell 0 rather than invoking
// undefined float-to-integer conversion.
std::array<long, 3> PointGrid::cell_of(const Point& p) const {
  std::array<long, 3> c{0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    const double t = (p[a] - box_.lo[a]) / cell_size_;
    if (!std::isfinite(t) || t <= 0) continue;
    c[a] = t >= static_cast<double>(dims_[a] - 1) ? dims_[a] - 1 : static_cast<long>(t);
  }
  return c;
}

size_t PointGrid::cell_index(long x, long y, long z) const {
  return static_cast<size_t>((z * dims_[1] + y) * dims_[0] + x);
}

double PointGrid::scan_cell(long x, long y, long z, const Point& q, double best) const {
  if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) return best;
  const size_t c = cell_index(x, y, z);
  for (uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
    best = std::min(best, squared_distance(q, vertex(mesh_, points_[k])));
  }
  return best;
}

// Visits the cells at Chebyshev distance exactly r from cell c.
double PointGrid::scan_shell(const std::array<long, 3>& c, long r, const Point& q,
                             double best) const {
  for (long dz = -r; dz <= r; ++dz) {
    for (long dy = -r; dy <= r; ++dy) {
      const bool on_face = std::abs(dz) == r || std::abs(dy) == r;
      const long step = on_face ? 1 : 2 * r;  // interior rows only touch their two ends
      for (long dx = -r; dx <= r; dx += step) {
        best = scan_cell(c[0] + dx, c[1] + dy, c[2] + dz, q, best);
      }
    }
  }
  return best;
}

// Every point not yet scanned lies in the grid but outside the block of cells
// within distance r of c, so it is beyond one of the block's faces that still
// has grid on its far side; the nearest such face bounds its distance from q.
// Returns infinity when the block already covers the whole grid.
double PointGrid::unsearched_lower_bound(const std::array<long, 3>& c, long r,
                                         const Point& q) const {
  double bound = kInfinity;
  for (int a = 0; a < 3; ++a) {
    if (c[a] - r > 0) {
      const double face = box_.lo[a] + static_cast<double>(c[a] - r) * cell_size_;
      bound = std::min(bound, std::max(0.0, q[a] - face));
    }
    if (c[a] + r + 1 < dims_[a]) {
      const double face = box_.lo[a] + static_cast<double>(c[a] + r + 1) * cell_size_;
      bound = std::min(bound, std::max(0.0, face - q[a]));
    }
  }
  return bound;
}

double PointGrid::nearest_squared(const Point& q) const {
  if (points_.empty()) return kInfinity;
  const auto c = cell_of(q);
  double best = kInfinity;
  for (long r = 0;; ++r) {
    best = scan_shell(c, r, q, best);
    const double bound = unsearched_lower_bound(c, r, q);
    if (bound == kInfinity || best <= bound * bound) return best;
  }
}

}  // namespace

ErrorMetrics correspondence_error(const qmc::Mesh& original, const qmc::Mesh& decoded,
                                  const std::vector<uint32_t>& decoded_to_original) {
  ErrorMetrics m = metrics_with_bbox(original);
  Accumulator acc;
  const size_t n = decoded.vertex_count();
  const bool length_ok = decoded_to_original.size() == n;
  for (size_t i = 0; i < std::min(n, decoded_to_original.size()); ++i) {
    const uint32_t o = decoded_to_original[i];
    acc.add(o < original.vertex_count() ? squared_distance(vertex(decoded, i), vertex(original, o))
                                        : kInfinity);
  }
  acc.finish(&m);
  if (!length_ok) m.max_error = m.rms_error = kInfinity;
  return m;
}

ErrorMetrics nearest_vertex_error(const qmc::Mesh& original, const qmc::Mesh& decoded) {
  ErrorMetrics m = metrics_with_bbox(original);
  const PointGrid grid(decoded);
  Accumulator acc;
  for (size_t i = 0; i < original.vertex_count(); ++i) {
    acc.add(grid.nearest_squared(vertex(original, i)));
  }
  acc.finish(&m);
  return m;
}

}  // namespace qmc::tools
