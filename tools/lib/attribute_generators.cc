#include "attribute_generators.h"

#include <cmath>
#include <vector>

#include "splitmix64.h"

namespace qmc::tools {
namespace {

MeshAttribute empty_texcoords() {
  MeshAttribute a;
  a.name = "texcoord";
  a.kind = AttributeKind::kTextureCoordinate;
  a.components = 2;
  return a;
}

}  // namespace

void add_chart_texcoords(Mesh* mesh) {
  const size_t v_count = mesh->vertex_count();
  MeshAttribute a = empty_texcoords();
  std::vector<uint32_t> value_of(2 * v_count, UINT32_MAX);
  size_t k0 = 0;
  for (uint32_t degree : mesh->face_sizes) {
    double centroid = 0;
    for (uint32_t i = 0; i < degree; ++i) centroid += mesh->positions[3 * size_t(mesh->corners[k0 + i])];
    const uint32_t chart = centroid < 0 ? 0 : 1;
    for (uint32_t i = 0; i < degree; ++i) {
      const uint32_t v = mesh->corners[k0 + i];
      uint32_t& value = value_of[chart * v_count + v];
      if (value == UINT32_MAX) {
        value = uint32_t(a.value_count());
        a.values.push_back(mesh->positions[3 * size_t(v) + 1] + 3.0f * float(chart));
        a.values.push_back(mesh->positions[3 * size_t(v) + 2]);
      }
      a.corner_values.push_back(value);
    }
    k0 += degree;
  }
  mesh->attributes.push_back(std::move(a));
}

void add_mirrored_texcoords(Mesh* mesh, uint32_t seam_one_in, uint64_t seed) {
  SplitMix64 random(seed);
  const size_t n = mesh->vertex_count();
  MeshAttribute a = empty_texcoords();
  std::vector<uint32_t> value_of(2 * n, UINT32_MAX);
  const auto add_value = [&](uint32_t v, int chart) {
    a.values.push_back(mesh->positions[3 * size_t(v)] + float(chart));
    a.values.push_back(mesh->positions[3 * size_t(v) + 1]);
    return uint32_t(a.value_count() - 1);
  };
  size_t k0 = 0;
  for (uint32_t degree : mesh->face_sizes) {
    double centroid = 0;
    for (uint32_t i = 0; i < degree; ++i) centroid += mesh->positions[3 * size_t(mesh->corners[k0 + i])];
    const int chart = centroid < 0 ? 0 : 1;
    const bool own = random.next() % seam_one_in == 0;
    for (uint32_t i = 0; i < degree; ++i) {
      const uint32_t v = mesh->corners[k0 + i];
      uint32_t& value = value_of[size_t(chart) * n + v];
      if (own) {
        a.corner_values.push_back(add_value(v, chart));
        continue;
      }
      if (value == UINT32_MAX) value = add_value(v, chart);
      a.corner_values.push_back(value);
    }
    k0 += degree;
  }
  mesh->attributes.push_back(std::move(a));
}

void add_vertex_normals(Mesh* mesh) {
  const size_t n = mesh->vertex_count();
  std::vector<double> sum(3 * n, 0.0);
  size_t k0 = 0;
  for (uint32_t degree : mesh->face_sizes) {
    double normal[3] = {0, 0, 0};
    for (uint32_t i = 0; i < degree; ++i) {  // Newell's method: any polygon
      const float* p = &mesh->positions[3 * size_t(mesh->corners[k0 + i])];
      const float* q = &mesh->positions[3 * size_t(mesh->corners[k0 + (i + 1) % degree])];
      normal[0] += (double(p[1]) - q[1]) * (double(p[2]) + q[2]);
      normal[1] += (double(p[2]) - q[2]) * (double(p[0]) + q[0]);
      normal[2] += (double(p[0]) - q[0]) * (double(p[1]) + q[1]);
    }
    for (uint32_t i = 0; i < degree; ++i)
      for (int a = 0; a < 3; ++a) sum[3 * size_t(mesh->corners[k0 + i]) + a] += normal[a];
    k0 += degree;
  }
  MeshAttribute a;
  a.name = "normal";
  a.kind = AttributeKind::kNormal;
  a.components = 3;
  for (size_t v = 0; v < n; ++v) {
    const double length = std::sqrt(sum[3 * v] * sum[3 * v] + sum[3 * v + 1] * sum[3 * v + 1] + sum[3 * v + 2] * sum[3 * v + 2]);
    for (int c = 0; c < 3; ++c) a.values.push_back(length > 0 ? float(sum[3 * v + c] / length) : (c == 2 ? 1.f : 0.f));
  }
  a.corner_values = mesh->corners;
  mesh->attributes.push_back(std::move(a));
}

void add_random_corner_attribute(Mesh* mesh, uint64_t seed, const char* name, AttributeKind kind,
                                 uint32_t components) {
  SplitMix64 rng(seed);
  MeshAttribute a;
  a.name = name;
  a.kind = kind;
  a.components = components;
  const size_t n = mesh->vertex_count();
  std::vector<uint32_t> first(n), count(n);
  for (size_t v = 0; v < n; ++v) {
    first[v] = uint32_t(a.value_count());
    count[v] = 1 + rng.below(3);
    for (uint32_t i = 0; i < count[v] * components; ++i) a.values.push_back(float(int(rng.below(8192)) - 4096) / 1024.f);
  }
  for (uint32_t v : mesh->corners) {
    if (rng.below(50) == 0 && a.value_count() > 0)
      a.corner_values.push_back(rng.below(uint32_t(a.value_count())));
    else
      a.corner_values.push_back(first[v] + rng.below(count[v]));
  }
  mesh->attributes.push_back(std::move(a));
}

void add_face_labels(Mesh* mesh, uint64_t seed, uint32_t run) {
  SplitMix64 rng(seed);
  FaceLabels material{"material", {"m.mtl"}, {"red", "green", "blue"}, {}};
  FaceLabels group{"group", {}, {"left", ""}, {}};
  uint32_t current = material.none();
  for (size_t f = 0; f < mesh->face_count(); ++f) {
    if (f >= 3 && rng.below(run) == 0) current = rng.below(3);
    material.face_values.push_back(current);
    group.face_values.push_back(uint32_t(f / 7 % 2));
  }
  mesh->face_labels.push_back(std::move(material));
  mesh->face_labels.push_back(std::move(group));
}

}  // namespace qmc::tools
