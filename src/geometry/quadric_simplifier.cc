// Seed 003 step II: Garland-Heckbert quadric simplification that keeps the
// topology (see quadric_simplifier.h), on OpenMesh's DecimaterT.
#include "geometry/quadric_simplifier.h"

// OpenMesh's VectorT is deliberately left uninitialized by its default
// constructor, and GCC says so wherever a property vector grows.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
// Property access by static_cast: OpenMesh's default dynamic_cast compares
// type names (strcmp) on every point() and status() compiled here, and the
// collapse test below is compiled here for the same reason (OmMesh).
#define OM_FORCE_STATIC_CAST
// The mesh first: QuadricT.hh uses vector_traits without including it.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Geometry/QuadricT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "common/union_find.h"
#include "geometry/manifold_cut.h"

namespace qmc {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
  VertexAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
};
// The decimater's mesh, with the test whether a halfedge collapse keeps the
// mesh a manifold of the same topology done here, inline: the prebuilt
// libOpenMeshCore's TriConnectivity::is_collapse_ok allocates and frees
// strings on every call: on stanford-bunny (K = 4) it took 11.0 of the
// simplification's 13.6 G instructions (callgrind), which this test brings
// down to 3.4 G, with the same collapses. DecimaterT<Mesh> calls
// mesh_.is_collapse_ok on its Mesh type, so this one is used.
struct OmMesh : OpenMesh::TriMesh_ArrayKernelT<DoubleTraits> {
  // The link condition of Dey, Edelsbrunner, Guha and Nekhayev ("Topology
  // preserving edge contraction", 1999) for collapsing v0 into v1 along
  // v0v1: the vertices adjacent to both are exactly the third corners vl,
  // vr of the edge's faces; besides, vl != vr (a lone tetrahedron), a face
  // beside the edge must keep an inner edge (its other two edges not both
  // on the boundary), and two boundary vertices collapse only along a
  // boundary edge. Deleted elements are refused.
  bool is_collapse_ok(HalfedgeHandle v0v1) {
    const HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
    const VertexHandle v0 = to_vertex_handle(v1v0), v1 = to_vertex_handle(v0v1);
    if (status(edge_handle(v0v1)).deleted() || status(v0).deleted() || status(v1).deleted()) return false;
    VertexHandle vl, vr;
    if (!third_corner(v0v1, &vl) || !third_corner(v1v0, &vr)) return false;
    if (vl.is_valid() && vl == vr) return false;
    if (!vl.is_valid() && !vr.is_valid()) return false;
    if (is_boundary(v0) && is_boundary(v1) && !is_boundary(v0v1) && !is_boundary(v1v0)) return false;
    for (VertexHandle w : vv_range(v0)) {
      if (w == vl || w == vr || w == v1) continue;
      for (VertexHandle u : vv_range(v1))
        if (u == w) return false;
    }
    return true;
  }

  // OpenMesh's find_halfedge, compiled here: BaseDecimaterT::is_collapse_
  // legal asks it whether vl and vr are joined for nearly every candidate
  // collapse, and the prebuilt library's copy, a call with a call per
  // handle check, made stanford-bunny's simplification (K = 4) 3.19 G
  // instructions; 2.71 G with this one, the same collapses.
  HalfedgeHandle find_halfedge(VertexHandle from, VertexHandle to) const {
    const HalfedgeHandle start = halfedge_handle(from);
    if (!start.is_valid()) return HalfedgeHandle();
    HalfedgeHandle h = start;
    do {
      if (to_vertex_handle(h) == to) return h;
      h = next_halfedge_handle(opposite_halfedge_handle(h));
    } while (h != start);
    return HalfedgeHandle();
  }

 private:
  // The corner of h's face opposite h (invalid for a boundary halfedge);
  // false if both other edges of that face lie on the boundary.
  bool third_corner(HalfedgeHandle h, VertexHandle* corner) {
    *corner = VertexHandle();
    if (is_boundary(h)) return true;
    const HalfedgeHandle h1 = next_halfedge_handle(h), h2 = next_halfedge_handle(h1);
    *corner = to_vertex_handle(h1);
    return !(is_boundary(opposite_halfedge_handle(h1)) && is_boundary(opposite_halfedge_handle(h2)));
  }
};
using Quadric = OpenMesh::Geometry::QuadricT<double>;

// A boundary edge's penalty plane weighs this many times its squared length,
// against face planes weighted by their area: strong enough that boundaries
// do not shrink or cut corners, weak enough that collinear boundary vertices
// still go.
constexpr double kBoundaryWeight = 10;
// A face may turn by at most 60 degrees in one collapse (cosine 1/2): more is
// a fold-over.
constexpr double kMinNormalCosine = 0.5;

// Garland-Heckbert quadrics, area-weighted, with boundary penalty planes
// (OpenMesh's ModQuadricT has neither, and keeps its quadrics private), and
// the fold-over test of OpenMesh's ModNormalFlippingT done here on
// unnormalized normals, with no face normals stored and updated: one module
// instead of two, a tenth of the simplifier's time.
template <class MeshT>
class ModLoopQuadricT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ModLoopQuadricT, MeshT, LoopQuadric);

  explicit ModLoopQuadricT(MeshT& mesh) : Base(mesh, false) { mesh.add_property(quadrics_); }
  ~ModLoopQuadricT() override { Base::mesh().remove_property(quadrics_); }

  void initialize() override {
    MeshT& m = Base::mesh();
    for (auto v : m.vertices()) m.property(quadrics_, v).clear();
    for (auto f : m.faces()) {
      auto fv = m.cfv_iter(f);
      const auto a = m.point(*fv), b = m.point(*++fv), c = m.point(*++fv);
      auto n = OpenMesh::cross(b - a, c - a);
      const double twice_area = n.norm();
      if (!(twice_area > 0)) continue;
      n /= twice_area;
      Quadric q(n[0], n[1], n[2], -OpenMesh::dot(n, a));
      q *= 0.5 * twice_area;
      for (auto v : m.fv_range(f)) m.property(quadrics_, v) += q;
    }
    for (auto h : m.halfedges()) {
      if (!m.is_boundary(h)) continue;
      // h has no face; its opposite's face decides the plane's tilt.
      const auto opposite = m.opposite_halfedge_handle(h);
      const auto from = m.point(m.from_vertex_handle(h)), to = m.point(m.to_vertex_handle(h));
      const auto edge = to - from;
      auto n = OpenMesh::cross(edge, m.calc_face_normal(m.face_handle(opposite)));
      const double length = n.norm();
      if (!(length > 0)) continue;
      n /= length;
      Quadric q(n[0], n[1], n[2], -OpenMesh::dot(n, from));
      q *= kBoundaryWeight * edge.sqrnorm();
      m.property(quadrics_, m.from_vertex_handle(h)) += q;
      m.property(quadrics_, m.to_vertex_handle(h)) += q;
    }
  }

  float collapse_priority(const CollapseInfo& ci) override {
    if (folds_over(ci)) return float(Base::ILLEGAL_COLLAPSE);
    Quadric q = Base::mesh().property(quadrics_, ci.v0);
    q += Base::mesh().property(quadrics_, ci.v1);
    return float(std::max(0.0, q(ci.p1)));
  }

  void postprocess_collapse(const CollapseInfo& ci) override {
    Base::mesh().property(quadrics_, ci.v1) += Base::mesh().property(quadrics_, ci.v0);
  }

 private:
  // Whether a face around v0 that survives the collapse turns by more than
  // the limit, or loses all its area, when v0 moves to v1.
  bool folds_over(const CollapseInfo& ci) {
    const MeshT& m = Base::mesh();
    for (auto h : m.voh_range(ci.v0)) {
      const auto f = m.face_handle(h);
      if (!f.is_valid() || f == ci.fl || f == ci.fr) continue;
      const auto a = m.point(m.to_vertex_handle(h)), b = m.point(m.to_vertex_handle(m.next_halfedge_handle(h)));
      const auto before = OpenMesh::cross(a - ci.p0, b - ci.p0), after = OpenMesh::cross(a - ci.p1, b - ci.p1);
      const double size = before.norm();
      if (size > 0 && !(OpenMesh::dot(before, after) > kMinNormalCosine * size * after.norm())) return true;
    }
    return false;
  }

  OpenMesh::VPropHandleT<Quadric> quadrics_;
};

Status invalid(const std::string& message) { return Status(ErrorCode::kInvalidArgument, message); }

// The referenced vertices of `mesh`, renumbered in input order; *dropped
// counts the others.
Status compact(const LoopMesh& mesh, LoopMesh* out, uint32_t* dropped) {
  if (mesh.positions.size() % 3 != 0 || mesh.triangles.size() % 3 != 0)
    return invalid("positions or triangle indices do not come in threes");
  const uint32_t n = mesh.vertex_count();
  std::vector<uint32_t> label(n, kNoVertex);
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const uint32_t v = mesh.triangles[i];
    if (v >= n)
      return invalid("face " + std::to_string(i / 3) + " names vertex " + std::to_string(v) + " of " +
                     std::to_string(n));
    label[v] = 0;
  }
  out->positions.clear();
  uint32_t next = 0;
  for (uint32_t v = 0; v < n; ++v) {
    if (label[v] == kNoVertex) continue;
    for (int k = 0; k < 3; ++k) {
      const double x = mesh.positions[3 * size_t(v) + k];
      if (!std::isfinite(x)) return invalid("vertex " + std::to_string(v) + " has a coordinate that is not finite");
      out->positions.push_back(x);
    }
    label[v] = next++;
  }
  out->triangles.resize(mesh.triangles.size());
  for (size_t i = 0; i < mesh.triangles.size(); ++i) out->triangles[i] = label[mesh.triangles[i]];
  *dropped = n - next;
  return Status::Ok();
}

// Two faces on the same three vertices: closed up (two faces of opposite
// orientation) they are a separate sphere of two triangles, which Loop
// subdivision cannot make smooth; build_loop_edges lets it pass (and has
// refused faces that repeat a vertex, which faces_by_vertex_set leaves out).
Status check_no_duplicate_faces(const LoopMesh& mesh) {
  const std::vector<std::array<uint32_t, 4>> keys = faces_by_vertex_set(mesh);
  for (size_t i = 1; i < keys.size(); ++i)
    if (std::equal(keys[i].begin(), keys[i].begin() + 3, keys[i - 1].begin()))
      return invalid("faces " + std::to_string(keys[i - 1][3]) + " and " + std::to_string(keys[i][3]) +
                     " have the same three vertices");
  return Status::Ok();
}

// build_loop_edges plus the duplicate-face test, as kInvalidArgument.
Status check_manifold(const LoopMesh& mesh, const std::string& what, LoopEdges* edges) {
  if (Status s = build_loop_edges(mesh, edges); !s.ok()) return invalid(what + ": " + s.message());
  if (Status s = check_no_duplicate_faces(mesh); !s.ok()) return invalid(what + ": " + s.message());
  return Status::Ok();
}

Status to_openmesh(const LoopMesh& mesh, OmMesh* om) {
  om->reserve(mesh.vertex_count(), size_t(mesh.face_count()) * 3 / 2 + 3, mesh.face_count());
  std::vector<OmMesh::VertexHandle> handles(mesh.vertex_count());
  for (uint32_t v = 0; v < mesh.vertex_count(); ++v)
    handles[v] = om->add_vertex(
        OmMesh::Point(mesh.positions[3 * size_t(v)], mesh.positions[3 * size_t(v) + 1], mesh.positions[3 * size_t(v) + 2]));
  for (uint32_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t* t = &mesh.triangles[3 * size_t(f)];
    if (!om->add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid())
      return invalid("OpenMesh could not add face " + std::to_string(f));
  }
  return Status::Ok();
}

// Surviving vertices in handle (= input) order, surviving faces likewise;
// unlike OpenMesh's garbage_collection, which moves elements from the end
// into the holes.
void from_openmesh(const OmMesh& om, LoopMesh* out) {
  std::vector<uint32_t> label(om.n_vertices(), kNoVertex);
  out->positions.clear();
  out->triangles.clear();
  uint32_t next = 0;
  for (auto v : om.all_vertices()) {
    if (om.status(v).deleted()) continue;
    label[v.idx()] = next++;
    const auto& p = om.point(v);
    out->positions.insert(out->positions.end(), {p[0], p[1], p[2]});
  }
  for (auto f : om.all_faces()) {
    if (om.status(f).deleted()) continue;
    for (auto v : om.fv_range(f)) out->triangles.push_back(label[v.idx()]);
  }
}

}  // namespace

LoopTopology loop_topology(const LoopMesh& mesh, const LoopEdges& edges) {
  LoopTopology t;
  const uint32_t n = mesh.vertex_count();
  t.euler = int64_t(n) - int64_t(edges.edge_count()) + int64_t(mesh.face_count());
  std::vector<uint32_t> parent(n), loop(n);
  for (uint32_t v = 0; v < n; ++v) parent[v] = loop[v] = v;
  for (uint32_t i = 0; i < edges.edge_count(); ++i) {
    union_find_join(parent, edges.a[i], edges.b[i]);
    if (edges.is_boundary(i)) union_find_join(loop, edges.a[i], edges.b[i]);
  }
  // Each boundary vertex has two boundary edges, so a loop has as many edges
  // as vertices.
  std::vector<uint32_t> loop_size(n, 0);
  for (uint32_t v = 0; v < n; ++v) {
    t.components += union_find_root(parent, v) == v;
    if (edges.boundary_prev[v] != kNoVertex) ++loop_size[union_find_root(loop, v)];
  }
  for (uint32_t v = 0; v < n; ++v) {
    if (loop_size[v] == 0) continue;
    ++t.boundary_loops;
    if (t.shortest_boundary_loop == 0 || loop_size[v] < t.shortest_boundary_loop) t.shortest_boundary_loop = loop_size[v];
  }
  return t;
}

Status simplify_for_loop(const LoopMesh& original, uint32_t target_faces, LoopMesh* simplified,
                         SimplifyStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  SimplifyStats st;
  st.input_vertices = original.vertex_count();
  st.input_faces = original.face_count();
  LoopMesh input;
  if (Status s = compact(original, &input, &st.unreferenced_vertices); !s.ok()) return s;
  std::string what = "the input is not a manifold oriented triangle mesh";
  if (st.unreferenced_vertices > 0)
    what += " (vertex numbers after dropping " + std::to_string(st.unreferenced_vertices) + " unreferenced ones)";
  LoopEdges edges;
  if (Status s = check_manifold(input, what, &edges); !s.ok()) return s;
  st.topology = loop_topology(input, edges);

  OmMesh om;
  if (Status s = to_openmesh(input, &om); !s.ok()) return s;
  OpenMesh::Decimater::DecimaterT<OmMesh> decimater(om);
  ModLoopQuadricT<OmMesh>::Handle quadric;
  decimater.add(quadric);
  if (!decimater.initialize()) return invalid("OpenMesh's decimater did not initialize");
  st.collapses = uint32_t(decimater.decimate_to_faces(0, target_faces));

  LoopMesh out;
  from_openmesh(om, &out);
  if (Status s = check_manifold(out, "simplification broke the mesh", &edges); !s.ok()) return s;
  const LoopTopology after = loop_topology(out, edges);
  if (!(after == st.topology))
    return invalid("simplification changed the topology: components " + std::to_string(st.topology.components) +
                   " -> " + std::to_string(after.components) + ", boundary loops " +
                   std::to_string(st.topology.boundary_loops) + " -> " + std::to_string(after.boundary_loops) +
                   ", Euler characteristic " + std::to_string(st.topology.euler) + " -> " + std::to_string(after.euler));
  if (after.boundary_loops > 0 && after.shortest_boundary_loop < 3)
    return invalid("simplification left a boundary loop of " + std::to_string(after.shortest_boundary_loop) + " edges");
  st.output_vertices = out.vertex_count();
  st.output_faces = out.face_count();
  *simplified = std::move(out);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  return Status::Ok();
}

}  // namespace qmc
