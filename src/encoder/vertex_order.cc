// Vertex relabelling of spec/qmc-format.md section 5.2.1: labels follow the
// first reference in the face list, so a decoder meeting a vertex for the
// first time always knows its label (the next unused one) and the indexed
// coding need not send it.
#include "encoder/vertex_order.h"

#include <algorithm>
#include <cmath>

namespace qmc {

static constexpr uint32_t kUnlabelled = UINT32_MAX;

VertexOrder first_reference_order(const Mesh& mesh) {
  const size_t n = mesh.vertex_count();
  VertexOrder order;
  order.label.assign(n, kUnlabelled);
  order.file_vertex.reserve(n);
  for (uint32_t v : mesh.corners) {
    if (order.label[v] != kUnlabelled) continue;
    order.label[v] = uint32_t(order.file_vertex.size());
    order.file_vertex.push_back(v);
  }
  order.referenced = uint32_t(order.file_vertex.size());
  for (uint32_t v = 0; v < n; ++v) {
    if (order.label[v] != kUnlabelled) continue;
    order.label[v] = uint32_t(order.file_vertex.size());
    order.file_vertex.push_back(v);
  }
  return order;
}

Mesh relabel(const Mesh& mesh, const VertexOrder& order) {
  Mesh out;
  out.face_sizes = mesh.face_sizes;
  out.corners.reserve(mesh.corners.size());
  for (uint32_t v : mesh.corners) out.corners.push_back(order.label[v]);
  out.positions.reserve(mesh.positions.size());
  for (uint32_t v : order.file_vertex)
    for (int a = 0; a < 3; ++a) out.positions.push_back(mesh.positions[3 * size_t(v) + a]);
  return out;
}

namespace {

// 21 bits of x, y and z interleaved (Morton code).
uint64_t interleave3(uint32_t x, uint32_t y, uint32_t z) {
  uint64_t key = 0;
  for (int b = 20; b >= 0; --b)
    key = (key << 3) | (uint64_t((x >> b) & 1) << 2) | (uint64_t((y >> b) & 1) << 1) | uint64_t((z >> b) & 1);
  return key;
}

}  // namespace

void sort_along_curve(const Mesh& mesh, std::vector<uint32_t>* vertices) {
  if (vertices->size() < 2) return;
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a) lo[a] = hi[a] = mesh.positions[3 * size_t((*vertices)[0]) + a];
  for (uint32_t v : *vertices)
    for (int a = 0; a < 3; ++a) {
      const float x = mesh.positions[3 * size_t(v) + a];
      if (x < lo[a]) lo[a] = x;  // NaN compares false and leaves the box alone
      if (x > hi[a]) hi[a] = x;
    }
  const double side = std::max({double(hi[0]) - lo[0], double(hi[1]) - lo[1], double(hi[2]) - lo[2]});
  const double cells = double((1u << 21) - 1);
  const double scale = side > 0 && std::isfinite(side) ? cells / side : 0;
  std::vector<std::pair<uint64_t, uint32_t>> keyed;
  keyed.reserve(vertices->size());
  for (uint32_t v : *vertices) {
    uint32_t cell[3];
    for (int a = 0; a < 3; ++a) {
      const double t = (double(mesh.positions[3 * size_t(v) + a]) - lo[a]) * scale;
      cell[a] = t >= 0 && t <= cells ? uint32_t(t) : 0;  // NaN too
    }
    keyed.emplace_back(interleave3(cell[0], cell[1], cell[2]), v);
  }
  std::sort(keyed.begin(), keyed.end());  // pairs: ties in input order
  for (size_t i = 0; i < keyed.size(); ++i) (*vertices)[i] = keyed[i].second;
}

}  // namespace qmc
