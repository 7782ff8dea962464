// Vertex relabelling of spec/qmc-format.md section 5.2.1: labels follow the
// first reference in the face list, so a decoder meeting a vertex for the
// first time always knows its label (the next unused one) and the indexed
// coding need not send it.
#include "encoder/vertex_order.h"

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

}  // namespace qmc
