// Metro-style surface distance (Cignoni, Rocchini, Scopigno 1998); the
// definitions are in mesh_distance.h.
#include "mesh_distance.h"

#include "splitmix64.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <string>

namespace qmc::tools {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Vec3d position(const qmc::Mesh& mesh, uint32_t v) {
  return {mesh.positions[3 * size_t(v)], mesh.positions[3 * size_t(v) + 1], mesh.positions[3 * size_t(v) + 2]};
}

// Sample points and closest points carry rounding errors of a few units in
// the last place of double coordinates, so a point on a shared surface comes
// out at 1e-17 instead of 0. Distances up to 2^-40 times the largest
// coordinate magnitude are such noise: they are 2^16 times finer than float
// input coordinates can resolve, and counting them as 0 makes coincident
// surfaces measure exactly 0 (and PSNR infinite).
double rounding_noise(const qmc::Mesh& a, const qmc::Mesh& b) {
  double largest = 0;
  for (const qmc::Mesh* m : {&a, &b})
    for (float v : m->positions) largest = std::max(largest, std::fabs(double(v)));
  return std::ldexp(largest, -40);
}

double bbox_diagonal(const qmc::Mesh& mesh) {
  if (mesh.vertex_count() == 0) return 0;
  double lo[3], hi[3];
  for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = mesh.positions[size_t(axis)];
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const int axis = int(i % 3);
    lo[axis] = std::min(lo[axis], double(mesh.positions[i]));
    hi[axis] = std::max(hi[axis], double(mesh.positions[i]));
  }
  double sum = 0;
  for (int axis = 0; axis < 3; ++axis) sum += (hi[axis] - lo[axis]) * (hi[axis] - lo[axis]);
  return std::sqrt(sum);
}

// Everything needed to measure distances from and to one mesh.
struct Surface {
  std::vector<Triangle> triangles;
  std::vector<uint32_t> vertices;
  SurfaceInfo info;
};

qmc::Status prepare(const qmc::Mesh& mesh, const char* name, Surface* s) {
  qmc::Status status = fan_triangulate(mesh, &s->triangles, &s->info.degenerate, &s->vertices);
  if (!status.ok()) return qmc::Status(status.code(), std::string("mesh ") + name + ": " + status.message());
  if (s->triangles.empty())
    return qmc::Status(qmc::ErrorCode::kInvalidArgument,
                       std::string("mesh ") + name + " has no face of non-zero area to measure distances to");
  s->info.triangles = s->triangles.size();
  s->info.referenced_vertices = s->vertices.size();
  for (const Triangle& t : s->triangles) s->info.area += triangle_area(t);
  return qmc::Status::Ok();
}

// Distances from the samples and vertices of `from` to the triangles in `to`.
class OneSidedMeasure {
 public:
  OneSidedMeasure(const TriangleBvh& to, double noise, const MeshDistanceOptions& options, size_t* done, size_t total)
      : to_(to), noise_squared_(noise * noise), options_(options), done_(done), total_(total) {}

  OneSidedDistance run(const std::vector<SurfaceSample>& samples, const qmc::Mesh& from_mesh,
                       const std::vector<uint32_t>& vertices) {
    OneSidedDistance r;
    double sum = 0, sum_squares = 0;
    for (const SurfaceSample& s : samples) {
      const double d2 = query(s.point);
      sum += std::sqrt(d2);
      sum_squares += d2;
    }
    for (uint32_t v : vertices) query(position(from_mesh, v));
    r.area_samples = samples.size();
    r.vertex_samples = vertices.size();
    if (!samples.empty()) {
      r.mean = sum / double(samples.size());
      r.rms = std::sqrt(sum_squares / double(samples.size()));
    }
    r.max = std::sqrt(max_squared_);
    return r;
  }

 private:
  double query(const Vec3d& p) {
    // Consecutive samples lie on the same or neighbouring triangles, so the
    // previous answer is usually the new one or close to it.
    double d2 = to_.distance_squared(p, hint_, &hint_, noise_squared_);
    if (d2 <= noise_squared_) d2 = 0;
    max_squared_ = std::max(max_squared_, d2);
    if ((++*done_ & 0x3fff) == 0 && options_.progress) options_.progress(*done_, total_);
    return d2;
  }

  const TriangleBvh& to_;
  double noise_squared_;
  const MeshDistanceOptions& options_;
  size_t* done_;
  size_t total_;
  uint32_t hint_ = UINT32_MAX;
  double max_squared_ = 0;
};

}  // namespace

double triangle_area(const Triangle& t) {
  const Vec3d n = cross(t.b - t.a, t.c - t.a);
  return 0.5 * std::sqrt(dot(n, n));
}

qmc::Status fan_triangulate(const qmc::Mesh& mesh, std::vector<Triangle>* triangles, size_t* degenerate,
                            std::vector<uint32_t>* vertices) {
  size_t total_corners = 0;
  for (uint32_t size : mesh.face_sizes) total_corners += size;
  if (total_corners != mesh.corners.size() || mesh.positions.size() % 3 != 0)
    return qmc::Status(qmc::ErrorCode::kInvalidArgument,
                       "face sizes add up to " + std::to_string(total_corners) + " corners, but there are " +
                           std::to_string(mesh.corners.size()));
  const size_t n = mesh.vertex_count();
  for (size_t i = 0; i < mesh.corners.size(); ++i)
    if (mesh.corners[i] >= n)
      return qmc::Status(qmc::ErrorCode::kInvalidArgument, "corner " + std::to_string(i) + " names vertex " +
                                                               std::to_string(mesh.corners[i]) + " of " +
                                                               std::to_string(n));
  std::vector<Triangle> out;
  size_t skipped = 0;
  size_t c = 0;
  for (uint32_t size : mesh.face_sizes) {
    for (uint32_t i = 1; i + 1 < size; ++i) {
      const Triangle t{position(mesh, mesh.corners[c]), position(mesh, mesh.corners[c + i]),
                       position(mesh, mesh.corners[c + i + 1])};
      if (triangle_area(t) > 0)
        out.push_back(t);
      else
        ++skipped;
    }
    c += size;
  }
  if (vertices) {
    std::vector<char> used(n, 0);
    for (uint32_t v : mesh.corners) used[v] = 1;
    vertices->clear();
    for (size_t v = 0; v < n; ++v)
      if (used[v]) vertices->push_back(uint32_t(v));
  }
  if (triangles) *triangles = std::move(out);
  if (degenerate) *degenerate = skipped;
  return qmc::Status::Ok();
}

std::vector<SurfaceSample> sample_surface(const std::vector<Triangle>& triangles, size_t count, uint64_t seed) {
  std::vector<double> area(triangles.size());
  double total = 0;
  size_t last_positive = 0;
  for (size_t i = 0; i < triangles.size(); ++i) {
    area[i] = triangle_area(triangles[i]);
    total += area[i];
    if (area[i] > 0) last_positive = i;
  }
  std::vector<SurfaceSample> out;
  if (count == 0 || !(total > 0)) return out;
  out.reserve(count);
  SplitMix64 rng(seed);
  // Systematic sampling: sample k sits at cumulative area (k + offset) * step.
  // Every point of the surface is equally likely to be picked, as with
  // independent draws, but each triangle gets its expected share rounded up
  // or down instead of a binomial count, so estimates vary less.
  const double step = total / double(count);
  const double offset = rng.unit();
  double cumulative = 0;
  for (size_t i = 0; i < triangles.size() && out.size() < count; ++i) {
    cumulative += area[i];
    size_t end = count;  // rounding must not lose samples past the last triangle
    if (i < last_positive) {
      const double k = std::ceil(cumulative / step - offset);
      end = k <= 0 ? 0 : std::min(count, size_t(k));
    }
    const Triangle& t = triangles[i];
    while (out.size() < end) {
      // sqrt makes the distance from a uniform in area, not in length.
      const double s = std::sqrt(rng.unit()), r = rng.unit();
      const double wa = 1 - s, wb = s * (1 - r), wc = s * r;
      out.push_back({{wa * t.a.x + wb * t.b.x + wc * t.c.x, wa * t.a.y + wb * t.b.y + wc * t.c.y,
                      wa * t.a.z + wb * t.b.z + wc * t.c.z},
                     uint32_t(i)});
    }
  }
  return out;
}

qmc::Status measure_mesh_distance(const qmc::Mesh& a, const qmc::Mesh& b, const MeshDistanceOptions& options,
                                  MeshDistance* out) {
  Surface sa, sb;
  if (qmc::Status s = prepare(a, "A", &sa); !s.ok()) return s;
  if (qmc::Status s = prepare(b, "B", &sb); !s.ok()) return s;
  // Different streams for the two surfaces, so identical meshes are not
  // sampled at identical points (which would hide nothing, but would make the
  // identical-mesh result a special case rather than an ordinary one).
  const std::vector<SurfaceSample> samples_a = sample_surface(sa.triangles, options.samples, options.seed);
  const std::vector<SurfaceSample> samples_b =
      sample_surface(sb.triangles, options.samples, options.seed ^ 0xD1B54A32D192ED03ull);
  const TriangleBvh bvh_a(sa.triangles), bvh_b(sb.triangles);
  const size_t total = samples_a.size() + sa.vertices.size() + samples_b.size() + sb.vertices.size();
  size_t done = 0;
  MeshDistance r;
  r.a = sa.info;
  r.b = sb.info;
  const double noise = rounding_noise(a, b);
  r.a_to_b = OneSidedMeasure(bvh_b, noise, options, &done, total).run(samples_a, a, sa.vertices);
  r.b_to_a = OneSidedMeasure(bvh_a, noise, options, &done, total).run(samples_b, b, sb.vertices);
  if (options.progress) options.progress(total, total);
  r.hausdorff = std::max(r.a_to_b.max, r.b_to_a.max);
  r.l2 = std::max(r.a_to_b.rms, r.b_to_a.rms);
  r.mean = std::max(r.a_to_b.mean, r.b_to_a.mean);
  r.bbox_diagonal = bbox_diagonal(a);
  r.psnr_db = r.l2 > 0 ? 20 * std::log10(r.bbox_diagonal / r.l2) : kInfinity;
  *out = r;
  return qmc::Status::Ok();
}

}  // namespace qmc::tools
