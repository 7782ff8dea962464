// Section 14.3 of spec/qmc-format.md: the prediction rules, one function
// per rule, combined by weight in units of 2^-16; and 15.12's guided rule
// for texture coordinates.
#include "common/vertex_prediction.h"

#include <algorithm>

#include "common/exact_arith.h"  // floor_div, floor_shift, integer_sqrt, shift_into_15_bits

namespace qmc {
namespace {

// 14.3.1: c_k = round(2^16 (1 + 2 cos(2 pi / k))) for k = 4 .. 12; larger
// polygons use c_12.
constexpr int64_t kPolygonCoefficient[9] = {65536, 106039, 131072, 147258, 158218, 165943, 171575, 175801, 179048};
constexpr int64_t kOne = 65536;

// 14.3.1: weights of the rules.
constexpr int64_t kWeightParallelogram = 1;
constexpr int64_t kWeightPolygon = 2;
constexpr int64_t kWeightStrip = 1;
constexpr int64_t kWeightGuided = 1;

int64_t polygon_coefficient(uint32_t degree) { return kPolygonCoefficient[std::min<uint32_t>(degree, 12) - 4]; }

// Adds a candidate w x (base + coefficient (p - r) / 2^16) per axis, from
// vertices' q, if there is room.
void add_candidate(VertexPrediction* out, int64_t w, const uint32_t* q, uint32_t base, uint32_t p, uint32_t r,
                   int64_t coefficient) {
  if (out->candidates >= kMaxCandidates) return;
  int64_t* value = out->candidate[out->candidates];
  for (int a = 0; a < 3; ++a) {
    const int64_t d = int64_t(q[3 * size_t(p) + a]) - int64_t(q[3 * size_t(r) + a]);
    value[a] = kOne * int64_t(q[3 * size_t(base) + a]) + coefficient * d;
    out->scale += uint64_t(d < 0 ? -d : d);
  }
  out->weight[out->candidates++] = w;
}

// 14.2: the corners of a vertex examined for a neighbour across an edge.
constexpr int kMaxExamined = 8;

// Whether a vertex u is decoded before the vertex v predicted: u < v in
// label order (14.2), rank(u) < rank(v) in the geometry order (14.6), where
// predicting over the original faces gives what 14.6's renamed faces give.
// kTriangleTwist: parallelogram candidates carry 14.9's twist (POSN method 8,
// in the geometry order only), a type of its own so that the other methods'
// predictions do not test for it.
struct LabelOrder {
  static constexpr bool kTriangleTwist = false;
  uint32_t key(uint32_t u) const { return u; }
};
struct RankOrder {
  static constexpr bool kTriangleTwist = false;
  const uint32_t* rank;
  uint32_t key(uint32_t u) const { return rank[u]; }
};
struct TwistedRankOrder : RankOrder {
  static constexpr bool kTriangleTwist = true;
};
template <class Order>
struct Visit {
  Order order;
  uint32_t v, key;  // the vertex predicted and order.key(v)
  int shear = 0;    // 14.12's weight k of the parallelograms' shear (POSN method 11), 0: none
  bool extrapolate = false;  // 14.13's edge extrapolation (POSN method 12)
  bool before(uint32_t u) const { return order.key(u) < key; }
};

// 14.2's bounded search: calls examine(k, other) for each corner k of u
// examined for w next to it (in triangles or in larger faces) that is not in
// `corner`'s face, other being u's other neighbour at k, until examine
// returns false or kMaxExamined corners (those in `corner`'s face too) are
// examined.
template <class Examine>
void search_across(const VertexCorners& m, uint32_t u, uint32_t w, bool triangles, uint32_t corner, Examine examine) {
  int examined = 0;
  m.for_each_link(u, w, triangles, [&](uint32_t k, uint32_t other) {
    if (m.face(k) != m.face(corner) && !examine(k, other)) return false;
    return ++examined < kMaxExamined;
  });
}

// 14.9: adds to sum the twist of the edge (o, s) of the triangle g, s - o -
// c + d: c is o's other neighbour in the first triangle across (o, s) whose
// c is decoded, d its other neighbour in the first triangle across (o, c)
// whose d is decoded; false if there is none. On a regular triangulation
// the triangles (o, s, c) and (o, c, d) make the parallelogram beside the
// one predicting v. o has 6 corners, so 14.2's searches are scans of them
// that the bound of 8 never stops.
template <class Order>
bool add_triangle_twist(const VertexCorners& m, uint32_t g, uint32_t o, uint32_t s, const Visit<Order>& at,
                        const uint32_t* q, int64_t sum[3]) {
  const uint32_t* corner = m.begin(o);
  const VertexCorners::Sides* side = m.sides(o);
  // The neighbour of o across w at corner i, if corner i is a triangle's with w next to o and not in face `skip`.
  const auto across = [&](int i, uint32_t w, uint32_t skip, uint32_t* other) {
    if ((side[i].next != w && side[i].previous != w) || m.degree(corner[i]) != 3 || m.face(corner[i]) == skip)
      return false;
    *other = side[i].next == w ? side[i].previous : side[i].next;
    return true;
  };
  for (int i = 0; i < 6; ++i) {
    uint32_t c = 0;
    if (!across(i, s, g, &c) || !at.before(c) || c == s || c == o) continue;
    for (int k = 0; k < 6; ++k) {
      uint32_t d = 0;
      if (!across(k, c, m.face(corner[i]), &d) || !at.before(d) || d == c || d == o || d == s) continue;
      for (int x = 0; x < 3; ++x)
        sum[x] += int64_t(q[3 * size_t(s) + x]) - int64_t(q[3 * size_t(o) + x]) - int64_t(q[3 * size_t(c) + x]) +
                  int64_t(q[3 * size_t(d) + x]);
      return true;
    }
    return false;  // only the first c
  }
  return false;
}

// 14.9: the twist of the parallelogram candidate just added from the triangle
// (a, b, o), if o has exactly six corners: the mean twist of its edges (o, b)
// and (o, a).
template <class Order>
void add_triangle_twists(const VertexCorners& m, uint32_t ka, uint32_t a, uint32_t b, uint32_t o,
                         const Visit<Order>& at, const uint32_t* q, VertexPrediction* c) {
  if (m.end(o) - m.begin(o) != 6) return;
  const uint32_t g = m.face(ka);
  int64_t sum[3] = {0, 0, 0};
  const int n = int(add_triangle_twist(m, g, o, b, at, q, sum)) + int(add_triangle_twist(m, g, o, a, at, q, sum));
  if (n == 0) return;
  const int k = c->candidates - 1;
  c->triangle_twisted |= 1u << k;
  for (int x = 0; x < 3; ++x) c->triangle_twist[k][x] = kOne / n * sum[x];
}

// 14.12: adds to the parallelogram candidate a + b - o (2^-16 units) k / 16
// of o's offset from the middle of (a, b) along b - a, f e with f the
// offset's fraction of e = b - a in 2^-16 units (clamped to +-2): on an
// irregular triangulation the parallelogram's reflection of o overshoots
// along the edge.
void add_shear(const uint32_t* q, uint32_t a, uint32_t b, uint32_t o, int k, int64_t candidate[3]) {
  int64_t e[3], g[3];
  for (int x = 0; x < 3; ++x) {
    e[x] = int64_t(q[3 * size_t(b) + x]) - int64_t(q[3 * size_t(a) + x]);
    g[x] = 2 * int64_t(q[3 * size_t(o) + x]) - int64_t(q[3 * size_t(a) + x]) - int64_t(q[3 * size_t(b) + x]);
  }
  int64_t es[3] = {e[0], e[1], e[2]}, gs[3] = {g[0], g[1], g[2]};
  shift_into_15_bits(es, gs);
  const int64_t ee = es[0] * es[0] + es[1] * es[1] + es[2] * es[2];
  if (ee == 0) return;
  const int64_t t = gs[0] * es[0] + gs[1] * es[1] + gs[2] * es[2];
  constexpr int64_t kLargest = int64_t(1) << 17;  // 2 in units of 2^-16
  const int64_t f = std::clamp<int64_t>(floor_div(t * (int64_t(1) << 15), ee), -kLargest, kLargest);
  for (int x = 0; x < 3; ++x) candidate[x] += floor_shift(int64_t(k) * f * e[x], 4);
}

// 14.3.1, across-edge parallelogram: the triangles over the edge (a, b)
// opposite v's corner, o being their third vertex; with 14.9's twist, each
// candidate's twist summed; with 14.12's shear, each candidate sheared.
template <class Order>
void add_parallelograms(const VertexCorners& m, uint32_t corner, const VertexCorners::Sides& sides,
                        const Visit<Order>& at, const uint32_t* q, VertexPrediction* c) {
  const uint32_t a = sides.next, b = sides.previous;
  if (!at.before(a) || !at.before(b) || a == b) return;
  search_across(m, a, b, true, corner, [&](uint32_t ka, uint32_t o) {
    if (at.before(o) && o != a && o != b) {
      const int before = c->candidates;
      add_candidate(c, kWeightParallelogram, q, a, b, o, kOne);
      if (at.shear != 0 && c->candidates > before) add_shear(q, a, b, o, at.shear, c->candidate[before]);
      if constexpr (Order::kTriangleTwist)
        if (c->candidates > before) add_triangle_twists(m, ka, a, b, o, at, q, c);
    }
    return c->candidates < kMaxCandidates;
  });
}

// 14.7: adds to sum the twist of the edge (s, p2) of v's quad, s - y - p2 + x
// from the first quad across it whose other corners are decoded, y being s's
// other neighbour there and x the corner opposite s; false if there is none.
template <class Order>
bool add_quad_twist(const VertexCorners& m, uint32_t corner, uint32_t s, uint32_t p2, const Visit<Order>& at,
                    const uint32_t* q, int64_t sum[3]) {
  bool found = false;
  search_across(m, s, p2, false, corner, [&](uint32_t k, uint32_t y) {
    const uint32_t x = m.along(k, 2);
    if (m.degree(k) != 4 || !at.before(y) || !at.before(x)) return true;
    for (int a = 0; a < 3; ++a)
      sum[a] += int64_t(q[3 * size_t(s) + a]) - int64_t(q[3 * size_t(y) + a]) - int64_t(q[3 * size_t(p2) + a]) +
                int64_t(q[3 * size_t(x) + a]);
    found = true;
    return false;  // one twist per edge
  });
  return found;
}

// 14.3.1, polygon run: the three vertices before v along the face (direction -1)
// or after it (+1), all decoded: p3 + c_k (p1 - p2); in a quad with
// twist (method 5, 14.7) plus the mean twist of the quads across (p1, p2)
// and (p3, p2).
template <class Order>
bool add_polygon_run(const VertexCorners& m, uint32_t corner, int direction, const Visit<Order>& at,
                     const uint32_t* q, bool twist, VertexPrediction* c) {
  const uint32_t p1 = m.along(corner, direction), p2 = m.along(corner, 2 * direction),
                 p3 = m.along(corner, 3 * direction);
  if (!at.before(p1) || !at.before(p2) || !at.before(p3) || c->candidates >= kMaxCandidates) return false;
  add_candidate(c, kWeightPolygon, q, p3, p1, p2, polygon_coefficient(m.degree(corner)));
  if (!twist || m.degree(corner) != 4) return true;
  int64_t sum[3] = {0, 0, 0};
  const int sides =
      int(add_quad_twist(m, corner, p1, p2, at, q, sum)) + int(add_quad_twist(m, corner, p3, p2, at, q, sum));
  if (sides == 0) return true;
  const int k = c->candidates - 1;
  c->twisted |= 1u << k;
  for (int a = 0; a < 3; ++a) {
    c->twist_term[k][a] = kOne / sides * sum[a];
    c->candidate[k][a] += c->twist_term[k][a];
  }
  return true;
}

// 14.3.1, strip across an edge: the polygon over the edge (p1, p2)
// continued to v, 2 p1 - y, y being p1's other neighbour in that polygon.
template <class Order>
void add_strip(const VertexCorners& m, uint32_t corner, int direction, const Visit<Order>& at, const uint32_t* q,
               VertexPrediction* c) {
  const uint32_t p1 = m.along(corner, direction), p2 = m.along(corner, 2 * direction);
  if (!at.before(p1) || !at.before(p2) || p1 == p2) return;
  search_across(m, p1, p2, false, corner, [&](uint32_t, uint32_t y) {
    if (at.before(y) && y != p1 && y != p2) add_candidate(c, kWeightStrip, q, p1, p1, y, kOne);
    return c->candidates < kMaxCandidates;
  });
}

// 15.12's side: -sgn(W) for the first o decoded before v, not a or b, with
// W = D x (q[o] - q[a]) != 0; 0 if there is none. In a triangle the o are
// the third vertices over the edge (a, b) that 14.2's search examines; in
// a larger face, along(corner, +2).
template <class Order>
int guided_side(const VertexCorners& m, uint32_t corner, uint32_t a, uint32_t b, const int64_t d[2],
                const Visit<Order>& at, const uint32_t* q) {
  const auto side_of = [&](uint32_t o) {
    if (!at.before(o) || o == a || o == b) return 0;
    const int64_t w = d[0] * (int64_t(q[3 * size_t(o) + 1]) - int64_t(q[3 * size_t(a) + 1])) -
                      d[1] * (int64_t(q[3 * size_t(o)]) - int64_t(q[3 * size_t(a)]));
    return w > 0 ? -1 : w < 0 ? 1 : 0;
  };
  if (m.degree(corner) > 3) return side_of(m.along(corner, 2));
  int side = 0;
  search_across(m, a, b, true, corner, [&](uint32_t, uint32_t o) {
    side = side_of(o);
    return side == 0;  // the first o that gives a side
  });
  return side;
}

// 15.12, the guided rule at v's corner: the value where the triangle of the
// corner and its two neighbours in space puts it, relative to the values of
// the neighbours a and b. False if the rule does not apply (the corner then
// contributes as 14.3.1 says).
template <class Order>
bool add_guided(const VertexCorners& m, uint32_t corner, const VertexCorners::Sides& sides, const Visit<Order>& at,
                const uint32_t* q, PositionGuide* guide, VertexPrediction* c) {
  const uint32_t a = sides.next, b = sides.previous;
  if (!at.before(a) || !at.before(b) || a == b) return false;
  const uint32_t* p = guide->positions;
  const size_t vc = guide->vertex_of_corner[corner], va = guide->vertex_of_corner[m.corner_along(corner, 1)],
               vb = guide->vertex_of_corner[m.corner_along(corner, -1)];
  int64_t e[3], f[3];
  for (int i = 0; i < 3; ++i) {
    e[i] = int64_t(p[3 * vb + i]) - int64_t(p[3 * va + i]);
    f[i] = int64_t(p[3 * vc + i]) - int64_t(p[3 * va + i]);
  }
  shift_into_15_bits(e, f);
  const int64_t ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
  if (ee == 0) return false;
  if (c->candidates >= kMaxCandidates) return true;
  const int64_t ef = e[0] * f[0] + e[1] * f[1] + e[2] * f[2];
  const int64_t g[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
  const int64_t x = integer_sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  const int64_t d[2] = {int64_t(q[3 * size_t(b)]) - int64_t(q[3 * size_t(a)]),
                        int64_t(q[3 * size_t(b) + 1]) - int64_t(q[3 * size_t(a) + 1])};
  const int side = guided_side(m, corner, a, b, d, at, q);
  if (side != 0) guide->orientation = side;
  const int64_t sigma = guide->orientation;
  const int64_t n[2] = {ef * d[0] - sigma * x * d[1], ef * d[1] + sigma * x * d[0]};
  int64_t* value = c->candidate[c->candidates];
  for (int k = 0; k < 2; ++k) {
    const int64_t whole = floor_div(n[k], ee), rest = n[k] - whole * ee;
    const int64_t base = std::clamp<int64_t>(int64_t(q[3 * size_t(a) + k]) + whole, -(int64_t(1) << 31),
                                             int64_t(1) << 31);
    value[k] = kOne * base + kOne * rest / ee;
  }
  value[2] = 0;
  c->scale += uint64_t(d[0] < 0 ? -d[0] : d[0]) + uint64_t(d[1] < 0 ? -d[1] : d[1]);
  c->weight[c->candidates++] = kWeightGuided;
  return true;
}

}  // namespace

void VertexCorners::build(uint32_t vertex_count, const std::vector<uint32_t>& face_sizes,
                          const std::vector<uint32_t>& corners) {
  corners_ = corners.data();
  triangles_only_ = std::all_of(face_sizes.begin(), face_sizes.end(), [](uint32_t d) { return d == 3; });
  if (!triangles_only_) build_faces(face_sizes, corners.size());
  first_.assign(size_t(vertex_count) + 1, 0);
  for (uint32_t v : corners) ++first_[v + 1];
  for (size_t v = 0; v < vertex_count; ++v) first_[v + 1] += first_[v];
  // first_[v + 1] is v's end; filling back to front moves it to v's start,
  // one place too far on, without a second table of cursors.
  corner_of_.allocate(corners.size());
  sides_.allocate(corners.size());
  for (uint32_t k = uint32_t(corners.size()); k-- > 0;) {
    const uint32_t i = --first_[corners[k] + 1];
    corner_of_[i] = k;
    sides_[i] = {along(k, 1), along(k, -1)};
  }
  std::copy(first_.begin() + 1, first_.end(), first_.begin());
  first_[vertex_count] = uint32_t(corners.size());
  build_links(true, &triangle_link_first_, &triangle_links_);
  build_links(false, &polygon_link_first_, &polygon_links_);
}

void VertexCorners::build_faces(const std::vector<uint32_t>& face_sizes, size_t corner_count) {
  face_start_.assign(face_sizes.size() + 1, 0);
  face_of_.allocate(corner_count);
  next_.allocate(corner_count);
  previous_.allocate(corner_count);
  for (size_t f = 0; f < face_sizes.size(); ++f) {
    const uint32_t start = face_start_[f], end = start + face_sizes[f];
    face_start_[f + 1] = end;
    for (uint32_t k = start; k < end; ++k) {
      face_of_[k] = uint32_t(f);
      next_[k] = k + 1 < end ? k + 1 : start;
      previous_[k] = k > start ? k - 1 : end - 1;
    }
  }
}

// Each corner k of a vertex u of many corners links u to the vertices the
// searches of 14.2 look for next to it: along(k, +1), and along(k, +2) for
// a triangle or along(k, -1) for a larger face, the second only when it
// differs (so a corner is found once).
void VertexCorners::build_links(bool triangles, std::vector<uint32_t>* first, std::vector<Link>* links) const {
  const uint32_t n = vertex_count();
  first->assign(size_t(n) + 1, 0);
  links->clear();
  for (uint32_t u = 0; u < n; ++u) {
    if (end(u) - begin(u) > kScannedCorners) {
      for (const uint32_t* k = begin(u); k != end(u); ++k) {
        if ((degree(*k) == 3) != triangles) continue;
        const uint32_t w1 = along(*k, 1), w2 = along(*k, triangles ? 2 : -1);
        links->push_back({w1, *k, w2});
        if (w2 != w1) links->push_back({w2, *k, w1});
      }
      std::sort(links->begin() + (*first)[u], links->end(), [](const Link& x, const Link& y) {
        return x.neighbour != y.neighbour ? x.neighbour < y.neighbour : x.corner < y.corner;
      });
    }
    (*first)[u + 1] = uint32_t(links->size());
  }
}

namespace {

// 14.13: the corners of v and of each neighbour u that the edge
// extrapolation examines, and how far along v's faces a w counts as v's.
constexpr int kExtrapolationCorners = 8;
constexpr int kExtrapolationReach = 3;

// 14.13, POSN method 12, for a vertex that 14.3.1 gave no candidate: the
// edge (w, u) continued past u to v, 2 u - w, for u in the neighbour list of
// v's first 8 corners and w next to u at u's first 8 corners, both decoded,
// w not near v (within 3 corners of v in the faces of those corners), each
// pair (u, w) once. Along a boundary, where no face lies across for 14.3.1's
// strip, this is the boundary continued.
template <class Order>
void add_edge_extrapolations(const VertexCorners& m, const Visit<Order>& at, const uint32_t* q,
                             VertexPrediction* c) {
  const uint32_t v = at.v;
  const int v_count = int(std::min<ptrdiff_t>(m.end(v) - m.begin(v), kExtrapolationCorners));
  uint32_t near[kExtrapolationCorners * 2 * kExtrapolationReach];
  int near_count = 0;
  for (int i = 0; i < v_count; ++i)
    for (int s = -kExtrapolationReach; s <= kExtrapolationReach; ++s)
      if (s != 0) near[near_count++] = m.along(m.begin(v)[i], s);
  const auto is_near = [&](uint32_t w) { return std::find(near, near + near_count, w) != near + near_count; };
  uint32_t pairs[kMaxCandidates][2];
  int paired = 0;
  const VertexCorners::Sides* v_sides = m.sides(v);
  for (int i = 0; i < v_count; ++i)
    for (const uint32_t u : {v_sides[i].previous, v_sides[i].next}) {
      if (!at.before(u)) continue;
      const VertexCorners::Sides* u_sides = m.sides(u);
      const int u_count = int(std::min<ptrdiff_t>(m.end(u) - m.begin(u), kExtrapolationCorners));
      for (int j = 0; j < u_count; ++j)
        for (const uint32_t w : {u_sides[j].previous, u_sides[j].next}) {
          if (!at.before(w) || w == u || is_near(w)) continue;
          bool seen = false;
          for (int k = 0; k < paired; ++k) seen = seen || (pairs[k][0] == u && pairs[k][1] == w);
          if (seen) continue;
          pairs[paired][0] = u;
          pairs[paired][1] = w;
          ++paired;
          add_candidate(c, kWeightStrip, q, u, u, w, kOne);
          if (c->candidates == kMaxCandidates) return;
        }
    }
}

// 14.3.1: the candidates one corner of v contributes (15.12: with a guide,
// the guided candidate alone where the guided rule applies).
template <class Order>
void add_corner_candidates(const VertexCorners& m, uint32_t corner, const VertexCorners::Sides& sides,
                           const Visit<Order>& at, const uint32_t* q, PositionGuide* guide, bool twist,
                           VertexPrediction* c) {
  if (guide && add_guided(m, corner, sides, at, q, guide, c)) return;
  if (m.degree(corner) == 3) return add_parallelograms(m, corner, sides, at, q, c);
  bool run = add_polygon_run(m, corner, -1, at, q, twist, c);
  if (m.degree(corner) > 4) run = add_polygon_run(m, corner, +1, at, q, false, c) || run;
  if (run) return;
  add_strip(m, corner, -1, at, q, c);
  add_strip(m, corner, +1, at, q, c);
}

// 14.3 for the vertex at.v; `previous` is the vertex decoded just before
// it, if any (14.3.2's fallback without neighbours).
template <class Order>
void predict(const VertexCorners& m, const Visit<Order>& at, const uint32_t* previous, const uint32_t* q,
             const uint32_t* activity, const uint32_t top[3], PositionGuide* guide, bool twist, VertexPrediction* out) {
  const uint32_t v = at.v;
  out->candidates = 0;
  out->scale = 0;
  out->twisted = 0;
  out->triangle_twisted = 0;
  out->twist_weight = 0;
  int64_t neighbour_sum[3] = {0, 0, 0};
  int64_t neighbours = 0;
  uint64_t activity_sum = 0;
  const VertexCorners::Sides* sides = m.sides(v);
  for (const uint32_t* corner = m.begin(v); corner != m.end(v); ++corner, ++sides) {
    for (const uint32_t u : {sides->previous, sides->next}) {  // 14.2: the neighbour list
      if (!at.before(u)) continue;
      for (int a = 0; a < 3; ++a) neighbour_sum[a] += q[3 * size_t(u) + a];
      activity_sum += activity[u];
      ++neighbours;
    }
    add_corner_candidates(m, *corner, *sides, at, q, guide, twist, out);
  }
  out->extrapolated = false;
  if (at.extrapolate && out->candidates == 0) {
    add_edge_extrapolations(m, at, q, out);
    out->extrapolated = out->candidates > 0;
  }
  if (out->candidates > 0) out->scale /= uint64_t(out->candidates);
  // 14.3.2: what the fallback is made of, and the activity of 14.4.
  for (int a = 0; a < 3; ++a) {
    out->neighbour_sum[a] = neighbour_sum[a];
    out->previous[a] = previous ? int64_t(q[3 * size_t(*previous) + a]) : int64_t(top[a] >> 1);
  }
  out->neighbours = neighbours;
  if (neighbours > 0)
    out->neighbour_activity = activity_sum / uint64_t(neighbours);
  else
    out->neighbour_activity = previous ? activity[*previous] : 0;
}

}  // namespace

void predict_vertex(const VertexCorners& m, uint32_t v, const uint32_t* q, const uint32_t* activity,
                    const uint32_t top[3], VertexPrediction* out, PositionGuide* guide) {
  const uint32_t previous = v - 1;
  predict(m, Visit<LabelOrder>{{}, v, v}, v > 0 ? &previous : nullptr, q, activity, top, guide, false, out);
}

void predict_vertex_in_order(const VertexCorners& m, const uint32_t* order, const uint32_t* rank, uint32_t i,
                             const uint32_t* q, const uint32_t* activity, const uint32_t top[3],
                             VertexPrediction* out, PositionGuide* guide, bool quad_twist, bool triangle_twist,
                             int shear, bool extrapolate) {
  const uint32_t* previous = i > 0 ? &order[i - 1] : nullptr;
  if (triangle_twist)
    predict(m, Visit<TwistedRankOrder>{{{rank}}, order[i], i, shear, extrapolate}, previous, q, activity, top, guide,
            quad_twist, out);
  else
    predict(m, Visit<RankOrder>{{rank}, order[i], i, shear, extrapolate}, previous, q, activity, top, guide, quad_twist,
            out);
}

namespace {

// floor(n[a] / W) for the three axes, W a constant: a division by a
// constant, which the compiler turns into a multiplication (a 64-bit
// division takes tens of cycles, and the encoder selects up to 15 subsets a
// vertex, 14.5), or a shift for a power of two.
template <int64_t W>
void floor_div_axes(const int64_t n[3], int64_t out[3]) {
  for (int a = 0; a < 3; ++a) {
    if constexpr (W == 1) out[a] = n[a];
    else if constexpr (W == 2) out[a] = floor_shift(n[a], 1);
    else if constexpr (W == 4) out[a] = floor_shift(n[a], 2);
    else if constexpr (W == 8) out[a] = floor_shift(n[a], 3);
    else out[a] = floor_div(n[a], W);
  }
}

// The same for a total weight w of 14.3.3 (1 .. 8: at most four candidates
// of weight 1 or 2), one dispatch for the three axes.
void floor_div_by_weight(const int64_t n[3], int64_t w, int64_t out[3]) {
  switch (w) {
    case 1: return floor_div_axes<1>(n, out);
    case 2: return floor_div_axes<2>(n, out);
    case 3: return floor_div_axes<3>(n, out);
    case 4: return floor_div_axes<4>(n, out);
    case 5: return floor_div_axes<5>(n, out);
    case 6: return floor_div_axes<6>(n, out);
    case 7: return floor_div_axes<7>(n, out);
    case 8: return floor_div_axes<8>(n, out);
    default:
      for (int a = 0; a < 3; ++a) out[a] = floor_div(n[a], w);
  }
}

}  // namespace

void select_candidates(VertexPrediction* p, unsigned mask, const uint32_t top[3]) {
  int64_t sum[3] = {0, 0, 0}, weight = 0;
  int used = 0;
  for (int i = 0; i < p->candidates; ++i) {
    if (!(mask >> i & 1)) continue;
    for (int a = 0; a < 3; ++a) sum[a] += p->weight[i] * p->candidate[i][a];
    weight += p->weight[i];
    ++used;
  }
  if (used == 0) {  // 14.3.2's fallback
    const int64_t n = p->neighbours;
    for (int a = 0; a < 3; ++a) {
      p->value[a] = std::clamp<int64_t>(n > 0 ? floor_div(2 * p->neighbour_sum[a] + n, 2 * n) : p->previous[a], 0, top[a]);
      p->mean[a] = p->value[a];
      p->twist_mean[a] = 0;
    }
    p->kind = n > 0 ? PredictionKind::kNeighbours : PredictionKind::kPrevious;
    return;
  }
  // 14.3.3's floor((2 S + W 2^16) / (2 W 2^16)), as floor(floor(x / 2^17) / W),
  // plus 14.9's correction floor((lambda T + 2^23) / 2^24), T = floor(twist_sum / W):
  // 0 but in POSN method 8 with the triangle twist.
  int64_t correction[3] = {0, 0, 0}, rounded_sum[3];
  for (int a = 0; a < 3; ++a) {
    rounded_sum[a] = floor_shift(2 * sum[a] + weight * kOne, 17);
    p->twist_mean[a] = 0;
  }
  floor_div_by_weight(rounded_sum, weight, p->mean);
  if (const unsigned twisted = p->triangle_twisted & mask; twisted != 0) {
    int64_t twist_sum[3] = {0, 0, 0};
    for (int i = 0; i < p->candidates; ++i)
      if (twisted >> i & 1)
        for (int a = 0; a < 3; ++a) twist_sum[a] += p->weight[i] * p->triangle_twist[i][a];
    floor_div_by_weight(twist_sum, weight, p->twist_mean);
    for (int a = 0; a < 3; ++a)
      correction[a] = floor_shift(p->twist_weight * p->twist_mean[a] + (int64_t(1) << 23), 24);
  }
  for (int a = 0; a < 3; ++a) p->value[a] = std::clamp<int64_t>(p->mean[a] + correction[a], 0, top[a]);
  p->kind = used > 1 ? PredictionKind::kSeveral : PredictionKind::kSingle;
}


// 14.9: N += e t, D += t t per axis, e and t in 1/16 of a step and clamped
// to +-2^20 (so |N| <= 2^20 D and nothing overflows), both halved while D
// is above 2^40.
void TriangleTwistWeight::learn_twisted(const VertexPrediction& p, const uint32_t* q) {
  constexpr int64_t kBound = int64_t(1) << 20;
  for (int a = 0; a < 3; ++a) {
    const int64_t t = std::clamp<int64_t>(floor_shift(p.twist_mean[a], 12), -kBound, kBound);
    const int64_t error = std::clamp<int64_t>(int64_t(q[a]) - p.mean[a], -kBound, kBound);
    const int64_t e = std::clamp<int64_t>(16 * error, -kBound, kBound);
    products_ += e * t;
    squares_ += t * t;
  }
  while (squares_ > (int64_t(1) << 40)) {
    products_ = floor_shift(products_, 1);
    squares_ = floor_shift(squares_, 1);
  }
}

}  // namespace qmc
