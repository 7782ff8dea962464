// The boundary of a triangle mesh as curves; see surface_rim.h.
#include "geometry/surface_rim.h"

#include <algorithm>
#include <map>
#include <utility>

#include "common/union_find.h"

namespace qmc {
namespace {

// The directed edges (a, b) of faces whose reverse (b, a) is in no face.
std::vector<std::pair<uint32_t, uint32_t>> boundary_edges(const LoopMesh& mesh) {
  std::vector<std::pair<uint32_t, uint32_t>> directed;
  directed.reserve(mesh.triangles.size());
  for (size_t f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < 3; ++k) directed.push_back({mesh.triangles[3 * f + k], mesh.triangles[3 * f + (k + 1) % 3]});
  std::vector<std::pair<uint32_t, uint32_t>> sorted = directed;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::pair<uint32_t, uint32_t>> out;
  for (const auto& [a, b] : directed)
    if (!std::binary_search(sorted.begin(), sorted.end(), std::make_pair(b, a))) out.push_back({a, b});
  return out;
}

// Per control vertex, its boundary loop's smallest vertex (kNoVertex inside).
std::vector<uint32_t> control_loops(const LoopMesh& control, const LoopEdges& edges) {
  UnionFind loop(control.vertex_count());
  for (uint32_t e = 0; e < edges.edge_count(); ++e)
    if (edges.is_boundary(e)) loop.unite(edges.a[e], edges.b[e]);
  std::vector<uint32_t> of(control.vertex_count(), kNoVertex);
  for (uint32_t v = 0; v < control.vertex_count(); ++v)
    if (edges.boundary_prev[v] != kNoVertex) of[v] = loop.find(v);
  return of;
}

}  // namespace

SurfaceRim::SurfaceRim(const LoopMesh& mesh) {
  const std::vector<std::pair<uint32_t, uint32_t>> edges = boundary_edges(mesh);
  if (edges.empty()) return;
  UnionFind loop(mesh.vertex_count());
  for (const auto& [a, b] : edges) loop.unite(a, b);
  std::map<uint32_t, uint32_t> index_of_root;
  std::vector<std::vector<Triangle3d>> per_loop;
  std::vector<Triangle3d> all;
  for (const auto& [a, b] : edges) {
    const auto [it, added] = index_of_root.insert({loop.find(a), uint32_t(per_loop.size())});
    if (added) per_loop.emplace_back();
    const Vec3d from = position_of(mesh.positions, a), to = position_of(mesh.positions, b);
    const Triangle3d segment{from, to, to};
    per_loop[it->second].push_back(segment);
    all.push_back(segment);
    loop_of_edge_.push_back(it->second);
  }
  all_ = TriangleBvh(all);
  for (const auto& segments : per_loop) loops_.emplace_back(segments);
}

uint32_t SurfaceRim::nearest_loop(const Vec3d& p) const { return loop_of_edge_[all_.closest_point(p).triangle]; }

Vec3d SurfaceRim::nearest_on_loop(uint32_t loop, const Vec3d& p) const { return loops_[loop].closest_point(p).point; }

RimAnchors rim_anchors(const SurfaceRim& rim, const LoopMesh& control, const LoopEdges& edges) {
  const uint32_t n = control.vertex_count();
  RimAnchors a;
  a.loop.assign(n, kNoVertex);
  a.anchor.resize(n);
  a.reach2.assign(n, 0);
  if (rim.empty()) return a;
  const std::vector<uint32_t> loop_of = control_loops(control, edges);
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> votes;  // (control loop, rim loop) -> vertices
  for (uint32_t v = 0; v < n; ++v)
    if (loop_of[v] != kNoVertex) ++votes[{loop_of[v], rim.nearest_loop(position_of(control.positions, v))}];
  std::map<uint32_t, std::pair<uint32_t, uint32_t>> winner;  // control loop -> (votes, rim loop)
  for (const auto& [key, count] : votes) {
    const auto [it, added] = winner.insert({key.first, {count, key.second}});
    if (!added && count > it->second.first) it->second = {count, key.second};
  }
  for (uint32_t v = 0; v < n; ++v) {
    if (loop_of[v] == kNoVertex) continue;
    a.loop[v] = winner[loop_of[v]].second;
    a.anchor[v] = rim.nearest_on_loop(a.loop[v], position_of(control.positions, v));
  }
  for (uint32_t v = 0; v < n; ++v) {
    if (loop_of[v] == kNoVertex) continue;
    const Vec3d before = a.anchor[edges.boundary_prev[v]] - a.anchor[v];
    const Vec3d after = a.anchor[edges.boundary_next[v]] - a.anchor[v];
    a.reach2[v] = kRimReach * kRimReach * std::max(dot(before, before), dot(after, after));
  }
  return a;
}

Vec3d rim_target(const SurfaceRim& rim, const RimAnchors& anchors, uint32_t v, const Vec3d& limit) {
  const Vec3d nearest = rim.nearest_on_loop(anchors.loop[v], limit);
  const Vec3d from_anchor = nearest - anchors.anchor[v];
  return dot(from_anchor, from_anchor) <= anchors.reach2[v] ? nearest : anchors.anchor[v];
}

}  // namespace qmc
