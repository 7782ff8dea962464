// Cutting a triangle mesh into a manifold oriented one (manifold_cut.h):
// corners of a vertex in the two faces of a joined edge are one fan, the
// rule of spec 12.5's manifold check, and each fan gets its own vertex.
#include "geometry/manifold_cut.h"

#include <algorithm>
#include <array>
#include <vector>

#include "common/union_find.h"

namespace qmc {
namespace {

// The faces kept: no repeated vertex, no second copy of a vertex set.
std::vector<uint32_t> faces_kept(const LoopMesh& mesh, ManifoldCut* cut) {
  const std::vector<std::array<uint32_t, 4>> keys = faces_by_vertex_set(mesh);
  cut->faces_without_area = mesh.face_count() - uint32_t(keys.size());
  std::vector<uint32_t> kept;
  kept.reserve(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    if (i > 0 && std::equal(keys[i].begin(), keys[i].begin() + 3, keys[i - 1].begin())) {
      ++cut->duplicate_faces;
      continue;
    }
    kept.push_back(keys[i][3]);
  }
  std::sort(kept.begin(), kept.end());  // input order
  return kept;
}

struct HalfEdge {
  uint64_t key;     // min << 32 | max of its two vertices
  uint32_t corner;  // 3 f + k: the edge runs from corner k to corner k + 1 of f
  bool operator<(const HalfEdge& o) const { return key != o.key ? key < o.key : corner < o.corner; }
};

// Joins the corners of each vertex across every edge of exactly two faces
// that run it opposite ways; counts the other edges, which are cut.
void join_fans(const std::vector<uint32_t>& triangles, UnionFind* fans, ManifoldCut* cut) {
  std::vector<HalfEdge> half(triangles.size());
  for (uint32_t c = 0; c < triangles.size(); ++c) {
    const uint32_t v = triangles[c], w = triangles[c - c % 3 + (c + 1) % 3];
    half[c] = {v < w ? (uint64_t(v) << 32 | w) : (uint64_t(w) << 32 | v), c};
  }
  std::sort(half.begin(), half.end());
  for (size_t i = 0; i < half.size();) {
    size_t j = i + 1;
    while (j < half.size() && half[j].key == half[i].key) ++j;
    const uint32_t c = half[i].corner, d = half[j - 1].corner;
    const auto next = [](uint32_t corner) { return corner - corner % 3 + (corner + 1) % 3; };
    if (j - i == 2 && triangles[c] == triangles[next(d)]) {
      fans->unite(c, next(d));
      fans->unite(next(c), d);
    } else if (j - i > 1) {
      ++cut->edges_cut;
    }
    i = j;
  }
}

}  // namespace

std::vector<std::array<uint32_t, 4>> faces_by_vertex_set(const LoopMesh& mesh) {
  std::vector<std::array<uint32_t, 4>> keys;
  keys.reserve(mesh.face_count());
  for (uint32_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t* t = &mesh.triangles[3 * size_t(f)];
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    std::array<uint32_t, 4> k = {t[0], t[1], t[2], f};
    std::sort(k.begin(), k.begin() + 3);
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

ManifoldCut cut_to_manifold(const LoopMesh& mesh, LoopMesh* out) {
  ManifoldCut cut;
  const std::vector<uint32_t> kept = faces_kept(mesh, &cut);
  out->triangles.resize(3 * kept.size());
  for (size_t i = 0; i < kept.size(); ++i)
    std::copy_n(mesh.triangles.begin() + 3 * std::ptrdiff_t(kept[i]), 3, out->triangles.begin() + 3 * std::ptrdiff_t(i));
  UnionFind fans(out->triangles.size());
  join_fans(out->triangles, &fans, &cut);

  // A vertex keeps its number for the fan of its first corner; each other
  // fan is a new vertex at the end, in the order its first corner comes.
  out->positions = mesh.positions;
  std::vector<uint32_t> fan_vertex(out->triangles.size(), kNoVertex);
  std::vector<uint8_t> numbered(mesh.vertex_count(), 0);
  for (uint32_t c = 0; c < out->triangles.size(); ++c) {
    const uint32_t v = out->triangles[c], fan = fans.find(c);
    if (fan_vertex[fan] == kNoVertex) {
      if (!numbered[v]) {
        numbered[v] = 1;
        fan_vertex[fan] = v;
      } else {
        fan_vertex[fan] = out->vertex_count();
        out->positions.insert(out->positions.end(), mesh.positions.begin() + 3 * std::ptrdiff_t(v),
                              mesh.positions.begin() + 3 * std::ptrdiff_t(v) + 3);
        ++cut.vertices_added;
      }
    }
    out->triangles[c] = fan_vertex[fan];
  }
  return cut;
}

}  // namespace qmc
