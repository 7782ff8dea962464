// Edge bookkeeping shared by the mesh tests: counts by brute force (maps and
// sets), deliberately unlike the codec's linear-time structures.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <utility>

#include "qmc/mesh.h"

namespace qmc::testing {

using Edge = std::pair<uint32_t, uint32_t>;

// Directed edges with multiplicity, walking each face cycle.
inline std::map<Edge, int> directed_edges(const Mesh& mesh) {
  std::map<Edge, int> edges;
  size_t first = 0;
  for (uint32_t size : mesh.face_sizes) {
    for (uint32_t i = 0; i < size; ++i) ++edges[{mesh.corners[first + i], mesh.corners[first + (i + 1) % size]}];
    first += size;
  }
  return edges;
}

inline std::set<Edge> undirected_edges(const Mesh& mesh) {
  std::set<Edge> edges;
  for (const auto& [e, count] : directed_edges(mesh)) edges.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
  return edges;
}

inline int64_t euler_characteristic(const Mesh& mesh) {
  return static_cast<int64_t>(mesh.vertex_count()) - static_cast<int64_t>(undirected_edges(mesh).size()) +
         static_cast<int64_t>(mesh.face_count());
}

// Closed and consistently oriented: every directed edge once, its reverse
// present exactly once.
inline void expect_closed_and_oriented(const Mesh& mesh) {
  const auto edges = directed_edges(mesh);
  for (const auto& [e, count] : edges) {
    EXPECT_EQ(count, 1) << "edge " << e.first << "->" << e.second;
    EXPECT_NE(e.first, e.second);
    auto reverse = edges.find({e.second, e.first});
    ASSERT_NE(reverse, edges.end()) << "edge " << e.first << "->" << e.second << " has no opposite";
    EXPECT_EQ(reverse->second, 1);
  }
}

// Six times the signed volume, fanning each face from its first corner:
// positive when a closed mesh's faces are oriented outward.
inline double signed_volume6(const Mesh& mesh) {
  double volume = 0;
  size_t first = 0;
  auto p = [&mesh](uint32_t v, int axis) { return static_cast<double>(mesh.positions[3 * size_t{v} + axis]); };
  for (uint32_t size : mesh.face_sizes) {
    const uint32_t a = mesh.corners[first];
    for (uint32_t i = 1; i + 1 < size; ++i) {
      const uint32_t b = mesh.corners[first + i];
      const uint32_t c = mesh.corners[first + i + 1];
      volume += p(a, 0) * (p(b, 1) * p(c, 2) - p(b, 2) * p(c, 1)) - p(a, 1) * (p(b, 0) * p(c, 2) - p(b, 2) * p(c, 0)) +
                p(a, 2) * (p(b, 0) * p(c, 1) - p(b, 1) * p(c, 0));
    }
    first += size;
  }
  return volume;
}

// Well-formed: whole positions, degrees >= 3 adding up to the corners,
// corners naming existing vertices, finite coordinates.
inline void expect_valid(const Mesh& mesh) {
  ASSERT_EQ(mesh.positions.size() % 3, 0u);
  size_t corners = 0;
  for (uint32_t size : mesh.face_sizes) {
    EXPECT_GE(size, 3u);
    corners += size;
  }
  ASSERT_EQ(corners, mesh.corners.size());
  for (uint32_t index : mesh.corners) ASSERT_LT(index, mesh.vertex_count());
  for (float value : mesh.positions) EXPECT_TRUE(std::isfinite(value));
}

// FNV-1a over the values' bits in little-endian byte order, to pin the exact
// output of a generator on every platform.
inline uint64_t fingerprint(const Mesh& mesh) {
  uint64_t hash = 0xcbf29ce484222325ull;
  auto mix = [&hash](uint32_t value) {
    for (int i = 0; i < 4; ++i) hash = (hash ^ ((value >> (8 * i)) & 0xff)) * 0x100000001b3ull;
  };
  for (float value : mesh.positions) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    mix(bits);
  }
  for (uint32_t size : mesh.face_sizes) mix(size);
  for (uint32_t index : mesh.corners) mix(index);
  return hash;
}

}  // namespace qmc::testing
