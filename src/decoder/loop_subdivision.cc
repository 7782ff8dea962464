// Loop subdivision, spec/qmc-format.md sections 12.3-12.6 (seed 003 §3.1.1
// masks and §3.1.2 limit normals; C. Loop 1987; Hoppe et al. 1994 for the
// boundary tangents). The arithmetic is binary64, one rounding per
// operation, in the order written; every product goes through mul()
// (common/exact_arith.h) so that no compiler flag fuses a multiply-add.
#include "decoder/loop_subdivision.h"

#include <string>

#include "common/exact_arith.h"
#include "common/union_find.h"

namespace qmc {
namespace {

Status bad_level(const std::string& message) { return Status(ErrorCode::kBadChunkPayload, message); }

// Open addressing over undirected edges; keys are (min << 32 | max).
class EdgeHash {
 public:
  explicit EdgeHash(size_t expected) {
    size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    keys_.assign(capacity, kEmpty);
    values_.resize(capacity);
  }
  // The edge index stored for {v, w}, or inserts `fresh` and returns it.
  uint32_t find_or_insert(uint32_t v, uint32_t w, uint32_t fresh) {
    const uint64_t key = v < w ? (uint64_t(v) << 32 | w) : (uint64_t(w) << 32 | v);
    size_t slot = size_t((key * 0x9E3779B97F4A7C15ull) >> 20) & (keys_.size() - 1);
    while (keys_[slot] != kEmpty) {
      if (keys_[slot] == key) return values_[slot];
      slot = (slot + 1) & (keys_.size() - 1);
    }
    keys_[slot] = key;
    values_[slot] = fresh;
    return fresh;
  }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t(0);
  std::vector<uint64_t> keys_;
  std::vector<uint32_t> values_;
};

// Names an edge in a rejection; built only when one is made.
std::string edge_of_face(uint32_t v, uint32_t w, uint32_t f) {
  return "edge (" + std::to_string(v) + ", " + std::to_string(w) + ") of face " + std::to_string(f);
}

Status number_edges(const LoopMesh& mesh, LoopEdges* e) {
  const uint32_t faces = mesh.face_count();
  EdgeHash hash(size_t(faces) * 3 / 2 + 3);
  e->face_edge.resize(size_t(faces) * 3);
  // A closed mesh has 3F / 2 edges; a boundary adds to them as they come.
  for (std::vector<uint32_t>* per_edge : {&e->a, &e->b, &e->c, &e->d, &e->face0, &e->corner0, &e->face1, &e->corner1})
    per_edge->reserve(size_t(faces) * 3 / 2 + 3);
  for (uint32_t f = 0; f < faces; ++f) {
    const uint32_t* t = &mesh.triangles[3 * size_t(f)];
    for (uint32_t k = 0; k < 3; ++k) {
      const uint32_t v = t[k], w = t[(k + 1) % 3], third = t[(k + 2) % 3];
      const uint32_t fresh = e->edge_count();
      const uint32_t edge = hash.find_or_insert(v, w, fresh);
      e->face_edge[3 * size_t(f) + k] = edge;
      if (edge == fresh) {
        e->a.push_back(v), e->b.push_back(w), e->c.push_back(third), e->d.push_back(kNoVertex);
        e->face0.push_back(f), e->corner0.push_back(k), e->face1.push_back(kNoVertex), e->corner1.push_back(kNoVertex);
        continue;
      }
      if (e->d[edge] != kNoVertex) return bad_level(edge_of_face(v, w, f) + " is in more than two faces");
      if (e->a[edge] == v)
        return bad_level(edge_of_face(v, w, f) + " runs the same way as in face " + std::to_string(e->face0[edge]));
      e->d[edge] = third, e->face1[edge] = f, e->corner1[edge] = k;
    }
  }
  return Status::Ok();
}

// Valence, the two boundary neighbours and the neighbour lists in edge order.
Status collect_neighbours(uint32_t vertices, LoopEdges* e) {
  e->valence.assign(vertices, 0);
  e->boundary_prev.assign(vertices, kNoVertex);
  e->boundary_next.assign(vertices, kNoVertex);
  std::vector<uint8_t> boundary_edges(vertices, 0);
  for (uint32_t i = 0; i < e->edge_count(); ++i) {
    ++e->valence[e->a[i]], ++e->valence[e->b[i]];
    if (!e->is_boundary(i)) continue;
    for (const auto& [v, w] : {std::pair{e->a[i], e->b[i]}, std::pair{e->b[i], e->a[i]}}) {
      if (++boundary_edges[v] > 2)
        return bad_level("vertex " + std::to_string(v) + " is on more than two boundary edges");
      (boundary_edges[v] == 1 ? e->boundary_prev : e->boundary_next)[v] = w;
    }
  }
  e->neighbour_offset.assign(size_t(vertices) + 1, 0);
  for (uint32_t v = 0; v < vertices; ++v) {
    if (e->valence[v] == 0) return bad_level("vertex " + std::to_string(v) + " is in no face");
    e->neighbour_offset[v + 1] = e->neighbour_offset[v] + e->valence[v];
  }
  std::vector<uint32_t> fill(e->neighbour_offset.begin(), e->neighbour_offset.end() - 1);
  e->neighbours.resize(e->neighbour_offset[vertices]);
  for (uint32_t i = 0; i < e->edge_count(); ++i) {
    e->neighbours[fill[e->a[i]]++] = e->b[i];
    e->neighbours[fill[e->b[i]]++] = e->a[i];
  }
  return Status::Ok();
}

// A vertex is manifold when its corners form one fan: corners of the vertex
// in the two faces of an edge through it are joined; one class must remain.
Status check_single_fans(const LoopMesh& mesh, const LoopEdges& e) {
  std::vector<uint32_t> parent(mesh.triangles.size());
  for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  for (uint32_t i = 0; i < e.edge_count(); ++i) {
    if (e.is_boundary(i)) continue;
    const uint32_t f = 3 * e.face0[i], g = 3 * e.face1[i];
    // a at f+corner0, b at f+corner0+1; b at g+corner1, a at g+corner1+1.
    union_find_join(parent, f + e.corner0[i], g + (e.corner1[i] + 1) % 3);
    union_find_join(parent, f + (e.corner0[i] + 1) % 3, g + e.corner1[i]);
  }
  std::vector<uint32_t> fan(mesh.vertex_count(), kNoVertex);
  for (uint32_t corner = 0; corner < parent.size(); ++corner) {
    const uint32_t v = mesh.triangles[corner], root = union_find_root(parent, corner);
    if (fan[v] == kNoVertex) fan[v] = root;
    else if (fan[v] != root) return bad_level("vertex " + std::to_string(v) + " joins two separate fans of faces");
  }
  return Status::Ok();
}

}  // namespace

Status number_loop_edges(const LoopMesh& mesh, LoopEdges* edges) {
  *edges = LoopEdges{};
  const uint32_t vertices = mesh.vertex_count();
  if (mesh.face_count() == 0) return bad_level("the mesh has no faces");
  for (uint32_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t* t = &mesh.triangles[3 * size_t(f)];
    for (int k = 0; k < 3; ++k)
      if (t[k] >= vertices)
        return bad_level("face " + std::to_string(f) + " names vertex " + std::to_string(t[k]) + " of " +
                         std::to_string(vertices));
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return bad_level("face " + std::to_string(f) + " repeats a vertex");
  }
  if (Status s = number_edges(mesh, edges); !s.ok()) return s;
  return collect_neighbours(vertices, edges);
}

Status build_loop_edges(const LoopMesh& mesh, LoopEdges* edges) {
  if (Status s = number_loop_edges(mesh, edges); !s.ok()) return s;
  return check_single_fans(mesh, *edges);
}

// Section 12.4: cos(2 pi / n) is exact for n = 2, 3, 4, 6 and otherwise the
// degree-20 Taylor polynomial below, evaluated by Horner's rule in y = x^2.
// The coefficients are the binary64 values nearest to (-1)^k / (2k)!.
double loop_beta(uint32_t n) {
  static constexpr double kTwoPi = 0x1.921fb54442d18p+2;
  static constexpr double kCos[10] = {
      -0x1.0000000000000p-1,  0x1.5555555555555p-5,  -0x1.6c16c16c16c17p-10, 0x1.a01a01a01a01ap-16,
      -0x1.27e4fb7789f5cp-22, 0x1.1eed8eff8d898p-29, -0x1.93974a8c07c9dp-37, 0x1.ae7f3e733b81fp-45,
      -0x1.6827863b97d97p-53, 0x1.e542ba4020225p-62};
  double c;
  switch (n) {
    case 2: c = -1.0; break;
    case 3: c = -0.5; break;
    case 4: c = 0.0; break;
    case 6: c = 0.5; break;
    default: {
      const double x = kTwoPi / double(n);
      const double y = mul(x, x);
      double h = kCos[9];
      for (int k = 8; k >= 0; --k) h = kCos[k] + mul(y, h);
      c = 1.0 + mul(y, h);
    }
  }
  const double inner = 0.375 + mul(0.25, c);
  return (0.625 - mul(inner, inner)) / double(n);
}

void loop_subdivide(const LoopMesh& coarse, const LoopEdges& e, LoopMesh* fine) {
  const uint32_t vertices = coarse.vertex_count(), edges = e.edge_count();
  const double* p = coarse.positions.data();
  fine->positions.resize(3 * (size_t(vertices) + edges));
  double* out = fine->positions.data();
  std::vector<double> beta_of_valence;
  for (uint32_t v = 0; v < vertices; ++v) {
    double* x = out + 3 * size_t(v);
    if (e.boundary_prev[v] != kNoVertex) {  // boundary vertex mask 1/8, 3/4, 1/8
      const double* q = p + 3 * size_t(e.boundary_prev[v]);
      const double* r = p + 3 * size_t(e.boundary_next[v]);
      for (int k = 0; k < 3; ++k) x[k] = mul(0.75, p[3 * size_t(v) + k]) + mul(0.125, q[k] + r[k]);
      continue;
    }
    const uint32_t n = e.valence[v];
    if (beta_of_valence.size() <= n) beta_of_valence.resize(n + 1, -1.0);
    if (beta_of_valence[n] < 0) beta_of_valence[n] = loop_beta(n);
    const double beta = beta_of_valence[n];
    const double alpha = 1.0 - mul(double(n), beta);
    const uint32_t* ring = &e.neighbours[e.neighbour_offset[v]];
    for (int k = 0; k < 3; ++k) {
      double sum = p[3 * size_t(ring[0]) + k];
      for (uint32_t j = 1; j < n; ++j) sum = sum + p[3 * size_t(ring[j]) + k];
      x[k] = mul(alpha, p[3 * size_t(v) + k]) + mul(beta, sum);
    }
  }
  for (uint32_t i = 0; i < edges; ++i) {
    double* x = out + 3 * (size_t(vertices) + i);
    const double* pa = p + 3 * size_t(e.a[i]);
    const double* pb = p + 3 * size_t(e.b[i]);
    if (e.is_boundary(i)) {
      for (int k = 0; k < 3; ++k) x[k] = mul(0.5, pa[k] + pb[k]);
      continue;
    }
    const double* pc = p + 3 * size_t(e.c[i]);
    const double* pd = p + 3 * size_t(e.d[i]);
    for (int k = 0; k < 3; ++k) x[k] = mul(0.375, pa[k] + pb[k]) + mul(0.125, pc[k] + pd[k]);
  }
  fine->triangles.resize(coarse.triangles.size() * 4);
  uint32_t* t = fine->triangles.data();
  for (uint32_t f = 0; f < coarse.face_count(); ++f) {
    const uint32_t* v = &coarse.triangles[3 * size_t(f)];
    const uint32_t m0 = vertices + e.face_edge[3 * size_t(f)], m1 = vertices + e.face_edge[3 * size_t(f) + 1],
                   m2 = vertices + e.face_edge[3 * size_t(f) + 2];
    const uint32_t four[12] = {v[0], m0, m2, v[1], m1, m0, v[2], m2, m1, m0, m1, m2};
    for (uint32_t k = 0; k < 12; ++k) t[12 * size_t(f) + k] = four[k];
  }
}

namespace {

void cross(const double* s, const double* t, double* n) {
  n[0] = mul(s[1], t[2]) - mul(s[2], t[1]);
  n[1] = mul(s[2], t[0]) - mul(s[0], t[2]);
  n[2] = mul(s[0], t[1]) - mul(s[1], t[0]);
}

}  // namespace

// Section 12.6. Interior edge point: ring r0..r5 counter-clockwise from the
// vertex point b, u = sum cos(2 pi j / 6) r_j and v = sum cos(2 pi (j+1) / 6)
// r_j (seed 003 §3.1.2, whose weights are exact in binary64), normal v x u.
// Boundary edge point: along = b - a, across = (e_bc + e_ca) - a - b.
void edge_point_normals(const LoopMesh& fine, const LoopEdges& e, uint32_t coarse_vertices, std::vector<double>* normals) {
  const double* p = fine.positions.data();
  normals->resize(3 * size_t(e.edge_count()));
  for (uint32_t i = 0; i < e.edge_count(); ++i) {
    const uint32_t f = 3 * e.face0[i], k = e.corner0[i];
    const double* A = p + 3 * size_t(e.a[i]);
    const double* B = p + 3 * size_t(e.b[i]);
    const double* Ebc = p + 3 * (size_t(coarse_vertices) + e.face_edge[f + (k + 1) % 3]);
    const double* Eca = p + 3 * (size_t(coarse_vertices) + e.face_edge[f + (k + 2) % 3]);
    double s[3], t[3];
    if (e.is_boundary(i)) {
      for (int x = 0; x < 3; ++x) {
        s[x] = B[x] - A[x];
        t[x] = ((Ebc[x] + Eca[x]) - A[x]) - B[x];
      }
      cross(s, t, &(*normals)[3 * size_t(i)]);
      continue;
    }
    const uint32_t g = 3 * e.face1[i], l = e.corner1[i];
    const double* Ead = p + 3 * (size_t(coarse_vertices) + e.face_edge[g + (l + 1) % 3]);
    const double* Edb = p + 3 * (size_t(coarse_vertices) + e.face_edge[g + (l + 2) % 3]);
    double u[3], v[3];
    for (int x = 0; x < 3; ++x) {
      u[x] = B[x] + mul(0.5, Ebc[x]) - mul(0.5, Eca[x]) - A[x] - mul(0.5, Ead[x]) + mul(0.5, Edb[x]);
      v[x] = mul(0.5, B[x]) - mul(0.5, Ebc[x]) - Eca[x] - mul(0.5, A[x]) + mul(0.5, Ead[x]) + Edb[x];
    }
    cross(v, u, &(*normals)[3 * size_t(i)]);
  }
}

}  // namespace qmc
