// Spirale Reversi for polygons, spec/qmc-format.md 5.4.5.
//
// The state is that of method 1 (5.3.6): loops as doubly linked lists of
// nodes naming temporary vertices, a loop stack, an inner-vertex stack and a
// union-find that merges the two nodes of an anchor split between two
// loops. One operation handles every face shape: pop one loop per detour
// beyond the first, cut the free vertices out of each detour's loop, and
// join the remaining paths with the edge gaps into the loop the encoder saw
// before the face. Every count used to index is checked first.
#include "decoder/polygon_spirale_reversi.h"

#include <algorithm>

#include <string>

#include "decoder/loop_nodes.h"

namespace qmc {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

Status invalid(size_t face, const std::string& why) {
  return Status(ErrorCode::kBadSymbol, "CONN: polygon face symbol " + std::to_string(face) + " " + why);
}

struct Loop {
  uint32_t gate = kNone;
  uint64_t length = 0;
};

// One detour gap of the face being undone (5.4.5).
struct Detour {
  uint32_t start = kNone, end = kNone;  // s and t
  uint32_t free_first = 0;              // index into free_nodes_
  uint64_t path_edges = 0;              // n - f - 1
};

class PolygonSpiraleReversi {
 public:
  // Capacities: the corners (0: not known yet, codings 7 and 8) and the coded
  // faces of the largest component; a face has at least 3 corners.
  PolygonSpiraleReversi(size_t node_capacity, size_t face_capacity) {
    nodes_.reserve(node_capacity);
    faces_at_.reserve(node_capacity);
    inner_.reserve(node_capacity);
    // Some room beyond 3 corners a face for larger faces (closed holes).
    face_vertices_.reserve(std::max(node_capacity, 3 * face_capacity + face_capacity / 8));
    face_degrees_.reserve(face_capacity);
  }

  // Counts each vertex's faces for gate_context() (codings 7 and 8 only: it costs
  // a find per corner).
  void count_faces() { counting_ = true; }
  // Section 5.4.10: the face counts at the gate node and its neighbours.
  GateContext gate_context();
  // Undoes face `index` of `shapes`, coded face `f` of the stream (for
  // messages).
  Status apply(const FaceShapes& shapes, size_t index, size_t f);
  // Ends a component whose first face has degree d: labels its vertices
  // from `first_label` and appends its faces to the surface; with no
  // surface (the encoder's context run) only checks that it closes.
  Status finish_component(uint32_t d, size_t first_coded, size_t coded, PolygonSurface* surface);
  // Section 5.4.5's last check, once every component is finished.
  Status check_directed_edges(const PolygonSurface& s);

 private:
  // Every node starts a vertex of no faces yet (5.4.10).
  uint32_t new_node() {
    if (counting_) faces_at_.push_back(0);
    return nodes_.new_node();
  }
  void link(uint32_t a, uint32_t b) { nodes_.link(a, b); }
  uint32_t find(uint32_t v) { return nodes_.find(v); }
  void merge(uint32_t kept, uint32_t gone);
  uint32_t capped_count(uint32_t node);
  void count_last_face(uint32_t d);

  Status whole_loop(uint32_t d);
  Status apply_triangle(size_t f, bool anchor, bool first_gap_edge, bool second_gap_edge);
  void add_triangle(uint32_t g0, uint32_t g1, uint32_t w);
  Status open_detour(size_t f, const Loop& loop, uint32_t free_count, Detour* detour);
  Status label_component(uint32_t d, size_t coded, PolygonSurface* surface);
  void clear_component();

  LoopNodes nodes_;
  std::vector<uint32_t>&prev_ = nodes_.prev, &next_ = nodes_.next, &vertex_ = nodes_.vertex, &parent_ = nodes_.parent;
  Loop current_;
  std::vector<Loop> loops_;
  std::vector<uint32_t> inner_;  // inner-vertex stack
  // Faces in the order they are undone: vertices (temporary ids), degrees.
  std::vector<uint32_t> face_vertices_, face_degrees_;
  // Scratch, reused across faces.
  std::vector<uint32_t> free_count_, free_nodes_, anchor_;
  std::vector<Detour> detours_;
  bool counting_ = false;
  std::vector<uint32_t> faces_at_;  // per vertex root: faces made with it (5.4.10); one per node
  std::vector<uint32_t> label_;     // per vertex root: its surface label (codings 0 - 5)
};

// Merged vertices pool their faces: no face has both (5.4.5: faces have
// distinct vertices), so the sum is the merged vertex's count.
void PolygonSpiraleReversi::merge(uint32_t kept, uint32_t gone) {
  if (!counting_) return nodes_.merge(kept, gone);
  const uint32_t a = find(vertex_[kept]), b = find(vertex_[gone]);
  if (a == b) return;
  faces_at_[a] += faces_at_[b];
  parent_[b] = a;
}

uint32_t PolygonSpiraleReversi::capped_count(uint32_t node) {
  const uint32_t n = faces_at_[find(vertex_[node])];
  return n < kGateCountCap ? n : kGateCountCap;
}

GateContext PolygonSpiraleReversi::gate_context() {
  const uint32_t h = current_.gate;
  if (h == kNone) return GateContext{};
  return GateContext{capped_count(h), capped_count(next_[h]), capped_count(prev_[h])};
}

void PolygonSpiraleReversi::count_last_face(uint32_t d) {
  for (size_t i = face_vertices_.size() - d; i < face_vertices_.size(); ++i) ++faces_at_[find(face_vertices_[i])];
}

Status PolygonSpiraleReversi::whole_loop(uint32_t d) {
  if (current_.gate != kNone) loops_.push_back(current_);
  const uint32_t first = new_node();
  uint32_t last = first;
  face_vertices_.push_back(vertex_[first]);
  for (uint32_t i = 1; i < d; ++i) {
    const uint32_t n = new_node();
    link(last, n);
    face_vertices_.push_back(vertex_[n]);
    last = n;
  }
  link(last, first);
  current_ = {first, d};
  face_degrees_.push_back(d);
  if (counting_) count_last_face(d);
  return Status::Ok();
}

// Out of line so that open_detour, once per face, stays small enough to inline.
Status detour_too_long(size_t f, const Loop& loop, uint32_t free_count) {
  return invalid(f, "has a detour of " + std::to_string(free_count) + " free vertices on a loop of only " +
                        std::to_string(loop.length) + " edges");
}

// 5.4.5: a detour of `free_count` free vertices needs a loop of free_count + 2 edges at least.
Status check_detour(size_t f, const Loop& loop, uint32_t free_count) {
  if (loop.length < uint64_t(free_count) + 2) return detour_too_long(f, loop, free_count);
  return Status::Ok();
}

Status PolygonSpiraleReversi::open_detour(size_t f, const Loop& loop, uint32_t free_count, Detour* detour) {
  if (Status s = check_detour(f, loop, free_count); !s.ok()) return s;
  detour->free_first = uint32_t(free_nodes_.size());
  uint32_t node = loop.gate;
  for (uint32_t i = 0; i < free_count; ++i) {
    free_nodes_.push_back(node);
    node = prev_[node];
  }
  detour->end = node;
  detour->start = next_[loop.gate];
  detour->path_edges = loop.length - free_count - 1;
  return Status::Ok();
}

void PolygonSpiraleReversi::add_triangle(uint32_t g0, uint32_t g1, uint32_t w) {
  const uint32_t a = vertex_[g0], b = vertex_[g1], c = vertex_[w];
  face_vertices_.push_back(a);
  face_vertices_.push_back(b);
  face_vertices_.push_back(c);
  face_degrees_.push_back(3);
  if (!counting_) return;
  // count_last_face(3) with the vertices at hand: re-reading them from
  // face_vertices_ cost stanford-bunny's decode 1 % more instructions.
  ++faces_at_[find(a)];
  ++faces_at_[find(b)];
  ++faces_at_[find(c)];
}

// The five triangle symbols (13..17) of apply() below, worked out for one
// anchor or one free vertex: the same nodes, links, merges, checks and
// faces, without the per-face scratch of the general case (a detour's
// loop is only checked to be long enough: check_detour).
Status PolygonSpiraleReversi::apply_triangle(size_t f, bool anchor, bool first_gap_edge, bool second_gap_edge) {
  if (anchor && first_gap_edge && second_gap_edge) return whole_loop(3);  // 14
  if (current_.gate == kNone) return invalid(f, "has a detour but there is no boundary to attach to");
  const uint32_t h = current_.gate;
  if (!anchor) {  // 13: the gate node's vertex becomes inner
    if (Status s = check_detour(f, current_, 1); !s.ok()) return s;
    const uint32_t before = prev_[h], after = next_[h];
    link(before, after);
    current_ = {before, current_.length - 1};
    add_triangle(before, after, h);
    inner_.push_back(vertex_[h]);
    return Status::Ok();
  }
  if (!first_gap_edge && !second_gap_edge) {  // 17: joins the current loop and the top of the stack
    if (loops_.empty()) return invalid(f, "needs 1 loops from a stack of 0");
    if (Status s = check_detour(f, current_, 0); !s.ok()) return s;
    const Loop popped = loops_.back();
    loops_.pop_back();
    if (Status s = check_detour(f, popped, 0); !s.ok()) return s;
    const uint32_t h2 = popped.gate, s1 = next_[h], s2 = next_[h2];
    link(h, next_[s2]);
    merge(h, s2);
    link(h2, s1);
    current_ = {h2, current_.length + popped.length - 1};
    add_triangle(h2, s1, h);
    return Status::Ok();
  }
  if (Status s = check_detour(f, current_, 0); !s.ok()) return s;
  const uint32_t fresh = new_node(), after = next_[h];
  if (first_gap_edge) {  // 15: a new vertex before the gate edge's end
    link(fresh, after);
    link(h, fresh);
    current_ = {h, current_.length + 1};
    add_triangle(h, fresh, after);
  } else {  // 16: a new vertex after the gate node
    link(h, fresh);
    link(fresh, after);
    current_ = {fresh, current_.length + 1};
    add_triangle(fresh, after, h);
  }
  return Status::Ok();
}

Status PolygonSpiraleReversi::apply(const FaceShapes& shapes, size_t index, size_t f) {
  const uint32_t d = shapes.degree[index], m = d - 2, gaps = shapes.gap_count(index);
  const uint8_t* status = &shapes.status[shapes.status_begin[index]];
  const uint8_t* edge = &shapes.gap_is_edge[shapes.gap_begin[index]];
  if (d == 3) return apply_triangle(f, status[0] != 0, edge[0] != 0, status[0] ? edge[1] != 0 : false);
  free_count_.assign(gaps, 0);
  for (uint32_t i = 0, g = 0; i < m; ++i) status[i] ? ++g : ++free_count_[g];
  uint32_t detour_count = 0;
  for (uint32_t g = 0; g < gaps; ++g) detour_count += edge[g] ? 0 : 1;
  if (detour_count == 0) return whole_loop(d);
  if (current_.gate == kNone) return invalid(f, "has a detour but there is no boundary to attach to");
  if (loops_.size() < detour_count - 1)
    return invalid(f, "needs " + std::to_string(detour_count - 1) + " loops from a stack of " +
                          std::to_string(loops_.size()));

  // Open every detour's loop: the current one for the first, pops after.
  detours_.assign(gaps, Detour{});
  free_nodes_.clear();
  bool first = true;
  for (uint32_t g = 0; g < gaps; ++g) {
    if (edge[g]) continue;
    Loop loop = current_;
    if (!first) {
      loop = loops_.back();
      loops_.pop_back();
    }
    first = false;
    if (Status s = open_detour(f, loop, free_count_[g], &detours_[g]); !s.ok()) return s;
  }

  // Anchor nodes a_0 = g1 .. a_(k+1) = g0 (5.4.5).
  anchor_.assign(gaps + 1, kNone);
  for (uint32_t i = 0; i <= gaps; ++i) {
    if (i >= 1 && !edge[i - 1]) anchor_[i] = detours_[i - 1].end;
    else if (i < gaps && !edge[i]) anchor_[i] = detours_[i].start;
    else anchor_[i] = new_node();
  }
  uint64_t length = 1;
  for (uint32_t g = 0; g < gaps; ++g) {
    if (edge[g]) {
      link(anchor_[g], anchor_[g + 1]);
      ++length;
      continue;
    }
    const Detour& det = detours_[g];
    if (det.start != anchor_[g]) {  // the previous gap was a detour too: s leaves
      link(anchor_[g], next_[det.start]);
      merge(anchor_[g], det.start);
    }
    length += det.path_edges;
  }
  const uint32_t g0 = anchor_[gaps], g1 = anchor_[0];
  link(g0, g1);
  current_ = {g0, length};

  // The face (g0, g1, w1 .. wm), then its free vertices on the inner stack,
  // last first so that they come off in cycle order.
  face_vertices_.push_back(vertex_[g0]);
  face_vertices_.push_back(vertex_[g1]);
  const size_t w_begin = face_vertices_.size();
  for (uint32_t i = 0, g = 0, k = 0; i < m; ++i) {
    if (status[i]) {
      face_vertices_.push_back(vertex_[anchor_[++g]]);
      k = 0;
    } else {
      face_vertices_.push_back(vertex_[free_nodes_[detours_[g].free_first + k++]]);
    }
  }
  for (uint32_t i = m; i-- > 0;)
    if (!status[i]) inner_.push_back(face_vertices_[w_begin + i]);
  face_degrees_.push_back(d);
  if (counting_) count_last_face(d);
  return Status::Ok();
}

Status PolygonSpiraleReversi::finish_component(uint32_t d, size_t first_coded, size_t coded,
                                               PolygonSurface* surface) {
  if (!loops_.empty() || current_.gate == kNone || current_.length != d)
    return Status(ErrorCode::kBadSymbol, "CONN: component ending at face symbol " + std::to_string(first_coded) +
                                             " does not close on its first face of degree " + std::to_string(d));
  if (surface != nullptr)
    if (Status s = label_component(d, coded, surface); !s.ok()) return s;
  clear_component();
  return Status::Ok();
}

Status PolygonSpiraleReversi::label_component(uint32_t d, size_t coded, PolygonSurface* surface) {
  // Per vertex root. The face counts (codings 7 and 8), one per node as
  // this is, are no longer needed: their pages serve again.
  std::vector<uint32_t>& label = counting_ ? faces_at_ : label_;
  label.assign(parent_.size(), kNone);
  const uint32_t base = surface->labels;
  uint32_t next_label = base;
  auto give = [&](uint32_t v) {
    uint32_t& l = label[find(v)];
    if (l != kNone) return false;
    l = next_label++;
    return true;
  };
  uint32_t node = current_.gate;
  for (uint32_t i = 0; i < d; ++i, node = next_[node]) {
    if (!give(vertex_[node])) return Status(ErrorCode::kBadSymbol, "CONN: a vertex is twice on a component's first face");
  }
  while (!inner_.empty()) {
    if (!give(inner_.back())) return Status(ErrorCode::kBadSymbol, "CONN: a vertex would get two labels");
    inner_.pop_back();
  }
  // First face (c0, c1, c2, .., c(d-1)) = loop labels (1, 0, d - 1, .., 2).
  surface->face_degree.push_back(d);
  surface->face_degree.insert(surface->face_degree.end(), face_degrees_.rbegin(), face_degrees_.rend());
  std::vector<uint32_t> first_face{base + 1, base};
  for (uint32_t i = d - 1; i >= 2; --i) first_face.push_back(base + i);
  // Coded faces in traversal order, the reverse of the order undone: the
  // labels in place, all reversed, then each face turned back.
  for (uint32_t& v : face_vertices_) v = label[find(v)];
  std::reverse(face_vertices_.begin(), face_vertices_.end());
  for (size_t k = coded, begin = 0; k-- > 0; begin += face_degrees_[k])
    std::reverse(face_vertices_.begin() + begin, face_vertices_.begin() + begin + face_degrees_[k]);
  face_vertices_.insert(face_vertices_.begin(), first_face.begin(), first_face.end());
  if (surface->corners.capacity() == 0)  // codings 7 and 8: the first component's faces stay where they are
    surface->corners.swap(face_vertices_);
  else
    surface->corners.insert(surface->corners.end(), face_vertices_.begin(), face_vertices_.end());
  surface->labels = next_label;
  return Status::Ok();
}

// The next component starts from nothing.
void PolygonSpiraleReversi::clear_component() {
  nodes_.clear();
  current_ = Loop{};
  face_vertices_.clear();
  face_degrees_.clear();
  faces_at_.clear();
  inner_.clear();
}

// Section 5.4.5: no directed edge twice among the surface's faces. After the
// last component, in the node tables' memory (their pages faulted in already).
Status PolygonSpiraleReversi::check_directed_edges(const PolygonSurface& s) {
  const uint32_t n = s.labels;
  std::vector<uint32_t>&start = prev_, &fill = next_, &mark = vertex_;
  start.assign(size_t(n) + 1, 0);
  for (uint32_t v : s.corners) ++start[v + 1];
  for (uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> target(s.corners.size());
  fill.assign(start.begin(), start.end() - 1);
  size_t begin = 0;
  for (uint32_t d : s.face_degree) {
    if (d == 0) continue;  // never (5.4.1: 3 corners or more), but face[d - 1] must stay in bounds
    const uint32_t* face = &s.corners[begin];
    for (uint32_t i = 0; i + 1 < d; ++i) target[fill[face[i]]++] = face[i + 1];
    target[fill[face[d - 1]]++] = face[0];
    begin += d;
  }
  mark.assign(n, kNone);
  for (uint32_t v = 0; v < n; ++v)
    for (uint32_t k = start[v]; k < start[v + 1]; ++k) {
      if (mark[target[k]] == v)
        return Status(ErrorCode::kBadSymbol, "CONN: the surface uses edge " + std::to_string(v) + "-" +
                                                 std::to_string(target[k]) + " twice in one direction");
      mark[target[k]] = v;
    }
  return Status::Ok();
}

// Codings 0 .. 5: every symbol was read before Spirale Reversi starts.
class StoredFaces : public FaceSymbolSource {
 public:
  explicit StoredFaces(const FaceShapes& shapes) : shapes_(shapes) {}
  Status face(const GateContext&, size_t f, const FaceShapes** shapes, size_t* index) override {
    *shapes = &shapes_;
    *index = f;
    return Status::Ok();
  }

 private:
  const FaceShapes& shapes_;
};

Status run_spirale_reversi(const std::vector<uint32_t>& components, const std::vector<uint32_t>& first_degree,
                           FaceSymbolSource* source, bool count_faces, size_t largest, size_t most_faces,
                           PolygonSurface* surface) {
  PolygonSpiraleReversi decoder{largest, most_faces};
  if (count_faces) decoder.count_faces();
  size_t first = 0, applied = 0;
  for (size_t c = 0; c < components.size(); ++c) {
    const size_t coded = components[c] - 1;
    for (size_t k = coded; k-- > 0; ++applied) {
      const FaceShapes* shapes = nullptr;
      size_t index = 0;
      const GateContext gate = count_faces ? decoder.gate_context() : GateContext{};
      if (Status s = source->face(gate, first + k, &shapes, &index); !s.ok()) return s;
      // Codings 7 and 8 stream the faces in the order they are applied (5.4.10);
      // the stored codings in the traversal's order, index = first + k.
      const size_t number = count_faces ? applied : index;
      if (Status s = decoder.apply(*shapes, index, number); !s.ok()) return s;
    }
    if (Status s = decoder.finish_component(first_degree[c], first, coded, surface); !s.ok()) return s;
    first += coded;
  }
  if (Status s = source->end(); !s.ok()) return s;
  return surface == nullptr ? Status::Ok() : decoder.check_directed_edges(*surface);
}

// The encoder's own symbols: its largest component's face count.
size_t largest_face_count(const std::vector<uint32_t>& components) {
  return components.empty() ? 0 : *std::max_element(components.begin(), components.end());
}

}  // namespace

Status polygon_spirale_reversi(const std::vector<uint32_t>& components, const std::vector<uint32_t>& first_degree,
                               const FaceShapes& shapes, PolygonSurface* surface) {
  *surface = PolygonSurface{};
  uint64_t largest = 0, most_faces = 0, all_corners = 0;  // nodes of a component: at most its corners
  for (size_t c = 0, f = 0; c < components.size(); ++c) {
    uint64_t corners = 0;
    for (uint32_t i = 1; i < components[c]; ++i, ++f) corners += shapes.degree[f];
    largest = std::max(largest, corners);
    most_faces = std::max<uint64_t>(most_faces, components[c]);
    // The coded faces only: their degrees are backed by the stream's bits
    // (5.4.3), a first face's degree is not until the spiral has built that face.
    all_corners += corners;
  }
  surface->face_degree.reserve(components.size() + shapes.size());
  surface->corners.reserve(size_t(all_corners));
  StoredFaces stored(shapes);
  return run_spirale_reversi(components, first_degree, &stored, false, size_t(largest), size_t(most_faces), surface);
}

Status polygon_spirale_reversi(const std::vector<uint32_t>& components, const std::vector<uint32_t>& first_degree,
                               FaceSymbolSource* source, size_t expected_faces, PolygonSurface* surface) {
  *surface = PolygonSurface{};
  surface->face_degree.reserve(expected_faces);
  // Nodes: about one a vertex, fewer than the faces of a closed mesh.
  return run_spirale_reversi(components, first_degree, source, true, expected_faces, expected_faces, surface);
}

Status polygon_spirale_contexts(const std::vector<uint32_t>& components, const std::vector<uint32_t>& first_degree,
                                FaceSymbolSource* source) {
  return run_spirale_reversi(components, first_degree, source, true, 0, largest_face_count(components), nullptr);
}

}  // namespace qmc
