// Two-sided RMS distance of a level to the input (level_distance.h).
#include "geometry/level_distance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bitio/splitmix64_mix.h"
#include "geometry/loop_fitting.h"

namespace qmc {
namespace {

// The midpoint of every edge of `mesh`, once, weighted by a third of the
// area of each face it borders; of a mesh of more than `most` edges, a
// pseudo-random share of about `most` of them (by a hash of the edge's ends,
// which no order of the mesh's numbering correlates with, so the same mesh
// gives the same samples). Each face's edge a -> b is
// listed under a with its face's third; an edge is sampled from its lower
// vertex, or from its upper one when nothing runs the other way (a boundary
// edge).
void midpoint_samples(const LoopMesh& mesh, size_t most, std::vector<double>* points, std::vector<double>* weights) {
  const uint32_t n = mesh.vertex_count();
  std::vector<uint32_t> offset(size_t(n) + 1, 0);
  for (uint32_t v : mesh.triangles) ++offset[v + 1];
  for (uint32_t v = 0; v < n; ++v) offset[v + 1] += offset[v];
  std::vector<uint32_t> to(mesh.triangles.size()), fill(offset.begin(), offset.end() - 1);
  std::vector<double> third(mesh.triangles.size());
  for (size_t f = 0; f < mesh.face_count(); ++f) {
    const uint32_t* t = &mesh.triangles[3 * f];
    const Vec3d a = position_of(mesh.positions, t[0]);
    const Vec3d normal = cross(position_of(mesh.positions, t[1]) - a, position_of(mesh.positions, t[2]) - a);
    const double third_of_area = std::sqrt(dot(normal, normal)) / 6;
    for (int k = 0; k < 3; ++k) {
      const uint32_t slot = fill[t[k]]++;
      to[slot] = t[(k + 1) % 3];
      third[slot] = third_of_area;
    }
  }
  auto reverse_third = [&](uint32_t a, uint32_t b) {  // of b -> a; -1 if no face has it
    for (uint32_t i = offset[b]; i < offset[b + 1]; ++i)
      if (to[i] == a) return third[i];
    return -1.0;
  };
  const double edges = 1.5 * double(mesh.face_count());
  const uint64_t threshold =
      edges <= double(most) ? UINT64_MAX : uint64_t(double(most) / edges * 18446744073709551615.0);
  for (uint32_t a = 0; a < n; ++a)
    for (uint32_t i = offset[a]; i < offset[a + 1]; ++i) {
      const uint32_t b = to[i];
      if (splitmix64_mix(uint64_t(std::min(a, b)) << 32 | std::max(a, b)) > threshold) continue;
      const double other = reverse_third(a, b);
      if (a > b && other >= 0) continue;  // sampled from b
      const Vec3d m = (position_of(mesh.positions, a) + position_of(mesh.positions, b)) * 0.5;
      points->insert(points->end(), {m.x, m.y, m.z});
      weights->push_back(third[i] + std::max(other, 0.0));
    }
}

// The weighted RMS distance from `points` to `surface`; each query seeds the
// next with its triangle, as consecutive midpoints mostly share one.
double rms_to(const TriangleBvh& surface, const std::vector<double>& points, const std::vector<double>& weights) {
  double sum = 0, total = 0;
  uint32_t hint = kNoTriangle;
  for (size_t i = 0; i < weights.size(); ++i) {
    if (!(weights[i] > 0)) continue;
    sum += weights[i] * surface.distance_squared(position_of(points, uint32_t(i)), hint, &hint);
    total += weights[i];
  }
  return total > 0 ? std::sqrt(sum / total) : std::numeric_limits<double>::infinity();
}

}  // namespace

LevelDistance::LevelDistance(const TriangleBvh& input, const LoopMesh& input_mesh, size_t most_input_samples)
    : input_(input) {
  midpoint_samples(input_mesh, most_input_samples, &input_points_, &input_weights_);
}

double LevelDistance::operator()(const LoopMesh& level) const {
  std::vector<double> points, weights;
  midpoint_samples(level, SIZE_MAX, &points, &weights);  // every one: a level's own error varies too much
  const double to_input = rms_to(input_, points, weights);
  if (!std::isfinite(to_input)) return to_input;
  const TriangleBvh level_surface(loop_mesh_triangles(level));
  return std::max(to_input, rms_to(level_surface, input_points_, input_weights_));
}

}  // namespace qmc
