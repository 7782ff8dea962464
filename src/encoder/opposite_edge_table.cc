// Opposite-edge table of seed 001 §3.1, built in linear time, with the
// manifold and orientation checks the quad coder relies on.
#include "encoder/opposite_edge_table.h"

#include "encoder/edge_buckets.h"

namespace qmc {
namespace {

uint32_t origin(const Mesh& mesh, uint32_t edge) { return mesh.corners[edge]; }
uint32_t destination(const Mesh& mesh, uint32_t edge) { return mesh.corners[OppositeEdgeTable::next(edge)]; }

// Linear time (seed 001 §3.5): for each vertex v, its outgoing edges are
// entered in a marker table keyed by destination; each edge arriving at v
// from u then finds its twin v -> u in one look-up, and a second outgoing
// edge to the same destination is a duplicate.
std::string pair_edges(const Mesh& mesh, OppositeEdgeTable* t) {
  const uint32_t edges = uint32_t(mesh.corners.size()), vertices = uint32_t(mesh.vertex_count());
  const EdgeBuckets out = bucket_edges(vertices, edges, [&](uint32_t e) { return origin(mesh, e); });
  const EdgeBuckets in = bucket_edges(vertices, edges, [&](uint32_t e) { return destination(mesh, e); });
  std::vector<uint32_t> mark(vertices, kNoEdge), edge_to(vertices, kNoEdge);
  t->across.assign(edges, kNoEdge);
  for (uint32_t v = 0; v < vertices; ++v) {
    for (uint32_t k = out.begin[v]; k < out.begin[v + 1]; ++k) {
      const uint32_t e = out.items[k], w = destination(mesh, e);
      if (mark[w] == v)
        return "edge " + std::to_string(v) + "-" + std::to_string(w) +
               " is used twice in the same direction (non-manifold edge or inconsistent orientation)";
      mark[w] = v;
      edge_to[w] = e;
    }
    for (uint32_t k = in.begin[v]; k < in.begin[v + 1]; ++k) {
      const uint32_t e = in.items[k], u = origin(mesh, e);
      if (mark[u] == v) t->across[e] = edge_to[u];
    }
  }
  return {};
}

// A vertex is manifold if rotating around it through the quads visits every
// edge that leaves it: one fan, open (boundary) or closed.
std::string check_vertex_fans(const Mesh& mesh, const OppositeEdgeTable& t) {
  const uint32_t edges = uint32_t(mesh.corners.size());
  std::vector<uint32_t> outgoing(mesh.vertex_count(), 0), start(mesh.vertex_count(), kNoEdge);
  for (uint32_t e = 0; e < edges; ++e) {
    const uint32_t v = origin(mesh, e);
    ++outgoing[v];
    // Prefer the edge that starts an open fan: a boundary edge leaving v,
    // which no rotation step leads to.
    if (start[v] == kNoEdge || t.across[e] == kNoEdge) start[v] = e;
  }
  for (uint32_t v = 0; v < mesh.vertex_count(); ++v) {
    if (outgoing[v] == 0) continue;
    uint32_t seen = 0;
    for (uint32_t e = start[v]; e != kNoEdge && seen <= outgoing[v];) {
      ++seen;
      const uint32_t back = t.across[OppositeEdgeTable::prev(e)];  // the edge v -> u in the next quad
      e = back == start[v] ? kNoEdge : back;
    }
    if (seen != outgoing[v])
      return "vertex " + std::to_string(v) + " is non-manifold (its quads form more than one fan)";
  }
  return {};
}

uint32_t count_components(const Mesh& mesh, const OppositeEdgeTable& t) {
  const uint32_t quads = uint32_t(mesh.face_count());
  std::vector<bool> seen(quads, false);
  std::vector<uint32_t> stack;
  uint32_t components = 0;
  for (uint32_t q = 0; q < quads; ++q) {
    if (seen[q]) continue;
    ++components;
    seen[q] = true;
    stack.push_back(q);
    while (!stack.empty()) {
      const uint32_t f = stack.back();
      stack.pop_back();
      for (uint32_t i = 0; i < 4; ++i) {
        const uint32_t other = t.across[4 * f + i];
        if (other != kNoEdge && !seen[OppositeEdgeTable::quad_of(other)]) {
          seen[OppositeEdgeTable::quad_of(other)] = true;
          stack.push_back(OppositeEdgeTable::quad_of(other));
        }
      }
    }
  }
  return components;
}

// Boundary edges chain into loops: after edge u -> v comes the boundary edge
// leaving v, found by rotating around v through the quads.
uint32_t count_boundary_loops(const Mesh& mesh, const OppositeEdgeTable& t) {
  const uint32_t edges = uint32_t(mesh.corners.size());
  std::vector<bool> seen(edges, false);
  uint32_t loops = 0;
  for (uint32_t e = 0; e < edges; ++e) {
    if (t.across[e] != kNoEdge || seen[e]) continue;
    ++loops;
    for (uint32_t b = e; !seen[b];) {
      seen[b] = true;
      uint32_t n = OppositeEdgeTable::next(b);
      while (t.across[n] != kNoEdge) n = OppositeEdgeTable::next(t.across[n]);
      b = n;
    }
  }
  return loops;
}

}  // namespace

std::string build_opposite_edge_table(const Mesh& mesh, OppositeEdgeTable* t) {
  size_t non_quads = 0;
  for (uint32_t d : mesh.face_sizes) non_quads += d != 4;
  if (non_quads) return std::to_string(non_quads) + " faces are not quads";
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t* c = &mesh.corners[4 * f];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (c[i] == c[j]) return "quad " + std::to_string(f) + " repeats a vertex";
  }
  if (std::string why = pair_edges(mesh, t); !why.empty()) return why;
  if (std::string why = check_vertex_fans(mesh, *t); !why.empty()) return why;
  t->components = count_components(mesh, *t);
  t->boundary_loops = count_boundary_loops(mesh, *t);
  std::vector<bool> used(mesh.vertex_count(), false);
  int64_t vertices = 0, half_edges = 0, boundary = 0;
  for (uint32_t v : mesh.corners) {
    vertices += !used[v];
    used[v] = true;
  }
  for (uint32_t e = 0; e < t->across.size(); ++e) {
    ++half_edges;
    boundary += t->across[e] == kNoEdge;
  }
  const int64_t edges_count = (half_edges + boundary) / 2;
  t->euler_characteristic = vertices - edges_count + int64_t(mesh.face_count());
  return {};
}

}  // namespace qmc
