// Section 14.6's geometry order computed literally, for tests and the
// geometry_order fuzz target to hold the decoder's priority queue to: every
// step counts, for every face, its corners at unplaced vertices (O(V F)).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "qmc/mesh.h"

namespace qmc::fuzz {

inline std::vector<uint32_t> geometry_order_by_the_rule(uint32_t vertex_count, const Mesh& m) {
  std::vector<uint8_t> placed(vertex_count, 0);
  std::vector<uint32_t> order;
  while (order.size() < vertex_count) {
    std::vector<uint32_t> closing(vertex_count, 0);
    size_t k = 0;
    for (uint32_t d : m.face_sizes) {
      uint32_t unplaced = 0, w = 0;
      for (uint32_t i = 0; i < d; ++i)
        if (!placed[m.corners[k + i]]) ++unplaced, w = m.corners[k + i];
      if (unplaced == 1) ++closing[w];
      k += d;
    }
    uint32_t next = vertex_count;
    for (uint32_t w = 0; w < vertex_count; ++w)
      if (!placed[w] && closing[w] >= 1 &&
          (next == vertex_count || std::min(closing[w], 2u) > std::min(closing[next], 2u)))
        next = w;
    if (next == vertex_count)
      for (next = 0; placed[next];) ++next;
    placed[next] = 1;
    order.push_back(next);
  }
  return order;
}

}  // namespace qmc::fuzz
