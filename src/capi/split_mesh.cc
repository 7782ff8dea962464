// qmc_decoder_split_mesh (include/qmc/qmc.h): the vertices a GPU draws a mesh
// with attributes per corner (spec 15) from, one per distinct (mesh vertex,
// value of every corner attribute) among the corners, so that a vertex is
// split only where a seam gives it several values. Built on the C API's own
// mesh and corner attributes, in a file of its own: the WebAssembly package,
// which does this in JavaScript (web/src/QMCLoader.js), leaves it out.
#include <cstdlib>
#include <cstring>
#include <vector>

#include "decoder/no_throw.h"
#include "qmc/qmc.h"

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// The corner attributes' corner_values, freed with the object.
struct CornerValues {
  std::vector<uint32_t*> arrays;
  ~CornerValues() {
    for (uint32_t* a : arrays) qmc_free(a);
  }
  bool same(uint32_t a, uint32_t b) const {
    for (const uint32_t* values : arrays)
      if (values[a] != values[b]) return false;
    return true;
  }
};

int read_corner_values(const qmc_decoder* decoder, CornerValues* out) {
  for (int i = 0; i < qmc_decoder_corner_attribute_count(decoder); ++i) {
    qmc_corner_attribute a;
    if (int error = qmc_decoder_corner_attribute(decoder, i, &a); error != QMC_OK) return error;
    qmc_free(a.values);
    out->arrays.push_back(a.corner_values);
  }
  return QMC_OK;
}

// Split vertices numbered in the order of their first corners. The split
// vertices of one mesh vertex are chained from its first, so a corner is
// compared with those of its own vertex only.
void split(const qmc_mesh& mesh, const CornerValues& values, std::vector<uint32_t>* first_corner,
           std::vector<uint32_t>* of_corner) {
  of_corner->resize(mesh.corner_count);
  std::vector<uint32_t> first_of(mesh.vertex_count, kNone), next_of;
  for (uint32_t k = 0; k < mesh.corner_count; ++k) {
    const uint32_t v = mesh.corners[k];
    uint32_t s = first_of[v];
    while (s != kNone && !values.same(k, (*first_corner)[s])) s = next_of[s];
    if (s == kNone) {
      s = uint32_t(first_corner->size());
      first_corner->push_back(k);
      next_of.push_back(first_of[v]);
      first_of[v] = s;
    }
    (*of_corner)[k] = s;
  }
}

// qmc_mesh's fans (each polygon from its first corner) over the split vertices.
std::vector<uint32_t> split_fans(const qmc_mesh& mesh, const std::vector<uint32_t>& of_corner) {
  std::vector<uint32_t> triangles;
  triangles.reserve(3 * size_t(mesh.triangle_count));
  for (uint32_t f = 0, first = 0; f < mesh.face_count; first += mesh.face_sizes[f++])
    for (uint32_t k = 1; k + 1 < mesh.face_sizes[f]; ++k) {
      triangles.push_back(of_corner[first]);
      triangles.push_back(of_corner[first + k]);
      triangles.push_back(of_corner[first + k + 1]);
    }
  return triangles;
}

template <typename T>
T* malloc_copy(const std::vector<T>& from) {
  T* to = static_cast<T*>(std::malloc(from.empty() ? 1 : from.size() * sizeof(T)));
  if (to && !from.empty()) std::memcpy(to, from.data(), from.size() * sizeof(T));
  return to;
}

}  // namespace

extern "C" {

void qmc_split_mesh_free(qmc_split_mesh* mesh) {
  if (!mesh) return;
  std::free(mesh->first_corner);
  std::free(mesh->triangles);
  std::memset(mesh, 0, sizeof(*mesh));
}

int qmc_decoder_split_mesh(const qmc_decoder* decoder, qmc_split_mesh* out) {
  if (!decoder || !out) return QMC_INVALID_ARGUMENT;
  std::memset(out, 0, sizeof(*out));
  qmc_mesh mesh;
  if (int error = qmc_decoder_mesh(decoder, QMC_FINEST, &mesh); error != QMC_OK) return error;
  int result = QMC_LIMIT_EXCEEDED;  // what an allocation that fails gives, as in qmc_decoder_mesh
  QMC_TRY {
    CornerValues values;
    result = read_corner_values(decoder, &values);
    if (result == QMC_OK) {
      std::vector<uint32_t> first_corner, of_corner;
      split(mesh, values, &first_corner, &of_corner);
      const std::vector<uint32_t> triangles = split_fans(mesh, of_corner);
      out->vertex_count = uint32_t(first_corner.size());
      out->triangle_count = uint32_t(triangles.size() / 3);
      out->first_corner = malloc_copy(first_corner);
      out->triangles = malloc_copy(triangles);
      if (!out->first_corner || !out->triangles) result = QMC_LIMIT_EXCEEDED;
    }
  }
  QMC_CATCH_ALL(result = QMC_LIMIT_EXCEEDED)
  qmc_mesh_free(&mesh);
  if (result != QMC_OK) qmc_split_mesh_free(out);
  return result;
}

}  // extern "C"
