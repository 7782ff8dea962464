// Seed 002 "Methods", "Relaxed grid" (eq. 3) and "Moving vertices to the
// integer position": every vertex on its own integer point, no fold-over, no
// degenerate triangle, then the blank rows and columns squeezed out
// (see gim_topology_preserving.h).
//
// Strategy (sound by construction, then checked exactly):
//  a. Grid interval S of eq. (3): the smallest Chebyshev length of an edge
//     (for each vertex the smallest max(|dx|, |dy|) to a neighbour, then the
//     minimum over vertices). Scale the rectangle by 1 / S and round every
//     vertex to its nearest integer point; boundary vertices snap to their
//     border line, corners to their corner, kSideOutward vertices (middles
//     of degenerate border triangles) to the first line beyond theirs.
//  b. Relaxation rounds: every vertex that shares its point or touches a
//     triangle of orientation <= 0 moves to the free integer point nearest
//     its target for which all its triangles are positive (a growing window;
//     border vertices only along their line, outward ones only beyond it,
//     at most kMaxOutward). int64 orientation tests.
//  c. If vertices remain unplaced, the grid is stretched x3 (the seed's "8
//     vacancies around each point") and a-b start again from the
//     parametrization. As the scale grows, rounding moves every vertex by a
//     vanishing fraction of its triangles' heights, so a valid
//     parametrization always places at some scale; the coordinates are kept
//     below 2^28 so every cross product fits in int64.
//  d. Compression, alternately along x and y: squeezing the gap between two
//     consecutive occupied columns shifts every vertex on one side by t,
//     and a triangle's doubled area is linear in t, so the largest safe t is
//     exact integer arithmetic; t may close the gap entirely (two columns
//     become one) when no two vertices meet. The seed's deletion of blank
//     rows / columns, done gap by gap; border lines stay border lines and the
//     map stays monotone, so order along the border is kept. With outward
//     vertices the boundary is no longer convex and a pass could make two
//     bulges touch, so then every pass is followed by the boundary polygon
//     check and undone if it fails.
//  e. The image is the vertices' bounding box (outward vertices may lie
//     beyond the rectangle's lines), and check_integer_layout verifies the
//     result before it is returned.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "geometry/gim_topology_preserving.h"

namespace qmc {
namespace {

constexpr int64_t kMaxCoordinate = int64_t(1) << 28;

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

struct Pt {
  int64_t x, y;
};

// Twice the signed area; exact for coordinates below 2^28.
int64_t orient(Pt a, Pt b, Pt c) { return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y); }

uint64_t key(int64_t x, int64_t y) { return (uint64_t(x) << 32) ^ uint64_t(y); }

// Eq. (3): min over vertices of min over neighbours of max(|dx|, |dy|).
double grid_spacing(const std::vector<uint32_t>& tris, const std::vector<double>& uv) {
  double s = INFINITY;
  for (size_t t = 0; t < tris.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = tris[t + k], b = tris[t + (k + 1) % 3];
      const double d = std::max(std::fabs(uv[2 * a] - uv[2 * b]), std::fabs(uv[2 * a + 1] - uv[2 * b + 1]));
      if (d > 0) s = std::min(s, d);
    }
  return s;
}

// The layout being built at one scale.
struct Grid {
  const PlanarDisk* disk = nullptr;
  const VertexCorners* inc = nullptr;
  int64_t X = 0, Y = 0;              // border lines x = 0, X and y = 0, Y
  std::vector<Pt> p;
  std::vector<double> target;        // 2 per vertex, scaled parametrization
  std::unordered_map<uint64_t, uint32_t> count;  // vertices per occupied point

  Pt at(uint32_t v) const { return p[v]; }
  const uint32_t* tri(uint32_t t) const { return &(*disk->triangles)[3 * size_t(t)]; }
};

// Integer point of a vertex constrained to its border line(s); an outward
// vertex strictly beyond its line, within the line's span along it.
Pt snap(const Grid& g, uint8_t sides, int64_t x, int64_t y) {
  if (sides & kSideOutward) {
    if (!(sides & (kSideMinX | kSideMaxX))) x = std::clamp<int64_t>(x, 0, g.X);
    if (!(sides & (kSideMinY | kSideMaxY))) y = std::clamp<int64_t>(y, 0, g.Y);
    if (sides & kSideMinX) x = std::min<int64_t>(x, -1);
    if (sides & kSideMaxX) x = std::max<int64_t>(x, g.X + 1);
    if (sides & kSideMinY) y = std::min<int64_t>(y, -1);
    if (sides & kSideMaxY) y = std::max<int64_t>(y, g.Y + 1);
    return {x, y};
  }
  if (sides == 0) {  // interior vertices stay off the border
    x = std::clamp<int64_t>(x, std::min<int64_t>(1, g.X), std::max<int64_t>(g.X - 1, 0));
    y = std::clamp<int64_t>(y, std::min<int64_t>(1, g.Y), std::max<int64_t>(g.Y - 1, 0));
  } else {
    x = std::clamp<int64_t>(x, 0, g.X), y = std::clamp<int64_t>(y, 0, g.Y);
  }
  if (sides & kSideMinX) x = 0;
  if (sides & kSideMaxX) x = g.X;
  if (sides & kSideMinY) y = 0;
  if (sides & kSideMaxY) y = g.Y;
  return {x, y};
}

bool triangles_positive(const Grid& g, uint32_t v, Pt at) {
  for (uint32_t k = g.inc->offset[v]; k < g.inc->offset[v + 1]; ++k) {
    const uint32_t* c = g.tri(g.inc->corner[k] / 3);
    Pt q[3];
    for (int i = 0; i < 3; ++i) q[i] = c[i] == v ? at : g.p[c[i]];
    if (orient(q[0], q[1], q[2]) <= 0) return false;
  }
  return true;
}

bool placed(const Grid& g, uint32_t v) {
  return g.count.at(key(g.p[v].x, g.p[v].y)) == 1 && triangles_positive(g, v, g.p[v]);
}

void move_vertex(Grid* g, uint32_t v, Pt to) {
  auto it = g->count.find(key(g->p[v].x, g->p[v].y));
  if (--it->second == 0) g->count.erase(it);
  g->p[v] = to;
  ++g->count[key(to.x, to.y)];
}

void round_at_scale(const PlanarDisk& disk, const std::vector<double>& uv, double w, double h, double scale,
                    Grid* g) {
  const size_t nv = disk.sides.size();
  g->X = std::max<int64_t>(2, std::llround(w * scale));
  g->Y = std::max<int64_t>(2, std::llround(h * scale));
  g->p.resize(nv);
  g->target.resize(2 * nv);
  g->count.clear();
  g->count.reserve(2 * nv);
  for (size_t v = 0; v < nv; ++v) {
    g->target[2 * v] = uv[2 * v] * double(g->X) / w;
    g->target[2 * v + 1] = uv[2 * v + 1] * double(g->Y) / h;
    g->p[v] = snap(*g, disk.sides[v], std::llround(g->target[2 * v]), std::llround(g->target[2 * v + 1]));
    ++g->count[key(g->p[v].x, g->p[v].y)];
  }
}

// --- Pockets: runs of outward vertices (see gim_topology_preserving.h). ---

// A maximal run of consecutive outward boundary vertices between the border
// vertices a and c, all on one border line, and the outward interior
// vertices enclosed with it.
struct Pocket {
  uint32_t a, c;
  uint8_t line;
  std::vector<uint32_t> run, inner;
};

// The outward interior vertices reached from the run through triangles.
void flood_pocket(const PlanarDisk& disk, const VertexCorners& inc, const std::vector<uint8_t>& on_loop, Pocket* pk) {
  std::vector<uint32_t> stack = pk->run;
  std::unordered_set<uint32_t> seen(stack.begin(), stack.end());
  while (!stack.empty()) {
    const uint32_t v = stack.back();
    stack.pop_back();
    for (uint32_t k = inc.offset[v]; k < inc.offset[v + 1]; ++k)
      for (int i = 0; i < 3; ++i) {
        const uint32_t u = (*disk.triangles)[3 * size_t(inc.corner[k] / 3) + i];
        if (on_loop[u] || !(disk.sides[u] & kSideOutward) || !seen.insert(u).second) continue;
        pk->inner.push_back(u), stack.push_back(u);
      }
  }
}

std::vector<Pocket> find_pockets(const PlanarDisk& disk, const VertexCorners& inc) {
  const std::vector<uint32_t>& loop = disk.boundary_loop;
  const size_t n = loop.size();
  std::vector<uint8_t> on_loop(disk.sides.size(), 0);
  for (uint32_t v : loop) on_loop[v] = 1;
  std::vector<Pocket> pockets;
  auto outward = [&](size_t i) { return (disk.sides[loop[i % n]] & kSideOutward) != 0; };
  for (size_t i = 0; i < n; ++i) {
    if (!outward(i) || outward(i + n - 1)) continue;  // i starts a run
    Pocket p{loop[(i + n - 1) % n], 0, uint8_t(disk.sides[loop[i]] & ~kSideOutward), {}, {}};
    for (size_t j = i; outward(j) && p.run.size() < n; ++j) p.run.push_back(loop[j % n]), p.c = loop[(j + 1) % n];
    flood_pocket(disk, inc, on_loop, &p);
    pockets.push_back(std::move(p));
  }
  return pockets;
}

// Tutte's barycentric embedding of the pocket's interior vertices inside
// its convex outline (bounded Gauss-Seidel), rounded; repair fixes ties.
void place_pocket_inner(const Pocket& pk, Grid* g) {
  if (pk.inner.empty()) return;
  std::unordered_map<uint32_t, size_t> index;
  for (size_t i = 0; i < pk.inner.size(); ++i) index[pk.inner[i]] = i;
  std::vector<double> x(2 * pk.inner.size());
  const Pt a = g->p[pk.a], c = g->p[pk.c];
  for (size_t i = 0; i < pk.inner.size(); ++i) x[2 * i] = 0.5 * double(a.x + c.x), x[2 * i + 1] = 0.5 * double(a.y + c.y);
  auto pos = [&](uint32_t u, int k) {
    auto it = index.find(u);
    return it != index.end() ? x[2 * it->second + k] : double(k == 0 ? g->p[u].x : g->p[u].y);
  };
  for (int sweep = 0; sweep < 2000; ++sweep) {
    double moved = 0;
    for (size_t i = 0; i < pk.inner.size(); ++i) {
      const uint32_t v = pk.inner[i];
      double sx = 0, sy = 0, m = 0;
      for (uint32_t k = g->inc->offset[v]; k < g->inc->offset[v + 1]; ++k)
        for (int j = 0; j < 3; ++j) {
          const uint32_t u = g->tri(g->inc->corner[k] / 3)[j];
          if (u != v) sx += pos(u, 0), sy += pos(u, 1), m += 1;  // each neighbour twice: same average
        }
      if (m == 0) continue;
      moved = std::max({moved, std::fabs(sx / m - x[2 * i]), std::fabs(sy / m - x[2 * i + 1])});
      x[2 * i] = sx / m, x[2 * i + 1] = sy / m;
    }
    if (moved < 1e-3) break;
  }
  for (size_t i = 0; i < pk.inner.size(); ++i) {
    const uint32_t v = pk.inner[i];
    g->target[2 * v] = x[2 * i], g->target[2 * v + 1] = x[2 * i + 1];
    move_vertex(g, v, snap(*g, g->disk->sides[v], std::llround(x[2 * i]), std::llround(x[2 * i + 1])));
  }
}

// Lays a pocket's run out as a strictly convex chain beyond its line: run
// vertex i (1-based) i * s steps from a along the line and
// s * sum_{j<i} (k - j) beyond it, so the chain's slopes fall k, k - 1, ...,
// 1 and the last edge returns to c. The pocket's triangles (a triangulation
// of that convex polygon, plus interior vertices placed inside by Tutte) are
// then positive. s = 1 for a plain run (exact); with interior vertices s
// spreads the chain over the span so that rounding them does not matter.
// Needs k + 1 steps between a and c; otherwise the run stays for repair /
// stretching.
void place_pocket(const Pocket& pk, Grid* g) {
  const int along = (pk.line & (kSideMinY | kSideMaxY)) ? 0 : 1;
  auto coord = [](Pt& q, int axis) -> int64_t& { return axis == 0 ? q.x : q.y; };
  Pt a = g->p[pk.a], c = g->p[pk.c];
  const int64_t k = int64_t(pk.run.size()), span = coord(c, along) - coord(a, along);
  if (std::llabs(span) < k + 1) return;
  for (uint32_t v : pk.run)
    if ((g->disk->sides[v] & ~kSideOutward) != pk.line) return;
  int64_t s = pk.inner.empty() ? 1 : std::llabs(span) / (k + 1);
  while (s > 1 && s * (k * (k + 1) / 2) > kMaxCoordinate / 4) s /= 2;
  if (s * (k * (k + 1) / 2) > kMaxCoordinate / 4) return;
  const int64_t step = span > 0 ? s : -s, out = (pk.line & (kSideMinX | kSideMinY)) ? -s : s;
  int64_t depth = 0;
  for (int64_t i = 1; i <= k; ++i) {
    depth += k - (i - 1);
    Pt q = a;
    coord(q, along) += i * step;
    coord(q, 1 - along) += out * depth;
    const uint32_t v = pk.run[size_t(i - 1)];
    move_vertex(g, v, q);
    g->target[2 * v] = double(q.x), g->target[2 * v + 1] = double(q.y);
  }
  place_pocket_inner(pk, g);
}

// The free point within `radius` of the vertex's target where all its
// triangles are positive, nearest the target; false if there is none.
bool best_point(const Grid& g, uint32_t v, int radius, Pt* best) {
  const uint8_t sides = g.disk->sides[v];
  const double tx = g.target[2 * v], ty = g.target[2 * v + 1];
  const Pt centre = snap(g, sides, std::llround(tx), std::llround(ty));
  const bool outward = sides & kSideOutward;
  const bool fixed_x = !outward && (sides & (kSideMinX | kSideMaxX));
  const bool fixed_y = !outward && (sides & (kSideMinY | kSideMaxY));
  double best_d = INFINITY;
  for (int dy = fixed_y ? 0 : -radius; dy <= (fixed_y ? 0 : radius); ++dy)
    for (int dx = fixed_x ? 0 : -radius; dx <= (fixed_x ? 0 : radius); ++dx) {
      const Pt q = snap(g, sides, centre.x + dx, centre.y + dy);
      if (q.x != centre.x + dx && !fixed_x) continue;  // clamped: already tried elsewhere
      if (q.y != centre.y + dy && !fixed_y) continue;
      const double d = (q.x - tx) * (q.x - tx) + (q.y - ty) * (q.y - ty);
      if (d >= best_d) continue;
      auto it = g.count.find(key(q.x, q.y));
      const bool own = q.x == g.p[v].x && q.y == g.p[v].y;
      if (it != g.count.end() && !(own && it->second == 1)) continue;
      if (!triangles_positive(g, v, q)) continue;
      best_d = d, *best = q;
    }
  return best_d < INFINITY;
}

// One relaxation round; returns the vertices still unplaced.
uint32_t repair_round(Grid* g, int radius, TopologyPreservingStats* st) {
  const uint32_t nv = uint32_t(g->p.size());
  std::vector<uint32_t> bad;
  for (uint32_t v = 0; v < nv; ++v)
    if (!placed(*g, v)) bad.push_back(v);
  for (uint32_t v : bad) {
    if (placed(*g, v)) continue;  // a neighbour's move fixed it
    Pt q{0, 0};
    if (best_point(*g, v, radius, &q)) move_vertex(g, v, q), ++st->vertices_repaired;
  }
  uint32_t left = 0;
  for (uint32_t v : bad) left += !placed(*g, v);
  return left;
}

// --- Compression (step d). ---

struct AxisView {
  int axis;  // 0: columns (x), 1: rows (y)
  int64_t& c(Pt& q) const { return axis == 0 ? q.x : q.y; }
  int64_t c(const Pt& q) const { return axis == 0 ? q.x : q.y; }
  int64_t o(const Pt& q) const { return axis == 0 ? q.y : q.x; }
};

// One pass along an axis; `fraction` caps how much of each gap may close
// (< 1 early on keeps the image from turning into a thin strip). Returns
// whether anything moved; *extent receives the new border line.
bool compress_pass(const std::vector<uint32_t>& tris, int axis, double fraction, std::vector<Pt>* p, int64_t* extent) {
  const AxisView ax{axis};
  const size_t nv = p->size(), nt = tris.size() / 3;
  std::vector<int64_t> vals;
  vals.reserve(nv + 2);
  vals.push_back(0), vals.push_back(*extent);
  for (const Pt& q : *p) vals.push_back(ax.c(q));
  std::sort(vals.begin(), vals.end());
  vals.erase(std::unique(vals.begin(), vals.end()), vals.end());
  const size_t m = vals.size();
  std::vector<uint32_t> col(nv), col_offset(m + 1, 0), col_vertices(nv);
  for (size_t v = 0; v < nv; ++v) {
    col[v] = uint32_t(std::lower_bound(vals.begin(), vals.end(), ax.c((*p)[v])) - vals.begin());
    ++col_offset[col[v] + 1];
  }
  for (size_t k = 0; k < m; ++k) col_offset[k + 1] += col_offset[k];
  {
    std::vector<uint32_t> fill(col_offset.begin(), col_offset.end() - 1);
    for (size_t v = 0; v < nv; ++v) col_vertices[fill[col[v]]++] = uint32_t(v);
  }
  // Triangles by their lowest column; each is active over its span.
  std::vector<uint32_t> lo(nt), hi(nt), start_offset(m + 1, 0), by_start(nt);
  for (size_t t = 0; t < nt; ++t) {
    const uint32_t a = col[tris[3 * t]], b = col[tris[3 * t + 1]], c = col[tris[3 * t + 2]];
    lo[t] = std::min({a, b, c}), hi[t] = std::max({a, b, c});
    ++start_offset[lo[t] + 1];
  }
  for (size_t k = 0; k < m; ++k) start_offset[k + 1] += start_offset[k];
  {
    std::vector<uint32_t> fill(start_offset.begin(), start_offset.end() - 1);
    for (size_t t = 0; t < nt; ++t) by_start[fill[lo[t]]++] = uint32_t(t);
  }

  std::vector<int64_t> now(m);  // new value per column
  now[0] = vals[0];
  int64_t shift = 0;
  std::unordered_set<int64_t> group;  // other coordinates on the current last line
  for (uint32_t i = col_offset[0]; i < col_offset[1]; ++i) group.insert(ax.o((*p)[col_vertices[i]]));
  std::vector<uint32_t> active;
  bool changed = false;
  auto position = [&](uint32_t v, size_t k, int64_t extra) {
    Pt q = (*p)[v];
    ax.c(q) = col[v] < k ? now[col[v]] : vals[col[v]] - shift - extra;
    return q;
  };
  for (size_t k = 1; k < m; ++k) {
    for (uint32_t i = start_offset[k - 1]; i < start_offset[k]; ++i) active.push_back(by_start[i]);
    size_t keep = 0;
    for (uint32_t t : active)
      if (hi[t] >= k) active[keep++] = t;
    active.resize(keep);
    const int64_t gap = vals[k] - shift - now[k - 1];
    int64_t t_max = fraction >= 1 ? gap : int64_t(std::floor(double(gap) * fraction));
    for (size_t i = 0; i < active.size() && t_max > 0; ++i) {
      const uint32_t* c = &tris[3 * size_t(active[i])];
      const int64_t d0 = orient(position(c[0], k, 0), position(c[1], k, 0), position(c[2], k, 0));
      const int64_t d1 = orient(position(c[0], k, 1), position(c[1], k, 1), position(c[2], k, 1));
      const int64_t slope = d1 - d0;
      if (slope < 0) t_max = std::min(t_max, (d0 - 1) / -slope);
    }
    if (t_max == gap) {
      for (uint32_t i = col_offset[k]; i < col_offset[k + 1] && t_max == gap; ++i)
        if (group.count(ax.o((*p)[col_vertices[i]]))) t_max = gap - 1;
    }
    t_max = std::max<int64_t>(t_max, 0);
    shift += t_max;
    changed = changed || t_max > 0;
    now[k] = vals[k] - shift;
    if (now[k] != now[k - 1]) group.clear();
    for (uint32_t i = col_offset[k]; i < col_offset[k + 1]; ++i) group.insert(ax.o((*p)[col_vertices[i]]));
  }
  for (size_t v = 0; v < nv; ++v) ax.c((*p)[v]) = now[col[v]];
  *extent = now[m - 1];
  return changed;
}

// --- The layout check. ---

// Every vertex inside the image, no two on one pixel.
Status check_points(const std::vector<Pt>& p, uint64_t width, uint64_t height) {
  std::unordered_set<uint64_t> seen;
  seen.reserve(2 * p.size());
  for (size_t v = 0; v < p.size(); ++v) {
    const std::string at = "(" + std::to_string(p[v].x) + ", " + std::to_string(p[v].y) + ")";
    if (p[v].x < 0 || p[v].y < 0 || p[v].x >= int64_t(width) || p[v].y >= int64_t(height))
      return invalid("vertex " + std::to_string(v) + " at " + at + " is outside the image");
    if (!seen.insert(key(p[v].x, p[v].y)).second)
      return invalid("vertex " + std::to_string(v) + " shares pixel " + at + " with another vertex");
  }
  return Status::Ok();
}

// The vertices of each border line (outward ones excepted) share its line,
// and only outward vertices of that line lie beyond it (compression may
// bring one back onto it, which is harmless).
Status check_border_lines(const std::vector<uint8_t>& sides, const std::vector<Pt>& p) {
  for (int b = 0; b < 4; ++b) {
    const uint8_t bit = uint8_t(1) << b;
    const bool is_x = bit & (kSideMinX | kSideMaxX), is_min = bit & (kSideMinX | kSideMinY);
    auto c = [&](size_t v) { return is_x ? p[v].x : p[v].y; };
    size_t first = p.size();
    for (size_t v = 0; v < p.size() && first == p.size(); ++v)
      if ((sides[v] & bit) && !(sides[v] & kSideOutward)) first = v;
    if (first == p.size()) continue;
    const int64_t line = c(first);
    for (size_t v = 0; v < p.size(); ++v) {
      const bool outward = (sides[v] & bit) && (sides[v] & kSideOutward);
      const bool on = (sides[v] & bit) && !outward;
      const bool beyond = is_min ? c(v) < line : c(v) > line;
      const bool inside = is_min ? c(v) > line : c(v) < line;
      if ((on && c(v) != line) || (outward && inside) || (!outward && beyond))
        return invalid("boundary vertex " + std::to_string(v) + " is off its border line or beyond another's");
    }
  }
  return Status::Ok();
}

// Whether segments ab and cd share a point (exact).
bool on_segment(Pt a, Pt b, Pt q) {
  return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y);
}
bool segments_touch(Pt a, Pt b, Pt c, Pt d) {
  const int64_t d1 = orient(a, b, c), d2 = orient(a, b, d), d3 = orient(c, d, a), d4 = orient(c, d, b);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && on_segment(a, b, c)) || (d2 == 0 && on_segment(a, b, d)) || (d3 == 0 && on_segment(c, d, a)) ||
         (d4 == 0 && on_segment(c, d, b));
}

// The boundary loop is a simple polygon of positive area. Edges sorted by
// their smallest x; each is compared with the later ones whose x range
// overlaps (quadratic at worst, a few million tests for thousands of edges).
Status check_boundary_polygon(const std::vector<uint32_t>& loop, const std::vector<Pt>& p) {
  const size_t n = loop.size();
  if (n < 3) return invalid("the boundary loop has " + std::to_string(n) + " vertices");
  auto at = [&](size_t i) { return p[loop[i % n]]; };
  __int128 area = 0;
  for (size_t i = 0; i < n; ++i) area += __int128(at(i).x) * at(i + 1).y - __int128(at(i + 1).x) * at(i).y;
  if (area <= 0) return invalid("the boundary loop does not wind counter-clockwise");
  std::vector<uint32_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = uint32_t(i);
  auto xmin = [&](size_t i) { return std::min(at(i).x, at(i + 1).x); };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return xmin(a) < xmin(b); });
  for (size_t k = 0; k < n; ++k) {
    const size_t i = order[k];
    const Pt a = at(i), b = at(i + 1);
    const int64_t xmax = std::max(a.x, b.x);
    for (size_t l = k + 1; l < n && xmin(order[l]) <= xmax; ++l) {
      const size_t j = order[l];
      const Pt c = at(j), d = at(j + 1);
      const bool j_after = (i + 1) % n == j, j_before = (j + 1) % n == i;
      bool bad;
      if (j_after) bad = orient(a, b, d) == 0 && (a.x - b.x) * (d.x - b.x) + (a.y - b.y) * (d.y - b.y) > 0;
      else if (j_before) bad = orient(c, d, b) == 0 && (c.x - d.x) * (b.x - d.x) + (c.y - d.y) * (b.y - d.y) > 0;
      else bad = segments_touch(a, b, c, d);
      if (n == 3) bad = false;  // a triangle with distinct positive corners is simple
      if (bad)
        return invalid("boundary edges " + std::to_string(i) + " and " + std::to_string(j) +
                       " of the layout touch or cross");
    }
  }
  return Status::Ok();
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

Status check_integer_layout(const PlanarDisk& disk, const std::vector<int64_t>& xy, uint64_t width, uint64_t height) {
  const size_t nv = disk.sides.size();
  if (xy.size() != 2 * nv) return invalid("layout has " + std::to_string(xy.size() / 2) + " points for " + std::to_string(nv) + " vertices");
  if (width < 2 || height < 2 || width > uint64_t(kMaxCoordinate) || height > uint64_t(kMaxCoordinate))
    return invalid("layout image " + std::to_string(width) + " x " + std::to_string(height) + " out of range");
  std::vector<Pt> p(nv);
  for (size_t v = 0; v < nv; ++v) p[v] = {xy[2 * v], xy[2 * v + 1]};
  if (Status s = check_points(p, width, height); !s.ok()) return s;
  if (Status s = check_border_lines(disk.sides, p); !s.ok()) return s;
  const std::vector<uint32_t>& tris = *disk.triangles;
  for (size_t t = 0; t < tris.size() / 3; ++t)
    if (orient(p[tris[3 * t]], p[tris[3 * t + 1]], p[tris[3 * t + 2]]) <= 0)
      return invalid("triangle " + std::to_string(t) + " is folded or degenerate on the grid");
  return check_boundary_polygon(disk.boundary_loop, p);
}

Status place_on_integer_grid(const PlanarDisk& disk, const std::vector<double>& uv, double w, double h,
                             const TopologyPreservingOptions& opt, std::vector<int64_t>* xy, uint64_t* width,
                             uint64_t* height, TopologyPreservingStats* stats,
                             const std::function<void(double)>& progress) {
  TopologyPreservingStats local;
  TopologyPreservingStats& st = stats ? *stats : local;
  const auto t0 = std::chrono::steady_clock::now();
  const size_t nv = disk.sides.size();
  const std::vector<uint32_t>& tris = *disk.triangles;
  if (uv.size() != 2 * nv || !(w > 0) || !(h > 0)) return invalid("placement: inconsistent parametrization");
  if (uint64_t(nv) > opt.max_pixels || uint64_t(nv) > uint64_t(opt.max_side) * opt.max_side)
    return invalid("an image of at most " + std::to_string(opt.max_side) + " x " + std::to_string(opt.max_side) + " and " +
                   std::to_string(opt.max_pixels) + " pixels cannot hold " + std::to_string(nv) + " vertices");
  const VertexCorners inc = vertex_corners(tris, nv);
  const std::vector<Pocket> pockets = find_pockets(disk, inc);
  const double S = grid_spacing(tris, uv);
  st.grid_spacing = S;
  // Never start beyond the coordinate limit; a tiny S just means fewer stretches.
  double scale = std::isfinite(S) ? 1 / S : 1;
  scale = std::min(scale, double(kMaxCoordinate / 4) / std::max(w, h));
  Grid g;
  g.disk = &disk, g.inc = &inc;
  uint32_t unplaced = uint32_t(nv);
  const int rounds = std::max(1, opt.repair_rounds);
  int stretch = 0;
  for (;; ++stretch) {
    if (std::max(w, h) * scale > double(kMaxCoordinate))
      return invalid("could not place " + std::to_string(unplaced) + " vertices on free grid points within " +
                     std::to_string(stretch) + " x3 stretches (" + std::to_string(st.repair_rounds) +
                     " relaxation rounds); the parametrization has triangles too thin for a 2^28 grid");
    round_at_scale(disk, uv, w, h, scale, &g);
    for (const Pocket& pk : pockets) place_pocket(pk, &g);
    for (int r = 0; r < rounds; ++r) {
      ++st.repair_rounds;
      unplaced = repair_round(&g, std::min(1 + r, 4), &st);
      if (unplaced == 0) break;
    }
    if (progress) progress(0.5 * (stretch + 1) / (opt.max_stretches + 1));
    if (unplaced == 0) break;
    if (stretch >= opt.max_stretches)
      return invalid("could not place " + std::to_string(unplaced) + " vertices on free grid points within " +
                     std::to_string(st.repair_rounds) + " relaxation rounds and " + std::to_string(stretch) +
                     " x3 stretches");
    scale *= 3;
  }
  st.stretches = stretch;
  st.placed_width = uint64_t(g.X) + 1, st.placed_height = uint64_t(g.Y) + 1;
  st.seconds_placement = seconds_since(t0);

  const auto t1 = std::chrono::steady_clock::now();
  int64_t extent[2] = {g.X, g.Y};
  // Partial passes first (each gap closes at most by `fraction`), so both
  // axes shrink together like a uniform scale-down until triangles block;
  // then full passes close what is left.
  const int passes = 2 * std::max(1, opt.compress_rounds);
  double fraction = 0.5;  // 0.25 and 0.1 measured no better on bunny_small
  int quiet = 0;  // consecutive passes that moved nothing
  for (int i = 0; i < passes + 128; ++i) {
    // With outward vertices the boundary is not convex and a pass could
    // make two bulges touch: such a pass is undone (counted as no move).
    const std::vector<Pt> before = pockets.empty() ? std::vector<Pt>() : g.p;
    const int64_t before_extent = extent[i % 2];
    bool moved = compress_pass(tris, i % 2, fraction, &g.p, &extent[i % 2]);
    if (moved && !pockets.empty() && !check_boundary_polygon(disk.boundary_loop, g.p).ok())
      g.p = before, extent[i % 2] = before_extent, moved = false;
    ++st.compress_passes;
    quiet = moved ? 0 : quiet + 1;
    if (quiet >= 2 && fraction >= 1) break;
    if (fraction < 1 && (quiet >= 2 || i >= 128)) fraction = 1, quiet = 0;
    if (progress) progress(0.5 + 0.5 * std::min(1.0, double(i + 1) / passes));
  }
  st.seconds_compression = seconds_since(t1);
  // Outward vertices may lie before x = 0 / y = 0 or beyond the far lines:
  // the image is the vertices' bounding box.
  Pt lo{0, 0}, hi{extent[0], extent[1]};
  for (const Pt& q : g.p) lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)}, hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
  *width = uint64_t(hi.x - lo.x) + 1, *height = uint64_t(hi.y - lo.y) + 1;
  xy->resize(2 * nv);
  for (size_t v = 0; v < nv; ++v) (*xy)[2 * v] = g.p[v].x - lo.x, (*xy)[2 * v + 1] = g.p[v].y - lo.y;
  if (*width > opt.max_side || *height > opt.max_side || *width * *height > opt.max_pixels)
    return invalid("image would be " + std::to_string(*width) + " x " + std::to_string(*height) +
                   " pixels, beyond the limit of " + std::to_string(opt.max_side) + " x " +
                   std::to_string(opt.max_side) + " and " + std::to_string(opt.max_pixels) + " pixels");
  return check_integer_layout(disk, *xy, *width, *height);
}

}  // namespace qmc
