// Least-squares fit of a control mesh's Loop subdivision surface to the
// input (see loop_surface_fit.h).
#include "geometry/loop_surface_fit.h"

#include <cmath>

namespace qmc {
namespace {

// The control mesh's own vertices count for this much of theirs: enough to
// keep it near the input (with the subdivided levels alone, armadillo's base
// of 16 vertices for K = 5 ended 0.9 of the diagonal away), little enough
// that its subdivision, not the control polygon, is what fits: with weight 1
// and the points pulling it too, the six-limbed sphere of
// tests/progressive_rate_test.cc had a base 0.0135 of the diagonal from the
// input and a first level 0.022 (Loop's masks draw the limbs in), with 0.1
// and no points on it 0.029 and 0.013, each later level nearer again.
constexpr double kControlMeshWeight = 0.1;

// The connectivity of `subdivisions` Loop steps of the control mesh, fixed
// while the positions move.
struct SubdivisionChain {
  std::vector<LoopEdges> edges;       // of each coarser level
  std::vector<uint32_t> vertices;     // of each coarser level
  std::vector<std::vector<uint32_t>> triangles;  // of every level, the control mesh's first
};

Status build_chain(const LoopMesh& control, int subdivisions, SubdivisionChain* chain) {
  LoopMesh level = control;
  chain->edges.assign(size_t(subdivisions), LoopEdges{});
  chain->triangles.push_back(level.triangles);
  for (int i = 0; i < subdivisions; ++i) {
    if (Status s = number_loop_edges(level, &chain->edges[i]); !s.ok()) return s;
    chain->vertices.push_back(level.vertex_count());
    LoopMesh fine;
    loop_subdivide(level, chain->edges[i], &fine);
    level = std::move(fine);
    chain->triangles.push_back(level.triangles);
  }
  return Status::Ok();
}

// The positions of every level 0 .. subdivisions of the control mesh with
// `positions` (3 per control vertex): each linear in them.
std::vector<std::vector<double>> subdivided(const LoopMesh& control, const SubdivisionChain& chain,
                                            const std::vector<double>& positions) {
  std::vector<std::vector<double>> levels{positions};
  LoopMesh level;
  level.triangles = control.triangles;
  level.positions = positions;
  for (const LoopEdges& e : chain.edges) {
    LoopMesh fine;
    loop_subdivide(level, e, &fine);
    level = std::move(fine);
    levels.push_back(level.positions);
  }
  return levels;
}

void add_scaled(std::vector<double>* to, uint32_t v, double weight, const double* x) {
  for (int k = 0; k < 3; ++k) (*to)[3 * size_t(v) + k] += weight * x[k];
}

// The transpose of one step of loop_subdivide (spec 12.5 steps 1-2): each
// new vertex's value goes back to the coarse vertices of its mask.
std::vector<double> transposed_step(const LoopEdges& e, uint32_t vertices, const std::vector<double>& fine) {
  std::vector<double> coarse(3 * size_t(vertices), 0.0);
  for (uint32_t v = 0; v < vertices; ++v) {
    const double* x = &fine[3 * size_t(v)];
    if (e.boundary_prev[v] != kNoVertex) {
      add_scaled(&coarse, v, 0.75, x);
      add_scaled(&coarse, e.boundary_prev[v], 0.125, x);
      add_scaled(&coarse, e.boundary_next[v], 0.125, x);
      continue;
    }
    const double beta = loop_beta(e.valence[v]);
    add_scaled(&coarse, v, 1.0 - double(e.valence[v]) * beta, x);
    for (uint32_t k = e.neighbour_offset[v]; k < e.neighbour_offset[v + 1]; ++k)
      add_scaled(&coarse, e.neighbours[k], beta, x);
  }
  for (uint32_t i = 0; i < e.edge_count(); ++i) {
    const double* x = &fine[3 * (size_t(vertices) + i)];
    const bool boundary = e.is_boundary(i);
    add_scaled(&coarse, e.a[i], boundary ? 0.5 : 0.375, x);
    add_scaled(&coarse, e.b[i], boundary ? 0.5 : 0.375, x);
    if (boundary) continue;
    add_scaled(&coarse, e.c[i], 0.125, x);
    add_scaled(&coarse, e.d[i], 0.125, x);
  }
  return coarse;
}

// The transpose of the first `steps` steps of the chain.
std::vector<double> transposed(const SubdivisionChain& chain, size_t steps, std::vector<double> fine) {
  for (size_t i = steps; i-- > 0;) fine = transposed_step(chain.edges[i], chain.vertices[i], fine);
  return fine;
}

Vec3d at(const std::vector<double>& p, size_t v) { return {p[3 * v], p[3 * v + 1], p[3 * v + 2]}; }

// Per vertex of a level, how far the closest point of the surface is.
std::vector<double> to_surface(const TriangleBvh& surface, const std::vector<double>& level) {
  std::vector<double> r(level.size());
  for (size_t v = 0; v < level.size() / 3; ++v) {
    const Vec3d d = surface.closest_point(at(level, v)).point - at(level, v);
    r[3 * v] = d.x, r[3 * v + 1] = d.y, r[3 * v + 2] = d.z;
  }
  return r;
}

// Each point pulls the finest level's vertex nearest it, scaled so that the
// points weigh as much as the level's own vertices.
void add_pulls(const std::vector<double>& points, const std::vector<uint32_t>& triangles,
               const std::vector<double>& fine, std::vector<double>* r) {
  std::vector<Triangle3d> faces(triangles.size() / 3);
  for (size_t t = 0; t < faces.size(); ++t)
    faces[t] = {at(fine, triangles[3 * t]), at(fine, triangles[3 * t + 1]), at(fine, triangles[3 * t + 2])};
  const TriangleBvh subdivided_surface(faces);
  const double weight = points.empty() ? 0 : double(fine.size() / 3) / double(points.size() / 3);
  for (size_t i = 0; i < points.size() / 3; ++i) {
    const Vec3d p = at(points, i);
    const uint32_t t = subdivided_surface.closest_point(p).triangle;
    uint32_t nearest = triangles[3 * size_t(t)];
    for (int c = 1; c < 3; ++c) {
      const uint32_t v = triangles[3 * size_t(t) + c];
      const Vec3d dv = at(fine, v) - p, dn = at(fine, nearest) - p;
      if (dot(dv, dv) < dot(dn, dn)) nearest = v;
    }
    const Vec3d d = (p - at(fine, nearest)) * weight;
    (*r)[3 * nearest] += d.x, (*r)[3 * nearest + 1] += d.y, (*r)[3 * nearest + 2] += d.z;
  }
}

double dot_all(const std::vector<double>& x, const std::vector<double>& y) {
  double s = 0;
  for (size_t i = 0; i < x.size(); ++i) s += x[i] * y[i];
  return s;
}

}  // namespace

Status fit_subdivided_surface(const TriangleBvh& surface, const std::vector<double>& points, int subdivisions,
                              int passes, LoopMesh* control, SurfaceFitStats* stats) {
  if (subdivisions < 1) return Status(ErrorCode::kInvalidArgument, "the surface fit needs a subdivision step");
  SubdivisionChain chain;
  if (Status s = build_chain(*control, subdivisions, &chain); !s.ok()) return s;
  const LoopEdges& base = chain.edges.front();
  SurfaceFitStats st;
  const size_t levels = chain.edges.size() + 1;
  for (; st.passes < passes; ++st.passes) {
    const std::vector<std::vector<double>> at_level = subdivided(*control, chain, control->positions);
    std::vector<std::vector<double>> r(levels);
    for (size_t l = 0; l < levels; ++l) r[l] = to_surface(surface, at_level[l]);
    for (size_t l = 1; l < levels; ++l) add_pulls(points, chain.triangles[l], at_level[l], &r[l]);
    for (double& x : r[0]) x *= kControlMeshWeight;
    double squares = 0, count = 0;
    std::vector<double> gradient(control->positions.size(), 0.0);
    for (size_t l = 0; l < levels; ++l) {
      squares += dot_all(r[l], r[l]), count += double(r[l].size() / 3);
      const std::vector<double> back = transposed(chain, l, r[l]);
      for (size_t i = 0; i < gradient.size(); ++i) gradient[i] += back[i];
    }
    if (st.passes == 0) st.initial_rms = std::sqrt(squares / count);
    st.final_rms = std::sqrt(squares / count);
    for (uint32_t v = 0; v < control->vertex_count(); ++v)
      if (base.boundary_prev[v] != kNoVertex)
        gradient[3 * size_t(v)] = gradient[3 * size_t(v) + 1] = gradient[3 * size_t(v) + 2] = 0;
    // Every level is linear in the control positions: the step along the
    // gradient that minimizes the quadratic of these targets.
    const std::vector<std::vector<double>> moved = subdivided(*control, chain, gradient);
    double along = 0, curvature = 0;
    for (size_t l = 0; l < levels; ++l) along += dot_all(moved[l], r[l]), curvature += dot_all(moved[l], moved[l]);
    if (!(curvature > 0)) break;
    const double step = along / curvature;
    for (size_t i = 0; i < gradient.size(); ++i) control->positions[i] += step * gradient[i];
  }
  if (stats) *stats = st;
  return Status::Ok();
}

}  // namespace qmc
