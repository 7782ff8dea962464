// The node pool of Spirale Reversi (spec 5.3.6, 5.4.5): boundary loops as
// doubly linked lists of nodes, each naming a temporary vertex; vertices
// that two nodes turn out to share are merged by union-find.
#pragma once

#include <cstdint>
#include <vector>

#include "common/union_find.h"

namespace qmc {

struct LoopNodes {
  static constexpr uint32_t kNone = UINT32_MAX;
  std::vector<uint32_t> prev, next, vertex, parent;

  void reserve(size_t nodes) {
    prev.reserve(nodes);
    next.reserve(nodes);
    vertex.reserve(nodes);
    parent.reserve(nodes);
  }
  void clear() {
    prev.clear();
    next.clear();
    vertex.clear();
    parent.clear();
  }
  uint32_t new_vertex() {
    parent.push_back(uint32_t(parent.size()));
    return uint32_t(parent.size() - 1);
  }
  uint32_t new_node(uint32_t v) {
    prev.push_back(kNone);
    next.push_back(kNone);
    vertex.push_back(v);
    return uint32_t(vertex.size() - 1);
  }
  uint32_t new_node() { return new_node(new_vertex()); }
  void link(uint32_t a, uint32_t b) {
    next[a] = b;
    prev[b] = a;
  }
  uint32_t find(uint32_t v) { return union_find_root(parent, v); }
  // The vertex of node `gone` is the vertex of node `kept`.
  void merge(uint32_t kept, uint32_t gone) { parent[find(vertex[gone])] = find(vertex[kept]); }
};

}  // namespace qmc
