// qmc tools: Catmull-Clark subdivision. See subdivision.h for the rules, the
// numbering of the output and the treatment of pinched vertices.
#include "subdivision.h"

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace qmc::tools {
namespace {

using qmc::ErrorCode;
using qmc::Mesh;
using qmc::Status;

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, "catmull_clark: " + std::move(message)); }

// Half-edge view of a polygon soup. Half-edge h is corner h of `corners`: it
// runs from that corner's vertex to the next corner's vertex in the same face.
struct HalfEdges {
  std::vector<uint32_t> face_of, next, prev;
  std::vector<uint32_t> twin;       // the opposite half-edge, kNone on a boundary
  std::vector<uint32_t> out_begin;  // CSR: half-edges leaving vertex v are
  std::vector<uint32_t> out_list;   // out_list[out_begin[v] .. out_begin[v+1]), ascending

  uint32_t from(const Mesh& mesh, uint32_t h) const { return mesh.corners[h]; }
  uint32_t to(const Mesh& mesh, uint32_t h) const { return mesh.corners[next[h]]; }
};

Status check_invariants(const Mesh& mesh) {
  if (mesh.positions.size() % 3 != 0) return invalid("position count is not a multiple of 3");
  const size_t vertices = mesh.vertex_count();
  size_t total = 0;
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    if (mesh.face_sizes[f] < 3) return invalid("face " + std::to_string(f) + " has fewer than 3 corners");
    total += mesh.face_sizes[f];
  }
  if (total != mesh.corners.size()) return invalid("face sizes do not add up to the corner count");
  // kNone must stay free as a marker, and every output index must fit.
  if (total >= kNone / 4) return invalid("mesh too large for 32-bit output indices");
  for (size_t c = 0; c < total; ++c) {
    if (mesh.corners[c] >= vertices) return invalid("corner " + std::to_string(c) + " refers to a missing vertex");
  }
  return Status::Ok();
}

// Links every half-edge to its opposite, rejecting what has no consistent
// opposite: degenerate edges, edges with three or more sides, and pairs of
// faces that run along an edge in the same direction.
Status build_half_edges(const Mesh& mesh, HalfEdges* he) {
  const uint32_t corner_count = static_cast<uint32_t>(mesh.corners.size());
  const size_t vertex_count = mesh.vertex_count();
  he->face_of.resize(corner_count);
  he->next.resize(corner_count);
  he->prev.resize(corner_count);
  uint32_t first = 0;
  for (uint32_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t size = mesh.face_sizes[f];
    for (uint32_t i = 0; i < size; ++i) {
      he->face_of[first + i] = f;
      he->next[first + i] = first + (i + 1) % size;
      he->prev[first + i] = first + (i + size - 1) % size;
    }
    first += size;
  }

  // Counting sort by start vertex keeps each vertex's half-edges ascending,
  // which fixes the order in which pinched vertices' fans are found.
  he->out_begin.assign(vertex_count + 1, 0);
  for (uint32_t h = 0; h < corner_count; ++h) ++he->out_begin[mesh.corners[h] + 1];
  for (size_t v = 0; v < vertex_count; ++v) he->out_begin[v + 1] += he->out_begin[v];
  he->out_list.resize(corner_count);
  std::vector<uint32_t> fill(he->out_begin.begin(), he->out_begin.end() - 1);
  for (uint32_t h = 0; h < corner_count; ++h) he->out_list[fill[mesh.corners[h]]++] = h;

  he->twin.assign(corner_count, kNone);
  for (uint32_t h = 0; h < corner_count; ++h) {
    const uint32_t a = he->from(mesh, h);
    const uint32_t b = he->to(mesh, h);
    if (a == b) {
      return invalid("face " + std::to_string(he->face_of[h]) + " has the degenerate edge " + std::to_string(a) + "-" +
                     std::to_string(b));
    }
    uint32_t same = 0;
    uint32_t other_same = kNone;
    for (uint32_t k = he->out_begin[a]; k < he->out_begin[a + 1]; ++k) {
      const uint32_t g = he->out_list[k];
      if (he->to(mesh, g) != b) continue;
      ++same;
      if (g != h) other_same = g;
    }
    uint32_t reverse = 0;
    for (uint32_t k = he->out_begin[b]; k < he->out_begin[b + 1]; ++k) {
      const uint32_t g = he->out_list[k];
      if (he->to(mesh, g) != a) continue;
      ++reverse;
      he->twin[h] = g;
    }
    if (same + reverse > 2) {
      return invalid("edge " + std::to_string(a) + "-" + std::to_string(b) + " is used by " +
                     std::to_string(same + reverse) + " face sides (non-manifold)");
    }
    if (same > 1) {
      return invalid("faces " + std::to_string(he->face_of[h]) + " and " + std::to_string(he->face_of[other_same]) +
                     " both run along edge " + std::to_string(a) + "->" + std::to_string(b) +
                     " (inconsistent orientation)");
    }
  }
  return Status::Ok();
}

struct Point {
  double x = 0, y = 0, z = 0;
};

Point input_point(const Mesh& mesh, uint32_t v) {
  return {mesh.positions[3 * size_t{v}], mesh.positions[3 * size_t{v} + 1], mesh.positions[3 * size_t{v} + 2]};
}

void add_to(Point* sum, const Point& p) {
  sum->x += p.x;
  sum->y += p.y;
  sum->z += p.z;
}

Point divided(const Point& p, double d) { return {p.x / d, p.y / d, p.z / d}; }

void store(const Point& p, size_t index, Mesh* mesh) {
  mesh->positions[3 * index] = static_cast<float>(p.x);
  mesh->positions[3 * index + 1] = static_cast<float>(p.y);
  mesh->positions[3 * index + 2] = static_cast<float>(p.z);
}

}  // namespace

Status catmull_clark(const Mesh& in, Mesh* out) {
  if (Status s = check_invariants(in); !s.ok()) return s;
  HalfEdges he;
  if (Status s = build_half_edges(in, &he); !s.ok()) return s;

  const uint32_t vertex_count = static_cast<uint32_t>(in.vertex_count());
  const uint32_t face_count = static_cast<uint32_t>(in.face_count());
  const uint32_t corner_count = static_cast<uint32_t>(in.corners.size());

  std::vector<uint32_t> edge_of(corner_count);
  uint32_t edge_count = 0;
  for (uint32_t h = 0; h < corner_count; ++h) {
    const uint32_t t = he.twin[h];
    edge_of[h] = (t != kNone && t < h) ? edge_of[t] : edge_count++;
  }

  std::vector<Point> face_points(face_count);
  for (uint32_t f = 0, first = 0; f < face_count; first += in.face_sizes[f], ++f) {
    Point sum;
    for (uint32_t i = 0; i < in.face_sizes[f]; ++i) add_to(&sum, input_point(in, in.corners[first + i]));
    face_points[f] = divided(sum, in.face_sizes[f]);
  }

  // Vertex points, one per fan of faces around a vertex. A fan is a maximal
  // run of corners at the vertex linked across shared edges; a manifold
  // vertex has exactly one.
  std::vector<uint32_t> fan_vertex(corner_count, kNone);  // output vertex of each corner
  std::vector<Point> vertex_points(vertex_count);
  std::vector<Point> extra_points;  // further fans of pinched vertices
  for (uint32_t v = 0; v < vertex_count; ++v) {
    const Point s = input_point(in, v);
    vertex_points[v] = s;  // kept by unreferenced vertices
    bool first_fan = true;
    for (uint32_t k = he.out_begin[v]; k < he.out_begin[v + 1]; ++k) {
      const uint32_t seed = he.out_list[k];
      if (fan_vertex[seed] != kNone) continue;
      // Rotate backwards to the fan's first corner (past a boundary edge
      // when the fan is open), so the forward walk sees the whole fan.
      uint32_t start = seed;
      bool closed = false;
      for (;;) {
        const uint32_t t = he.twin[he.prev[start]];
        if (t == kNone) break;
        if (t == seed) {
          closed = true;
          start = seed;
          break;
        }
        start = t;
      }
      const uint32_t index = first_fan ? v : vertex_count + face_count + edge_count + static_cast<uint32_t>(extra_points.size());
      Point face_sum, spoke_sum;  // spoke_sum: sum of (S + far end) over the fan's outgoing edges
      uint32_t n = 0;
      uint32_t end = start;
      for (uint32_t c = start;;) {
        fan_vertex[c] = index;
        ++n;
        add_to(&face_sum, face_points[he.face_of[c]]);
        add_to(&spoke_sum, s);
        add_to(&spoke_sum, input_point(in, he.to(in, c)));
        end = c;
        const uint32_t t = he.twin[c];
        if (t == kNone || he.next[t] == start) break;
        c = he.next[t];
      }
      Point moved;
      if (closed) {
        // (Q + 2R + (n-3)S) / n; spoke_sum / n is 2R. (n-3)*S is exact in
        // double because S is a float.
        const Point q = divided(face_sum, n);
        const Point two_r = divided(spoke_sum, n);
        const double w = static_cast<double>(n) - 3;
        moved = divided({q.x + two_r.x + w * s.x, q.y + two_r.y + w * s.y, q.z + two_r.z + w * s.z}, n);
      } else {
        // Boundary rule: only the two boundary neighbours pull, so the
        // boundary curve refines as a cubic B-spline of its own.
        const Point a = input_point(in, he.from(in, he.prev[start]));
        const Point b = input_point(in, he.to(in, end));
        moved = divided({a.x + 6 * s.x + b.x, a.y + 6 * s.y + b.y, a.z + 6 * s.z + b.z}, 8);
      }
      if (first_fan) {
        vertex_points[v] = moved;
        first_fan = false;
      } else {
        extra_points.push_back(moved);
      }
    }
  }

  const uint64_t total = uint64_t{vertex_count} + face_count + edge_count + extra_points.size();
  if (total > kNone) return invalid("output too large for 32-bit vertex indices");

  Mesh result;
  result.positions.resize(3 * total);
  for (uint32_t v = 0; v < vertex_count; ++v) store(vertex_points[v], v, &result);
  for (uint32_t f = 0; f < face_count; ++f) store(face_points[f], size_t{vertex_count} + f, &result);
  const size_t edge_base = size_t{vertex_count} + face_count;
  for (uint32_t h = 0; h < corner_count; ++h) {
    const uint32_t t = he.twin[h];
    if (t != kNone && t < h) continue;  // the edge's point was made at its first half-edge
    const Point a = input_point(in, he.from(in, h));
    const Point b = input_point(in, he.to(in, h));
    Point e;
    if (t == kNone) {
      e = divided({a.x + b.x, a.y + b.y, a.z + b.z}, 2);
    } else {
      const Point& f = face_points[he.face_of[h]];
      const Point& g = face_points[he.face_of[t]];
      e = divided({a.x + b.x + f.x + g.x, a.y + b.y + f.y + g.y, a.z + b.z + f.z + g.z}, 4);
    }
    store(e, edge_base + edge_of[h], &result);
  }
  for (size_t i = 0; i < extra_points.size(); ++i) store(extra_points[i], edge_base + edge_count + i, &result);

  result.face_sizes.assign(corner_count, 4);
  result.corners.resize(4 * size_t{corner_count});
  for (uint32_t h = 0; h < corner_count; ++h) {
    uint32_t* quad = &result.corners[4 * size_t{h}];
    quad[0] = fan_vertex[h];
    quad[1] = static_cast<uint32_t>(edge_base + edge_of[h]);
    quad[2] = vertex_count + he.face_of[h];
    quad[3] = static_cast<uint32_t>(edge_base + edge_of[he.prev[h]]);
  }
  *out = std::move(result);
  return Status::Ok();
}

}  // namespace qmc::tools
