// Seed 002 "Methods" (Floater parametrization of the cut disk onto a
// rectangle with mean-value coordinates, eqs. (4)-(5)), with the boundary
// laid out so that the two sides of every cut land on matching border pixels
// (seed 002: "the edge of the pairs is recorded to ensure that no cracks
// occur on the surface"). See gim_parametrization.h for the contract.
#include "geometry/gim_parametrization.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace qmc {
namespace {

Status invalid(std::string message) { return Status(ErrorCode::kInvalidArgument, std::move(message)); }

void report(const std::function<void(double)>& progress, double f) {
  if (progress) progress(f);
}

struct P3 {
  double x, y, z;
};
P3 point(const GimTriMesh& mesh, const DiskCut& cut, uint32_t disk_vertex) {
  const double* p = &mesh.positions[3 * size_t(cut.original_vertex[disk_vertex])];
  return {p[0], p[1], p[2]};
}
double distance(P3 a, P3 b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

Status check_cut(const GimTriMesh& mesh, const DiskCut& cut) {
  const size_t nv = cut.original_vertex.size(), n = cut.boundary_loop.size();
  if (cut.triangles.size() != mesh.triangles.size())
    return invalid("the cut has " + std::to_string(cut.triangles.size() / 3) + " triangles, the mesh " +
                   std::to_string(mesh.triangle_count()));
  for (uint32_t v : cut.original_vertex)
    if (v >= mesh.vertex_count())
      return invalid("the cut refers to input vertex " + std::to_string(v) + " of " +
                     std::to_string(mesh.vertex_count()));
  for (uint32_t v : cut.triangles)
    if (v >= nv)
      return invalid("a cut triangle refers to disk vertex " + std::to_string(v) + " of " + std::to_string(nv));
  if (n < 3 || cut.boundary_mate.size() != n)
    return invalid("the cut's boundary loop has " + std::to_string(n) + " edges and " +
                   std::to_string(cut.boundary_mate.size()) + " mates");
  for (size_t i = 0; i < n; ++i) {
    if (cut.boundary_loop[i] >= nv)
      return invalid("the boundary loop refers to disk vertex " + std::to_string(cut.boundary_loop[i]));
    const int32_t m = cut.boundary_mate[i];
    if (m >= int32_t(n) || (m >= 0 && cut.boundary_mate[m] != int32_t(i)))
      return invalid("boundary edge " + std::to_string(i) + " has an inconsistent mate " + std::to_string(m));
  }
  return Status::Ok();
}

// Arc length of every boundary edge (3-D).
std::vector<double> edge_lengths(const GimTriMesh& mesh, const DiskCut& cut) {
  const size_t n = cut.boundary_loop.size();
  std::vector<double> len(n);
  for (size_t i = 0; i < n; ++i)
    len[i] = distance(point(mesh, cut, cut.boundary_loop[i]), point(mesh, cut, cut.boundary_loop[(i + 1) % n]));
  return len;
}

// Pixel steps per run: proportional to 3-D length, a run and its mate the
// same, P in total, each >= 1 (largest remainder; a mated pair is one unit
// that takes two steps at a time).
Status allocate_steps(std::vector<GimBorderRun>* runs, const std::vector<double>& run_length, uint32_t P) {
  const size_t nr = runs->size();
  struct Unit {
    std::vector<uint32_t> members;
    double ideal = 0;
    uint32_t count = 1;
  };
  std::vector<Unit> units;
  double total = 0;
  for (size_t r = 0; r < nr; ++r) {
    total += run_length[r];
    const int32_t m = (*runs)[r].mate;
    if (m >= 0 && uint32_t(m) < r) continue;
    units.push_back(
        {m >= 0 ? std::vector<uint32_t>{uint32_t(r), uint32_t(m)} : std::vector<uint32_t>{uint32_t(r)}, run_length[r]});
  }
  if (nr > P)
    return invalid("image too small for the cut: " + std::to_string(nr) + " runs, " + std::to_string(P) +
                   " border pixels");
  int64_t left = P;
  for (Unit& u : units) {
    u.ideal = total > 0 ? P * u.ideal / total : double(P) / nr;
    u.count = std::max<uint32_t>(1, uint32_t(std::floor(u.ideal)));
    left -= int64_t(u.count) * u.members.size();
  }
  // Each step moves `left` towards 0 by one unit's multiplicity (1 or 2).
  // Taking a pair back may overshoot to +1; an unmated run then exists
  // (pairs alone add up to an even total, and P is even) and takes it. So
  // 2 P + units steps are plenty.
  for (size_t step = 0; left != 0 && step < 2 * size_t(P) + units.size(); ++step) {
    Unit* best = nullptr;
    for (Unit& u : units) {
      const double gap = u.ideal - u.count;
      if (left > 0 && int64_t(u.members.size()) <= left && (!best || gap > best->ideal - best->count)) best = &u;
      if (left < 0 && u.count > 1 && (!best || gap < best->ideal - best->count)) best = &u;
    }
    if (!best) break;
    const int64_t sign = left > 0 ? 1 : -1;
    best->count = uint32_t(int64_t(best->count) + sign);
    left -= sign * int64_t(best->members.size());
  }
  if (left != 0)
    return invalid("image too small for the cut: " + std::to_string(nr) + " runs (" + std::to_string(units.size()) +
                   " independent) do not fit " + std::to_string(P) + " border pixels");
  for (const Unit& u : units)
    for (uint32_t r : u.members) (*runs)[r].pixel_steps = u.count;
  return Status::Ok();
}

// Border index q (0 .. P) -> (u, v), counter-clockwise in (u, v) from (0, 0).
void border_uv(double q, uint32_t W, uint32_t H, double* u, double* v) {
  const double w = W - 1.0, h = H - 1.0;
  if (q <= w)
    *u = q, *v = 0;
  else if (q <= w + h)
    *u = w, *v = q - w;
  else if (q <= 2 * w + h)
    *u = w - (q - w - h), *v = h;
  else
    *u = 0, *v = h - (q - 2 * w - h);
}

bool is_corner(uint32_t q, uint32_t W, uint32_t H) {
  return q == 0 || q == W - 1 || q == W - 1 + H - 1 || q == 2 * (W - 1) + H - 1;
}

// A path end (a node where a run meets its own mate, the ends of the genus-0
// long path) must not sit on a corner: its two neighbouring border pixels
// are one surface point, and at a corner they are two corners of the same
// 2 x 2 block, which would make the rebuilt grid's corner quad degenerate.
// On a straight side they belong to two different blocks that just fold
// onto each other along the seam.
uint32_t corner_free_offset(const std::vector<GimBorderRun>& runs, uint32_t W, uint32_t H, uint32_t P) {
  std::vector<uint32_t> tips;
  uint32_t q = 0;
  for (size_t r = 0; r < runs.size(); ++r) {
    const size_t prev = (r + runs.size() - 1) % runs.size();
    if (runs[prev].mate == int32_t(r)) tips.push_back(q);
    q += runs[r].pixel_steps;
  }
  for (uint32_t offset = 0; offset < P; ++offset) {
    bool ok = true;
    for (uint32_t t : tips) ok = ok && !is_corner((t + offset) % P, W, H);
    if (ok) return offset;
  }
  return 0;
}

// Position along the boundary loop (edge index + fraction) at fraction t of
// run r's 3-D length.
double run_arc(const GimBorderRun& run, const std::vector<double>& len, double run_length, double t, size_t n) {
  if (t <= 0) return run.first_edge;
  double target = t * run_length, acc = 0;
  for (uint32_t j = 0; j < run.edge_count; ++j) {
    const size_t e = (run.first_edge + j) % n;
    const double l = run_length > 0 ? len[e] : 1.0;
    if (acc + l >= target || j + 1 == run.edge_count) {
      const double f = l > 0 ? std::min(1.0, std::max(0.0, (target - acc) / l)) : 0;
      const double arc = e + f;
      return arc >= n ? arc - n : arc;
    }
    acc += l;
  }
  return run.first_edge;
}

double tan_half_angle(P3 o, P3 a, P3 b) {
  const P3 e1{a.x - o.x, a.y - o.y, a.z - o.z}, e2{b.x - o.x, b.y - o.y, b.z - o.z};
  const P3 c{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x};
  const double sin_part = std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z);
  const double cos_part =
      std::sqrt(e1.x * e1.x + e1.y * e1.y + e1.z * e1.z) * std::sqrt(e2.x * e2.x + e2.y * e2.y + e2.z * e2.z) +
      e1.x * e2.x + e1.y * e2.y + e1.z * e2.z;
  // tan(a / 2) = sin a / (1 + cos a), written without cancellation.
  return sin_part / cos_part;
}

}  // namespace

std::vector<GimBorderRun> find_border_runs(const DiskCut& cut) {
  const size_t n = cut.boundary_loop.size();
  std::vector<GimBorderRun> runs;
  if (n == 0 || cut.boundary_mate.size() != n) return runs;
  auto mate = [&](size_t i) { return cut.boundary_mate[i % n]; };
  // A run starts at edge i + 1 unless it continues edge i's run.
  auto starts = [&](size_t i1) {
    const size_t i = (i1 + n - 1) % n;
    const int32_t a = mate(i), b = mate(i1);
    if ((a < 0) != (b < 0)) return true;
    if (a < 0) return false;
    if (b == int32_t(i)) return true;  // a path end: the run meets its own mate
    return b != int32_t((size_t(a) + n - 1) % n);
  };
  std::vector<uint32_t> first;
  for (size_t i = 0; i < n; ++i)
    if (starts(i)) first.push_back(uint32_t(i));
  if (first.empty()) first.push_back(0);
  for (size_t k = 0; k < first.size(); ++k) {
    const uint32_t end = k + 1 < first.size() ? first[k + 1] : first[0] + uint32_t(n);
    runs.push_back({first[k], end - first[k], -1, 0, 0});
  }
  std::vector<int32_t> run_of_edge(n);
  for (size_t r = 0; r < runs.size(); ++r)
    for (uint32_t j = 0; j < runs[r].edge_count; ++j) run_of_edge[(runs[r].first_edge + j) % n] = int32_t(r);
  for (GimBorderRun& run : runs)
    if (mate(run.first_edge) >= 0) run.mate = run_of_edge[mate(run.first_edge)];
  return runs;
}

Status mean_value_weights(const GimTriMesh& mesh, const DiskCut& cut, MeanValueWeights* out) {
  if (Status s = check_cut(mesh, cut); !s.ok()) return s;
  const uint32_t nv = uint32_t(cut.original_vertex.size());
  std::vector<uint8_t> on_boundary(nv, 0);
  for (uint32_t v : cut.boundary_loop) on_boundary[v] = 1;
  struct Entry {
    uint32_t v, w;
    double weight;
  };
  std::vector<Entry> entries;
  for (size_t t = 0; t < cut.triangles.size() / 3; ++t) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t o = cut.triangles[3 * t + k], a = cut.triangles[3 * t + (k + 1) % 3],
                     b = cut.triangles[3 * t + (k + 2) % 3];
      if (on_boundary[o]) continue;
      const P3 po = point(mesh, cut, o), pa = point(mesh, cut, a), pb = point(mesh, cut, b);
      const double th = tan_half_angle(po, pa, pb);
      entries.push_back({o, a, th / distance(po, pa)});
      entries.push_back({o, b, th / distance(po, pb)});
    }
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& x, const Entry& y) { return x.v != y.v ? x.v < y.v : x.w < y.w; });
  out->offset.assign(nv + 1, 0);
  out->neighbour.clear(), out->weight.clear();
  for (size_t i = 0; i < entries.size();) {
    size_t j = i;
    double sum = 0;
    for (; j < entries.size() && entries[j].v == entries[i].v && entries[j].w == entries[i].w; ++j)
      sum += entries[j].weight;
    out->neighbour.push_back(entries[i].w);
    out->weight.push_back(sum);
    ++out->offset[entries[i].v + 1];
    i = j;
  }
  for (uint32_t v = 0; v < nv; ++v) out->offset[v + 1] += out->offset[v];
  // Coincident points or a 180-degree angle make eq. (5) infinite or
  // undefined there; uniform weights (Tutte) keep the map a convex
  // combination for that vertex.
  for (uint32_t v = 0; v < nv; ++v) {
    bool finite = true;
    double sum = 0;
    for (uint32_t k = out->offset[v]; k < out->offset[v + 1]; ++k)
      finite = finite && std::isfinite(out->weight[k]) && out->weight[k] >= 0, sum += out->weight[k];
    if (!finite || !(sum > 0))
      for (uint32_t k = out->offset[v]; k < out->offset[v + 1]; ++k) out->weight[k] = 1;
  }
  return Status::Ok();
}

Status parametrize_on_rectangle(const GimTriMesh& mesh, const DiskCut& cut, uint32_t width, uint32_t height,
                                DiskParametrization* out, const std::function<void(double)>& progress,
                                GimParamStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  if (width < 2 || height < 2 || width > (1u << 15) || height > (1u << 15))
    return invalid("image size " + std::to_string(width) + " x " + std::to_string(height) + " outside 2 .. 32768");
  if (Status s = check_cut(mesh, cut); !s.ok()) return s;
  const uint32_t P = 2 * (width - 1) + 2 * (height - 1);
  const size_t n = cut.boundary_loop.size();
  const uint32_t nv = uint32_t(cut.original_vertex.size());

  std::vector<GimBorderRun> runs = find_border_runs(cut);
  for (size_t r = 0; r < runs.size(); ++r) {
    const int32_t m = runs[r].mate;
    if (m >= 0 && (runs[m].mate != int32_t(r) || runs[m].edge_count != runs[r].edge_count))
      return invalid("boundary runs " + std::to_string(r) + " and " + std::to_string(m) +
                     " are not mates of the same length");
  }
  const std::vector<double> len = edge_lengths(mesh, cut);
  std::vector<double> run_length(runs.size(), 0);
  for (size_t r = 0; r < runs.size(); ++r)
    for (uint32_t j = 0; j < runs[r].edge_count; ++j) run_length[r] += len[(runs[r].first_edge + j) % n];
  if (Status s = allocate_steps(&runs, run_length, P); !s.ok()) return s;
  const uint32_t offset = corner_free_offset(runs, width, height, P);
  uint32_t q = offset;
  for (GimBorderRun& run : runs) run.first_border_pixel = q, q = (q + run.pixel_steps) % P;

  DiskParametrization param;
  param.width = width, param.height = height;
  param.uv.assign(2 * size_t(nv), 0);
  // Boundary vertices by arc length within their run.
  for (size_t r = 0; r < runs.size(); ++r) {
    double acc = 0;
    for (uint32_t j = 0; j < runs[r].edge_count; ++j) {
      const size_t e = (runs[r].first_edge + j) % n;
      const double t = run_length[r] > 0 ? acc / run_length[r] : double(j) / runs[r].edge_count;
      double b = runs[r].first_border_pixel + t * runs[r].pixel_steps;
      if (b >= P) b -= P;
      const uint32_t v = cut.boundary_loop[e];
      border_uv(b, width, height, &param.uv[2 * v], &param.uv[2 * v + 1]);
      acc += len[e];
    }
  }
  // Border pixels: index within their run -> arc position.
  param.border_pixels.resize(P);
  param.border_arc.resize(P);
  for (uint32_t k = 0; k < P; ++k) {
    double u, v;
    border_uv(k, width, height, &u, &v);
    param.border_pixels[k] = uint32_t(v) * width + uint32_t(u);
  }
  for (size_t r = 0; r < runs.size(); ++r)
    for (uint32_t k = 0; k < runs[r].pixel_steps; ++k)
      param.border_arc[(runs[r].first_border_pixel + k) % P] =
          run_arc(runs[r], len, run_length[r], double(k) / runs[r].pixel_steps, n);
  report(progress, 0.1);

  // Interior: sum_j w_ij (x_i - x_j) = 0 (eq. (4) with eq. (5)'s weights).
  MeanValueWeights mv;
  if (Status s = mean_value_weights(mesh, cut, &mv); !s.ok()) return s;
  std::vector<int32_t> unknown(nv, -1);
  std::vector<uint8_t> on_boundary(nv, 0), referenced(nv, 0);
  for (uint32_t v : cut.boundary_loop) on_boundary[v] = 1;
  for (uint32_t v : cut.triangles) referenced[v] = 1;
  int32_t ni = 0;
  for (uint32_t v = 0; v < nv; ++v)
    if (!on_boundary[v] && referenced[v]) unknown[v] = ni++;
  if (ni > 0) {
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
    for (uint32_t v = 0; v < nv; ++v) {
      if (unknown[v] < 0) continue;
      double sum = 0;
      for (uint32_t k = mv.offset[v]; k < mv.offset[v + 1]; ++k) {
        const uint32_t w = mv.neighbour[k];
        sum += mv.weight[k];
        if (unknown[w] >= 0)
          triplets.emplace_back(unknown[v], unknown[w], -mv.weight[k]);
        else
          rhs(unknown[v], 0) += mv.weight[k] * param.uv[2 * w],
              rhs(unknown[v], 1) += mv.weight[k] * param.uv[2 * w + 1];
      }
      triplets.emplace_back(unknown[v], unknown[v], sum);
    }
    Eigen::SparseMatrix<double> A(ni, ni);
    A.setFromTriplets(triplets.begin(), triplets.end());
    A.makeCompressed();
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    lu.compute(A);
    report(progress, 0.7);
    if (lu.info() != Eigen::Success)
      return invalid("mean-value system (" + std::to_string(ni) +
                     " unknowns) could not be factorized: " + lu.lastErrorMessage());
    const Eigen::MatrixXd x = lu.solve(rhs);
    if (lu.info() != Eigen::Success || !x.allFinite())
      return invalid("mean-value system (" + std::to_string(ni) + " unknowns) has no finite solution");
    for (uint32_t v = 0; v < nv; ++v)
      if (unknown[v] >= 0) param.uv[2 * v] = x(unknown[v], 0), param.uv[2 * v + 1] = x(unknown[v], 1);
  }
  report(progress, 0.9);

  GimParamStats st;
  st.runs = uint32_t(runs.size());
  st.interior_vertices = uint32_t(ni);
  st.border_offset = offset;
  const double eps = 1e-12 * double(width) * height;
  for (size_t t = 0; t < cut.triangles.size() / 3; ++t) {
    const double* a = &param.uv[2 * size_t(cut.triangles[3 * t])];
    const double* b = &param.uv[2 * size_t(cut.triangles[3 * t + 1])];
    const double* c = &param.uv[2 * size_t(cut.triangles[3 * t + 2])];
    const double area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    if (area < -eps)
      ++st.flipped_triangles;
    else if (area <= eps)
      ++st.degenerate_triangles;
  }
  for (uint32_t v = 0; v < nv; ++v) {
    if (unknown[v] < 0) continue;
    double sum = 0, ru = 0, rv = 0;
    for (uint32_t k = mv.offset[v]; k < mv.offset[v + 1]; ++k) sum += mv.weight[k];
    for (uint32_t k = mv.offset[v]; k < mv.offset[v + 1]; ++k) {
      const uint32_t w = mv.neighbour[k];
      ru += mv.weight[k] / sum * (param.uv[2 * w] - param.uv[2 * v]);
      rv += mv.weight[k] / sum * (param.uv[2 * w + 1] - param.uv[2 * v + 1]);
    }
    st.max_residual = std::max(st.max_residual, std::hypot(ru, rv));
  }
  param.runs = std::move(runs);
  *out = std::move(param);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  report(progress, 1.0);
  return Status::Ok();
}

}  // namespace qmc
