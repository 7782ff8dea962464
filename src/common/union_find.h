// Union-find over dense ids, with path halving: used wherever the codec joins
// vertices that turn out to be one (Spirale Reversi's merges, seams and
// vertex identifications of spec 5.4.7, the encoder's fans).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace qmc {

inline uint32_t union_find_root(std::vector<uint32_t>& parent, uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// Joins the classes of a and b; the smaller root stays the root, so every
// class is named by its smallest member.
inline void union_find_join(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
  a = union_find_root(parent, a);
  b = union_find_root(parent, b);
  if (a < b) parent[b] = a;
  else parent[a] = b;
}

// The same as an object over 0 .. n - 1.
struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n) : parent(n) {
    for (size_t i = 0; i < n; ++i) parent[i] = uint32_t(i);
  }
  uint32_t find(uint32_t x) { return union_find_root(parent, x); }
  void unite(uint32_t a, uint32_t b) { union_find_join(parent, a, b); }
};

}  // namespace qmc
