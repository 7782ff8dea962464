// Surface preparation for the polygon coder (spec/qmc-format.md 5.4.9).
#include "encoder/polygon_surface.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include "common/union_find.h"
#include "encoder/edge_buckets.h"

namespace qmc {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

uint32_t find(std::vector<uint32_t>& parent, uint32_t v) { return union_find_root(parent, v); }

// Linear in the face's degree (a face may have millions of corners):
// `listed_by[v]` is the last face seen to list v.
bool repeats_a_vertex(const uint32_t* c, uint32_t d, uint32_t face, std::vector<uint32_t>* listed_by) {
  for (uint32_t i = 0; i < d; ++i) {
    if ((*listed_by)[c[i]] == face) return true;
    (*listed_by)[c[i]] = face;
  }
  return false;
}

// Pairs half-edges u->v and v->u that are the only ones of their direction,
// among those not yet paired. Linear however many faces share one edge: the
// unpaired half-edges are bucketed by their smaller endpoint (edge_buckets.h),
// and within a bucket tallied by their larger endpoint, as in the
// opposite-edge table of the quad coder.
void pair_unique_edges(PolygonSurfaceModel* s) {
  const uint32_t n = uint32_t(s->corners.size()), nv = s->vertex_count();
  auto low = [&](uint32_t h) { return std::min(s->corners[h], s->corners[s->next(h)]); };
  auto high = [&](uint32_t h) { return std::max(s->corners[h], s->corners[s->next(h)]); };
  std::vector<uint32_t> unpaired;
  unpaired.reserve(size_t(std::count(s->twin.begin(), s->twin.end(), kNone)));
  for (uint32_t h = 0; h < n; ++h)
    if (s->twin[h] == kNone) unpaired.push_back(h);
  const EdgeBuckets by_low = bucket_edges(nv, uint32_t(unpaired.size()), [&](uint32_t i) { return low(unpaired[i]); });
  // Per larger endpoint b, for the current smaller endpoint a: the half-edges
  // a->b and b->a seen, and the last of each.
  std::vector<uint32_t> tallied_for(nv, kNone), up_count(nv), down_count(nv), up(nv), down(nv);
  for (uint32_t a = 0; a < nv; ++a) {
    for (uint32_t k = by_low.begin[a]; k < by_low.begin[a + 1]; ++k) {
      const uint32_t h = unpaired[by_low.items[k]], b = high(h);
      if (tallied_for[b] != a) {
        tallied_for[b] = a;
        up_count[b] = down_count[b] = 0;
      }
      if (s->corners[h] == a) {
        ++up_count[b];
        up[b] = h;
      } else {
        ++down_count[b];
        down[b] = h;
      }
    }
    for (uint32_t k = by_low.begin[a]; k < by_low.begin[a + 1]; ++k) {
      const uint32_t b = high(unpaired[by_low.items[k]]);
      if (up_count[b] != 1 || down_count[b] != 1) continue;
      s->twin[up[b]] = down[b];
      s->twin[down[b]] = up[b];
    }
  }
}

// One vertex id per fan: corners joined through paired edges share it.
void split_fans(PolygonSurfaceModel* s) {
  const uint32_t n = uint32_t(s->corners.size());
  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (uint32_t h = 0; h < n; ++h) {
    const uint32_t t = s->twin[h];
    if (t == kNone || t < h) continue;
    // h: u->v at corner h (u); t: v->u at corner t (v).
    for (auto [a, b] : {std::make_pair(h, s->next(t)), std::make_pair(s->next(h), t)}) {
      const uint32_t ra = find(parent, a), rb = find(parent, b);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  }
  std::vector<uint32_t> first_fan(s->original.size(), kNone), id_of_fan(n, kNone);
  for (uint32_t c = 0; c < n; ++c) {
    const uint32_t v = s->corners[c], fan = find(parent, c);
    if (id_of_fan[fan] == kNone) {
      if (first_fan[v] == kNone) {
        first_fan[v] = fan;
        id_of_fan[fan] = v;
      } else {
        id_of_fan[fan] = uint32_t(s->original.size());
        s->original.push_back(s->original[v]);
        ++s->vertex_copies;
      }
    }
    s->corners[c] = id_of_fan[fan];
  }
}

// The face of `degree` corners `cycle[0 .. degree - 1]`.
uint32_t add_face(PolygonSurfaceModel* s, const uint32_t* cycle, uint32_t degree, uint32_t source) {
  const uint32_t f = s->face_count();
  const uint32_t begin = uint32_t(s->corners.size());
  for (uint32_t i = 0; i < degree; ++i) {
    s->corners.push_back(cycle[i]);
    s->twin.push_back(kNone);
    s->face_of.push_back(f);
    s->next_edge.push_back(i + 1 < degree ? begin + i + 1 : begin);
  }
  s->face_begin.push_back(uint32_t(s->corners.size()));
  s->source.push_back(source);
  return f;
}

// Closes every hole with a virtual face. At a fan's end there is exactly one
// unpaired half-edge leaving and one arriving.
std::string close_holes(PolygonSurfaceModel* s) {
  const uint32_t n = uint32_t(s->corners.size());
  std::vector<uint32_t> arriving(s->vertex_count(), kNone);
  for (uint32_t h = 0; h < n; ++h) {
    if (s->twin[h] != kNone) continue;
    const uint32_t v = s->corners[s->next(h)];
    if (arriving[v] != kNone) return "internal: two boundary edges arrive at one vertex copy";
    arriving[v] = h;
  }
  std::vector<uint32_t> cycle, sides;
  for (uint32_t h = 0; h < n; ++h) {
    if (s->twin[h] != kNone) continue;
    // The cap runs b -> a -> c ..., against the boundary half-edges.
    cycle.clear();
    sides.clear();
    uint32_t e = h;
    do {
      if (sides.size() > n) return "internal: a hole does not close";
      sides.push_back(e);
      cycle.push_back(s->corners[s->next(e)]);
      e = arriving[s->corners[e]];
      if (e == kNone) return "internal: a hole is open";
    } while (e != h);
    const uint32_t f = add_face(s, cycle.data(), uint32_t(cycle.size()), kVirtualFace);
    // Cap half-edge i runs cycle[i] -> cycle[i + 1], the reverse of sides[i].
    for (uint32_t i = 0; i < sides.size(); ++i) {
      s->twin[s->face_begin[f] + i] = sides[i];
      s->twin[sides[i]] = s->face_begin[f] + i;
    }
    ++s->holes;
  }
  return {};
}

// Faces of each component (through twins), components in order of their
// first face.
// The faces of the component of face f0, in breadth-first order from it,
// marked `id` in `component` (where none is marked `id` yet).
std::vector<uint32_t> faces_reached(const PolygonSurfaceModel& s, uint32_t f0, uint32_t id,
                                    std::vector<uint32_t>* component, size_t expected = 1) {
  std::vector<uint32_t> faces;
  faces.reserve(expected);
  faces.push_back(f0);
  (*component)[f0] = id;
  for (size_t i = 0; i < faces.size(); ++i)
    for (uint32_t h = s.face_begin[faces[i]]; h < s.face_begin[faces[i] + 1]; ++h) {
      const uint32_t g = s.face_of[s.twin[h]];
      if ((*component)[g] != id) {
        (*component)[g] = id;
        faces.push_back(g);
      }
    }
  return faces;
}

std::vector<std::vector<uint32_t>> components_of(const PolygonSurfaceModel& s) {
  std::vector<uint32_t> component(s.face_count(), kNone);
  std::vector<std::vector<uint32_t>> out;
  for (uint32_t f0 = 0; f0 < s.face_count(); ++f0)
    if (component[f0] == kNone) out.push_back(faces_reached(s, f0, uint32_t(out.size()), &component));
  return out;
}

int64_t euler_characteristic(const PolygonSurfaceModel& s, const std::vector<uint32_t>& faces,
                             std::vector<uint32_t>* seen_mark, uint32_t mark) {
  int64_t v = 0, e = 0;
  for (uint32_t f : faces)
    for (uint32_t h = s.face_begin[f]; h < s.face_begin[f + 1]; ++h) {
      ++e;
      uint32_t& m = (*seen_mark)[s.corners[h]];
      if (m != mark) {
        m = mark;
        ++v;
      }
    }
  return v - e / 2 + int64_t(faces.size());
}

// The arrays of non_separating_cycle, kept between calls and cleared only
// where a component used them: a surface may have a great many small
// components with a handle each, and fresh surface-sized arrays for each
// would make cutting them all quadratic.
struct CycleScratch {
  std::vector<uint32_t> up, depth, out_edge;  // per vertex; up and out_edge are written before read
  std::vector<uint8_t> in_tree, in_cotree;    // per half-edge
  std::vector<uint8_t> face_seen;             // per face
  std::vector<uint32_t> queue, face_queue;    // the two searches' queues, emptied by each

  // The surface grows as handles are cut.
  void fit(const PolygonSurfaceModel& s) {
    up.resize(s.vertex_count(), kNone);
    depth.resize(s.vertex_count(), kNone);
    out_edge.resize(s.vertex_count(), kNone);
    in_tree.resize(s.corners.size(), 0);
    in_cotree.resize(s.corners.size(), 0);
    face_seen.resize(s.face_count(), 0);
  }
  // Back to "unseen" for `faces`, before the cut changes their corners.
  void clear(const PolygonSurfaceModel& s, const std::vector<uint32_t>& faces) {
    for (uint32_t f : faces) {
      face_seen[f] = 0;
      for (uint32_t h = s.face_begin[f]; h < s.face_begin[f + 1]; ++h) {
        depth[s.corners[h]] = kNone;
        in_tree[h] = in_cotree[h] = 0;
      }
    }
  }
};

// A non-separating cycle (as half-edges, each with its face on the left):
// the fundamental cycle of a leftover edge of a tree-cotree decomposition.
std::vector<uint32_t> non_separating_cycle(const PolygonSurfaceModel& s, const std::vector<uint32_t>& faces,
                                           CycleScratch* scratch) {
  scratch->fit(s);
  std::vector<uint32_t>& up = scratch->up;
  std::vector<uint32_t>& depth = scratch->depth;
  std::vector<uint32_t>& out_edge = scratch->out_edge;
  // One half-edge leaving each vertex of the component.
  for (uint32_t f : faces)
    for (uint32_t h = s.face_begin[f]; h < s.face_begin[f + 1]; ++h) out_edge[s.corners[h]] = h;
  std::vector<uint8_t>& in_tree = scratch->in_tree;
  const uint32_t root = s.corners[s.face_begin[faces[0]]];
  std::vector<uint32_t>& queue = scratch->queue;
  queue.assign(1, root);
  depth[root] = 0;
  for (size_t i = 0; i < queue.size(); ++i) {
    const uint32_t v = queue[i];
    // Around v: leaving half-edges by rotation (twin, then next).
    const uint32_t start = out_edge[v];
    uint32_t h = start;
    do {
      const uint32_t w = s.corners[s.next(h)];
      if (depth[w] == kNone) {
        depth[w] = depth[v] + 1;
        up[w] = h;  // v -> w
        in_tree[h] = in_tree[s.twin[h]] = 1;
        queue.push_back(w);
      }
      h = s.next(s.twin[h]);
    } while (h != start);
  }
  // Dual tree over faces through edges not in the primal tree.
  std::vector<uint8_t>& face_seen = scratch->face_seen;
  std::vector<uint8_t>& in_cotree = scratch->in_cotree;
  std::vector<uint32_t>& fq = scratch->face_queue;
  fq.assign(1, faces[0]);
  face_seen[faces[0]] = 1;
  for (size_t i = 0; i < fq.size(); ++i)
    for (uint32_t h = s.face_begin[fq[i]]; h < s.face_begin[fq[i] + 1]; ++h) {
      if (in_tree[h]) continue;
      const uint32_t g = s.face_of[s.twin[h]];
      if (face_seen[g]) continue;
      face_seen[g] = 1;
      in_cotree[h] = in_cotree[s.twin[h]] = 1;
      fq.push_back(g);
    }
  // The leftover edge with the shortest fundamental cycle (by depths).
  uint32_t best = kNone;
  uint64_t best_len = UINT64_MAX;
  for (uint32_t f : faces)
    for (uint32_t h = s.face_begin[f]; h < s.face_begin[f + 1]; ++h) {
      if (in_tree[h] || in_cotree[h]) continue;
      const uint64_t len = uint64_t(depth[s.corners[h]]) + depth[s.corners[s.next(h)]];
      if (len < best_len) {
        best_len = len;
        best = h;
      }
    }
  if (best == kNone) return {};
  // best: a -> b. Cycle: b up to the common ancestor, then down to a, then a -> b.
  uint32_t a = s.corners[best], b = s.corners[s.next(best)];
  std::vector<uint32_t> from_b, from_a;  // half-edges
  while (depth[a] > depth[b]) { from_a.push_back(up[a]); a = s.corners[up[a]]; }
  while (depth[b] > depth[a]) { from_b.push_back(s.twin[up[b]]); b = s.corners[up[b]]; }
  while (a != b) {
    from_a.push_back(up[a]);
    a = s.corners[up[a]];
    from_b.push_back(s.twin[up[b]]);
    b = s.corners[up[b]];
  }
  // from_b: b -> parent(b) -> ... (upward); from_a reversed: ancestor -> ... -> a.
  std::vector<uint32_t> cycle{best};
  cycle.insert(cycle.end(), from_b.begin(), from_b.end());
  for (size_t i = from_a.size(); i-- > 0;) cycle.push_back(from_a[i]);
  return cycle;
}

// Cuts along `cycle` (half-edges v_i -> v_(i+1)); the faces on the right
// get copies of the cycle's vertices; both sides are closed by a seam.
void cut_handle(PolygonSurfaceModel* s, const std::vector<uint32_t>& cycle) {
  const uint32_t k = uint32_t(cycle.size());
  std::vector<uint32_t> copy(k), right_twin(k);
  for (uint32_t i = 0; i < k; ++i) right_twin[i] = s->twin[cycle[i]];
  for (uint32_t i = 0; i < k; ++i) {
    const uint32_t v = s->corners[cycle[i]];
    copy[i] = uint32_t(s->original.size());
    s->original.push_back(s->original[v]);
    // Rotate from the face left of the outgoing cycle edge; corners after
    // crossing the incoming cycle edge (into the right side) get the copy.
    const uint32_t incoming = cycle[(i + k - 1) % k];
    uint32_t h = cycle[i];
    bool right = false;
    do {
      if (right) s->corners[h] = copy[i];
      const uint32_t in = s->prev(h);
      if (in == incoming) right = true;
      h = s->twin[in];
    } while (h != cycle[i]);
  }
  std::vector<uint32_t> left(k), other(k);
  for (uint32_t j = 0; j < k; ++j) {
    left[j] = s->corners[cycle[(1 + k - j) % k]];  // a_j = v_(1 - j)
    other[j] = copy[j];                              // b_j = v_j'
  }
  const uint32_t a = add_face(s, left.data(), uint32_t(left.size()), kVirtualFace);
  const uint32_t b = add_face(s, other.data(), uint32_t(other.size()), kVirtualFace);
  for (uint32_t j = 0; j < k; ++j) {
    // a_j -> a_(j+1) = v_(1-j) -> v_(-j), the reverse of cycle[-j].
    const uint32_t ha = s->face_begin[a] + j, ci = (k - j) % k;
    s->twin[ha] = cycle[ci];
    s->twin[cycle[ci]] = ha;
    // b_j -> b_(j+1) = v_j' -> v_(j+1)', the reverse of the right face's edge.
    const uint32_t hb = s->face_begin[b] + j;
    s->twin[hb] = right_twin[j];
    s->twin[right_twin[j]] = hb;
  }
  s->seams.push_back({a, b, 1 % k});
  ++s->handles;
}

// Cuts every handle, one per component and round, in the order of the
// components' first faces. A cut keeps its component whole (the cycle does
// not separate it) and raises its Euler characteristic by 2; only that
// component's faces are listed again, in the order a new search of the whole
// surface would list them, so the cycles found are the same.
std::string cut_handles(PolygonSurfaceModel* s) {
  std::vector<std::vector<uint32_t>> components = components_of(*s);
  std::vector<uint32_t> mark(s->vertex_count(), kNone);
  std::vector<int64_t> chi(components.size());
  for (uint32_t c = 0; c < components.size(); ++c) chi[c] = euler_characteristic(*s, components[c], &mark, c);
  // Per face, the last listing that reached it: each listing has its own
  // number, so nothing is cleared between them.
  std::vector<uint32_t> listed(s->face_count(), kNone);
  uint32_t listing = 0;
  CycleScratch scratch;
  for (int round = 0;; ++round) {
    bool cut = false;
    for (uint32_t c = 0; c < components.size(); ++c) {
      if (chi[c] == 2) continue;
      if (chi[c] > 2 || chi[c] % 2 != 0) return "internal: a component has Euler characteristic " + std::to_string(chi[c]);
      const std::vector<uint32_t> cycle = non_separating_cycle(*s, components[c], &scratch);
      scratch.clear(*s, components[c]);
      if (cycle.size() < 3) return "internal: no cycle found through a handle";
      cut_handle(s, cycle);
      cut = true;
      const size_t faces = components[c].size() + 2;  // the two faces that close the cut
      listed.resize(s->face_count(), kNone);
      components[c] = faces_reached(*s, components[c][0], listing++, &listed, faces);
      if (components[c].size() != faces) return "internal: a handle's cut separated its component";
      chi[c] += 2;
    }
    if (!cut) break;
    if (round > 1 << 20) return "internal: handle cutting does not end";
  }
  return {};
}

}  // namespace

std::string build_polygon_surface(const Mesh& mesh, PolygonSurfaceModel* s) {
  *s = PolygonSurfaceModel{};
  s->original.resize(mesh.vertex_count());
  std::iota(s->original.begin(), s->original.end(), 0u);
  std::vector<uint32_t> listed_by(mesh.vertex_count(), kNone);
  s->corners.reserve(mesh.corners.size());
  s->twin.reserve(mesh.corners.size());
  s->face_of.reserve(mesh.corners.size());
  s->next_edge.reserve(mesh.corners.size());
  s->face_begin.reserve(mesh.face_count() + 1);
  s->source.reserve(mesh.face_count());
  for (uint32_t f = 0, begin = 0; f < mesh.face_count(); begin += mesh.face_sizes[f], ++f) {
    const uint32_t* c = &mesh.corners[begin];
    if (repeats_a_vertex(c, mesh.face_sizes[f], f, &listed_by)) {
      s->loose.push_back(f);
      continue;
    }
    add_face(s, c, mesh.face_sizes[f], f);
  }
  pair_unique_edges(s);
  split_fans(s);
  // Copies can make a cut edge unique again (5.4.9); without copies the
  // corners are unchanged and so is the pairing.
  if (s->vertex_copies > 0) pair_unique_edges(s);
  if (std::string why = close_holes(s); !why.empty()) return why;
  return cut_handles(s);
}

}  // namespace qmc
