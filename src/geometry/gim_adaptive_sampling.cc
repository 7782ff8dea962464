// Seed 000 §3.1, vertex density equalization (see gim_adaptive_sampling.h).
#include "geometry/gim_adaptive_sampling.h"

#include <algorithm>

namespace qmc {
namespace {

// Strips narrower than this fraction of the uniform spacing are not split.
constexpr double kMinStripFraction = 1.0 / 16;

struct Strip {
  double lo, hi;
  size_t count;
};

// Vertices with lo <= c < hi, or lo <= c <= hi for the last strip.
size_t count_in(const std::vector<double>& sorted, double lo, double hi, bool last) {
  const auto first = std::lower_bound(sorted.begin(), sorted.end(), lo);
  const auto end = last ? std::upper_bound(sorted.begin(), sorted.end(), hi)
                        : std::lower_bound(sorted.begin(), sorted.end(), hi);
  return end > first ? size_t(end - first) : 0;
}

// The fullest splittable strip; ties to the wider, then to the first.
size_t fullest(const std::vector<Strip>& strips, double min_width) {
  size_t best = strips.size();
  for (size_t s = 0; s < strips.size(); ++s) {
    const double width = strips[s].hi - strips[s].lo;
    if (width < min_width) continue;
    if (best == strips.size() || strips[s].count > strips[best].count ||
        (strips[s].count == strips[best].count && width > strips[best].hi - strips[best].lo))
      best = s;
  }
  return best;
}

}  // namespace

std::vector<double> equalized_lines(std::vector<double> coordinates, uint32_t n, double extent) {
  if (n <= 1 || !(extent > 0)) return std::vector<double>(n ? 1 : 0, 0.0);
  std::sort(coordinates.begin(), coordinates.end());
  const uint32_t target = n - 1;
  const uint32_t initial = std::max<uint32_t>(1, std::min(n / 2, target));
  std::vector<Strip> strips(initial);
  for (uint32_t s = 0; s < initial; ++s) {
    strips[s].lo = extent * s / initial;
    strips[s].hi = s + 1 == initial ? extent : extent * (s + 1) / initial;
    strips[s].count = count_in(coordinates, strips[s].lo, strips[s].hi, s + 1 == initial);
  }
  const double min_width = kMinStripFraction * extent / target;
  // One split per missing strip: the loop runs exactly target - initial times.
  while (strips.size() < target) {
    const size_t s = fullest(strips, min_width);
    if (s == strips.size()) break;  // unreachable: the widest strip is >= extent / target wide
    const bool last = s + 1 == strips.size();
    const double mid = 0.5 * (strips[s].lo + strips[s].hi);
    Strip right{mid, strips[s].hi, count_in(coordinates, mid, strips[s].hi, last)};
    strips[s].hi = mid;
    strips[s].count -= std::min(strips[s].count, right.count);
    strips.insert(strips.begin() + std::ptrdiff_t(s) + 1, right);
  }
  std::vector<double> lines;
  lines.reserve(strips.size() + 1);
  lines.push_back(0.0);
  for (const Strip& s : strips) lines.push_back(s.hi);
  lines.back() = extent;
  return lines;
}

void vertex_density_equalization(const std::vector<double>& uv, uint32_t n_columns, uint32_t n_rows, double u_max,
                                 double v_max, std::vector<double>* column_u, std::vector<double>* row_v) {
  std::vector<double> us(uv.size() / 2), vs(uv.size() / 2);
  for (size_t i = 0; i < us.size(); ++i) us[i] = uv[2 * i], vs[i] = uv[2 * i + 1];
  *column_u = equalized_lines(std::move(us), n_columns, u_max);
  *row_v = equalized_lines(std::move(vs), n_rows, v_max);
}

}  // namespace qmc
