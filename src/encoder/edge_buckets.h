// Edges grouped by a vertex in linear time (a counting sort): the grouping
// behind the opposite-edge table (seed 001 §3.5) and the polygon surface's
// edge pairing, both linear however many edges share a vertex.
#pragma once

#include <cstdint>
#include <vector>

namespace qmc {

// Items 0 .. count - 1 grouped by key: the items of key v are
// items[begin[v] .. begin[v + 1]), in increasing order.
struct EdgeBuckets {
  std::vector<uint32_t> begin, items;
};

template <typename KeyOf>
EdgeBuckets bucket_edges(uint32_t keys, uint32_t count, KeyOf key) {
  EdgeBuckets b;
  b.begin.assign(size_t(keys) + 1, 0);
  for (uint32_t e = 0; e < count; ++e) ++b.begin[key(e) + 1];
  for (uint32_t v = 0; v < keys; ++v) b.begin[v + 1] += b.begin[v];
  b.items.resize(count);
  std::vector<uint32_t> fill(b.begin.begin(), b.begin.end() - 1);
  for (uint32_t e = 0; e < count; ++e) b.items[fill[key(e)]++] = e;
  return b;
}

}  // namespace qmc
