// Seed 002 "Methods": Euler circuit cutting to obtain a topological disk (Gu
// et al.'s cut graph, its pruning and straightening, a long path for closed
// genus 0). See gim_cut.h for the contract.
#include "common/union_find.h"
#include "geometry/gim_cut.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace qmc {
namespace {

constexpr uint32_t kNone = UINT32_MAX;
// Straightening passes over all cut paths (seed 002: "iterate this process
// several times"); each pass only shortens paths, so few are needed.
constexpr int kStraightenPasses = 3;

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

// Internal consistency failures: the input was accepted, but the cut it led
// to is not a disk. Never hand such a cut on.
Status internal(const std::string& message) { return invalid("cut_to_disk internal check failed: " + message); }

void report(const std::function<void(double)>& progress, double f) {
  if (progress) progress(f);
}

uint32_t next_he(uint32_t h) { return h - h % 3 + (h % 3 + 1) % 3; }
uint32_t prev_he(uint32_t h) { return h - h % 3 + (h % 3 + 2) % 3; }

// Half-edge h = 3 t + k runs from corner k of triangle t to corner k + 1.
// After fan splitting, `vertex` holds split-vertex ids (one per fan).
struct Surface {
  std::vector<uint32_t> vertex;    // per half-edge: its origin
  std::vector<uint32_t> twin;      // kNone on the input boundary
  std::vector<uint32_t> input_of;  // split vertex -> input vertex
  std::vector<double> pos;         // per split vertex, 3 each
  // Undirected edges: endpoints and the half-edge(s).
  std::vector<uint32_t> edge_of;  // per half-edge
  std::vector<uint32_t> edge_he;  // per edge: one half-edge
  // Vertex adjacency (CSR): neighbour and edge.
  std::vector<uint32_t> adj_offset, adj_vertex, adj_edge;
  uint32_t vertex_count = 0;
  uint32_t dest(uint32_t h) const { return vertex[next_he(h)]; }
  double length(uint32_t e) const {
    const uint32_t a = vertex[edge_he[e]], b = dest(edge_he[e]);
    double s = 0;
    for (int k = 0; k < 3; ++k) s += (pos[3 * a + k] - pos[3 * b + k]) * (pos[3 * a + k] - pos[3 * b + k]);
    return std::sqrt(s);
  }
  bool boundary_edge(uint32_t e) const { return twin[edge_he[e]] == kNone; }
};

std::string edge_name(uint32_t a, uint32_t b) { return "(" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

Status check_triangles(const GimTriMesh& mesh) {
  if (mesh.positions.size() % 3 != 0)
    return invalid("positions hold " + std::to_string(mesh.positions.size()) + " values, not a multiple of 3");
  if (mesh.triangles.size() % 3 != 0)
    return invalid("triangle list holds " + std::to_string(mesh.triangles.size()) + " indices, not a multiple of 3");
  if (mesh.triangles.empty()) return invalid("the mesh has no triangles");
  if (mesh.triangles.size() / 3 >= kNone / 4) return invalid("too many triangles for 32-bit half-edge indices");
  const size_t n = mesh.vertex_count();
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const uint32_t* c = &mesh.triangles[3 * t];
    for (int k = 0; k < 3; ++k)
      if (c[k] >= n)
        return invalid("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(c[k]) + " of " +
                       std::to_string(n));
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0])
      return invalid("triangle " + std::to_string(t) + " repeats a vertex");
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a)
        if (!std::isfinite(mesh.positions[3 * size_t(c[k]) + a]))
          return invalid("vertex " + std::to_string(c[k]) + " has a non-finite coordinate");
  }
  return Status::Ok();
}

// Twins by sorting undirected edge keys; rejects non-manifold edges and
// inconsistent orientation.
Status pair_half_edges(const GimTriMesh& mesh, Surface* s) {
  const uint32_t nh = uint32_t(mesh.triangles.size());
  std::vector<std::pair<uint64_t, uint32_t>> keys(nh);
  for (uint32_t h = 0; h < nh; ++h) {
    const uint64_t a = mesh.triangles[h], b = mesh.triangles[next_he(h)];
    keys[h] = {(std::min(a, b) << 32) | std::max(a, b), h};
  }
  std::sort(keys.begin(), keys.end());
  s->twin.assign(nh, kNone);
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    while (j < keys.size() && keys[j].first == keys[i].first) ++j;
    const uint32_t h = keys[i].second;
    const uint32_t a = mesh.triangles[h], b = mesh.triangles[next_he(h)];
    if (j - i > 2)
      return invalid("edge " + edge_name(a, b) + " is non-manifold: " + std::to_string(j - i) + " triangles");
    if (j - i == 2) {
      const uint32_t g = keys[i + 1].second;
      if (mesh.triangles[g] == a)
        return invalid("inconsistent orientation: triangles " + std::to_string(h / 3) + " and " +
                       std::to_string(g / 3) + " both run edge " + edge_name(a, b) + " the same way");
      s->twin[h] = g, s->twin[g] = h;
    }
    i = j;
  }
  return Status::Ok();
}

// One split vertex per fan: outgoing half-edges h and twin(prev(h)) share a
// fan. A pinched vertex (several fans) becomes several vertices, which cuts
// the surface there and keeps every later step manifold.
void split_fans(const GimTriMesh& mesh, Surface* s, uint32_t* pinched) {
  const uint32_t nh = uint32_t(mesh.triangles.size());
  UnionFind fans(nh);
  for (uint32_t h = 0; h < nh; ++h)
    if (s->twin[prev_he(h)] != kNone) fans.unite(h, s->twin[prev_he(h)]);
  s->vertex.assign(nh, kNone);
  std::vector<uint32_t> id_of_root(nh, kNone), fans_of_input(mesh.vertex_count(), 0);
  for (uint32_t h = 0; h < nh; ++h) {
    const uint32_t r = fans.find(h);
    if (id_of_root[r] == kNone) {
      id_of_root[r] = s->vertex_count++;
      const uint32_t v = mesh.triangles[h];
      s->input_of.push_back(v);
      for (int k = 0; k < 3; ++k) s->pos.push_back(mesh.positions[3 * size_t(v) + k]);
      ++fans_of_input[v];
    }
    s->vertex[h] = id_of_root[r];
  }
  *pinched = uint32_t(std::count_if(fans_of_input.begin(), fans_of_input.end(), [](uint32_t f) { return f > 1; }));
}

void build_edges(Surface* s) {
  const uint32_t nh = uint32_t(s->vertex.size());
  s->edge_of.assign(nh, kNone);
  for (uint32_t h = 0; h < nh; ++h) {
    if (s->twin[h] != kNone && s->twin[h] < h) continue;
    s->edge_of[h] = uint32_t(s->edge_he.size());
    if (s->twin[h] != kNone) s->edge_of[s->twin[h]] = uint32_t(s->edge_he.size());
    s->edge_he.push_back(h);
  }
  s->adj_offset.assign(s->vertex_count + 1, 0);
  for (uint32_t h : s->edge_he) ++s->adj_offset[s->vertex[h] + 1], ++s->adj_offset[s->dest(h) + 1];
  for (uint32_t v = 0; v < s->vertex_count; ++v) s->adj_offset[v + 1] += s->adj_offset[v];
  s->adj_vertex.resize(s->adj_offset.back());
  s->adj_edge.resize(s->adj_offset.back());
  std::vector<uint32_t> fill(s->adj_offset.begin(), s->adj_offset.end() - 1);
  for (uint32_t e = 0; e < s->edge_he.size(); ++e) {
    const uint32_t a = s->vertex[s->edge_he[e]], b = s->dest(s->edge_he[e]);
    s->adj_vertex[fill[a]] = b, s->adj_edge[fill[a]++] = e;
    s->adj_vertex[fill[b]] = a, s->adj_edge[fill[b]++] = e;
  }
}

Status check_connected(const Surface& s, uint32_t triangles) {
  UnionFind comp(triangles);
  for (uint32_t h = 0; h < s.twin.size(); ++h)
    if (s.twin[h] != kNone) comp.unite(h / 3, s.twin[h] / 3);
  std::vector<uint32_t> size(triangles, 0);
  for (uint32_t t = 0; t < triangles; ++t) ++size[comp.find(t)];
  std::vector<uint32_t> sizes;
  for (uint32_t c : size)
    if (c) sizes.push_back(c);
  if (sizes.size() == 1) return Status::Ok();
  std::sort(sizes.rbegin(), sizes.rend());
  std::string list;
  for (size_t i = 0; i < sizes.size() && i < 5; ++i) list += (i ? ", " : "") + std::to_string(sizes[i]);
  if (sizes.size() > 5) list += ", ...";
  return invalid(std::to_string(sizes.size()) + " connected components (" + list +
                 " triangles); the geometry image takes one");
}

// With a manifold vertex, the boundary half-edge leaving h's end: rotate
// around it until an edge without a twin (or a cut edge) is reached.
template <typename IsOpen>
uint32_t next_boundary(const Surface& s, uint32_t h, IsOpen open, uint32_t bound) {
  uint32_t x = next_he(h);
  for (uint32_t step = 0; step <= bound; ++step) {
    if (open(x)) return x;
    x = next_he(s.twin[x]);
  }
  return kNone;
}

uint32_t count_boundary_loops(const Surface& s) {
  const uint32_t nh = uint32_t(s.vertex.size());
  std::vector<uint8_t> seen(nh, 0);
  auto open = [&](uint32_t x) { return s.twin[x] == kNone; };
  uint32_t loops = 0;
  for (uint32_t h = 0; h < nh; ++h) {
    if (!open(h) || seen[h]) continue;
    ++loops;
    for (uint32_t x = h, step = 0; x != kNone && !seen[x] && step <= nh; ++step) {
      seen[x] = 1;
      x = next_boundary(s, x, open, nh);
    }
  }
  return loops;
}

// Dijkstra over vertices; `blocked` vertices are never entered (except
// `target`), `blocked_edge` edges never used. Returns distances and the edge
// that reached each vertex.
struct ShortestPaths {
  std::vector<double> dist;
  std::vector<uint32_t> via;
};

template <typename VertexOk, typename EdgeOk>
ShortestPaths dijkstra(const Surface& s, uint32_t source, uint32_t target, VertexOk vertex_ok, EdgeOk edge_ok) {
  ShortestPaths sp{std::vector<double>(s.vertex_count, std::numeric_limits<double>::infinity()),
                   std::vector<uint32_t>(s.vertex_count, kNone)};
  using Item = std::pair<double, uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  sp.dist[source] = 0;
  queue.push({0, source});
  // Each vertex is settled once and pushes at most its degree, so the loop is
  // bounded by the number of adjacency entries.
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (v == target) break;  // settled: nothing later can shorten it
    if (d > sp.dist[v]) continue;
    for (uint32_t k = s.adj_offset[v]; k < s.adj_offset[v + 1]; ++k) {
      const uint32_t w = s.adj_vertex[k], e = s.adj_edge[k];
      if (!edge_ok(v, w, e) || (w != target && !vertex_ok(w))) continue;
      const double nd = d + s.length(e);
      if (nd < sp.dist[w]) sp.dist[w] = nd, sp.via[w] = e, queue.push({nd, w});
    }
  }
  return sp;
}

uint32_t other_end(const Surface& s, uint32_t e, uint32_t v) {
  const uint32_t a = s.vertex[s.edge_he[e]];
  return a == v ? s.dest(s.edge_he[e]) : a;
}

// Seed 002: a closed genus-0 mesh is cut along a long path, approximately
// between the two farthest vertices.
void long_path_cut(const Surface& s, std::vector<uint8_t>* cut) {
  auto any = [](uint32_t) { return true; };
  auto any_edge = [](uint32_t, uint32_t, uint32_t) { return true; };
  auto farthest = [&](const ShortestPaths& sp) {
    uint32_t best = 0;
    for (uint32_t v = 0; v < s.vertex_count; ++v)
      if (std::isfinite(sp.dist[v]) && sp.dist[v] > sp.dist[best]) best = v;
    return best;
  };
  const uint32_t a = farthest(dijkstra(s, s.vertex[0], kNone, any, any_edge));
  const ShortestPaths sp = dijkstra(s, a, kNone, any, any_edge);
  uint32_t v = farthest(sp);
  for (uint32_t step = 0; v != a && step < s.vertex_count; ++step) {
    const uint32_t e = sp.via[v];
    (*cut)[e] = 1;
    v = other_end(s, e, v);
  }
}

// Gu's cut graph: the edges not crossed by a BFS spanning tree of the dual
// graph, with dangling interior edges pruned away. Boundary edges stay in the
// graph (they are never crossed); only interior edges end up cut.
void gu_cut_graph(const Surface& s, std::vector<uint8_t>* cut) {
  const uint32_t nt = uint32_t(s.vertex.size() / 3);
  const uint32_t ne = uint32_t(s.edge_he.size());
  std::vector<uint8_t> in_graph(ne, 1), reached(nt, 0);
  std::vector<uint32_t> queue{0};
  reached[0] = 1;
  for (size_t q = 0; q < queue.size(); ++q) {
    for (uint32_t k = 0; k < 3; ++k) {
      const uint32_t h = 3 * queue[q] + k, g = s.twin[h];
      if (g == kNone || reached[g / 3]) continue;
      reached[g / 3] = 1, in_graph[s.edge_of[h]] = 0;
      queue.push_back(g / 3);
    }
  }
  std::vector<uint32_t> degree(s.vertex_count, 0);
  for (uint32_t e = 0; e < ne; ++e)
    if (in_graph[e]) ++degree[s.vertex[s.edge_he[e]]], ++degree[s.dest(s.edge_he[e])];
  std::vector<uint32_t> leaves;
  for (uint32_t v = 0; v < s.vertex_count; ++v)
    if (degree[v] == 1) leaves.push_back(v);
  // Each removal takes one edge away, so at most ne iterations do work.
  for (size_t i = 0; i < leaves.size() && i <= ne; ++i) {
    const uint32_t v = leaves[i];
    if (degree[v] != 1) continue;
    for (uint32_t k = s.adj_offset[v]; k < s.adj_offset[v + 1]; ++k) {
      const uint32_t e = s.adj_edge[k];
      if (!in_graph[e]) continue;
      in_graph[e] = 0, --degree[v];
      const uint32_t w = s.adj_vertex[k];
      if (--degree[w] == 1) leaves.push_back(w);
      break;
    }
  }
  for (uint32_t e = 0; e < ne; ++e) (*cut)[e] = in_graph[e] && !s.boundary_edge(e);
}

// A chain of interior cut edges between two cut-graph vertices.
struct CutPath {
  std::vector<uint32_t> vertices;  // first and last are the ends (distinct)
  std::vector<uint32_t> edges;
};

// Splits the interior cut edges into paths between nodes (degree != 2 in the
// cut graph, input boundary included). A closed chain through no node is
// split at two vertices, a loop from a node to itself at its middle vertex,
// so every path has two distinct ends (see straighten_cut for why).
std::vector<CutPath> cut_paths(const Surface& s, const std::vector<uint8_t>& cut) {
  const uint32_t ne = uint32_t(s.edge_he.size());
  std::vector<uint32_t> degree(s.vertex_count, 0);
  for (uint32_t e = 0; e < ne; ++e)
    if (cut[e] || s.boundary_edge(e)) ++degree[s.vertex[s.edge_he[e]]], ++degree[s.dest(s.edge_he[e])];
  std::vector<uint8_t> used(ne, 0);
  std::vector<CutPath> paths;
  auto walk = [&](uint32_t start, uint32_t first_edge) {
    CutPath p{{start}, {}};
    uint32_t v = start, e = first_edge;
    for (uint32_t step = 0; step < ne && e != kNone; ++step) {
      used[e] = 1;
      p.edges.push_back(e);
      v = other_end(s, e, v);
      p.vertices.push_back(v);
      if (degree[v] != 2 || v == start) break;
      uint32_t next = kNone;
      for (uint32_t k = s.adj_offset[v]; k < s.adj_offset[v + 1]; ++k)
        if (cut[s.adj_edge[k]] && !used[s.adj_edge[k]]) next = s.adj_edge[k];
      e = next;
    }
    return p;
  };
  auto add = [&](CutPath p) {
    if (p.vertices.front() != p.vertices.back()) return paths.push_back(std::move(p));
    if (p.edges.size() < 2) return;  // cannot happen in a simple graph; keep the edge as it is
    const size_t mid = p.edges.size() / 2;
    paths.push_back({{p.vertices.begin(), p.vertices.begin() + mid + 1}, {p.edges.begin(), p.edges.begin() + mid}});
    paths.push_back({{p.vertices.begin() + mid, p.vertices.end()}, {p.edges.begin() + mid, p.edges.end()}});
  };
  for (uint32_t v = 0; v < s.vertex_count; ++v) {
    if (degree[v] == 2 || degree[v] == 0) continue;
    for (uint32_t k = s.adj_offset[v]; k < s.adj_offset[v + 1]; ++k)
      if (cut[s.adj_edge[k]] && !used[s.adj_edge[k]]) add(walk(v, s.adj_edge[k]));
  }
  for (uint32_t e = 0; e < ne; ++e)  // closed chains through no node
    if (cut[e] && !used[e]) add(walk(s.vertex[s.edge_he[e]], e));
  return paths;
}

double path_length(const Surface& s, const std::vector<uint32_t>& edges) {
  double l = 0;
  for (uint32_t e : edges) l += s.length(e);
  return l;
}

// The edges around path end v that lie in the same wedge of the cut graph
// as the path's own edge e (the cut graph without the path): rotate both
// ways from e until a cut or boundary edge. Returns them sorted.
template <typename InGraph>
std::vector<uint32_t> wedge_edges(const Surface& s, uint32_t v, uint32_t e, InGraph in_graph) {
  const uint32_t h = s.edge_he[e];
  const uint32_t x0 = s.vertex[h] == v ? h : s.twin[h];
  std::vector<uint32_t> edges{e};
  const uint32_t bound = s.adj_offset[v + 1] - s.adj_offset[v] + 1;
  uint32_t x = x0;
  for (uint32_t step = 0; step < bound && s.twin[x] != kNone; ++step) {
    x = next_he(s.twin[x]);
    if (x == x0 || in_graph(s.edge_of[x])) break;
    edges.push_back(s.edge_of[x]);
  }
  x = x0;
  for (uint32_t step = 0; step < bound; ++step) {
    const uint32_t back = prev_he(x);
    if (in_graph(s.edge_of[back]) || s.twin[back] == kNone || s.twin[back] == x0) break;
    x = s.twin[back];
    edges.push_back(s.edge_of[x]);
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// Seed 002's straightening: each path between two cut nodes is replaced by
// the shortest path between its ends that touches no other part of the cut
// graph (no other path's vertices, no input-boundary vertex, no cut edge).
// Why that keeps a disk: removing the path from the cut glues the disk back
// along it, which yields an annulus whose two boundary loops hold the two
// (distinct) ends; any simple arc through the annulus' interior from one
// boundary loop to the other cuts it into a disk again. Shortest paths are
// simple, and avoiding every other cut vertex keeps the arc interior. An end
// that keeps other cut edges is several points of the annulus (one per
// wedge); only the wedge the old path left through lies on the right
// boundary loop, so the new path must leave (and arrive) through it.
// Paths are visited in discovery order rather than along an Euler circuit
// of the doubled graph: each replacement only depends on the rest of the
// cut, not on the order, and passes repeat until nothing shortens.
uint32_t straighten_cut(const Surface& s, std::vector<uint8_t>* cut, const std::function<void(double)>& progress) {
  std::vector<CutPath> paths = cut_paths(s, *cut);
  std::vector<uint32_t> on_cut(s.vertex_count, 0);  // how many cut-graph edges touch each vertex
  for (uint32_t e = 0; e < s.edge_he.size(); ++e)
    if ((*cut)[e] || s.boundary_edge(e)) ++on_cut[s.vertex[s.edge_he[e]]], ++on_cut[s.dest(s.edge_he[e])];
  auto set_path = [&](const CutPath& p, int sign) {
    for (uint32_t e : p.edges) {
      (*cut)[e] = sign > 0;
      on_cut[s.vertex[s.edge_he[e]]] += sign, on_cut[s.dest(s.edge_he[e])] += sign;
    }
  };
  uint32_t kept = 0;
  for (int pass = 0; pass < kStraightenPasses; ++pass) {
    uint32_t changed = 0;
    for (size_t i = 0; i < paths.size(); ++i) {
      CutPath& p = paths[i];
      const uint32_t a = p.vertices.front(), b = p.vertices.back();
      const double old_length = path_length(s, p.edges);
      set_path(p, -1);
      auto in_graph = [&](uint32_t e) { return (*cut)[e] || s.boundary_edge(e); };
      const std::vector<uint32_t> wedge_a = wedge_edges(s, a, p.edges.front(), in_graph);
      const std::vector<uint32_t> wedge_b = wedge_edges(s, b, p.edges.back(), in_graph);
      auto edge_ok = [&](uint32_t v, uint32_t w, uint32_t e) {
        if (in_graph(e)) return false;
        if (v == a && !std::binary_search(wedge_a.begin(), wedge_a.end(), e)) return false;
        return w != b || std::binary_search(wedge_b.begin(), wedge_b.end(), e);
      };
      const ShortestPaths sp = dijkstra(
          s, a, b, [&](uint32_t w) { return on_cut[w] == 0; }, edge_ok);
      CutPath q{{b}, {}};
      if (std::isfinite(sp.dist[b]) && sp.dist[b] < old_length * (1 - 1e-9)) {
        for (uint32_t v = b, step = 0; v != a && step < s.vertex_count; ++step) {
          q.edges.push_back(sp.via[v]);
          v = other_end(s, sp.via[v], v);
          q.vertices.push_back(v);
        }
        std::reverse(q.edges.begin(), q.edges.end());
        std::reverse(q.vertices.begin(), q.vertices.end());
        p = std::move(q);
        ++changed;
      }
      set_path(p, +1);
      report(progress, 0.4 + 0.4 * (pass + double(i + 1) / paths.size()) / kStraightenPasses);
    }
    kept += changed;
    if (!changed) break;
  }
  return kept;
}

// Opens the surface along the cut edges: one disk vertex per wedge, the
// boundary loop with the disk on its left, and the mates of cut edges.
Status open_along_cut(const Surface& s, const std::vector<uint8_t>& cut, DiskCut* out) {
  const uint32_t nh = uint32_t(s.vertex.size());
  auto open = [&](uint32_t h) { return s.twin[h] == kNone || cut[s.edge_of[h]]; };
  UnionFind wedges(nh);
  for (uint32_t h = 0; h < nh; ++h)
    if (!open(prev_he(h))) wedges.unite(h, s.twin[prev_he(h)]);
  std::vector<uint32_t> disk_of_root(nh, kNone), disk_vertex(nh);
  out->original_vertex.clear();
  for (uint32_t h = 0; h < nh; ++h) {
    const uint32_t r = wedges.find(h);
    if (disk_of_root[r] == kNone) {
      disk_of_root[r] = uint32_t(out->original_vertex.size());
      out->original_vertex.push_back(s.input_of[s.vertex[h]]);
    }
    disk_vertex[h] = disk_of_root[r];
  }
  out->triangles = disk_vertex;  // corner k of triangle t is the origin of half-edge 3t + k

  std::vector<uint32_t> position(nh, kNone);
  uint32_t boundary_count = 0, first = kNone;
  for (uint32_t h = 0; h < nh; ++h)
    if (open(h)) boundary_count += 1, first = first == kNone ? h : first;
  if (first == kNone) return internal("the cut leaves no boundary");
  std::vector<uint32_t> loop;
  for (uint32_t x = first, step = 0; step < boundary_count; ++step) {
    if (x == kNone || position[x] != kNone) break;
    position[x] = uint32_t(loop.size());
    loop.push_back(x);
    x = next_boundary(s, x, open, nh);
  }
  if (loop.size() != boundary_count)
    return internal("the boundary is not a single loop (" + std::to_string(loop.size()) + " of " +
                    std::to_string(boundary_count) + " boundary edges in the first loop)");
  if (next_boundary(s, loop.back(), open, nh) != first) return internal("the boundary loop does not close");

  out->boundary_loop.resize(loop.size());
  out->boundary_mate.resize(loop.size());
  std::vector<uint8_t> on_loop(out->original_vertex.size(), 0);
  for (size_t i = 0; i < loop.size(); ++i) {
    const uint32_t h = loop[i], v = disk_vertex[h];
    if (on_loop[v]++) return internal("disk vertex " + std::to_string(v) + " appears twice on the boundary loop");
    out->boundary_loop[i] = v;
    out->boundary_mate[i] = s.twin[h] == kNone ? -1 : int32_t(position[s.twin[h]]);
    if (s.twin[h] != kNone && position[s.twin[h]] == kNone)
      return internal("a cut edge has one side off the boundary loop");
  }
  // Euler characteristic of the disk: V - E + F == 1.
  const int64_t interior_edges = (int64_t(nh) - boundary_count) / 2;
  const int64_t chi = int64_t(out->original_vertex.size()) - (interior_edges + boundary_count) + nh / 3;
  if (chi != 1) return internal("the opened mesh has Euler characteristic " + std::to_string(chi) + ", not 1");
  return Status::Ok();
}

}  // namespace

Status cut_to_disk(const GimTriMesh& mesh, DiskCut* out, const std::function<void(double)>& progress,
                   GimCutStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  if (Status st = check_triangles(mesh); !st.ok()) return st;
  Surface s;
  if (Status st = pair_half_edges(mesh, &s); !st.ok()) return st;
  uint32_t pinched = 0;
  split_fans(mesh, &s, &pinched);
  build_edges(&s);
  const uint32_t nt = uint32_t(mesh.triangle_count());
  if (Status st = check_connected(s, nt); !st.ok()) return st;
  report(progress, 0.1);

  const uint32_t loops = count_boundary_loops(s);
  const int64_t chi = int64_t(s.vertex_count) - int64_t(s.edge_he.size()) + nt;
  if ((2 - int64_t(loops) - chi) % 2 != 0 || 2 - int64_t(loops) - chi < 0)
    return internal("Euler characteristic " + std::to_string(chi) + " with " + std::to_string(loops) +
                    " boundary loops is not an orientable surface");
  DiskCut disk;
  disk.genus = int((2 - int64_t(loops) - chi) / 2);
  disk.input_boundary_loops = int(loops);
  disk.split_fan_vertices = pinched;

  std::vector<uint8_t> cut(s.edge_he.size(), 0);
  GimCutStats st;
  if (disk.genus == 0 && loops == 0) {
    long_path_cut(s, &cut);
  } else if (!(disk.genus == 0 && loops == 1)) {
    gu_cut_graph(s, &cut);
    report(progress, 0.4);
    for (uint32_t e = 0; e < cut.size(); ++e) st.cut_length_before += cut[e] ? s.length(e) : 0;
    st.cut_paths = uint32_t(cut_paths(s, cut).size());
    st.paths_straightened = straighten_cut(s, &cut, progress);
  }
  report(progress, 0.8);
  for (uint32_t e = 0; e < cut.size(); ++e) {
    disk.cut_edge_count += cut[e];
    st.cut_length += cut[e] ? s.length(e) : 0;
  }
  if (st.cut_length_before == 0) st.cut_length_before = st.cut_length;
  if (Status r = open_along_cut(s, cut, &disk); !r.ok()) return r;
  {
    std::vector<uint32_t> degree(s.vertex_count, 0);
    for (uint32_t e = 0; e < cut.size(); ++e)
      if (cut[e] || s.boundary_edge(e)) ++degree[s.vertex[s.edge_he[e]]], ++degree[s.dest(s.edge_he[e])];
    for (uint32_t d : degree) st.cut_nodes += d != 0 && d != 2;
  }
  *out = std::move(disk);
  std::vector<uint8_t> referenced(mesh.vertex_count(), 0);
  for (uint32_t v : mesh.triangles) referenced[v] = 1;
  st.vertices_used = s.vertex_count;
  st.unreferenced_vertices = uint32_t(std::count(referenced.begin(), referenced.end(), 0));
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  report(progress, 1.0);
  return Status::Ok();
}

GimTriMesh gim_mesh_from(const Mesh& mesh, size_t* polygons_split) {
  GimTriMesh out;
  out.positions.assign(mesh.positions.begin(), mesh.positions.end());
  size_t split = 0, first = 0;
  for (uint32_t d : mesh.face_sizes) {
    split += d > 3;
    for (uint32_t k = 1; k + 1 < d; ++k)
      out.triangles.insert(out.triangles.end(),
                           {mesh.corners[first], mesh.corners[first + k], mesh.corners[first + k + 1]});
    first += d;
  }
  if (polygons_split) *polygons_split = split;
  return out;
}

}  // namespace qmc
