// Spirale Reversi (seed 001 §3.3, Program 2), spec/qmc-format.md 5.3.6.
//
// State: the current boundary loop as a doubly linked list of nodes, each
// naming a (temporary) vertex; the active gate is the edge from the gate node
// to its successor. Loops split off by the encoder come back from the loop
// stack; the two copies of a vertex that a split shared are then merged
// (union-find). Vertices leaving the boundary go on the inner-vertex stack,
// which at the end yields them in the encoder's order. Every step checks
// what it relies on, so no input can index outside the pools.
#include "decoder/spirale_reversi_decoder.h"

#include <string>

#include "decoder/loop_nodes.h"

namespace qmc {
namespace {

constexpr uint32_t kNone = UINT32_MAX;

struct Loop {
  uint32_t gate = kNone;  // node whose edge to its successor is the active gate
  uint64_t length = 0;
};

class SpiraleReversi {
 public:
  explicit SpiraleReversi(size_t operations) {
    nodes_.reserve(4 * operations);
    quads_.reserve(4 * operations);
  }

  Status apply(int type);
  Status finish(bool closed, uint32_t vertex_count, Mesh* mesh);

 private:
  // Nodes and temporary vertices (loop_nodes.h); merge is spec 5.3.6's.
  uint32_t new_vertex() { return nodes_.new_vertex(); }
  uint32_t new_node(uint32_t vertex) { return nodes_.new_node(vertex); }
  void link(uint32_t a, uint32_t b) { nodes_.link(a, b); }
  uint32_t find(uint32_t v) { return nodes_.find(v); }
  void merge(uint32_t kept, uint32_t gone) { nodes_.merge(kept, gone); }
  void emit(uint32_t g0, uint32_t g1, uint32_t x, uint32_t y) {
    quads_.insert(quads_.end(), {vertex_[g0], vertex_[g1], vertex_[x], vertex_[y]});
  }

  Status need_current(int type) const;
  Status pop(int type, Loop* loop);

  // Q3 and Q9: a new node joins c to b, and a takes the place of d (d's
  // vertex merges into a's). Returns the new node.
  uint32_t splice_through_new_vertex(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const uint32_t n = new_node(new_vertex()), after = next_[d];
    link(c, n);
    link(n, b);
    link(a, after);
    merge(a, d);
    return n;
  }

  Status q1();
  Status grow(int type);       // Q2, Q4, Q6: two new vertices along the gate
  Status swap_corner(int type);  // Q5, Q12: one new vertex, one leaves
  Status q13();
  Status join_two(int type);   // Q3, Q7, Q9, Q10, Q11
  Status q8();

  LoopNodes nodes_;
  std::vector<uint32_t>&prev_ = nodes_.prev, &next_ = nodes_.next, &vertex_ = nodes_.vertex, &parent_ = nodes_.parent;
  std::vector<uint32_t> quads_;  // temporary vertices, 4 per quad, decoding order
  std::vector<uint32_t> inner_;  // inner-vertex stack
  std::vector<Loop> loops_;      // loop stack
  Loop current_;
};

// Spec 5.3.6: every directed edge at most once. Q13 links g0 -> g1, which a
// stream can ask for where the decoded part already joins g0 and g1 by an
// interior edge; the face list would then not be a manifold mesh. Linear:
// outgoing edges grouped per vertex, duplicates found with a marker array.
Status check_edges_unique(const Mesh& mesh, uint32_t vertices) {
  std::vector<uint32_t> start(size_t(vertices) + 1, 0);
  for (uint32_t v : mesh.corners) ++start[v + 1];
  for (uint32_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> target(mesh.corners.size()), fill(start.begin(), start.end() - 1);
  for (size_t f = 0; f < mesh.face_count(); ++f)
    for (int i = 0; i < 4; ++i) target[fill[mesh.corners[4 * f + i]]++] = mesh.corners[4 * f + (i + 1) % 4];
  std::vector<uint32_t> mark(vertices, UINT32_MAX);
  for (uint32_t v = 0; v < vertices; ++v)
    for (uint32_t k = start[v]; k < start[v + 1]; ++k) {
      if (mark[target[k]] == v)
        return Status(ErrorCode::kBadSymbol, "CONN: the quads use edge " + std::to_string(v) + "-" +
                                                 std::to_string(target[k]) + " twice in one direction");
      mark[target[k]] = v;
    }
  return Status::Ok();
}

Status invalid(int type, const std::string& why) {
  return Status(ErrorCode::kBadSymbol, "CONN: Q" + std::to_string(type) + " " + why);
}

Status SpiraleReversi::need_current(int type) const {
  if (current_.gate == kNone) return invalid(type, "with no boundary to attach to (the last code must be Q1)");
  return Status::Ok();
}

Status SpiraleReversi::pop(int type, Loop* loop) {
  if (loops_.empty()) return invalid(type, "needs a boundary from the loop stack, which is empty");
  *loop = loops_.back();
  loops_.pop_back();
  return Status::Ok();
}

Status SpiraleReversi::q1() {
  if (current_.gate != kNone) loops_.push_back(current_);
  uint32_t n[4];
  for (uint32_t& node : n) node = new_node(new_vertex());
  for (int i = 0; i < 4; ++i) link(n[i], n[(i + 1) % 4]);
  emit(n[0], n[1], n[2], n[3]);
  current_ = {n[0], 4};
  return Status::Ok();
}

// Q2: gate x->g1 gets y, g0 inserted. Q4: gate y->x gets g0, g1.
// Q6: gate g0->y gets g1, x. The new gate is g0->g1 in all three.
Status SpiraleReversi::grow(int type) {
  if (Status s = need_current(type); !s.ok()) return s;
  const uint32_t a = current_.gate, b = next_[a];
  const uint32_t m = new_node(new_vertex()), n = new_node(new_vertex());
  link(a, m);
  link(m, n);
  link(n, b);
  current_.length += 2;
  if (type == 2) {  // (g0, g1, x, y) = (n, b, a, m)
    emit(n, b, a, m);
    current_.gate = n;
  } else if (type == 4) {  // (m, n, b, a)
    emit(m, n, b, a);
    current_.gate = m;
  } else {  // Q6: (a, m, n, b)
    emit(a, m, n, b);
    current_.gate = a;
  }
  return Status::Ok();
}

// Q5: gate x->g1, the node before is y: x leaves, g0 comes between y and g1.
// Q12: gate y->x, the node before is g0: y leaves, g1 comes between g0 and x.
Status SpiraleReversi::swap_corner(int type) {
  if (Status s = need_current(type); !s.ok()) return s;
  const uint32_t a = current_.gate, b = next_[a], c = prev_[a];
  const uint32_t n = new_node(new_vertex());
  link(c, n);
  link(n, b);
  inner_.push_back(vertex_[a]);
  if (type == 5) {  // (g0, g1, x, y) = (n, b, a, c)
    emit(n, b, a, c);
    current_.gate = n;
  } else {  // Q12: (c, n, b, a)
    emit(c, n, b, a);
    current_.gate = c;
  }
  return Status::Ok();
}

// Q13: gate x->g1 with y and g0 before it: x and y leave, g0->g1 is the gate.
Status SpiraleReversi::q13() {
  if (Status s = need_current(13); !s.ok()) return s;
  if (current_.length < 6) return invalid(13, "on a boundary of fewer than 6 edges");
  const uint32_t x = current_.gate, g1 = next_[x], y = prev_[x], g0 = prev_[y];
  link(g0, g1);
  inner_.push_back(vertex_[y]);
  inner_.push_back(vertex_[x]);
  emit(g0, g1, x, y);
  current_ = {g0, current_.length - 2};
  return Status::Ok();
}

// Joins the current loop with one popped loop (spec 5.3.6 table):
//   Q3:  current x->g1, popped y->x'; x' merges into x; new g0 between y and g1.
//   Q9:  current y->x,  popped g0->y'; y' merges into y; new g1 between g0 and x.
//   Q7:  current x->g1, popped g0->y; g0 links to g1 and x to y.
//   Q10: current x->g1 after y, popped g0->y'; y' merges into y; x leaves.
//   Q11: current x->g1, popped y->x' after g0; x' merges into x; y leaves.
Status SpiraleReversi::join_two(int type) {
  if (Status s = need_current(type); !s.ok()) return s;
  Loop other;
  if (Status s = pop(type, &other); !s.ok()) return s;
  const uint32_t a = current_.gate, b = next_[a], c = other.gate, d = next_[c];
  uint64_t length = current_.length + other.length;
  switch (type) {
    case 3: {  // a = x, b = g1, c = y, d = x'
      const uint32_t g0 = splice_through_new_vertex(a, b, c, d);
      emit(g0, b, a, c);
      current_.gate = g0;
      break;
    }
    case 9: {  // a = y, b = x, c = g0, d = y'
      const uint32_t g1 = splice_through_new_vertex(a, b, c, d);
      emit(c, g1, b, a);
      current_.gate = c;
      break;
    }
    case 7:  // a = x, b = g1, c = g0, d = y
      link(c, b);
      link(a, d);
      emit(c, b, a, d);
      current_.gate = c;
      break;
    case 10: {  // a = x, b = g1, c = g0, d = y'; y = prev(a)
      const uint32_t y = prev_[a], after = next_[d];
      link(c, b);
      link(y, after);
      merge(y, d);
      inner_.push_back(vertex_[a]);
      emit(c, b, a, y);
      current_.gate = c;
      length -= 2;
      break;
    }
    case 11: {  // a = x, b = g1, c = y, d = x'; g0 = prev(c)
      const uint32_t g0 = prev_[c], after = next_[d];
      link(g0, b);
      link(a, after);
      merge(a, d);
      inner_.push_back(vertex_[c]);
      emit(g0, b, a, c);
      current_.gate = g0;
      length -= 2;
      break;
    }
  }
  current_.length = length;
  return Status::Ok();
}

// Q8: current x->g1, popped y->x' (the O loop), then g0->y' (the L loop).
Status SpiraleReversi::q8() {
  if (Status s = need_current(8); !s.ok()) return s;
  Loop o, l;
  if (Status s = pop(8, &o); !s.ok()) return s;
  if (Status s = pop(8, &l); !s.ok()) return s;
  const uint32_t x = current_.gate, g1 = next_[x];
  const uint32_t y = o.gate, x2 = next_[y];
  const uint32_t g0 = l.gate, y2 = next_[g0];
  const uint32_t after_x2 = next_[x2], after_y2 = next_[y2];
  link(g0, g1);
  link(x, after_x2);
  link(y, after_y2);
  merge(x, x2);
  merge(y, y2);
  emit(g0, g1, x, y);
  current_ = {g0, current_.length + o.length + l.length - 2};
  return Status::Ok();
}

Status SpiraleReversi::apply(int type) {
  switch (type) {
    case 1: return q1();
    case 2: case 4: case 6: return grow(type);
    case 5: case 12: return swap_corner(type);
    case 13: return q13();
    case 8: return q8();
    case 3: case 7: case 9: case 10: case 11: return join_two(type);
  }
  return Status(ErrorCode::kBadSymbol, "CONN: interaction type " + std::to_string(type) + " is not Q1..Q13");
}

// Labels (spec 5.3.4): the final loop from the gate on, then the inner-vertex
// stack from its top. Faces come out in the encoder's order.
Status SpiraleReversi::finish(bool closed, uint32_t vertex_count, Mesh* mesh) {
  if (current_.gate == kNone) return Status(ErrorCode::kBadSymbol, "CONN: no quads decoded");
  if (!loops_.empty())
    return Status(ErrorCode::kBadSymbol, "CONN: " + std::to_string(loops_.size()) + " boundaries left unjoined");
  if (closed && current_.length != 4)
    return Status(ErrorCode::kBadSymbol, "CONN: closed mesh ends with a boundary of " +
                                             std::to_string(current_.length) + " edges, not 4");
  std::vector<uint32_t> label(parent_.size(), kNone);
  uint32_t next_label = 0;
  auto give = [&](uint32_t temp) -> bool {
    const uint32_t root = find(temp);
    if (label[root] != kNone || next_label >= vertex_count) return false;
    label[root] = next_label++;
    return true;
  };
  uint32_t node = current_.gate;
  for (uint64_t i = 0; i < current_.length; ++i, node = next_[node])
    if (!give(vertex_[node])) return Status(ErrorCode::kBadSymbol, "CONN: boundary vertex labelled twice or beyond vertex_count");
  for (size_t i = inner_.size(); i-- > 0;)
    if (!give(inner_[i])) return Status(ErrorCode::kBadSymbol, "CONN: inner vertex labelled twice or beyond vertex_count");
  const size_t quads = quads_.size() / 4 + (closed ? 1 : 0);
  mesh->face_sizes.assign(quads, 4);
  mesh->corners.clear();
  mesh->corners.reserve(4 * quads);
  if (closed) mesh->corners.insert(mesh->corners.end(), {1, 0, 3, 2});
  for (size_t q = quads_.size() / 4; q-- > 0;)
    for (int i = 0; i < 4; ++i) {
      const uint32_t l = label[find(quads_[4 * q + i])];
      if (l == kNone) return Status(ErrorCode::kBadSymbol, "CONN: a quad corner never reached the boundary");
      mesh->corners.push_back(l);
    }
  return check_edges_unique(*mesh, next_label);
}

}  // namespace

Status spirale_reversi_decode(const std::vector<uint8_t>& types, bool closed, uint32_t vertex_count, Mesh* mesh) {
  SpiraleReversi decoder(types.size());
  for (size_t i = types.size(); i-- > 0;)
    if (Status s = decoder.apply(types[i]); !s.ok()) return s;
  return decoder.finish(closed, vertex_count, mesh);
}

}  // namespace qmc
